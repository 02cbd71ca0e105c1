#!/usr/bin/env bash
# Rebuilds content/gestures/weights.json, the gesture recognizer's weights,
# from the repository alone (docs/gestures.md, "Retraining"): strokes from
# garden/gesture/stroke_generator.cpp, trained by hg_gesture_train with the
# recipe in garden/gesture/gesture_training.h. Deterministic: the same
# build writes the same file, and a test (tests/gesture/committed_weights_test.cpp)
# checks that the committed file is what this writes. Also prints the
# accuracy on held-out generated strokes and on the committed hand-like set.
#
#   scripts/train-gestures.sh [BUILD_DIR]      (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target hg_gesture_train
"$build/hg_gesture_train" -o content/gestures/weights.json --check content/gestures/handlike.json
