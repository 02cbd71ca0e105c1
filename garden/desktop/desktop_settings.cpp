#include "garden/desktop/desktop_settings.h"

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "garden/window/user_settings_file.h"

namespace hg::garden {

std::string desktopSettingsPath() { return userSettingsPath("HG_DESKTOP_SETTINGS", "desktop.json"); }

DesktopUserSettings loadDesktopSettings(const std::string& path, std::string& warning) {
    DesktopUserSettings s;
    const std::optional<nlohmann::json> j = readSettingsObject(path, warning);
    if (!j) return s;
    if (const auto it = j->find("first_run_done"); it != j->end()) {
        if (!it->is_boolean()) {
            warning = path + ": " + JsonError("$.first_run_done", "must be true or false").what() + "; using the default settings";
            return s;
        }
        s.firstRunDone = it->get<bool>();
    }
    return s;
}

std::string saveDesktopSettings(const std::string& path, const DesktopUserSettings& s) {
    return writeSettingsFile(path, {{"first_run_done", s.firstRunDone}}, "HG_DESKTOP_SETTINGS");
}

}  // namespace hg::garden
