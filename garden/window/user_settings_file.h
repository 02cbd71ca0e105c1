// The user settings files that the desktop window and the headset keep
// between runs (garden/desktop/desktop_settings.h, xr/xr_settings.h): where
// one lives, reading it as a JSON object, and writing it atomically.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace hg::garden {

// Where a user settings file called `fileName` lives: $`overrideVariable`
// when set, else under $XDG_CONFIG_HOME/hypergarden, else under
// ~/.config/hypergarden; "" when none of them is set.
std::string userSettingsPath(const char* overrideVariable, const char* fileName);

// A settings file's JSON object (the headset's and the desktop's): none
// when `path` is "" or no file is there, or when it cannot be read or is
// not a JSON object (then `warning` names the path and the fault).
std::optional<nlohmann::json> readSettingsObject(const std::string& path, std::string& warning);
// Writes `settings` to `path` atomically, making its folder; "" or why not
// (`overrideVariable` named when there is no place for it).
std::string writeSettingsFile(const std::string& path, const nlohmann::json& settings, const char* overrideVariable);

}  // namespace hg::garden
