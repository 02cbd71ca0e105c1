// The desktop mapping onto hands (docs/design.md §6): keys and mouse become a
// navigation hand and a tool hand, so the tools and the navigator run the
// same code on the desktop, in XR and in scripts.
//
//   W A S D       navigation thumbstick (forward, left, back, right)
//   Q / E         down / up (thumbstick of the tool hand, y axis)
//   right button  mouse look (drag)
//   wheel         walking speed (each notch x1.25); with the move tool and
//                 a selection, the selected sculpture's scale instead (a
//                 tool intent; notches less than 0.4 s apart: one undo)
//   left button   tool trigger; the tool hand's aim is the ray under the mouse
//   Shift         held: the tool hand's secondary button (the move tool
//                 turns the sculpture instead of moving it)
//   space         stick click: fly / walk
//   O             primary button: orbit the selected sculpture
//   Ctrl+Z        undo (the tool hand's undo button)
//   Ctrl+Shift+Z, Ctrl+Y  redo (its redo button)
//
// What the tool hand holds is set by keys that become the hands' tool
// intents (garden/desktop/desktop_keys.h, garden/hands/tool_intents.h):
// 0 none (the morph selector), 1 carve, 2 add, 3 melt, 4 perturb,
// 5 impacts, 6 move, 7 sketch; [ and ] the tool's size (x1.25 a press); R reverse;
// M the selected sculpture's mirror plane. Other keys: G the detail
// sphere, F9 the headset (and back), F12 a screenshot, Esc quits. Keys and clicks that ImGui wants are not taken.
#pragma once

#include <glm/mat4x4.hpp>

#include "garden/hands/hand_state.h"
#include "garden/hands/pointer_events.h"

namespace hg::garden {

// The raw state of keys and mouse this frame, as the window saw it.
struct DesktopInput {
    bool forward = false, back = false, left = false, right = false, up = false, down = false;
    bool lookButton = false;   // right button held
    bool toolButton = false;   // left button held
    bool flyToggle = false, orbitToggle = false, undo = false, redo = false;  // pressed this frame
    bool turn = false;         // Shift held
    glm::vec2 mouse{0.0f};     // pixels, origin top-left
    glm::vec2 mouseDelta{0.0f};
    float wheel = 0.0f;        // notches this frame
    glm::vec2 viewport{1280.0f, 720.0f};
};

// This frame's pointer (its events folded, garden/hands/pointer_events.h)
// into `in`: the buttons held, the tool's pixel in framebuffer pixels
// (`windowToFramebuffer` scales window pixels; HiDPI) and the look drag.
// `free`: the panels do not have the mouse; else neither button acts.
void applyPointer(DesktopInput& in, const PointerFrame& p, glm::vec2 windowToFramebuffer, bool free);

struct DesktopMapping {
    float lookRadiansPerPixel = 0.004f;
    float speedStep = 1.25f;
};

// `view` and `projection` are the camera's this frame: the tool's aim is the
// ray through the mouse. Hands keep the speed scale from frame to frame.
Hands mapDesktop(const DesktopInput& in, const glm::mat4& view, const glm::mat4& projection, const DesktopMapping& m,
                 float previousSpeedScale);

// The world ray through a pixel (origin at the camera, unit direction).
Pose rayThroughPixel(glm::vec2 pixel, glm::vec2 viewport, const glm::mat4& view, const glm::mat4& projection);

}  // namespace hg::garden
