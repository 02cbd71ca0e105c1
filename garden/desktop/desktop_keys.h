// The desktop's keys (the full list is in garden/hands/desktop_hands.h): a
// GLFW key press becomes a command, gathered between frames in DesktopKeys.
// The frame hands undo, redo and the navigation toggles to the hands
// (DesktopInput, mapDesktop); the tool keys change what the tool hand holds
// and are applied to the session here.
#pragma once

#include <optional>

#include <glm/mat4x4.hpp>

#include "garden/hands/desktop_hands.h"
#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

class GardenSession;

// Key presses since the last frame.
struct DesktopKeys {
    std::optional<ToolSettings::Kind> tool;  // 0 none, 1 carve, 2 add, 3 melt, 4 perturb, 5 impacts, 6 move
    int sizeSteps = 0;                       // ] +1, [ -1, summed
    bool reverse = false;                    // R
    bool mirror = false;                     // M
    bool undo = false;                       // Ctrl+Z
    bool redo = false;                       // Ctrl+Shift+Z, Ctrl+Y
    bool fly = false, orbit = false, detail = false, screenshot = false, quit = false;  // space, O, G, F12, Esc
    bool resetView = false;                  // Home: back to the garden's start
    bool help = false;                       // F1: the key list
    bool headset = false;                    // F9: into the headset, and back
};

// Adds one press of a GLFW key with its modifier bits; false when the key
// means nothing here.
bool addKeyPress(DesktopKeys& keys, int glfwKey, int glfwMods);

// Esc quits, unless it was pressed to close a drop-down or popup of the
// panels (open in the last frame): then it is the panel's.
bool quitRequested(const DesktopKeys& keys);

// The size factor of one [ or ] press.
constexpr double kToolSizeStep = 1.25;

// Applies the tool keys: the tool picked; its size (scaleToolSize), or with
// the move tool the selected sculpture's scale by `wheel` notches and the
// size steps together (one undoable move; the wheel is consumed, set to 0,
// else left for the walking speed); reverse toggled; the selected
// sculpture's mirror plane (centralMirror) on or off.
void applyToolKeys(const DesktopKeys& keys, float& wheel, GardenSession& session);

// One desktop frame's hands: the tool keys applied to the session, then
// `in` with this frame's undo, redo, fly and orbit presses (and the wheel
// the tool keys left) mapped onto hands (mapDesktop) with the session's
// view and `projection`. `speed` is the walking speed scale, kept from
// frame to frame. The window and the tests both run this.
Hands desktopHands(DesktopInput in, const DesktopKeys& keys, GardenSession& session, const glm::mat4& projection,
                   float& speed);

}  // namespace hg::garden
