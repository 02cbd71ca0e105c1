#include "xr/xr_settings.h"

#include <algorithm>
#include <iterator>

#include <nlohmann/json.hpp>

#include "garden/window/user_settings_file.h"
#include "garden/scene/json_reader.h"

namespace hg::xr {

std::string xrSettingsPath() { return garden::userSettingsPath("HG_XR_SETTINGS", "xr.json"); }

XrUserSettings loadXrSettings(const std::string& path, std::string& warning) {
    warning.clear();
    XrUserSettings s;
    const std::optional<nlohmann::json> found = garden::readSettingsObject(path, warning);
    if (!found) return s;
    const nlohmann::json& j = *found;
    try {
        XrUserSettings read;
        for (const auto& [key, target] : {std::pair<const char*, bool*>{"left_handed", &read.leftHanded},
                                          std::pair<const char*, bool*>{"seated", &read.seated},
                                          std::pair<const char*, bool*>{"smooth_turn", &read.smoothTurn}}) {
            const auto it = j.find(key);
            if (it == j.end()) continue;
            if (!it->is_boolean()) throw garden::JsonError(std::string("$.") + key, "must be true or false");
            *target = it->get<bool>();
        }
        if (const auto it = j.find("seated_height_offset"); it != j.end()) {
            if (!it->is_number() || it->get<double>() < 0.0 || it->get<double>() > kMaxSeatedHeightOffset)
                throw garden::JsonError("$.seated_height_offset", "must be a number of metres from 0 to 1");
            read.seatedHeightOffset = it->get<double>();
        }
        if (const auto it = j.find("snap_degrees"); it != j.end()) {
            const auto* end = std::end(kSnapAngles);
            const bool offered = it->is_number_integer() && std::find(std::begin(kSnapAngles), end, it->get<int>()) != end;
            if (!offered) throw garden::JsonError("$.snap_degrees", "must be 15, 30, 45 or 90");
            read.snapDegrees = it->get<int>();
        }
        return read;
    } catch (const garden::JsonError& e) {
        warning = path + ": " + e.what() + "; using the default settings";
    }
    return s;
}

std::string saveXrSettings(const std::string& path, const XrUserSettings& s) {
    const nlohmann::json j = {{"left_handed", s.leftHanded},
                              {"seated", s.seated},
                              {"seated_height_offset", s.seatedHeightOffset},
                              {"smooth_turn", s.smoothTurn},
                              {"snap_degrees", s.snapDegrees}};
    return garden::writeSettingsFile(path, j, "HG_XR_SETTINGS");
}

}  // namespace hg::xr
