// A session folder (DESIGN §6, docs/session-format.md): the garden and its
// sculptures' sources copied in, the journal of finished actions, and
// snapshots of the edited grids. Opening a folder that holds no session
// creates one from a garden file; opening one that does replays its journal
// (a damaged tail is reported with its record number and byte offset, kept
// in a copy, and everything before it recovered). Saving needs no action:
// every finished action is synced to the journal as it ends, and snapshots
// are written atomically (write, then rename).
//
//   DIR/session.json        {"format": "hypergarden-session", "version": 1}
//   DIR/garden.json         the garden, its "file" entries pointing into sources/
//   DIR/sources/*.hf        the sculptures' HyperFun files as they were
//   DIR/journal.hgj         garden/session/journal.h
//   DIR/snapshots/          snapshot.json (the record count it covers) and one
//                           NAME.vdb per edited sculpture
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "garden/session/journal.h"

namespace hg::garden {

class GardenSession;

constexpr int kSessionVersion = 1;
// A snapshot every this many journalled actions (and when the session closes).
constexpr std::size_t kSnapshotEvery = 100;

struct SessionPaths {
    std::string dir, manifest, garden, journal, snapshots, snapshotManifest;
    explicit SessionPaths(const std::string& dir);
};

// Creates DIR as a session of `gardenFile` when DIR holds no session.json
// (DIR may exist, empty). "" on success, else why not (nothing half-made is
// left as a session: session.json is written last).
std::string ensureSession(const std::string& dir, const std::string& gardenFile, bool& created);

// The version and format check of DIR/session.json; "" when it is ours.
std::string checkSessionManifest(const SessionPaths& paths);

struct SnapshotInfo {
    bool present = false;
    std::size_t records = 0;               // journal records it covers
    std::vector<std::string> sculptures;   // edited sculptures with a grid in it
    std::string error;                     // unreadable snapshot.json
};
SnapshotInfo readSnapshotInfo(const SessionPaths& paths);

// Keeps a running GardenSession's journal: attach() replays what the
// journal holds into the session, then appends every finished action.
class SessionRecorder {
public:
    explicit SessionRecorder(std::string dir);
    ~SessionRecorder();

    const SessionPaths& paths() const { return paths_; }
    // Reads the journal (before the session is built). "" or why the
    // session cannot be opened (an unknown journal version, say).
    std::string readJournal();
    const JournalRead& journal() const { return read_; }
    // Notes for the user: the damaged tail and where its copy is.
    const std::vector<std::string>& notes() const { return notes_; }

    // Replays the journal into `session` and journals its actions from now
    // on. "" or why a record could not be played (the records before it are).
    std::string attach(GardenSession& session);
    // Writes the snapshot now (atomically). "" or why not.
    std::string snapshot();
    std::size_t records() const { return records_; }

private:
    void onAction(const JournalRecord& r);

    SessionPaths paths_;
    JournalRead read_;
    JournalWriter writer_;
    GardenSession* session_ = nullptr;
    std::size_t records_ = 0;
    std::size_t lastSnapshot_ = 0;
    std::vector<std::string> notes_;
};

}  // namespace hg::garden
