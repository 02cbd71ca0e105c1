// Session folders (garden/session/session_folder.h, open_session.h): a
// session reopens with identical grids and its undo history; a damaged
// journal tail is reported, kept in a copy and cut, with everything before
// it recovered; an unknown version is refused; and a process killed with
// SIGKILL at any moment reopens with every finished action.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include "garden/scene/materials.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/session/open_session.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionFolderTest : public test::SmallGarden {};

SessionSettings settings() {
    SessionSettings s;
    s.chunkSize = 16;
    s.maxLevel = 1;
    s.viewportHeight = 200;
    return s;
}


const voxel::Volume& grid(const OpenedSession& o, const char* name) {
    return *o.session->sculptures()[static_cast<std::size_t>(o.session->findSculpture(name))].volume;
}

void sculpt(GardenSession& s) {
    ASSERT_EQ(s.applyStroke(s.findSculpture("a"), StrokeTool::Carve, {{-0.3, 0.6, -1.8}, {0.3, 0.6, -1.8}}, 0.08), "");
    ASSERT_EQ(s.applyPerturbation(s.findSculpture("b"), QuadricShape::Ellipsoid, {-2, 0.9, 1.15}, {0.1, 0.1, 0.1}, 2.0), "");
    ASSERT_EQ(s.applyStroke(s.findSculpture("a"), StrokeTool::Melt, {{0, 0.9, -2.3}, {0, 0.95, -2.0}}, 0.1, 2.0), "");
    ASSERT_TRUE(s.undo());
    ASSERT_EQ(s.applyStroke(s.findSculpture("c"), StrokeTool::Add, {{2.6, 0.5, 1.15}, {2.8, 0.6, 1.15}}, 0.1), "");
}

TEST_F(SessionFolderTest, AGardenOpensLoadedOrInItsFolderWithItsMessages) {
    const std::string garden = writeGarden();
    // No folder: the loaded garden as it is, nothing journalled, only the
    // missing sculpture to tell (its message on one line).
    OpenedSession loaded = openLoadedOrSession(loadGarden(garden), {"", garden}, test::smallSessionSettings());
    ASSERT_TRUE(loaded.error.empty()) << loaded.error;
    ASSERT_TRUE(loaded.session);
    EXPECT_FALSE(loaded.recorder);
    std::vector<std::string> messages = openedMessages(loaded);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(messages[0].rfind("warning: sculpture 'lost' is missing: ", 0), 0u) << messages[0];
    EXPECT_EQ(messages[0].find('\n'), std::string::npos) << messages[0];
    // A folder: made from the garden file, the note first.
    const std::string folder = (dir / "session").string();
    OpenedSession made = openLoadedOrSession(std::nullopt, {folder, garden}, test::smallSessionSettings());
    ASSERT_TRUE(made.error.empty()) << made.error;
    EXPECT_TRUE(made.recorder);
    messages = openedMessages(made);
    ASSERT_EQ(messages.size(), 3u);
    EXPECT_EQ(messages[0], "note: created the folder " + folder);
    EXPECT_EQ(messages[1], "note: created the session " + folder + " from " + garden);
    EXPECT_EQ(messages[2].rfind("warning: sculpture 'lost'", 0), 0u) << messages[2];
}

TEST_F(SessionFolderTest, ASessionReopensWithIdenticalGridsAndItsUndoHistory) {
    const std::string garden = writeGarden();
    const std::string folder = (dir / "session").string();
    std::vector<voxel::Volume> saved;
    {
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        sculpt(*o.session);
        for (const char* n : {"a", "b", "c"}) saved.push_back(grid(o, n).clone());
    }
    OpenedSession o = openSession({folder, garden}, settings());
    ASSERT_EQ(o.error, "");
    EXPECT_EQ(o.session->editCount(o.session->findSculpture("a")), 1u);
    EXPECT_EQ(o.session->editCount(o.session->findSculpture("c")), 1u);
    int i = 0;
    for (const char* n : {"a", "b", "c"}) EXPECT_EQ(test::differingVoxels(grid(o, n), saved[static_cast<std::size_t>(i++)]), 0) << n;
    // The undo history came back too: undo removes c's stroke, then b's bump.
    const voxel::Volume before = o.session->sculptures()[static_cast<std::size_t>(o.session->findSculpture("c"))].edits->base().clone();
    ASSERT_TRUE(o.session->undo());
    EXPECT_EQ(test::differingVoxels(grid(o, "c"), before), 0);
    ASSERT_TRUE(o.session->undo());
    EXPECT_EQ(o.session->editCount(o.session->findSculpture("b")), 0u);
    // The snapshot agrees with a rebuild from the journal.
    EXPECT_TRUE(readSnapshotInfo(SessionPaths(folder)).present);
}

