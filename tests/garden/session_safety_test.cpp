// Sessions never lose work silently (docs/session-format.md, "What is
// promised"), in one process on the real file system, with faults made by
// the write seam (io/write_faults.h): a failed journal write at any step
// and with any errno keeps the action in memory, says NOT SAVED with the
// reason, keeps every later action in order and writes them all once the
// journal takes writes again; the reopened session then equals the one in
// memory, voxel for voxel. A failed snapshot is never published; a record
// that cannot be played opens the session read-only and says what to do;
// leftovers of dead writers are removed and told; only sessions (or new or
// empty folders) are opened as sessions; one writer at a time.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "garden/sculpt/sculpture_edits.h"
#include "garden/session/open_session.h"
#include "io/write_faults.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

class SessionSafetyTest : public test::SmallGarden {
protected:
    void TearDown() override {
        io::setFaultPlan(std::nullopt);
        test::SmallGarden::TearDown();
    }
    std::string folder() const { return (dir / "session").string(); }
    OpenedSession open(const std::string& garden) {
        return openSession({folder(), garden, false, "session safety test"}, test::smallSessionSettings());
    }
    std::string readAll(const std::string& path) const {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::vector<std::string> temporariesIn(const fs::path& p) const {
        std::vector<std::string> out;
        if (!fs::exists(p)) return out;
        for (const auto& e : fs::recursive_directory_iterator(p))
            if (e.path().filename().string().find(".partial-") != std::string::npos) out.push_back(e.path().string());
        return out;
    }
};

io::FaultPlan failAt(io::WriteSite site, std::size_t first, std::size_t last, int error) {
    io::FaultPlan p;
    p.anySite = false;
    p.site = site;
    p.first = first;
    p.last = last;
    p.error = error;
    return p;
}

// Stroke n of a repeatable series over the three balls.
void stroke(GardenSession& s, int n) {
    const char* names[] = {"a", "b", "c"};
    const double centres[3][2] = {{0, -2.3094}, {-2, 1.1547}, {2, 1.1547}};
    const int k = n % 3;
    const double x = centres[k][0] + 0.02 * (n % 5), z = centres[k][1] + 0.45;
    ASSERT_EQ(s.applyStroke(s.findSculpture(names[k]), n % 2 ? StrokeTool::Carve : StrokeTool::Add,
                            {{x - 0.15, 0.45 + 0.01 * n, z}, {x + 0.15, 0.5 + 0.01 * n, z}}, 0.06),
              "");
}

void expectSameGrids(const GardenSession& a, const GardenSession& b) {
    ASSERT_EQ(a.sculptures().size(), b.sculptures().size());
    for (std::size_t i = 0; i < a.sculptures().size(); ++i) {
        const Sculpture& s = a.sculptures()[i];
        EXPECT_EQ(a.editCount(static_cast<int>(i)), b.editCount(static_cast<int>(i))) << s.name;
        if (s.volume && !s.morphResult()) {
            EXPECT_EQ(test::differingVoxels(*s.volume, *b.sculptures()[i].volume), 0) << s.name;
        }
    }
}

// Every errno, at each of a journal append's steps (the write, the sync,
// the cut of what a failed append left): NOT SAVED at once with the
// reason, later actions kept, and all of them written, in order, once the
// fault clears; the reopened session is the one in memory.
TEST_F(SessionSafetyTest, AFailedJournalWriteKeepsTheWorkShowsItAndWritesItWhenItCan) {
    const std::string garden = writeGarden();
    const std::pair<int, const char*> errors[] = {{ENOSPC, "No space left on device"},
                                                  {EIO, "Input/output error"},
                                                  {EDQUOT, "Disk quota exceeded"},
                                                  {EROFS, "Read-only file system"},
                                                  {EFBIG, "File too large"}};
    int run = 0;
    for (const auto& [error, text] : errors)
        for (std::size_t step = 1; step <= 3; ++step, ++run) {
            SCOPED_TRACE(std::string(text) + " at step " + std::to_string(step));
            fs::remove_all(folder());
            std::unique_ptr<GardenSession> memory;
            {
                OpenedSession o = open(garden);
                ASSERT_EQ(o.error, "");
                std::vector<SaveStatus> told;
                o.recorder->setStatusListener([&](const SaveStatus& s) { told.push_back(s); });
                stroke(*o.session, 0);
                stroke(*o.session, 1);
                EXPECT_TRUE(o.session->journal()->saveStatus().saved());
                // Steps 1-2 of the third append are its write and sync; step 3
                // is the first step of the fourth (the earlier cut succeeded).
                io::setFaultPlan(failAt(io::WriteSite::Journal, step, step + 3, error));
                stroke(*o.session, 2);
                stroke(*o.session, 3);
                ASSERT_FALSE(told.empty());
                const SaveStatus bad = told.front();
                EXPECT_EQ(bad.state, SaveStatus::State::NotSaved);
                EXPECT_NE(bad.reason.find(text), std::string::npos) << bad.reason;
                EXPECT_NE(bad.headline().find("NOT SAVED to " + folder()), std::string::npos) << bad.headline();
                EXPECT_GE(o.session->journal()->saveStatus().unsaved, 1u);
                // The journal on disk holds whole records only, a prefix.
                const JournalRead mid = readJournal(SessionPaths(folder()).journal);
                ASSERT_TRUE(mid.ok());
                EXPECT_FALSE(mid.damaged()) << mid.damage;
                EXPECT_LE(mid.records.size(), 3u);
                stroke(*o.session, 4);
                o.session->undo();
                stroke(*o.session, 5);
                // Retried with each action: once the fault has passed, the
                // backlog is written and the banner clears.
                if (!o.session->journal()->saveStatus().saved()) {
                    EXPECT_TRUE(o.session->journal()->retrySave());
                }
                EXPECT_TRUE(o.session->journal()->saveStatus().saved());
                EXPECT_EQ(o.session->journal()->saveStatus().unsaved, 0u);
                EXPECT_TRUE(told.back().saved());
                io::setFaultPlan(std::nullopt);
                memory = std::make_unique<GardenSession>(loadGarden(SessionPaths(folder()).garden),
                                                         test::smallSessionSettings());
                const JournalRead all = readJournal(SessionPaths(folder()).journal);
                ASSERT_TRUE(all.ok());
                EXPECT_FALSE(all.damaged());
                ASSERT_EQ(all.records.size(), 7u);  // six strokes and an undo, in the order made
                EXPECT_TRUE(std::holds_alternative<UndoAction>(all.records[5]));
                ASSERT_EQ(memory->restore(all.records), "");
                expectSameGrids(*o.session, *memory);
            }
            OpenedSession again = open(garden);
            ASSERT_EQ(again.error, "");
            expectSameGrids(*again.session, *memory);
            EXPECT_TRUE(temporariesIn(folder()).empty());
        }
    EXPECT_EQ(run, 15);
}

// A disk that stays full: every action is kept, in order, the status
// counts them, retrying fails with the reason; closing reports them.
TEST_F(SessionSafetyTest, ADiskThatStaysFullKeepsEveryActionAndClosingSaysHowManyWereNotSaved) {
    const std::string garden = writeGarden();
    OpenedSession o = open(garden);
    ASSERT_EQ(o.error, "");
    stroke(*o.session, 0);
    io::setFaultPlan(failAt(io::WriteSite::Journal, 1, SIZE_MAX, ENOSPC));
    for (int n = 1; n <= 4; ++n) stroke(*o.session, n);
    SaveStatus s = o.session->journal()->saveStatus();
    EXPECT_EQ(s.state, SaveStatus::State::NotSaved);
    EXPECT_EQ(s.unsaved, 4u);
    EXPECT_FALSE(o.session->journal()->retrySave());
    EXPECT_NE(s.headline().find("4 actions are kept in memory"), std::string::npos) << s.headline();
    std::vector<std::string> lines;
    EXPECT_EQ(closeSession(o, lines), 1);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines.back().find("4 finished actions were not saved to " + folder()), std::string::npos) << lines.back();
    io::setFaultPlan(std::nullopt);
    // No snapshot was taken of grids the journal does not hold.
    EXPECT_FALSE(fs::exists(SessionPaths(folder()).snapshotManifest));
    EXPECT_EQ(readJournal(SessionPaths(folder()).journal).records.size(), 1u);
}

