#include "garden/session/open_session.h"

#include <filesystem>
#include <iostream>

namespace hg::garden {

namespace fs = std::filesystem;

namespace {

OpenedSession refused(const std::string& why, int status) {
    OpenedSession out;
    out.error = why;
    out.exitStatus = status;
    return out;
}

// Makes a missing DIR, naming every folder made; a parent that is not a
// folder is refused.
std::string makeFolder(const std::string& dir, std::vector<std::string>& notes) {
    std::vector<fs::path> missing;
    for (fs::path p = fs::absolute(dir); !p.empty() && !fs::exists(p); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return "cannot create the session folder " + dir + ": " + ec.message();
    std::string made;
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) made += (made.empty() ? "" : ", ") + it->string();
    notes.push_back("created the folder" + std::string(missing.size() > 1 ? "s " : " ") + made);
    return "";
}

}  // namespace

OpenedSession openSession(const SessionRequest& request, const SessionSettings& settings) {
    const std::string& dir = request.dir;
    std::vector<std::string> notes;
    FolderKind kind = folderKind(dir);
    if (kind == FolderKind::Other)
        return refused(dir + " is not a Hypergarden session and not empty: a session is made only in a new or empty "
                             "folder (choose another, or empty this one)",
                       2);
    if (kind == FolderKind::Missing) {
        if (std::string why = makeFolder(dir, notes); !why.empty()) return refused(why, 2);
        kind = FolderKind::Empty;
    }
    // One writer: the lock before anything in the folder is read or written.
    std::string why;
    std::optional<io::LockHolder> holder;
    std::unique_ptr<io::FolderLock> lock = io::FolderLock::acquire(dir, kSessionLockFile, request.program, why, holder);
    if (!lock) return refused(why, 2);
    // Checked again under the lock: another process may have made it meanwhile.
    kind = folderKind(dir);
    const SessionPaths paths(dir);
    if (kind == FolderKind::Session) {
        if (std::string bad = checkSessionManifest(paths); !bad.empty()) return refused(bad, 2);
        if (request.gardenGiven)
            notes.push_back("the session keeps its own garden (" + paths.garden + "); " + request.gardenFile +
                            " is not used");
    } else if (kind == FolderKind::Empty || kind == FolderKind::Unfinished) {
        if (std::string bad = makeSession(dir, request.gardenFile); !bad.empty()) return refused(bad, 2);
        notes.push_back("created the session " + dir + " from " + request.gardenFile);
    } else {
        return refused(dir + " is not a Hypergarden session and not empty", 2);
    }
    const std::vector<std::string> removed = removeLeftovers(paths);
    if (!removed.empty()) {
        std::string list;
        for (const std::string& r : removed) list += (list.empty() ? "" : ", ") + fs::path(r).filename().string();
        notes.push_back("removed " + std::to_string(removed.size()) + " leftover file" + (removed.size() > 1 ? "s" : "") +
                        " of an interrupted write by a process that ended: " + list);
    }
    auto recorder = std::make_unique<SessionRecorder>(dir, std::move(lock));
    if (std::string bad = recorder->readJournal(); !bad.empty()) return refused(bad, 2);
    GardenLoad load = loadGarden(paths.garden);
    if (!load.ok()) return refused(load.error, 2);
    OpenedSession out;
    out.notes = std::move(notes);
    out.session = std::make_unique<GardenSession>(std::move(load), settings);
    recorder->attach(*out.session);
    for (const std::string& n : recorder->notes()) out.notes.push_back(n);
    if (kind == FolderKind::Session)
        out.notes.push_back("reopened the session " + dir + " with " + std::to_string(recorder->restored().played) +
                            " journalled actions");
    const SaveStatus status = recorder->saveStatus();
    if (!status.saved()) out.warning = status.headline() + (status.remedy.empty() ? "" : "; " + status.remedy);
    out.recorder = std::move(recorder);
    return out;
}

OpenedSession openLoadedOrSession(std::optional<GardenLoad> loaded, const SessionRequest& request,
                                  const SessionSettings& settings) {
    if (request.dir.empty() && loaded) {
        OpenedSession out;
        out.session = std::make_unique<GardenSession>(std::move(*loaded), settings);
        return out;
    }
    return openSession(request, settings);
}

std::vector<std::string> openedMessages(const OpenedSession& opened) {
    std::vector<std::string> lines;
    for (const std::string& n : opened.notes) lines.push_back("note: " + n);
    if (!opened.warning.empty()) lines.push_back("warning: " + opened.warning);
    if (opened.session)
        for (const Sculpture& s : opened.session->sculptures()) {
            if (!s.missing()) continue;
            std::string error = s.error;
            while (!error.empty() && error.back() == '\n') error.pop_back();  // a parser's message may end its line
            lines.push_back("warning: sculpture '" + s.name + "' is missing: " + error);
        }
    return lines;
}

int closeSession(OpenedSession& opened, std::vector<std::string>& lines) {
    if (!opened.recorder) return 0;
    const SaveStatus s = opened.recorder->close();
    if (!opened.recorder->snapshotProblem().empty())
        lines.push_back("warning: " + opened.recorder->paths().dir + ": " + opened.recorder->snapshotProblem() +
                        " (the journal holds every action; the last snapshot stands)");
    if (s.saved()) return 0;
    if (s.state == SaveStatus::State::ReadOnly && s.unsaved == 0) {
        lines.push_back("note: the session " + s.folder + " was opened read-only; nothing in it was changed" +
                        (s.remedy.empty() ? "" : "; " + s.remedy));
        return 0;
    }
    if (s.state == SaveStatus::State::NotSaved)
        lines.push_back("error: " + std::to_string(s.unsaved) + " finished action" + (s.unsaved == 1 ? " was" : "s were") +
                        " not saved to " + s.folder + ": " + s.reason + "; the journal holds the actions before them");
    else
        lines.push_back("error: the session " + s.folder + " was read-only: " + s.reason +
                        (s.unsaved ? "; " + std::to_string(s.unsaved) + " actions made here were not saved" : "") +
                        (s.remedy.empty() ? "" : "; " + s.remedy));
    return 1;
}

void reportSaveChangesOnStderr(OpenedSession& opened) {
    if (!opened.recorder) return;
    opened.recorder->setStatusListener([](const SaveStatus& s) {
        if (s.saved()) std::cerr << "note: saved again: every action is in the journal of " << s.folder << "\n";
        else std::cerr << "error: " << s.headline() << (s.remedy.empty() ? "" : "; " + s.remedy) << "\n";
    });
}

}  // namespace hg::garden
