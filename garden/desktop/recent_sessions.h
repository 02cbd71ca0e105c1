// The sessions the desktop opened last, newest first, kept between runs in
// $XDG_CONFIG_HOME/hypergarden/recent-sessions.json (else
// ~/.config/hypergarden/; $HG_RECENT_SESSIONS names the file instead):
//   {"sessions": ["/home/me/garden-week1", ...]}
// The Garden panel's Session section lists them to open (session_panel.h).
#pragma once

#include <string>
#include <vector>

namespace hg::garden {

// How many sessions the list keeps.
constexpr std::size_t kRecentSessions = 8;

std::string recentSessionsPath();

// The list in `path`, newest first (empty when there is no file); a file
// that cannot be read or holds a wrong value gives an empty list and a
// `warning` with the path and the JSON path of the fault.
std::vector<std::string> loadRecentSessions(const std::string& path, std::string& warning);

// `dir` (made absolute) put first in the list at `path`, once, the list cut
// to kRecentSessions and written atomically; "" or why not.
std::string rememberSession(const std::string& path, const std::string& dir);

}  // namespace hg::garden