// A snapshot that fails at any of its steps is not published: the one
// before stands, whole, and nothing of the failed one is left.
TEST_F(SessionSafetyTest, AFailedSnapshotIsNeverPublished) {
    const std::string garden = writeGarden();
    OpenedSession o = open(garden);
    ASSERT_EQ(o.error, "");
    stroke(*o.session, 0);
    stroke(*o.session, 1);
    ASSERT_EQ(o.recorder->snapshot(), "");
    const SessionPaths paths(folder());
    const std::string manifest = readAll(paths.snapshotManifest);
    const SnapshotInfo first = readSnapshotInfo(paths);
    ASSERT_TRUE(first.present);
    EXPECT_EQ(first.records, 2u);
    EXPECT_EQ(first.sculptures.size(), 2u);
    stroke(*o.session, 2);
    const std::pair<io::WriteSite, std::size_t> sites[] = {
        {io::WriteSite::SnapshotGrid, 1},     {io::WriteSite::SnapshotGrid, 2},  // the first grid's write and sync
        {io::WriteSite::SnapshotGrid, 5},                                        // the third grid's write
        {io::WriteSite::SnapshotManifest, 1}, {io::WriteSite::SnapshotManifest, 2},
        {io::WriteSite::SnapshotGrid, 7},                                        // the first grid's rename
        {io::WriteSite::SnapshotManifest, 3},                                    // the manifest's rename
    };
    for (const auto& [site, step] : sites)
        for (int error : {ENOSPC, EIO, EDQUOT, EROFS, EFBIG}) {
            SCOPED_TRACE(std::string(io::writeSiteName(site)) + " step " + std::to_string(step));
            io::setFaultPlan(failAt(site, step, step, error));
            const std::string why = o.recorder->snapshot();
            io::setFaultPlan(std::nullopt);
            EXPECT_NE(why.find("the snapshot was not written"), std::string::npos) << why;
            EXPECT_EQ(o.recorder->snapshotProblem(), why);
            EXPECT_EQ(readAll(paths.snapshotManifest), manifest);
            EXPECT_TRUE(temporariesIn(folder()).empty());
            // Only the standing snapshot's grids are in the folder.
            std::size_t grids = 0;
            for (const auto& e : fs::directory_iterator(paths.snapshots)) grids += e.path().extension() == ".vdb";
            EXPECT_EQ(grids, first.files.size());
        }
    // The journal was never touched: it still holds every action.
    EXPECT_TRUE(o.session->journal()->saveStatus().saved());
    ASSERT_EQ(o.recorder->snapshot(), "");
    EXPECT_EQ(readSnapshotInfo(paths).records, 3u);
    EXPECT_EQ(o.recorder->snapshotProblem(), "");
}

