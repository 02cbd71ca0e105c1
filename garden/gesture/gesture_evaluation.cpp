#include "garden/gesture/gesture_evaluation.h"

#include <cstdio>

namespace hg::garden {

namespace {

constexpr int kNone = 0;  // labelIndex(GestureLabel::None)

double ratio(int a, int b) { return b > 0 ? static_cast<double>(a) / b : 0.0; }

}  // namespace

int ConfusionTable::total() const {
    int n = 0;
    for (const auto& row : counts)
        for (int c : row) n += c;
    return n;
}

int ConfusionTable::correct() const {
    int n = 0;
    for (int k = 0; k < kGestureLabelCount; ++k) n += counts[k][k];
    return n;
}

double ConfusionTable::accuracy() const { return ratio(correct(), total()); }

int ConfusionTable::gestures() const { return total() - nones(); }

double ConfusionTable::gestureAccuracy() const { return ratio(correct() - counts[kNone][kNone], gestures()); }

int ConfusionTable::nones() const {
    int n = 0;
    for (int c : counts[kNone]) n += c;
    return n;
}

double ConfusionTable::falseGestureRate() const { return ratio(nones() - counts[kNone][kNone], nones()); }

std::string ConfusionTable::format(bool all) const {
    std::string out = "truth \\ answer";
    char cell[32];
    for (GestureLabel l : kGestureLabels) {
        std::snprintf(cell, sizeof cell, " %9s", labelName(l));
        out += cell;
    }
    out += "\n";
    for (GestureLabel truth : kGestureLabels) {
        int rowTotal = 0;
        for (int c : counts[labelIndex(truth)]) rowTotal += c;
        if (rowTotal == 0 && !all) continue;
        std::snprintf(cell, sizeof cell, "%-14s", labelName(truth));
        out += cell;
        for (int c : counts[labelIndex(truth)]) {
            std::snprintf(cell, sizeof cell, " %9d", c);
            out += cell;
        }
        out += "\n";
    }
    return out;
}

ConfusionTable confusionOf(const std::vector<GestureLabel>& truth, const std::vector<GestureLabel>& answers) {
    ConfusionTable t;
    for (std::size_t i = 0; i < truth.size() && i < answers.size(); ++i) t.add(truth[i], answers[i]);
    return t;
}

}  // namespace hg::garden
