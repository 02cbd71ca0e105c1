#include "garden/desktop/recent_sessions.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <system_error>

#include <nlohmann/json.hpp>

#include "garden/window/user_settings_file.h"
#include "garden/scene/json_reader.h"

namespace hg::garden {

namespace {

constexpr const char* kOverride = "HG_RECENT_SESSIONS";

}  // namespace

std::string recentSessionsPath() { return userSettingsPath(kOverride, "recent-sessions.json"); }

std::vector<std::string> loadRecentSessions(const std::string& path, std::string& warning) {
    const std::optional<nlohmann::json> j = readSettingsObject(path, warning);
    if (!j) return {};
    try {
        ObjectReader r(*j, "$", {"sessions"});
        std::vector<std::string> list;
        if (const nlohmann::json* s = r.optional("sessions")) {
            if (!s->is_array()) throw JsonError(r.pathOf("sessions"), "expected an array of folders");
            for (std::size_t i = 0; i < s->size(); ++i)
                list.push_back(readString((*s)[i], indexPath(r.pathOf("sessions"), i)));
        }
        r.finish();
        if (list.size() > kRecentSessions) list.resize(kRecentSessions);
        return list;
    } catch (const JsonError& e) {
        warning = path + ": " + e.what() + "; the recent sessions are forgotten";
    }
    return {};
}

std::string rememberSession(const std::string& path, const std::string& dir) {
    std::error_code ec;
    std::filesystem::path absolute = std::filesystem::absolute(dir, ec);
    if (ec) absolute = dir;
    const std::string entry = absolute.lexically_normal().string();
    std::string warning;  // a broken list is started again
    std::vector<std::string> list = loadRecentSessions(path, warning);
    list.erase(std::remove(list.begin(), list.end(), entry), list.end());
    list.insert(list.begin(), entry);
    if (list.size() > kRecentSessions) list.resize(kRecentSessions);
    return writeSettingsFile(path, {{"sessions", list}}, kOverride);
}

}  // namespace hg::garden