// A record in the middle that cannot be played: the session shows what
// played, read-only, and says which record, why, how many follow and what
// to do; nothing is appended; the journal on disk is left as it was.
TEST_F(SessionSafetyTest, AnUnplayableRecordOpensTheSessionReadOnlyAndSaysWhatToDo) {
    const std::string garden = writeGarden();
    {
        OpenedSession o = open(garden);
        ASSERT_EQ(o.error, "");
        for (int n = 0; n < 3; ++n) stroke(*o.session, n);
    }
    // A redo with nothing to redo (what two writers interleaving made),
    // then two more strokes: records 4, 5 and 6.
    const SessionPaths paths(folder());
    {
        std::ofstream j(paths.journal, std::ios::app | std::ios::binary);
        for (const Action& r : std::vector<Action>{RedoAction{}}) {
            const std::string json = actionJson(r);
            char crc[16];
            std::snprintf(crc, sizeof crc, "%08x ", crc32(json));
            j << crc << json << "\n";
        }
    }
    {
        // Two strokes after it, written by a session that played them.
        GardenSession other(loadGarden(paths.garden), test::smallSessionSettings());
        std::vector<Action> more;
        struct Keep : JournalSink {
            std::vector<Action>* out;
            void append(const Action& r) override { out->push_back(r); }
            SaveStatus saveStatus() const override { return {}; }
            bool retrySave() override { return true; }
        } keep;
        keep.out = &more;
        other.setJournal(&keep);
        stroke(other, 3);
        stroke(other, 4);
        other.setJournal(nullptr);
        std::ofstream j(paths.journal, std::ios::app | std::ios::binary);
        for (const Action& r : more) {
            const std::string json = actionJson(r);
            char crc[16];
            std::snprintf(crc, sizeof crc, "%08x ", crc32(json));
            j << crc << json << "\n";
        }
    }
    const std::string before = readAll(paths.journal);
    {
        OpenedSession o = open(garden);
        ASSERT_EQ(o.error, "");
        const SaveStatus s = o.session->journal()->saveStatus();
        EXPECT_EQ(s.state, SaveStatus::State::ReadOnly);
        EXPECT_NE(s.reason.find("record 4 (redo): nothing to redo"), std::string::npos) << s.reason;
        EXPECT_NE(s.reason.find("the 2 records after it are kept on disk"), std::string::npos) << s.reason;
        EXPECT_NE(s.remedy.find("hypergarden session " + folder() + " --cut-at 4"), std::string::npos) << s.remedy;
        EXPECT_NE(o.warning.find("READ-ONLY"), std::string::npos) << o.warning;
        EXPECT_EQ(o.recorder->restored().played, 3u);
        // The session shows the three that played; work here is not saved.
        EXPECT_EQ(o.session->editCount(o.session->findSculpture("a")), 1u);
        stroke(*o.session, 7);
        EXPECT_EQ(o.session->journal()->saveStatus().unsaved, 1u);
        EXPECT_FALSE(o.session->journal()->retrySave());
        std::vector<std::string> lines;
        EXPECT_EQ(closeSession(o, lines), 1);
        ASSERT_FALSE(lines.empty());
        EXPECT_NE(lines.back().find("read-only"), std::string::npos) << lines.back();
    }
    EXPECT_EQ(readAll(paths.journal), before);
    // Opened and closed without a change: told, and not an error.
    OpenedSession o = open(garden);
    std::vector<std::string> lines;
    EXPECT_EQ(closeSession(o, lines), 0);
    EXPECT_EQ(readAll(paths.journal), before);
}

