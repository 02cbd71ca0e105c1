// The desktop's keys (the one table of them is garden/render/key_table.*):
// a GLFW key press becomes a command, gathered between frames in DesktopKeys.
// The frame hands undo, redo and the navigation toggles to the hands
// (DesktopInput, mapDesktop); the tool keys and the wheel become the
// hands' tool intents (garden/hands/tool_intents.h), which the session
// applies as it applies the headset's (GardenSession::applyToolIntents).
#pragma once

#include <optional>
#include <string>

#include <glm/mat4x4.hpp>

#include "garden/hands/desktop_hands.h"
#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

class GardenSession;

// Key presses since the last frame.
struct DesktopKeys {
    std::optional<ToolSettings::Kind> tool;  // 0 none, 1 carve, ... 7 sketch
    int sizeSteps = 0;                       // ] +1, [ -1, summed
    bool reverse = false;                    // R
    bool mirror = false;                     // M
    bool undo = false;                       // Ctrl+Z
    bool redo = false;                       // Ctrl+Shift+Z, Ctrl+Y
    bool undoSelected = false;               // Ctrl+Alt+Z: the selection's last action
    bool history = false;                    // H: the history panel
    bool fly = false, orbit = false, detail = false, screenshot = false;  // space, O, G, F12
    bool escape = false;                     // Esc (escapeDoes)
    bool frameGarden = false;                // Home: every sculpture in view
    bool help = false;                       // F1: the key list
    bool stats = false;                      // F3: the frame statistics open / collapsed
    bool clayView = false;                   // C: the clay view on / off
    bool wireframe = false;                  // X: the wireframe overlay on / off
    bool headset = false;                    // F9: into the headset, and back
};

// Adds one press of a GLFW key with its modifier bits (looked up in the key
// table); false when the key means nothing here or is a held key (walking,
// Shift: polled each frame).
bool addKeyPress(DesktopKeys& keys, int glfwKey, int glfwMods);

// What Esc does, the first that applies: an open drop-down or pop-up of
// the panels closes (ImGui's, open in the last frame), the help or the
// first-run overlay closes, a "quit without saving?" question opens when
// something is not saved, else the window closes.
enum class EscapeDoes { ClosePopup, CloseHelp, AskToQuit, Quit };
EscapeDoes escapeDoes(bool popupOpen, bool helpOpen, bool unsaved);
// A drop-down or pop-up of the panels is open (false without ImGui);
// closes them all.
bool popupOpen();
void closePopups();
// Work that closing would lose: with a session folder, actions its journal
// could not write; without one, any action at all.
bool unsavedWork(const GardenSession& session);
// What would be lost, for the question.
std::string unsavedWhat(const GardenSession& session);

// The size factor of one [ or ] press, and of one wheel notch scaling the
// selection.
constexpr double kToolSizeStep = 1.25;
// Wheel notches and [ ] presses scaling the selection less than this apart
// (seconds) are one burst: one live move, one undo step.
constexpr double kScaleBurstSeconds = 0.4;

// What the desktop's hands keep from frame to frame.
struct DesktopCarry {
    float speed = 1.0f;                          // the walking speed scale
    double sinceScaleStep = kScaleBurstSeconds;  // seconds since the last notch or press that scaled the selection
};

// The tool keys and the wheel as this frame's tool intents: the tool
// picked; [ and ] as size steps (x1.25 a press: the tool's size, or with
// the move tool the selection's scale); with the move tool and a selection
// the wheel's notches as selection scale steps (the wheel is consumed, set
// to 0, else left for the walking speed); R the reverse toggled; M the
// selected sculpture's mirror plane toggled. Steps that scale the selection
// within kScaleBurstSeconds of each other keep the gesture `held`. `dt` is
// the time since the last frame.
ToolIntents desktopIntents(const DesktopKeys& keys, float& wheel, const GardenSession& session, double dt,
                           DesktopCarry& carry);

// One desktop frame's hands: `in` with this frame's undo, redo, fly and
// orbit presses (and the wheel the tool keys left) mapped onto hands
// (mapDesktop) with the session's view and `projection`, carrying the
// tool keys' intents (desktopIntents). The window and the tests both run
// this.
Hands desktopHands(DesktopInput in, const DesktopKeys& keys, const GardenSession& session, const glm::mat4& projection,
                   double dt, DesktopCarry& carry);

}  // namespace hg::garden
