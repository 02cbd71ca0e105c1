// `hypergarden --xr`: the garden in a headset (docs/design.md §8, docs/xr.md). The
// same GardenSession, tools and renderer as the desktop window; the
// controllers become the Hands (xr/controllers.h), both eyes are drawn into
// the runtime's sRGB swapchains, and the frame follows xrWaitFrame with the
// predicted display period as the frame budget. A small window mirrors the
// left eye. The desktop and the headset switch without a restart: F9 (or
// the mirror's button) goes to the desktop on the same open garden, and the
// desktop's F9 comes back (headsetFromDesktop).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "garden/render/render_quality.h"
#include "garden/window/mode_switch.h"

namespace hg::garden {
class GardenSession;
struct FrameStats;
}

namespace hg::xr {

// Exit statuses besides 0 (done), 1 (the runtime or GL failed) and 2 (a
// garden, session or script that cannot be read).
constexpr int kExitNoRuntime = 3;

struct XrOptions {
    std::string garden;      // the garden file ("" with a script: the script's)
    bool gardenGiven = false;  // named by the user: told when an existing session keeps its own
    std::string session;     // a session folder ("" : none)
    // What the sculptures may hold (SessionSettings::memoryBudgetBytes; --memory-budget).
    std::size_t memoryBudgetBytes = std::size_t{1024} << 20;
    std::string script;      // a replay script whose commands run at their frames ("" : none)
    int frames = 0;          // ask the runtime to end the session after this many frames (0: never)
    // The left hand holds the tool; seated: raise the tracked heights by a
    // seated user's shorter reach (the settings' offset, 0.5 m unless
    // changed); smooth turn: the left stick turns smoothly instead of in
    // snaps. Unset: the user's settings (xr/xr_settings.h), which the hand
    // panel changes and keeps.
    std::optional<bool> leftHanded;
    std::optional<bool> seated;
    std::optional<bool> smoothTurn;
    std::string settingsFile;  // the user's settings ("" : xrSettingsPath())
    // What the eyes' picture spends (--quality): a preset kept all along, or
    // with autoQuality a QualityGovernor stepping down from `autoCeiling`
    // (unset: the GL renderer's preset, as the desktop's auto) by both eyes'
    // GPU time against the headset's display period (docs/rendering.md).
    // Neither: the renderer's quality as it is.
    std::optional<garden::RenderQuality> quality;
    bool autoQuality = false;
    float impostorDistance = 30.0f;  // far sculptures as cards beyond it (0: never; --impostor-distance)
    std::optional<garden::QualityPreset> autoCeiling;
    bool mirror = true;      // show the mirror window (hidden when false)
    // Called after every focused frame with its stats and its index from
    // the first focused frame (benchmarks).
    std::function<void(const garden::FrameStats&, int)> onFrame;
    // The desktop that F9 and the mirror's "Desktop" button open on the same
    // garden and window (the headset session ends first): the program's
    // entry gives it (cli/, desktopAfterHeadset); unset: no desktop, the run
    // ends with the headset session.
    garden::DesktopEntry desktop;
    // Called after every submitted frame with their count; true asks for
    // the desktop as F9 does (tests).
    std::function<bool(int)> askDesktop;
};

// What a run did, for the caller (tests) at its end.
struct XrRunInfo {
    int framesSubmitted = 0;   // xrEndFrame calls
    int framesRendered = 0;    // ... with both views drawn
    int focusedFrames = 0;
    bool lost = false;         // the runtime lost the session or the instance
    std::string endReason;
    std::string interactionProfile;
    std::string space;         // STAGE or LOCAL
    bool depthSubmitted = false;
    float worldScale = 1.0f;   // the stage rig's scale at the end (world metres per stage metre)
    garden::RenderQuality quality;  // the eyes' at the end
    int qualityChanges = 0;         // the automatic quality's steps
    double qualityBudgetMs = 0.0;   // the period it steered by (0: none)
};

// Runs until the session ends. `atEnd` (if set) sees the garden session
// after the last frame, its finished strokes journalled.
int runXrGarden(const XrOptions& options,
                const std::function<void(garden::GardenSession&, const XrRunInfo&)>& atEnd = {});

// The desktop's way into the headset (DesktopOptions::headset): a headset
// session with `options` (its garden, session and script are the desktop's,
// ignored here) on the garden open in the desktop's window, until the
// runtime ends it or the user asks for the desktop. No runtime or a failure:
// back at once, the message says why. `ran` (if set) sees each run's info.
garden::HeadsetEntry headsetFromDesktop(XrOptions options, std::function<void(const XrRunInfo&)> ran = {});

}  // namespace hg::xr