TEST_F(SessionSafetyTest, LeftoversOfDeadWritersAreRemovedAndTold) {
    const std::string garden = writeGarden();
    {
        OpenedSession o = open(garden);
        ASSERT_EQ(o.error, "");
        stroke(*o.session, 0);
    }
    const SessionPaths paths(folder());
    const SnapshotInfo snap = readSnapshotInfo(paths);
    ASSERT_TRUE(snap.present);
    // What a snapshot killed half-way leaves: temporaries, and a grid that
    // was renamed before its manifest.
    std::ofstream(fs::path(paths.snapshots) / "a.9.vdb.partial-4242") << "half";
    std::ofstream(fs::path(paths.snapshots) / "snapshot.json.partial-4242") << "{";
    std::ofstream(fs::path(paths.snapshots) / "b.9.vdb") << "orphan";
    std::ofstream(fs::path(folder()) / "garden.json.partial-77") << "{";
    OpenedSession o = open(garden);
    ASSERT_EQ(o.error, "");
    std::string note;
    for (const std::string& n : o.notes)
        if (n.find("leftover") != std::string::npos) note = n;
    EXPECT_NE(note.find("removed 4 leftover files of an interrupted write"), std::string::npos) << note;
    EXPECT_TRUE(temporariesIn(folder()).empty());
    EXPECT_FALSE(fs::exists(fs::path(paths.snapshots) / "b.9.vdb"));
    for (const std::string& f : snap.files) EXPECT_TRUE(fs::exists(fs::path(paths.snapshots) / f)) << f;
}

