#include "garden/window/user_settings_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"
#include "io/checked_write.h"

namespace hg::garden {

namespace {

const char* nonEmptyEnv(const char* name) {
    const char* v = std::getenv(name);
    return v && *v ? v : nullptr;
}

}  // namespace

std::string userSettingsPath(const char* overrideVariable, const char* fileName) {
    if (const char* p = nonEmptyEnv(overrideVariable)) return p;
    if (const char* x = nonEmptyEnv("XDG_CONFIG_HOME")) return (std::filesystem::path(x) / "hypergarden" / fileName).string();
    if (const char* h = nonEmptyEnv("HOME")) return (std::filesystem::path(h) / ".config" / "hypergarden" / fileName).string();
    return "";
}

std::optional<nlohmann::json> readSettingsObject(const std::string& path, std::string& warning) {
    warning.clear();
    std::error_code ec;
    if (path.empty() || !std::filesystem::exists(path, ec)) return std::nullopt;
    std::ifstream in(path);
    if (!in) {
        warning = path + ": cannot read: " + std::strerror(errno) + "; using the default settings";
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    try {
        nlohmann::json j = parseStrictJson(text.str());
        if (!j.is_object()) throw JsonError("$", "must be an object");
        return j;
    } catch (const JsonError& e) {
        warning = path + ": " + e.what() + "; using the default settings";
    }
    return std::nullopt;
}

std::string writeSettingsFile(const std::string& path, const nlohmann::json& settings, const char* overrideVariable) {
    if (path.empty())
        return std::string("no place for the settings (neither ") + overrideVariable + ", XDG_CONFIG_HOME nor HOME is set)";
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    if (ec) return "cannot write " + path + ": cannot make its folder: " + ec.message();
    return io::writeFileAtomically(path, settings.dump(2) + "\n", io::WriteSite::Settings);
}

}  // namespace hg::garden
