#!/usr/bin/env bash
# Runs the fuzzers for a bounded time (seconds, default 60, for the HyperFun
# parser; half as long for the garden files and replay scripts, for the
# session journal and for the export mesher's grids), seeded with
# the bundled and shared files. Needs `cmake --preset fuzz`.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
corpus="build/fuzz/corpus"
mkdir -p "$corpus"
for dir in content/hyperfun tests/data/hyperfun/conformance tests/data/hyperfun/corpus; do
  if [ -d "$dir" ]; then cp -f "$dir"/*.hf "$corpus"/ 2>/dev/null || true; fi
done
./build/fuzz/tests/fuzz/hg_parser_fuzz -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 "$corpus"

json="build/fuzz/corpus-json"
mkdir -p "$json"
cp -f content/gardens/*.json content/replays/*.json "$json"/
./build/fuzz/tests/fuzz/hg_garden_files_fuzz -max_total_time="$(( (seconds + 1) / 2 ))" -max_len=8192 -timeout=10 \
  -rss_limit_mb=2048 "$json"

journal="build/fuzz/corpus-journal"
mkdir -p "$journal"
printf 'hypergarden-journal 1\n%s\n' \
  '1b1e7ea1 {"action":"undo"}' > "$journal/seed.hgj"
./build/fuzz/tests/fuzz/hg_journal_fuzz -max_total_time="$(( (seconds + 1) / 2 ))" -max_len=8192 -timeout=10 \
  -rss_limit_mb=2048 "$journal"

# Grids for the export mesher: every mesh closed, manifold and outward. The
# seed is two cells whose shared face is a checkerboard both loop through
# (a plate with a pit and a rod across it), which once meshed an edge of four
# triangles. Full-length inputs from the start (-len_control=0): a grid
# needs a few hundred values before such cells are likely.
grids="build/fuzz/corpus-grids"
mkdir -p "$grids"
printf '\000\001\000\000\240\240\140\240\240\240\240\140\240\140\240\140' > "$grids/saddle.grid"
./build/fuzz/tests/fuzz/hg_export_mesher_fuzz -max_total_time="$(( (seconds + 1) / 2 ))" -max_len=4096 -len_control=0 \
  -timeout=10 -rss_limit_mb=2048 "$grids"
