// How well a recognizer does on labelled strokes: the confusion table and
// the two numbers issue 22 sets targets for (at least 95% of gestures
// right; at most 2% of non-gestures taken for a gesture).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "garden/gesture/gesture_labels.h"

namespace hg::garden {

struct ConfusionTable {
    // counts[truth][answer], in label order.
    std::array<std::array<int, kGestureLabelCount>, kGestureLabelCount> counts{};

    void add(GestureLabel truth, GestureLabel answer) { ++counts[labelIndex(truth)][labelIndex(answer)]; }
    int total() const;
    int correct() const;
    double accuracy() const;           // correct / total (0 when empty)
    int gestures() const;              // strokes whose truth is a gesture
    double gestureAccuracy() const;    // of those, the share answered right
    int nones() const;                 // strokes whose truth is none
    double falseGestureRate() const;   // of those, the share answered with a gesture

    // A fixed-width text table, a row per true label that occurs (or every
    // label with `all`), columns the answers.
    std::string format(bool all = false) const;
};

ConfusionTable confusionOf(const std::vector<GestureLabel>& truth, const std::vector<GestureLabel>& answers);

}  // namespace hg::garden