TEST_F(SessionFolderTest, AMaterialChosenSurvivesReopeningAndUndoes) {
    const std::string garden = writeGarden();
    const std::string folder = (dir / "session").string();
    Material marble = *builtinMaterial("marble");
    marble.color = {0.8f, 0.85f, 0.9f};  // its own colour: the whole material is kept, not only the name
    {
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        GardenSession& s = *o.session;
        ASSERT_EQ(s.setMaterial(s.findSculpture("a"), *builtinMaterial("bronze")), "");
        ASSERT_EQ(s.setMaterial(s.findSculpture("b"), marble), "");
        ASSERT_EQ(s.setMaterial(s.findSculpture("a"), *builtinMaterial("wood")), "");
        ASSERT_TRUE(s.undo());  // a: bronze again
        EXPECT_EQ(s.history().back().action, "material");
    }
    OpenedSession o = openSession({folder, garden}, settings());
    ASSERT_EQ(o.error, "");
    GardenSession& s = *o.session;
    const auto material = [&](const char* name) { return s.sculptures()[static_cast<std::size_t>(s.findSculpture(name))].material; };
    EXPECT_EQ(material("a"), *builtinMaterial("bronze"));
    EXPECT_EQ(material("b"), marble);
    EXPECT_EQ(material("b").kind, MaterialKind::Marble);
    // Its undo history came back: undo gives b the garden file's "red" again.
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(material("b").name, "red");
    EXPECT_EQ(material("b").kind, MaterialKind::Plain);
    ASSERT_TRUE(s.redo());
    EXPECT_EQ(material("b"), marble);
}

TEST_F(SessionFolderTest, ADamagedTailIsReportedKeptAndCutAndTheRestRecovered) {
    const std::string garden = writeGarden();
    const std::string folder = (dir / "session").string();
    {
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        sculpt(*o.session);
    }
    const SessionPaths paths(folder);
    const auto goodSize = std::filesystem::file_size(paths.journal);
    std::ofstream(paths.journal, std::ios::app | std::ios::binary) << "0badc0de {\"action\":\"stro";  // a torn write
    {
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        bool reported = false;
        for (const std::string& n : o.notes)
            reported = reported || (n.find("record 6 at byte " + std::to_string(goodSize)) != std::string::npos &&
                                    n.find("5 records before it are recovered") != std::string::npos);
        EXPECT_TRUE(reported) << ::testing::PrintToString(o.notes);
        EXPECT_TRUE(std::filesystem::exists(paths.journal + ".damaged"));
        EXPECT_EQ(o.session->editCount(o.session->findSculpture("a")), 1u);
        ASSERT_EQ(o.session->applyStroke(o.session->findSculpture("b"), StrokeTool::Carve, {{-2, 0.9, 1.5}}, 0.1), "");
    }
    const JournalRead r = readJournal(paths.journal);
    EXPECT_FALSE(r.damaged()) << r.damage;
    EXPECT_EQ(r.records.size(), 6u);
}

TEST_F(SessionFolderTest, AnUnknownJournalVersionIsRefusedAndLeftAlone) {
    const std::string garden = writeGarden();
    const std::string folder = (dir / "session").string();
    { OpenedSession o = openSession({folder, garden}, settings()); }
    const SessionPaths paths(folder);
    std::ofstream(paths.journal, std::ios::binary) << "hypergarden-journal 9\nfuture records\n";
    OpenedSession o = openSession({folder, garden}, settings());
    EXPECT_NE(o.error.find("version '9'"), std::string::npos) << o.error;
    EXPECT_EQ(o.exitStatus, 2);
    std::ifstream in(paths.journal);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "hypergarden-journal 9");
}

#ifdef HG_HYPERGARDEN_EXE
// Complete lines (records) in a journal being written; 0 while it is missing.
std::size_t recordsIn(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::size_t lines = 0;
    for (char c; in.get(c);) lines += c == '\n' ? 1 : 0;
    return lines;
}

