// Sessions never lose work silently, tried with real processes of the
// `hypergarden` executable on real file systems (docs/session-format.md,
// "How it is tested"): a second writer is refused while the first works on;
// read-only commands read a held session and say so; a write that fails
// (the write seam's errno at every session site, a 32 KiB and a 128 KiB
// tmpfs mounted in a private mount namespace) is reported and exits
// non-zero, and reopening gives every journalled action with 0 voxels
// different from the snapshot; a process killed by SIGKILL in the middle
// of a snapshot leaves nothing that survives reopening.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "garden/session/session_folder.h"
#include "io/folder_lock.h"
#include "session_garden.h"

#ifdef HG_HYPERGARDEN_EXE

namespace hg::garden {
namespace {

namespace fs = std::filesystem;
using test::shell;
using test::ShellRun;

const char* const kNames[] = {"a", "b", "c"};

class SessionProcessTest : public test::SmallGarden {
protected:
    // `strokes` strokes across the three balls (an undo after every ninth),
    // each path `points` long, `gap` frames apart; then `tail` idle frames.
    std::string script(int strokes, int points, int gap, int tail = 1) {
        const std::string garden = writeGarden();
        const double centres[3][2] = {{0, -2.3094}, {-2, 1.1547}, {2, 1.1547}};
        std::string steps;
        for (int i = 0; i < strokes; ++i) {
            const int s = i % 3;
            const double x = centres[s][0] + 0.01 * (i % 7), z = centres[s][1] + 0.5;
            std::string path;
            for (int p = 0; p < points; ++p) {
                const double t = points > 1 ? static_cast<double>(p) / (points - 1) : 0.0;
                path += std::string(p ? ", " : "") + "[" + std::to_string(x - 0.2 + 0.4 * t) + ", " +
                        std::to_string(0.4 + 0.01 * i + 0.1 * t) + ", " + std::to_string(z) + "]";
            }
            steps += R"({"commands": [{"stroke": {"sculpture": ")" + std::string(kNames[s]) + R"(", "tool": ")" +
                     (i % 2 ? "carve" : "add") + R"(", "radius": 0.07, "path": [)" + path + "]}}]},";
            if (i % 9 == 8) steps += R"({"commands": [{"undo": 1}]},)";
            steps += R"({"frames": )" + std::to_string(gap) + "},";
        }
        return write("script.json", R"({"garden": ")" + garden + R"(", "steps": [)" + steps + R"({"frames": )" +
                                        std::to_string(tail) + "}]}");
    }
    static std::string replay(const std::string& script, const std::string& folder) {
        return "$HG replay '" + script + "' --headless --remesh-chunks 1 --res 96 --session '" + folder + "'";
    }
    std::size_t temporariesIn(const fs::path& p) const {
        std::size_t n = 0;
        if (fs::exists(p))
            for (const auto& e : fs::recursive_directory_iterator(p))
                n += e.path().filename().string().find(".partial-") != std::string::npos;
        return n;
    }
};

// The journal holds a prefix of the script's actions, in order.
void expectPrefixOfScript(const JournalRead& r, std::size_t strokesInScript) {
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_FALSE(r.damaged()) << r.damage;
    std::size_t strokes = 0;
    for (const Action& rec : r.records) {
        if (const auto* st = std::get_if<StrokeAction>(&rec)) {
            EXPECT_EQ(st->sculpture, kNames[strokes % 3]) << "stroke " << strokes;
            ++strokes;
        } else {
            EXPECT_TRUE(std::holds_alternative<UndoAction>(rec));
            EXPECT_EQ(strokes % 9, 0u);
        }
    }
    EXPECT_LE(strokes, strokesInScript);
}

std::size_t actionsOf(std::size_t strokes) { return strokes + strokes / 9; }

