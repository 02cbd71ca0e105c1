// The recognizer's vocabulary (issue 22, docs/gestures.md). Directions are
// as seen on the screen (y down): a "left" turn is counter-clockwise on
// the screen, as a pen turning to its own left.
#pragma once

#include <array>
#include <optional>
#include <string>

namespace hg::garden {

enum class GestureLabel {
    None,       // no gesture: scribbles, straight lines, gentle or random curves
    Sketch,     // a V: one sharp turn (either way)
    Union,      // a U drawn from its left tip: a half turn to the left
    Intersect,  // an arch drawn from its left foot: a half turn to the right
    Deform,     // a Z: two sharp turns, alternating (right then left, or left then right)
    Shrink,     // a loop circling clockwise on screen (one or more turns)
    Grow,       // a loop circling counter-clockwise on screen
};

constexpr int kGestureLabelCount = 7;

// In the network's output order (the enum's order).
constexpr std::array<GestureLabel, kGestureLabelCount> kGestureLabels = {
    GestureLabel::None,  GestureLabel::Sketch, GestureLabel::Union, GestureLabel::Intersect,
    GestureLabel::Deform, GestureLabel::Shrink, GestureLabel::Grow};

inline int labelIndex(GestureLabel label) { return static_cast<int>(label); }

// "none", "sketch", "union", "intersect", "deform", "shrink", "grow".
const char* labelName(GestureLabel label);
// The label named `name`, or nothing.
std::optional<GestureLabel> labelFromName(const std::string& name);
// "none, sketch, ..." for messages.
std::string labelNameList();

}  // namespace hg::garden
