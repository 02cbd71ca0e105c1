// The view a session was left with (issue 23, docs/session-format.md): the
// desktop writes DIR/view.json when it closes a session and reads it when
// it opens one, so a reopened session looks where the user left off.
//   {"mode": "walk" | "fly", "eye": [x, y, z], "yaw": degrees, "pitch": degrees,
//    "tool": {the tool in hand and its settings, garden/sculpt/tool_settings_json.h},
//    "panels": "the desktop's panel layout, as ImGui's ini text"}
// ("tool" and "panels" are optional: files written before them read fine)
// (an orbit is kept as flying from where it stood: its target may be gone).
// The view is not an action: it is not journalled and undo leaves it alone.
#pragma once

#include <optional>
#include <string>

#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

class Navigator;

constexpr const char* kSessionViewFile = "view.json";

// Writes the navigator's pose (and the tool in hand and the panel layout,
// when given; an empty layout is left out) to DIR/view.json atomically;
// "" or why not.
std::string writeSessionView(const std::string& dir, const Navigator& navigator, const ToolSettings* tool = nullptr,
                             const std::string* panels = nullptr);

// Sets the navigator from DIR/view.json: true when it did. False with
// `warning` "" when the session has no view yet; false with `warning`
// naming the file and the fault when the file is unreadable or wrong (the
// navigator is left as it was).
// `tool`, when given, receives the tool the file holds (none from a file
// written before tools were kept); `panels` the panel layout (none from a
// file written before layouts were kept).
bool readSessionView(const std::string& dir, Navigator& navigator, std::string& warning,
                     std::optional<ToolSettings>* tool = nullptr, std::optional<std::string>* panels = nullptr);

}  // namespace hg::garden
