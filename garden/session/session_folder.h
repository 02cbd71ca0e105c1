// A session folder (docs/design.md §10, docs/session-format.md): the garden and its
// sculptures' sources copied in, the journal of finished actions, and
// snapshots of the edited grids. One process writes a session at a time
// (it holds DIR/session.lock); every write is checked, and a failed one
// leaves the work in memory, shown as "not saved" and retried, never lost
// without a word.
//
//   DIR/session.json        {"format": "hypergarden-session", "version": 1}
//   DIR/session.lock        the writer's lock and who holds it (io/folder_lock.h)
//   DIR/garden.json         the garden, its "file" entries pointing into sources/
//   DIR/sources/            the sculptures' HyperFun files (and scanned volumes) as they were
//   DIR/imports/            meshes and volumes added in the session, as the journal names them
//   DIR/journal.hgj         garden/session/journal.h
//   DIR/snapshots/          snapshot.json (the record count it covers and the
//                           grids' files) and one NAME.RECORDS.vdb per edited
//                           sculpture
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "garden/session/journal.h"
#include "garden/action/action_sink.h"
#include "io/folder_lock.h"
#include "io/read_text.h"

namespace hg::garden {

class GardenSession;

constexpr int kSessionVersion = 1;
// A snapshot every this many journalled actions (and when the session closes).
constexpr std::size_t kSnapshotEvery = 100;
constexpr const char* kSessionLockFile = "session.lock";

struct SessionPaths {
    std::string dir, manifest, garden, journal, snapshots, snapshotManifest;
    explicit SessionPaths(const std::string& dir);
};

// What DIR is to `--session DIR`.
enum class FolderKind {
    Session,     // holds session.json
    Unfinished,  // a session whose making was cut short (only our files, no session.json)
    Empty,       // empty
    Missing,     // does not exist
    Other,       // a file, or a folder with other things in it: never made a session
};
FolderKind folderKind(const std::string& dir);

// Makes DIR a session of `gardenFile` (DIR exists, Empty or Unfinished;
// the caller holds its lock). "" on success, else why not (nothing
// half-made is taken for a session: session.json is written last).
std::string makeSession(const std::string& dir, const std::string& gardenFile);

// A session file's whole contents; "" or "PATH: reason" (io/read_text.h).
using io::readText;

// The version and format check of DIR/session.json; "" when it is ours.
std::string checkSessionManifest(const SessionPaths& paths);

struct SnapshotInfo {
    bool present = false;
    std::size_t records = 0;               // journal records it covers
    std::vector<std::string> sculptures;   // edited sculptures with a grid in it
    std::vector<std::string> files;        // their grids' file names in snapshots/
    std::string error;                     // unreadable snapshot.json
};
SnapshotInfo readSnapshotInfo(const SessionPaths& paths);

// Removes what dead writers left (the caller holds the lock): temporaries
// (NAME.partial-PID) in the folder, sources/ and snapshots/, and grids in
// snapshots/ that no published snapshot names. The removed paths.
std::vector<std::string> removeLeftovers(const SessionPaths& paths);

// Keeps a running GardenSession's journal: attach() replays what the
// journal holds into the session, then appends every finished action.
class SessionRecorder : public JournalSink {
public:
    SessionRecorder(std::string dir, std::unique_ptr<io::FolderLock> lock);
    ~SessionRecorder() override;
    SessionRecorder(const SessionRecorder&) = delete;
    SessionRecorder& operator=(const SessionRecorder&) = delete;

    const SessionPaths& paths() const { return paths_; }
    // Reads the journal (before the session is built). "" or why the
    // session cannot be opened (an unknown journal version, say).
    std::string readJournal();
    const JournalRead& journal() const { return read_; }
    // Notes for the user: the damaged tail and where its copy is.
    const std::vector<std::string>& notes() const { return notes_; }

    // Replays the journal into `session` and journals its actions from now
    // on. A record that cannot be played leaves the session read-only on
    // what played (saveStatus() says which record and what to do); a
    // journal that cannot be opened for writing leaves it not saved.
    void attach(GardenSession& session);
    const JournalPlayed& restored() const { return restored_; }

    // JournalSink: every finished action is written at once; after a
    // failure it is kept in memory with the ones after it, in order, and
    // written with the next action or retrySave().
    void append(const Action& record) override;
    SaveStatus saveStatus() const override { return status_; }
    bool retrySave() override;
    // Called at each change of saveStatus() (the terminal's line).
    void setStatusListener(std::function<void(const SaveStatus&)> listener) { listener_ = std::move(listener); }

    // Writes the snapshot now, only when everything is saved. "" or why
    // not (a failed snapshot is never published).
    std::string snapshot();
    // The last snapshot's failure, "" when it was written.
    const std::string& snapshotProblem() const { return snapshotProblem_; }
    // Ends the session: the backlog tried once more, the last snapshot
    // written. The final status (also kept by saveStatus()).
    SaveStatus close();
    std::size_t records() const { return records_; }

private:
    bool writeBacklog();
    void setStatus(SaveStatus::State state, const std::string& reason, const std::string& remedy = "");

    SessionPaths paths_;
    std::unique_ptr<io::FolderLock> lock_;
    JournalRead read_;
    JournalWriter writer_;
    bool writerOpen_ = false;
    GardenSession* session_ = nullptr;
    JournalPlayed restored_;
    std::vector<Action> backlog_;  // finished, not yet on disk, in order
    SaveStatus status_;
    std::function<void(const SaveStatus&)> listener_;
    std::size_t records_ = 0;
    std::size_t lastSnapshot_ = 0;
    std::string snapshotProblem_;
    bool closed_ = false;
    std::vector<std::string> notes_;
};

}  // namespace hg::garden
