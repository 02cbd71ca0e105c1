#!/usr/bin/env bash
# Runs the parser fuzzer for a bounded time (seconds, default 60), seeded
# with the bundled and shared HyperFun files. Needs `cmake --preset fuzz`.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
corpus="build/fuzz/corpus"
mkdir -p "$corpus"
for dir in content/hyperfun ../shared/hyperfun/conformance ../shared/hyperfun/corpus; do
  if [ -d "$dir" ]; then cp -f "$dir"/*.hf "$corpus"/ 2>/dev/null || true; fi
done
./build/fuzz/tests/fuzz/hg_parser_fuzz -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 "$corpus"
