// The headset's user settings kept between runs (issue 13): left-handed
// and seated, in a small JSON file
//   {"left_handed": false, "seated": false}
// at $HG_XR_SETTINGS, else $XDG_CONFIG_HOME/hypergarden/xr.json, else
// ~/.config/hypergarden/xr.json. Read at start; written (atomically) when
// the hand panel changes them. The command line's --left-handed and
// --seated override them for one run without writing them.
#pragma once

#include <string>

namespace hg::xr {

struct XrUserSettings {
    bool leftHanded = false;
    bool seated = false;
};

// Where the settings are ("" when neither the variables nor HOME say).
std::string xrSettingsPath();

// The settings in `path`; the defaults when it does not exist. A file that
// cannot be read or parsed gives the defaults and `warning` says why, with
// the file and the place in it.
XrUserSettings loadXrSettings(const std::string& path, std::string& warning);

// Writes `s` to `path` atomically, making its folder; "" or why not.
std::string saveXrSettings(const std::string& path, const XrUserSettings& s);

}  // namespace hg::xr
