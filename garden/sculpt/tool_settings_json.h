// The tool in hand as JSON (issue 23, "sessions remember the tool"): what a
// session's view.json keeps of it (docs/session-format.md) so a reopened
// session has the tool and its settings where the user left them.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

// Every setting a user can change: the tool, its sizes and strengths, its
// shapes, the reverse, what the sketch tool makes.
nlohmann::json toolSettingsJson(const ToolSettings& tool);

// The settings `v` gives on top of `tool` (fields left out keep theirs),
// kept within the bounds every device shares (clampToolSettings); throws
// JsonError with the path of a bad value.
ToolSettings readToolSettings(const nlohmann::json& v, const std::string& path, ToolSettings tool = {});

}  // namespace hg::garden
