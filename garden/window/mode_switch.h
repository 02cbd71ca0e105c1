// The desktop and the headset switch without a restart, on one open
// garden and one window (docs/xr.md, "Desktop and headset"): each mode is
// handed the other's way in as a function, so neither folder includes the
// other; the program's entry (cli/) joins them.
#pragma once

#include <functional>
#include <string>

namespace hg::garden {

class GardenSession;
class GardenWindow;

// How a headset run that the desktop started came back.
enum class HeadsetReturn {
    Desktop,  // the headset session ended (or could not start: `message` says why): the desktop goes on
    Quit,     // the window was closed meanwhile: the program ends
};

// Runs the headset on the garden open in the window; the desktop loop
// waits meanwhile. `message` is for the user (no runtime, a failure).
using HeadsetEntry = std::function<HeadsetReturn(GardenSession&, GardenWindow&, std::string& message)>;

// Runs the desktop on the garden open in the window after the headset
// session ended at the user's asking (F9, the mirror's button): the
// program's exit status.
using DesktopEntry = std::function<int(GardenSession&, GardenWindow&)>;

}  // namespace hg::garden
