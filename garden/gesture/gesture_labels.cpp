#include "garden/gesture/gesture_labels.h"

namespace hg::garden {

const char* labelName(GestureLabel label) {
    switch (label) {
        case GestureLabel::None: return "none";
        case GestureLabel::Sketch: return "sketch";
        case GestureLabel::Union: return "union";
        case GestureLabel::Intersect: return "intersect";
        case GestureLabel::Deform: return "deform";
        case GestureLabel::Shrink: return "shrink";
        case GestureLabel::Grow: return "grow";
    }
    return "none";
}

std::optional<GestureLabel> labelFromName(const std::string& name) {
    for (GestureLabel l : kGestureLabels)
        if (name == labelName(l)) return l;
    return std::nullopt;
}

std::string labelNameList() {
    std::string s;
    for (GestureLabel l : kGestureLabels) s += (s.empty() ? "" : ", ") + std::string(labelName(l));
    return s;
}

}  // namespace hg::garden
