// Labelled training strokes made from templates (docs/gestures.md, "Data"):
// each gesture drawn as a pen path of straight runs and arcs with random
// proportions, then perturbed as a hand and a mouse perturb it: wobble,
// uneven stretching, hooks and overshoot at the ends, any rotation, size
// and position, uneven drawing speed (so uneven point spacing), jitter and
// whole-pixel rounding. `none` strokes are straight and bent lines, gentle
// arcs, soft S curves, zigzags and random scribbles.
#pragma once

#include <cstdint>
#include <vector>

#include "garden/gesture/gesture_labels.h"
#include "garden/gesture/stroke.h"

namespace hg::garden {

struct LabelledStroke {
    StrokePoints points;
    GestureLabel label = GestureLabel::None;
};

// One stroke of `label`; the same (label, seed) gives the same stroke.
StrokePoints generateStroke(GestureLabel label, std::uint64_t seed);

// `perGesture` strokes of each gesture and `none` strokes of no gesture,
// in label order. Sets made from different `seed`s share no stroke.
std::vector<LabelledStroke> generateStrokeSet(int perGesture, int none, std::uint64_t seed);

}  // namespace hg::garden
