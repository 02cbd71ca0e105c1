// The desktop garden: a window onto the garden, walked with the keys and
// mouse (garden/hands/desktop_hands.h), the morph selected in an on-screen
// triangle or on the ground, the tool picked and shaped in the tool panel
// and with keys (desktop_keys.h) and drawn where the mouse points
// (render/tool_gizmo.h), frame stats in an overlay, F12 screenshots. F9 (or
// the Garden panel's Headset button) puts the same open garden into a
// headset and comes back when the headset session ends.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "garden/render/render_quality.h"
#include "garden/window/mode_switch.h"

namespace hg::garden {

class GardenSession;
class GardenWindow;
class SessionPanel;
class SessionRecorder;

struct DesktopOptions;
// The folder F12 writes into (made when missing), per DesktopOptions::screenshotDir.
std::string screenshotFolder(const DesktopOptions& options);

struct DesktopOptions {
    std::string garden;         // the garden file
    bool gardenGiven = false;   // named by the user: told when an existing session keeps its own
    int width = 1280, height = 720;
    bool vsync = true;
    double budgetMs = 11.1;
    // What the sculptures may hold (SessionSettings::memoryBudgetBytes; --memory-budget).
    std::size_t memoryBudgetBytes = std::size_t{1024} << 20;
    // Where F12 screenshots go; "": the session's screenshots/ folder, or
    // ~/Pictures/hypergarden without a session (screenshotFolder).
    std::string screenshotDir;
    int frames = 0;             // stop after this many frames (0: until closed); smoke tests
    std::string exitScreenshot; // a PNG of the last frame, overlay included ("" : none)
    std::string session;        // a session folder (made from `garden` when new); "" : none
    RenderQuality quality;      // --quality: what the renderer spends on the picture
    float impostorDistance = 30.0f;  // --impostor-distance: far sculptures as cards beyond it (0: never)
    bool autoQuality = false;   // instead: from rendererPreset, stepped by the GPU's time (QualityGovernor)
    HeadsetEntry headset;       // F9 and the Headset button (empty: the desktop only)
    // Called at the end of every desktop frame with its index; true asks
    // for the headset as F9 does (tests, scripts).
    std::function<bool(GardenSession&, int)> onFrame;
    // Called at the end of every desktop frame on a session folder; a
    // folder returned is gone on in, as the Session section's Save As and
    // recent sessions do (tests, scripts).
    std::function<std::string(int)> goToSession;
    // The desktop's user settings file (desktop_settings.h); none: the
    // user's (desktopSettingsPath()).
    std::optional<std::string> settingsPath;
    // The recent-sessions file (recent_sessions.h); none: the user's
    // (recentSessionsPath()).
    std::optional<std::string> recentSessionsPath;
};

// Runs until the window closes. 0 on a normal close, 1 when the window or
// GL cannot be had, 2 when the garden file is refused.
int runDesktopGarden(const DesktopOptions& options);

// The desktop loop on a garden and window already open (a headset run's
// "back to the desktop"): until the window closes or `options.frames`
// desktop frames. 0, or 1 when a screenshot cannot be written.
// `link`: the session folder the window writes and the Session section
// (session_panel.h); when the user picks another folder to go on in (Save
// As, a recent session) the loop ends with it in link->goTo.
struct DesktopSessionLink {
    const SessionRecorder* recorder = nullptr;
    SessionPanel* panel = nullptr;
    std::string goTo;
};
int runDesktopOn(GardenSession& session, GardenWindow& window, const DesktopOptions& options,
                 DesktopSessionLink* link = nullptr);

// The desktop window's size and title for `options` (a window the headset
// opened as its mirror takes them when the user goes to the desktop).
void showAsDesktop(GardenWindow& window, const DesktopOptions& options);

// The desktop's way in after a headset run (xr::XrOptions::desktop): the
// headset's mirror window shown as the desktop's, then runDesktopOn.
// `options.headset` is the way back (F9).
DesktopEntry desktopAfterHeadset(DesktopOptions options);

}  // namespace hg::garden
