#!/usr/bin/env bash
# Installs the dependencies, builds the release preset and runs the program's
# main job: until the garden window exists, `hypergarden check` over every
# bundled HyperFun sculpture.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)" --target hypergarden
status=0
for f in content/hyperfun/*.hf; do
  ./build/release/hypergarden check "$f" || status=1
done
exit $status
