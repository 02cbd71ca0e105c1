// The mouse's buttons and moves as events, in the order the window got them
// between two frames (docs/desktop.md "Input"), folded into one frame's
// pointer state. Polling the buttons once a frame loses a click shorter
// than a frame and takes a move made just before a right-button press as a
// look drag (the view jumps at low frame rates); the events do neither.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace hg::garden {

enum class PointerButton { Tool, Look, Gesture };  // the left, right and middle button

struct PointerEvent {
    enum class Kind { Move, Press, Release } kind = Kind::Move;
    PointerButton button = PointerButton::Tool;  // Press, Release
    glm::vec2 position{0.0f};                    // window pixels, origin top-left (Move: where to; else where)
};

// What the buttons and the mouse were at the end of the last frame.
struct PointerState {
    bool toolDown = false, lookDown = false, gestureDown = false;
    glm::vec2 position{0.0f};
};

// One frame of the pointer.
struct PointerFrame {
    // Held this frame: down at its end, or pressed during it (a click
    // shorter than a frame is one frame of held, then released).
    bool toolButton = false, lookButton = false, gestureButton = false;
    bool toolPressed = false;    // a tool press came this frame
    glm::vec2 toolPosition{0.0f};  // where the tool points: the press's place in the frame of a press, else the end
    glm::vec2 lookDelta{0.0f};     // moves made while the look button was down (not those before its press)
};

// Folds this frame's events into `state` (left as at the frame's end).
PointerFrame foldPointerEvents(const std::vector<PointerEvent>& events, PointerState& state);

}  // namespace hg::garden
