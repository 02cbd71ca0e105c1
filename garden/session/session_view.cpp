#include "garden/session/session_view.h"

#include <cmath>
#include <filesystem>
#include <system_error>

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include "garden/app/navigator.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/tool_settings_json.h"
#include "io/checked_write.h"
#include "io/read_text.h"

namespace hg::garden {

namespace {

std::string viewPath(const std::string& dir) { return (std::filesystem::path(dir) / kSessionViewFile).string(); }

constexpr double kDegrees = 180.0 / glm::pi<double>();

}  // namespace

std::string writeSessionView(const std::string& dir, const Navigator& navigator, const ToolSettings* tool,
                             const std::string* panels) {
    const glm::vec3& e = navigator.eye();
    nlohmann::json j;
    j["mode"] = navigator.mode() == NavigationMode::Walk ? "walk" : "fly";
    j["eye"] = {static_cast<double>(e.x), static_cast<double>(e.y), static_cast<double>(e.z)};
    j["yaw"] = static_cast<double>(navigator.yaw()) * kDegrees;
    j["pitch"] = static_cast<double>(navigator.pitch()) * kDegrees;
    if (tool) j["tool"] = toolSettingsJson(*tool);
    if (panels && !panels->empty()) j["panels"] = *panels;
    return io::writeFileAtomically(viewPath(dir), j.dump(2) + "\n", io::WriteSite::SessionFile);
}

bool readSessionView(const std::string& dir, Navigator& navigator, std::string& warning,
                     std::optional<ToolSettings>* tool, std::optional<std::string>* panels) {
    warning.clear();
    const std::string path = viewPath(dir);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return false;
    std::string text;
    if (std::string why = io::readText(path, text); !why.empty()) {
        warning = why + "; the session opens at the garden's start";
        return false;
    }
    try {
        const nlohmann::json j = parseStrictJson(text);
        ObjectReader r(j, "$", {"mode", "eye", "yaw", "pitch", "tool", "panels"});
        const std::string mode = readString(r.required("mode"), r.pathOf("mode"));
        if (mode != "walk" && mode != "fly") throw JsonError(r.pathOf("mode"), "expected \"walk\" or \"fly\"");
        const std::array<double, 3> eye = readVec3(r.required("eye"), r.pathOf("eye"));
        for (double v : eye)
            if (!(std::fabs(v) <= 1e6)) throw JsonError(r.pathOf("eye"), "must be within a million metres");
        const double yaw = readNumber(r.required("yaw"), r.pathOf("yaw"), -1e6, 1e6);
        const double pitch = readNumber(r.required("pitch"), r.pathOf("pitch"), -90.0, 90.0);
        std::optional<ToolSettings> inHand;
        if (const auto* t = r.optional("tool")) inHand = readToolSettings(*t, r.pathOf("tool"));
        std::optional<std::string> layout;
        if (const auto* p = r.optional("panels")) layout = readString(*p, r.pathOf("panels"));
        r.finish();
        if (tool) *tool = inHand;
        if (panels) *panels = layout;
        navigator.setMode(mode == "walk" ? NavigationMode::Walk : NavigationMode::Fly);
        navigator.setPose(glm::vec3(static_cast<float>(eye[0]), static_cast<float>(eye[1]), static_cast<float>(eye[2])),
                          static_cast<float>(yaw / kDegrees), static_cast<float>(pitch / kDegrees));
        return true;
    } catch (const JsonError& e) {
        warning = path + ": " + e.what() + "; the session opens at the garden's start";
    }
    return false;
}

}  // namespace hg::garden
