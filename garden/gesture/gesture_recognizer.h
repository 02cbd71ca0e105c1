// A trained network with its confidence threshold: a stroke in, a label
// out. Below the threshold, or for a stroke too short to be meant, the
// answer is `none` and nothing should happen (issue 22).
#pragma once

#include <array>

#include "garden/gesture/gesture_labels.h"
#include "garden/gesture/gesture_network.h"
#include "garden/gesture/stroke.h"

namespace hg::garden {

struct GestureResult {
    GestureLabel label = GestureLabel::None;  // what to act on: `best`, or none below the threshold
    GestureLabel best = GestureLabel::None;   // the network's most probable label
    double confidence = 0.0;                  // the probability of `best`
    std::array<double, kGestureLabelCount> probabilities{};
    bool tooShort = false;                    // shorter than minimumLength (or a single point)
};

struct GestureRecognizer {
    GestureNetwork network;
    // The least probability that acts; chosen with the training (docs/gestures.md).
    double threshold = 0.7;
    // Strokes shorter than this (pixels) are clicks or pen slips, not
    // gestures. The one place where size matters.
    double minimumLength = 12.0;

    GestureResult classify(const StrokePoints& points) const;
};

}  // namespace hg::garden
