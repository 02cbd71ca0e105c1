// The desktop mapping onto hands (docs/design.md §6): keys and mouse become a
// navigation hand and a tool hand, so the tools and the navigator run the
// same code on the desktop, in XR and in scripts. W A S D walk (the
// navigation thumbstick), Q / E go down and up (the tool hand's stick), the
// right button looks, the left button is the tool's trigger aimed along the
// mouse ray, Shift its secondary button, space and O the stick click and
// the primary button, Ctrl+Z and Ctrl+Shift+Z its undo and redo. Which key
// is which, and every other key, is the one key table the window binds:
// garden/render/key_table.h (also the F1 help, `hypergarden keys` and the
// README's table). The mouse's buttons come as events: pointer_events.h.
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
    bool gestureButton = false;  // middle button held: the mouse draws a gesture
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