TEST_F(SessionProcessTest, ASecondProcessIsRefusedWhileTheFirstWritesAndReadersSaySo) {
    const std::string s = script(18, 2, 10, 150000);  // then about five seconds idle: time for the others
    const std::string folder = (dir / "session").string();
    const pid_t first = ::fork();
    ASSERT_GE(first, 0);
    if (first == 0) {
        const int out = ::open((dir / "first.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        ::dup2(out, 2);
        ::execl(HG_HYPERGARDEN_EXE, HG_HYPERGARDEN_EXE, "replay", s.c_str(), "--headless", "--remesh-chunks", "1",
                "--res", "96", "--session", folder.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Once the first holds the session (and has journalled something).
    const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    std::optional<io::LockHolder> holder;
    int early = 0;
    bool ended = false;
    while (std::chrono::steady_clock::now() < giveUp) {
        holder = io::lockHolder(folder, kSessionLockFile);
        if (holder && fs::exists(SessionPaths(folder).journal)) break;
        if (::waitpid(first, &early, WNOHANG) == first) {
            ended = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const auto log = [&] {
        std::ifstream in(dir / "first.log");
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    };
    ASSERT_FALSE(ended) << "the first process ended early (status " << early << "): " << log();
    ASSERT_TRUE(holder) << log();
    EXPECT_EQ(holder->pid, static_cast<long>(first));
    const ShellRun second = shell(replay(s, folder));
    const ShellRun verify = shell("$HG session '" + folder + "' --verify");
    const ShellRun report = shell("$HG session '" + folder + "'");
    const ShellRun exported = shell("$HG export '" + folder + "' --sculpture a -o '" + (dir / "a.hf").string() + "'");
    // The first was still at work through all of them (else the test
    // proved nothing).
    int status = 0;
    ASSERT_EQ(::waitpid(first, &status, WNOHANG), 0) << "the first process ended before the second was tried";
    const std::string held = "is open in process " + std::to_string(first) + " (hypergarden replay) on ";
    EXPECT_EQ(second.status, 2) << second.output;
    EXPECT_NE(second.output.find(held), std::string::npos) << second.output;
    EXPECT_NE(second.output.find(" since "), std::string::npos) << second.output;
    EXPECT_EQ(verify.status, 2) << verify.output;
    EXPECT_NE(verify.output.find(held), std::string::npos) << verify.output;
    EXPECT_EQ(report.status, 0) << report.output;
    EXPECT_NE(report.output.find("changes nothing"), std::string::npos) << report.output;
    EXPECT_EQ(exported.status, 0) << exported.output;
    EXPECT_NE(exported.output.find(held), std::string::npos) << exported.output;
    EXPECT_TRUE(fs::exists(dir / "a.hf"));
    ASSERT_EQ(::waitpid(first, &status, 0), first);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    // The first's work is whole: every action, and the grids verified.
    const JournalRead r = readJournal(SessionPaths(folder).journal);
    expectPrefixOfScript(r, 18);
    EXPECT_EQ(r.records.size(), actionsOf(18));
    const ShellRun after = shell("$HG session '" + folder + "' --verify");
    EXPECT_EQ(after.status, 0) << after.output;
    EXPECT_NE(after.output.find("compared voxel by voxel: all equal"), std::string::npos) << after.output;
}

// The seam fails the n-th step at each session site with each errno: told
// at once and at exit (non-zero where an action was not saved), and the
// session reopens with a prefix of the actions, verified.
TEST_F(SessionProcessTest, EveryFailedWriteIsToldAndReopeningVerifiesWithoutADifference) {
    const std::string s = script(12, 2, 2);
    struct Case {
        const char* plan;
        int status;            // the replay's exit status
        const char* told;      // on its stderr
        std::size_t records;   // journalled (all: 13)
        bool snapshot;         // a snapshot was published
    };
    const Case cases[] = {
        {"journal:3-:ENOSPC", 1, "NOT SAVED to", 1, false},
        {"journal:5-:EDQUOT", 1, "Disk quota exceeded", 2, false},
        {"journal:1-:EROFS", 1, "Read-only file system", 0, false},
        {"journal:7-:EFBIG", 1, "File too large", 3, false},
        {"journal:4:EIO", 0, "saved again", 13, true},  // one failed sync, written with the next action
        {"snapshot-grid:3:ENOSPC", 0, "the snapshot was not written", 13, false},
        {"snapshot-manifest:1:EIO", 0, "the snapshot was not written", 13, false},
        {"snapshot-grid:7:EROFS", 0, "the snapshot was not written", 13, false},
        {"snapshot-manifest:3:EDQUOT", 0, "the snapshot was not written", 13, false},
    };
    int n = 0;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.plan);
        const std::string folder = (dir / ("s" + std::to_string(n++))).string();
        const ShellRun r = shell("HG_FAIL_WRITE=" + std::string(c.plan) + " " + replay(s, folder));
        EXPECT_EQ(r.status, c.status) << r.output;
        EXPECT_NE(r.output.find(c.told), std::string::npos) << r.output;
        const JournalRead j = fs::exists(SessionPaths(folder).journal) ? readJournal(SessionPaths(folder).journal)
                                                                       : JournalRead{};
        expectPrefixOfScript(j, 12);
        EXPECT_EQ(j.records.size(), c.records);
        EXPECT_EQ(readSnapshotInfo(SessionPaths(folder)).present, c.snapshot);
        EXPECT_EQ(temporariesIn(folder), 0u);
        const ShellRun verify = shell("$HG session '" + folder + "' --verify");
        EXPECT_EQ(verify.status, 0) << verify.output;
        EXPECT_NE(verify.output.find(c.snapshot ? "all equal" : "no snapshot yet"), std::string::npos) << verify.output;
    }
    // A session that cannot be made is not left looking like one, and the
    // next opening makes it.
    const std::string folder = (dir / "unmade").string();
    const ShellRun r = shell("HG_FAIL_WRITE=session-file:3-:ENOSPC " + replay(s, folder));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(SessionPaths(folder).manifest));
    EXPECT_EQ(shell(replay(s, folder)).status, 0);
    EXPECT_EQ(readJournal(SessionPaths(folder).journal).records.size(), actionsOf(12));
    // The replay's statistics and an export: refused with the reason, no file.
    const ShellRun stats = shell("HG_FAIL_WRITE=stats:1:EIO " + replay(s, (dir / "st").string()) + " --stats '" +
                            (dir / "stats.json").string() + "'");
    EXPECT_EQ(stats.status, 1) << stats.output;
    EXPECT_NE(stats.output.find("Input/output error"), std::string::npos) << stats.output;
    EXPECT_FALSE(fs::exists(dir / "stats.json"));
    for (const char* out : {"a.hf", "a.stl", "a.obj", "a.glb", "a.vdb"}) {
        const ShellRun e = shell("HG_FAIL_WRITE=export:1:ENOSPC $HG export '" + folder + "' --sculpture a --res 48 -o '" +
                            (dir / out).string() + "'");
        EXPECT_EQ(e.status, 1) << out << ": " << e.output;
        EXPECT_NE(e.output.find("No space left on device"), std::string::npos) << e.output;
        EXPECT_FALSE(fs::exists(dir / out)) << out;
    }
    EXPECT_EQ(temporariesIn(dir), 0u);
}

// A real full disk: tmpfs of 32 KiB (the journal fills it) and 128 KiB
// (the snapshot does not fit), mounted in a private mount namespace.
TEST_F(SessionProcessTest, AFullFileSystemIsToldAndNothingBrokenIsPublished) {
    const std::string s = script(30, 24, 1);  // long paths: records of about 1.5 KiB
    for (const char* size : {"32k", "128k"}) {
        SCOPED_TRACE(size);
        const fs::path mount = dir / ("mnt" + std::string(size)), copy = dir / ("copy" + std::string(size));
        fs::create_directories(mount);
        const std::string m = mount.string();
        const ShellRun r = shell("unshare -rm sh -c \"mount -t tmpfs -o size=" + std::string(size) + " tmpfs '" + m +
                            "' || exit 99; " + replay(s, m + "/s") + "; echo replay-status=\\$?; $HG session '" + m +
                            "/s' --verify; echo verify-status=\\$?; cp -r '" + m + "/s' '" + copy.string() + "'\"");
        ASSERT_NE(r.status, 99) << "cannot mount a tmpfs: " << r.output;
        EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("verify-status=0"), std::string::npos) << r.output;
        const JournalRead j = readJournal(SessionPaths(copy.string()).journal);
        expectPrefixOfScript(j, 30);
        if (std::string(size) == "32k") {
            EXPECT_NE(r.output.find("replay-status=1"), std::string::npos) << r.output;
            EXPECT_NE(r.output.find("were not saved to"), std::string::npos) << r.output;
            EXPECT_LT(j.records.size(), actionsOf(30));
            EXPECT_GT(j.records.size(), 0u);
        } else {
            // The journal fits; the snapshot does not and is not published.
            EXPECT_NE(r.output.find("replay-status=0"), std::string::npos) << r.output;
            EXPECT_NE(r.output.find("the snapshot was not written"), std::string::npos) << r.output;
            EXPECT_EQ(j.records.size(), actionsOf(30));
        }
        const SnapshotInfo snap = readSnapshotInfo(SessionPaths(copy.string()));
        for (const std::string& f : snap.files) EXPECT_GT(fs::file_size(fs::path(SessionPaths(copy.string()).snapshots) / f), 0u);
        EXPECT_EQ(temporariesIn(copy), 0u);
        // Reopened (with room): what the journal holds, verified.
        EXPECT_EQ(shell("$HG session '" + copy.string() + "' --verify").status, 0);
    }
}

// SIGKILL in the middle of a snapshot, at each of its steps: the next
// opening removes what the dead writer left, says so, and verifies.
TEST_F(SessionProcessTest, AProcessKilledInASnapshotLeavesNothingAfterReopening) {
    const std::string s = script(6, 2, 2);
    const char* plans[] = {"snapshot-grid:1:KILL", "snapshot-grid:4:KILL", "snapshot-manifest:2:KILL",
                           "snapshot-grid:7:KILL", "snapshot-manifest:3:KILL", "snapshot-manifest:4:KILL"};
    int n = 0;
    for (const char* plan : plans) {
        SCOPED_TRACE(plan);
        const std::string folder = (dir / ("k" + std::to_string(n++))).string();
        const ShellRun killed = shell("HG_FAIL_WRITE=" + std::string(plan) + " " + replay(s, folder) + "; echo status=$?");
        EXPECT_NE(killed.output.find("status=137"), std::string::npos) << killed.output;  // 128 + SIGKILL
        const ShellRun reopened = shell("$HG session '" + folder + "' --verify");
        EXPECT_EQ(reopened.status, 0) << reopened.output;
        // Writers remove leftovers when they open: a replay of nothing more.
        const ShellRun writer = shell("$HG replay '" + write("idle.json", R"({"garden": ")" + writeGarden() +
                                                                      R"(", "steps": [{"frames": 1}]})") +
                                 "' --headless --res 96 --session '" + folder + "'");
        EXPECT_EQ(writer.status, 0) << writer.output;
        EXPECT_EQ(temporariesIn(folder), 0u);
        const JournalRead j = readJournal(SessionPaths(folder).journal);
        expectPrefixOfScript(j, 6);
        EXPECT_EQ(j.records.size(), 6u);
        // Only grids a published snapshot names are left.
        const SnapshotInfo snap = readSnapshotInfo(SessionPaths(folder));
        std::size_t grids = 0;
        if (fs::exists(SessionPaths(folder).snapshots))
            for (const auto& e : fs::directory_iterator(SessionPaths(folder).snapshots)) grids += e.path().extension() == ".vdb";
        EXPECT_EQ(grids, snap.files.size());
        const ShellRun verify = shell("$HG session '" + folder + "' --verify");
        EXPECT_EQ(verify.status, 0) << verify.output;
    }
}

