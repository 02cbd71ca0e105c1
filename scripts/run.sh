#!/usr/bin/env bash
# Installs the dependencies, builds the release preset and opens the garden
# (content/gardens/default.json): walk with WASD and the mouse (right button
# looks), pick the metamorphosis in the triangle at the top right.
# Extra arguments go to `hypergarden` (for example --garden FILE).
#
# Without a display (a server, a container) there is no window to open:
# it plays content/replays/walk_and_morph.json offscreen instead and says
# where the screenshots went.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)" --target hypergarden
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec ./build/release/hypergarden "$@"
fi
echo "run.sh: no display, so no window: replaying a walk through the garden offscreen instead"
mkdir -p build/screenshots
xvfb-run -a ./build/release/hypergarden replay content/replays/walk_and_morph.json \
  --offscreen 1280x720 --screenshot-every 60 --screenshot-dir build/screenshots \
  --stats build/screenshots/stats.json
echo "run.sh: screenshots and frame statistics in build/screenshots/"
