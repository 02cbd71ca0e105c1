// Opening a garden inside a session folder, the same way for the desktop
// window and `replay --session`: the folder made from the garden file when
// new, the garden loaded from the folder's copy, the journal read and
// replayed, and every later action journalled.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "garden/app/garden_session.h"
#include "garden/session/session_folder.h"

namespace hg::garden {

struct OpenedSession {
    std::unique_ptr<GardenSession> session;
    std::unique_ptr<SessionRecorder> recorder;
    std::string error;               // the session cannot be opened (nothing else set)
    int exitStatus = 0;              // for `error`: 2 for bad input, 1 otherwise
    std::vector<std::string> notes;  // created, recovered from a damaged tail, a record not played
};

// `gardenFile` is used only when `dir` holds no session yet.
OpenedSession openSession(const std::string& dir, const std::string& gardenFile, const SessionSettings& settings);

// How the desktop window, the headset and replay open their garden: with no
// session folder, `loaded` (a garden file already read and accepted; nothing
// journalled), else the folder `dir` as openSession opens it.
OpenedSession openLoadedOrSession(std::optional<GardenLoad> loaded, const std::string& dir, const std::string& gardenFile,
                                  const SessionSettings& settings);

// What the user is told once a garden opened, a line each (no newline):
// the session's notes ("note: ...") and every missing sculpture
// ("warning: sculpture 'NAME' is missing: ...").
std::vector<std::string> openedMessages(const OpenedSession& opened);

}  // namespace hg::garden
