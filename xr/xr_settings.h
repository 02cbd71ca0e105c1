// The headset's user settings kept between runs (issue 13): left-handed,
// seated and how high a seated user is raised, smooth or snap turning and
// the snap's angle, in a small JSON file
//   {"left_handed": false, "seated": false, "seated_height_offset": 0.5,
//    "smooth_turn": false, "snap_degrees": 30}
// at $HG_XR_SETTINGS, else $XDG_CONFIG_HOME/hypergarden/xr.json, else
// ~/.config/hypergarden/xr.json. Read at start (a key that is missing keeps
// its default, so older files still read); written (atomically) when the
// hand panel changes them. The command line's --left-handed, --seated and
// --smooth-turn override them for one run without writing them.
#pragma once

#include <string>

namespace hg::xr {

// The snap angles offered (degrees); a file may hold only these.
constexpr int kSnapAngles[] = {15, 30, 45, 90};
// How far a seated user's tracked heights may be raised (metres).
constexpr double kMaxSeatedHeightOffset = 1.0;

struct XrUserSettings {
    bool leftHanded = false;
    bool seated = false;
    // Added to tracked heights when seated: a seated user's eyes are about
    // this much lower than a standing one's.
    double seatedHeightOffset = 0.5;
    bool smoothTurn = false;
    int snapDegrees = 30;
};

// Where the settings are ("" when neither the variables nor HOME say).
std::string xrSettingsPath();

// The settings in `path`; the defaults when it does not exist. A file that
// cannot be read or parsed, or holds a value out of range, gives the
// defaults and `warning` says why, with the file and the place in it.
XrUserSettings loadXrSettings(const std::string& path, std::string& warning);

// Writes `s` to `path` atomically, making its folder; "" or why not.
std::string saveXrSettings(const std::string& path, const XrUserSettings& s);

}  // namespace hg::xr
