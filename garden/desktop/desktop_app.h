// The desktop garden: a window onto the garden, walked with the keys and
// mouse (garden/hands/desktop_hands.h), the morph selected in an on-screen
// triangle or on the ground, the tool picked and shaped in the tool panel
// and with keys (desktop_keys.h) and drawn where the mouse points
// (render/tool_gizmo.h), frame stats in an overlay, F12 screenshots.
#pragma once

#include <string>

namespace hg::garden {

struct DesktopOptions {
    std::string garden;         // the garden file
    int width = 1280, height = 720;
    bool vsync = true;
    double budgetMs = 11.1;
    std::string screenshotDir = ".";
    int frames = 0;             // stop after this many frames (0: until closed); smoke tests
    std::string exitScreenshot; // a PNG of the last frame, overlay included ("" : none)
    std::string session;        // a session folder (made from `garden` when new); "" : none
};

// Runs until the window closes. 0 on a normal close, 1 when the window or
// GL cannot be had, 2 when the garden file is refused.
int runDesktopGarden(const DesktopOptions& options);

}  // namespace hg::garden