TEST_F(SessionFolderTest, AProcessKilledAtAnyMomentReopensWithEveryFinishedAction) {
    const std::string garden = writeGarden();
    // Forty strokes across the three balls, ten frames apart, at 96^3: the
    // child runs for most of a second, and is killed somewhere in it.
    std::string steps;
    const char* names[] = {"a", "b", "c"};
    const double centres[3][2] = {{0, -2.3094}, {-2, 1.1547}, {2, 1.1547}};
    for (int i = 0; i < 40; ++i) {
        const int s = i % 3;
        const double x = centres[s][0] + 0.01 * (i % 7), z = centres[s][1] + 0.5;
        steps += R"({"commands": [{"stroke": {"sculpture": ")" + std::string(names[s]) +
                 R"(", "tool": ")" + (i % 2 ? "carve" : "add") + R"(", "radius": 0.07, "path": [[)" +
                 std::to_string(x - 0.2) + ", " + std::to_string(0.4 + 0.01 * i) + ", " + std::to_string(z) + "], [" +
                 std::to_string(x + 0.2) + ", " + std::to_string(0.5 + 0.01 * i) + ", " + std::to_string(z) + "]]}}]},";
        if (i % 9 == 8) steps += R"({"commands": [{"undo": 1}]},)";
        steps += R"({"frames": 10},)";
    }
    const std::string script = write("kill.json", R"({"garden": ")" + garden + R"(", "steps": [)" + steps +
                                                      R"({"frames": 1}]})");
    std::mt19937 rng(2024);
    int interrupted = 0;
    std::size_t finished = 0;
    for (int run = 0; run < 6; ++run) {
        const std::string folder = (dir / ("killed" + std::to_string(run))).string();
        const pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            const int devnull = ::open("/dev/null", O_WRONLY);
            ::dup2(devnull, 1);
            ::dup2(devnull, 2);
            ::execl(HG_HYPERGARDEN_EXE, HG_HYPERGARDEN_EXE, "replay", script.c_str(), "--headless", "--remesh-chunks",
                    "1", "--res", "96", "--session", folder.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        // The moment is chosen by the child's progress, not the clock (a
        // loaded machine may not finish a stroke in a fixed time): once the
        // journal holds a random number of records, a random few
        // milliseconds later, mid-stroke, mid-write or mid-snapshot.
        const std::size_t target = std::uniform_int_distribution<std::size_t>(0, 30)(rng);
        const std::string journal = SessionPaths(folder).journal;
        int status = 0;
        bool exited = false;
        const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < giveUp) {
            if (::waitpid(pid, &status, WNOHANG) == pid) {
                exited = true;
                break;
            }
            if (recordsIn(journal) >= target) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(std::uniform_int_distribution<int>(0, 40)(rng)));
        if (!exited) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
        }
        interrupted += WIFSIGNALED(status) ? 1 : 0;
        if (!std::filesystem::exists(SessionPaths(folder).manifest)) continue;  // killed before the folder was made
        const JournalRead r = std::filesystem::exists(SessionPaths(folder).journal) ? readJournal(SessionPaths(folder).journal)
                                                                                     : JournalRead{};
        ASSERT_TRUE(r.ok()) << r.error;
        // What reopens is every record that was written whole, in order.
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        // Nothing the killed writer left half-made survives the opening.
        for (const auto& e : std::filesystem::recursive_directory_iterator(folder))
            EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
        // ... and they are a prefix of the script's actions: strokes in order,
        // an undo after every ninth.
        std::size_t strokes = 0;
        for (const Action& rec : r.records) {
            if (const auto* st = std::get_if<StrokeAction>(&rec)) {
                EXPECT_EQ(st->sculpture, names[strokes % 3]);
                ++strokes;
            } else {
                EXPECT_TRUE(std::holds_alternative<UndoAction>(rec));
                EXPECT_EQ(strokes % 9, 0u);
            }
        }
        finished += r.records.size();
        // The reopened grids equal a fresh replay of those records.
        GardenSession fresh(loadGarden(SessionPaths(folder).garden), settings());
        ASSERT_EQ(fresh.restore(r.records), "");
        for (std::size_t i = 0; i < fresh.sculptures().size(); ++i) {
            const Sculpture& s = o.session->sculptures()[i];
            EXPECT_EQ(o.session->editCount(static_cast<int>(i)), fresh.editCount(static_cast<int>(i))) << s.name;
            if (s.volume) {
                EXPECT_EQ(test::differingVoxels(*s.volume, *fresh.sculptures()[i].volume), 0) << s.name << " run " << run;
            }
        }
    }
    EXPECT_GT(interrupted, 0);
    EXPECT_GT(finished, 0u);
}
#endif

}  // namespace
}  // namespace hg::garden
