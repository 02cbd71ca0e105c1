// Opening a garden inside a session folder, the same way for the desktop
// window, the headset and `replay --session`: the folder rules (a session,
// or a new or empty folder to make one in; nothing else), the writer's
// lock, leftovers of dead writers removed and told, the journal read and
// replayed, and every later action journalled.
#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "garden/app/garden_session.h"
#include "garden/session/session_folder.h"

namespace hg::garden {

struct SessionRequest {
    SessionRequest(std::string dirIn = "", std::string gardenFileIn = "", bool gardenGivenIn = false,
                   std::string programIn = "hypergarden")
        : dir(std::move(dirIn)), gardenFile(std::move(gardenFileIn)), gardenGiven(gardenGivenIn), program(std::move(programIn)) {}
    std::string dir;           // the session folder ("" : none)
    std::string gardenFile;    // what a new session is made from
    bool gardenGiven;          // the user named gardenFile: told when an existing session keeps its own
    std::string program;       // who holds the lock, for a second opener's message ("hypergarden replay")
};

struct OpenedSession {
    OpenedSession() = default;
    OpenedSession(OpenedSession&&) = default;
    // The recorder is closed before the session it journals goes.
    OpenedSession& operator=(OpenedSession&& other) noexcept {
        recorder.reset();
        session = std::move(other.session);
        recorder = std::move(other.recorder);
        error = std::move(other.error);
        exitStatus = other.exitStatus;
        notes = std::move(other.notes);
        warning = std::move(other.warning);
        return *this;
    }
    std::unique_ptr<GardenSession> session;
    std::unique_ptr<SessionRecorder> recorder;  // declared after the session: closed before it
    std::string error;               // the session cannot be opened (nothing else set)
    int exitStatus = 0;              // for `error`: 2 for bad input or a session held by another process, 1 otherwise
    std::vector<std::string> notes;  // created, recovered, leftovers removed
    // The session is read-only or not saved from the start (a record that
    // cannot be played, a journal that cannot be written): the headline.
    std::string warning;
};

OpenedSession openSession(const SessionRequest& request, const SessionSettings& settings);

// How the desktop window, the headset and replay open their garden: with no
// session folder, `loaded` (a garden file already read and accepted; nothing
// journalled), else the folder as openSession opens it.
OpenedSession openLoadedOrSession(std::optional<GardenLoad> loaded, const SessionRequest& request,
                                  const SessionSettings& settings);

// What the user is told once a garden opened, a line each (no newline):
// the session's notes ("note: ..."), a session not saved or read-only
// ("warning: ...") and every missing sculpture ("warning: sculpture 'NAME'
// is missing: ...").
std::vector<std::string> openedMessages(const OpenedSession& opened);

// The exit status and last words of a program that ran on `opened`: the
// recorder closed (the backlog tried once more, the last snapshot
// written); 0 when everything is saved, else 1 with the lines to print on
// stderr.
int closeSession(OpenedSession& opened, std::vector<std::string>& lines);

// Prints each change of the session's save status on stderr as it happens
// ("error: NOT SAVED ...", then "note: saved again ...").
void reportSaveChangesOnStderr(OpenedSession& opened);

}  // namespace hg::garden