TEST_F(SessionSafetyTest, OnlySessionsAndNewOrEmptyFoldersAreOpenedAsSessions) {
    const std::string garden = writeGarden();
    // A folder of the user's own: refused, and nothing written into it.
    write("mine/notes.txt", "my own notes\n");
    OpenedSession refused = openSession({(dir / "mine").string(), garden}, test::smallSessionSettings());
    EXPECT_EQ(refused.exitStatus, 2);
    EXPECT_NE(refused.error.find("is not a Hypergarden session and not empty"), std::string::npos) << refused.error;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator()), 1);
    // A file is not a folder.
    OpenedSession file = openSession({(dir / "mine/notes.txt").string(), garden}, test::smallSessionSettings());
    EXPECT_EQ(file.exitStatus, 2);
    // Missing parents are made and named.
    const std::string deep = (dir / "x" / "y" / "z").string();
    OpenedSession made = openSession({deep, garden}, test::smallSessionSettings());
    ASSERT_EQ(made.error, "");
    ASSERT_FALSE(made.notes.empty());
    EXPECT_EQ(made.notes[0], "created the folders " + (dir / "x").string() + ", " + (dir / "x" / "y").string() + ", " + deep);
    // An empty folder becomes a session.
    fs::create_directories(dir / "empty");
    OpenedSession empty = openSession({(dir / "empty").string(), garden}, test::smallSessionSettings());
    EXPECT_EQ(empty.error, "");
    // A session whose making was cut short (no session.json) is made again.
    fs::create_directories(dir / "unfinished" / "sources");
    write("unfinished/garden.json", "{\"half");
    OpenedSession unfinished = openSession({(dir / "unfinished").string(), garden}, test::smallSessionSettings());
    EXPECT_EQ(unfinished.error, "");
    EXPECT_TRUE(fs::exists(dir / "unfinished" / "session.json"));
    // An existing session keeps its own garden, and says so when another was named.
    unfinished = OpenedSession{};
    const std::string other = test::writeSmallGarden(dir / "other");
    OpenedSession again = openSession({(dir / "unfinished").string(), other, true}, test::smallSessionSettings());
    ASSERT_EQ(again.error, "");
    bool told = false;
    for (const std::string& n : again.notes)
        told |= n == "the session keeps its own garden (" + SessionPaths((dir / "unfinished").string()).garden + "); " +
                         other + " is not used";
    EXPECT_TRUE(told);
}

TEST_F(SessionSafetyTest, ASecondWriterIsRefusedWithWhoHoldsTheSession) {
    const std::string garden = writeGarden();
    OpenedSession first = open(garden);
    ASSERT_EQ(first.error, "");
    stroke(*first.session, 0);
    OpenedSession second = openSession({folder(), garden, false, "second"}, test::smallSessionSettings());
    EXPECT_EQ(second.exitStatus, 2);
    EXPECT_FALSE(second.session);
    EXPECT_NE(second.error.find("is open in process " + std::to_string(::getpid()) + " (session safety test)"),
              std::string::npos)
        << second.error;
    EXPECT_NE(second.error.find(" since "), std::string::npos) << second.error;
    // The first goes on, and its work is whole.
    stroke(*first.session, 1);
    EXPECT_TRUE(first.session->journal()->saveStatus().saved());
    EXPECT_EQ(readJournal(SessionPaths(folder()).journal).records.size(), 2u);
    first = OpenedSession{};
    OpenedSession third = open(garden);
    EXPECT_EQ(third.error, "");
}

}  // namespace
}  // namespace hg::garden