// A record that cannot be played, in the middle of the journal: said with
// its number, action and reason, read-only; --cut-at keeps a copy and
// makes the session writable again.
TEST_F(SessionProcessTest, AnUnplayableRecordIsToldAndCutAtMakesTheSessionWritableAgain) {
    const std::string s = script(4, 2, 2);
    const std::string folder = (dir / "session").string();
    ASSERT_EQ(shell(replay(s, folder)).status, 0);
    // Two writers' interleaving, as it was seen: a redo with nothing to redo.
    const SessionPaths paths(folder);
    std::string text;
    {
        std::ifstream in(paths.journal, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        text = ss.str();
    }
    const std::string redo = actionJson(RedoAction{});
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x ", crc32(redo));
    // After record 2: record 3 is the redo, records 4 and 5 the last two strokes.
    std::size_t at = 0;
    for (int line = 0; line < 3; ++line) at = text.find('\n', at) + 1;
    text.insert(at, std::string(crc) + redo + "\n");
    std::ofstream(paths.journal, std::ios::binary | std::ios::trunc) << text;

    const ShellRun report = shell("$HG session '" + folder + "'");
    EXPECT_EQ(report.status, 1);
    EXPECT_NE(report.output.find("not played: record 3 (redo): nothing to redo; 2 records after it"), std::string::npos)
        << report.output;
    // Export reads what the session shows: the records before it.
    const ShellRun exported = shell("$HG export '" + folder + "' --sculpture a -o '" + (dir / "a.hf").string() + "'");
    EXPECT_EQ(exported.status, 0) << exported.output;
    EXPECT_NE(exported.output.find("exporting the 2 records before it"), std::string::npos) << exported.output;
    EXPECT_TRUE(fs::exists(dir / "a.hf"));
    const ShellRun opened = shell(replay(s, folder));
    EXPECT_EQ(opened.status, 1) << opened.output;
    EXPECT_NE(opened.output.find("READ-ONLY"), std::string::npos) << opened.output;
    EXPECT_NE(opened.output.find("--cut-at 3"), std::string::npos) << opened.output;
    {
        std::ifstream in(paths.journal, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        EXPECT_EQ(ss.str(), text) << "a read-only session wrote to its journal";
    }
    const ShellRun cut = shell("$HG session '" + folder + "' --cut-at 3");
    EXPECT_EQ(cut.status, 0) << cut.output;
    EXPECT_NE(cut.output.find("records 1 to 2 kept, 3 removed"), std::string::npos) << cut.output;
    EXPECT_TRUE(fs::exists(paths.journal + ".before-cut-at-3"));
    EXPECT_EQ(readJournal(paths.journal).records.size(), 2u);
    EXPECT_EQ(readJournal(paths.journal + ".before-cut-at-3").records.size(), 5u);
    const ShellRun again = shell(replay(s, folder));
    EXPECT_EQ(again.status, 0) << again.output;
    EXPECT_EQ(readJournal(paths.journal).records.size(), 2u + actionsOf(4));
    EXPECT_EQ(shell("$HG session '" + folder + "' --verify").status, 0);
}

TEST_F(SessionProcessTest, FoldersThatAreNotSessionsAreRefusedByEveryCommand) {
    const std::string s = script(2, 2, 2);
    write("mine/notes.txt", "mine\n");
    const ShellRun r = shell(replay(s, (dir / "mine").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("is not a Hypergarden session and not empty"), std::string::npos) << r.output;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "mine"), fs::directory_iterator()), 1);
    const ShellRun deep = shell(replay(s, (dir / "p" / "q").string()));
    EXPECT_EQ(deep.status, 0) << deep.output;
    EXPECT_NE(deep.output.find("note: created the folders " + (dir / "p").string() + ", " + (dir / "p" / "q").string()),
              std::string::npos)
        << deep.output;
    // Without a snapshot, --verify says what it checked.
    fs::remove_all(SessionPaths((dir / "p" / "q").string()).snapshots);
    const ShellRun verify = shell("$HG session '" + (dir / "p" / "q").string() + "' --verify");
    EXPECT_EQ(verify.status, 0) << verify.output;
    EXPECT_NE(verify.output.find("verify: no snapshot yet"), std::string::npos) << verify.output;
    EXPECT_NE(verify.output.find("the journal's 2 records play"), std::string::npos) << verify.output;
}

}  // namespace
}  // namespace hg::garden

#endif
