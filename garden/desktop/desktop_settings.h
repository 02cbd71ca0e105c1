// The desktop window's user settings kept between runs, in a small JSON
// file beside the headset's (xr/xr_settings.h):
//   {"first_run_done": true}
// at $HG_DESKTOP_SETTINGS, else $XDG_CONFIG_HOME/hypergarden/desktop.json,
// else ~/.config/hypergarden/desktop.json. Read at start (a missing file or
// key keeps the default: the first-run overlay is shown); written
// atomically when the first-run overlay is dismissed.
#pragma once

#include <optional>
#include <string>


namespace hg::garden {

struct DesktopUserSettings {
    bool firstRunDone = false;  // the first-run overlay was dismissed once
};

std::string desktopSettingsPath();

// The settings in `path` (the defaults when it is "" or no file is there);
// a file that cannot be read or holds a wrong value gives the defaults and
// a `warning` with the path and the JSON path of the fault.
DesktopUserSettings loadDesktopSettings(const std::string& path, std::string& warning);

// Writes them atomically, making the folder; "" or why not.
std::string saveDesktopSettings(const std::string& path, const DesktopUserSettings& settings);

}  // namespace hg::garden
