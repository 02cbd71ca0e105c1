#!/usr/bin/env bash
# Installs the dependencies, builds the release preset and runs the program's
# main job: until the garden window exists, `hypergarden check` and
# `hypergarden voxelize` (256 voxels, with statistics) over every bundled
# HyperFun sculpture; the grids go to build/content/*.vdb.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)" --target hypergarden
mkdir -p build/content
status=0
for f in content/hyperfun/*.hf; do
  ./build/release/hypergarden check "$f" || status=1
  ./build/release/hypergarden voxelize "$f" --res 256 --stats -o "build/content/$(basename "$f" .hf).vdb" || status=1
done
exit $status
