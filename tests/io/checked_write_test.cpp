// Checked writes (io/checked_write.h), the fault seam (io/write_faults.h)
// and the folder lock (io/folder_lock.h), on the real file system: every
// errno the seam injects comes back as a message naming the file and the
// reason, leaves the target as it was and no temporary behind; a kernel
// limit on file size (RLIMIT_FSIZE) gives the same as an injected EFBIG;
// two opens of one lock exclude each other and the second names the holder.
#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/checked_write.h"
#include "io/folder_lock.h"
#include "io/write_faults.h"

namespace hg::io {
namespace {

namespace fs = std::filesystem;

class CheckedWriteTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("hg_io_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    void TearDown() override {
        setFaultPlan(std::nullopt);
        fs::remove_all(dir);
    }
    std::string read(const fs::path& p) const {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::size_t temporaries() const {
        std::size_t n = 0;
        for (const auto& e : fs::directory_iterator(dir)) n += isTemporaryName(e.path().filename().string());
        return n;
    }
    fs::path dir;
};

FaultPlan failing(WriteSite site, std::size_t step, int error) {
    FaultPlan p;
    p.anySite = false;
    p.site = site;
    p.first = p.last = step;
    p.error = error;
    return p;
}

TEST(FaultPlanTest, ParsesSitesStepsRangesAndErrorsAndRefusesTheRest) {
    std::string why;
    auto p = parseFaultPlan("journal:3:ENOSPC", why);
    ASSERT_TRUE(p) << why;
    EXPECT_FALSE(p->anySite);
    EXPECT_EQ(p->site, WriteSite::Journal);
    EXPECT_EQ(p->first, 3u);
    EXPECT_EQ(p->last, 3u);
    EXPECT_EQ(p->error, ENOSPC);
    p = parseFaultPlan("5-:EIO", why);
    ASSERT_TRUE(p) << why;
    EXPECT_TRUE(p->anySite);
    EXPECT_EQ(p->first, 5u);
    EXPECT_EQ(p->last, SIZE_MAX);
    p = parseFaultPlan("snapshot-grid:2-4:KILL", why);
    ASSERT_TRUE(p) << why;
    EXPECT_TRUE(p->kill);
    EXPECT_EQ(p->last, 4u);
    for (const char* bad : {"", "3", "journal:0:EIO", "journal:3:EPERM", "disk:1:EIO", "4-2:EIO", "x:EIO"}) {
        EXPECT_FALSE(parseFaultPlan(bad, why)) << bad;
        EXPECT_FALSE(why.empty()) << bad;
    }
}

TEST_F(CheckedWriteTest, EveryInjectedErrorAtEveryStepLeavesTheTargetAsItWasAndNoTemporary) {
    const fs::path target = dir / "file.txt";
    std::ofstream(target) << "old contents\n";
    const std::string big(3 << 20, 'x');  // several buffered writes
    const std::pair<int, const char*> errors[] = {
        {ENOSPC, "No space left on device"}, {EIO, "Input/output error"}, {EDQUOT, "Disk quota exceeded"},
        {EROFS, "Read-only file system"},     {EFBIG, "File too large"}};
    // The steps of one atomic write: its write() calls, the sync of the
    // temporary, the rename; the folder's sync after the rename is last.
    // Counted by failing ever later steps until the write succeeds.
    std::size_t steps = 1;
    for (; steps < 100; ++steps) {
        setFaultPlan(failing(WriteSite::Export, steps, EIO));
        if (writeFileAtomically(target.string(), big, WriteSite::Export).empty()) break;
        std::ofstream(target) << "old contents\n";
    }
    std::ofstream(target) << "old contents\n";
    ASSERT_GE(steps, 4u);  // at least a write, a sync, a rename and the folder's sync
    for (const auto& [error, text] : errors)
        for (std::size_t step = 1; step < steps; ++step) {
            setFaultPlan(failing(WriteSite::Export, step, error));
            const std::string why = writeFileAtomically(target.string(), big, WriteSite::Export);
            ASSERT_NE(why, "") << "step " << step;
            EXPECT_NE(why.find(text), std::string::npos) << why;
            EXPECT_NE(why.find(target.string()), std::string::npos) << why;
            EXPECT_EQ(temporaries(), 0u) << "step " << step;
            // Before the rename the target is untouched; a failed folder
            // sync comes after it, and the new file is whole.
            const std::string now = read(target);
            EXPECT_TRUE(now == "old contents\n" || now == big) << "step " << step;
            std::ofstream(target) << "old contents\n";
        }
    // A fault at another site does not touch this one.
    setFaultPlan(failing(WriteSite::Journal, 1, ENOSPC));
    EXPECT_EQ(writeFileAtomically(target.string(), "new\n", WriteSite::Export), "");
    EXPECT_EQ(read(target), "new\n");
}

TEST_F(CheckedWriteTest, AFailedBufferedWriteSticksAndFinishReportsTheFirstFailure) {
    setFaultPlan(failing(WriteSite::Export, 2, ENOSPC));
    CheckedFile f((dir / "out.bin").string(), WriteSite::Export);
    const std::string chunk(1 << 20, 'a');
    f.write(chunk);
    f.write(chunk);
    f.write(chunk);
    f.write(chunk);
    const std::string why = f.finish();
    EXPECT_NE(why.find("No space left on device"), std::string::npos) << why;
    EXPECT_FALSE(f.ok());
}

// The kernel's own limit on a file's size: the write fails with EFBIG
// (SIGXFSZ ignored), as on a file system that cannot hold the file.
TEST_F(CheckedWriteTest, TheKernelsFileSizeLimitIsReportedAndLeavesTheTargetAlone) {
    const fs::path target = dir / "big.bin";
    std::ofstream(target) << "kept\n";
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {};
        limit.rlim_cur = limit.rlim_max = 64 * 1024;
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const std::string why = writeFileAtomically(target.string(), std::string(1 << 20, 'z'), WriteSite::Export);
        ::_exit(why.find("File too large") != std::string::npos ? 0 : 1);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(read(target), "kept\n");
    EXPECT_EQ(temporaries(), 0u);
}

TEST_F(CheckedWriteTest, ALockIsHeldOnceAndTheSecondOpenerIsToldWhoHoldsIt) {
    std::string why;
    std::optional<LockHolder> holder;
    EXPECT_FALSE(lockHolder(dir.string(), "x.lock"));
    auto first = FolderLock::acquire(dir.string(), "x.lock", "first program", why, holder);
    ASSERT_TRUE(first) << why;
    EXPECT_FALSE(holder);
    auto second = FolderLock::acquire(dir.string(), "x.lock", "second program", why, holder);
    EXPECT_FALSE(second);
    ASSERT_TRUE(holder);
    EXPECT_EQ(holder->pid, static_cast<long>(::getpid()));
    EXPECT_EQ(holder->program, "first program");
    EXPECT_FALSE(holder->since.empty());
    EXPECT_NE(why.find("process " + std::to_string(::getpid()) + " (first program)"), std::string::npos) << why;
    const auto seen = lockHolder(dir.string(), "x.lock");
    ASSERT_TRUE(seen);
    EXPECT_EQ(seen->pid, static_cast<long>(::getpid()));
    // Released with its holder: the next one takes it.
    first.reset();
    EXPECT_FALSE(lockHolder(dir.string(), "x.lock"));
    auto third = FolderLock::acquire(dir.string(), "x.lock", "third", why, holder);
    EXPECT_TRUE(third) << why;
}

// A holder that dies (SIGKILL) leaves no stale lock: the kernel drops it.
TEST_F(CheckedWriteTest, ALockDiesWithItsProcess) {
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        std::string why;
        std::optional<LockHolder> holder;
        auto lock = FolderLock::acquire(dir.string(), "x.lock", "child", why, holder);
        const char c = lock ? 'y' : 'n';
        (void)!::write(ready[1], &c, 1);
        ::pause();
        ::_exit(0);
    }
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    ASSERT_EQ(c, 'y');
    const auto held = lockHolder(dir.string(), "x.lock");
    ASSERT_TRUE(held);
    EXPECT_EQ(held->pid, static_cast<long>(pid));
    EXPECT_EQ(held->program, "child");
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    EXPECT_FALSE(lockHolder(dir.string(), "x.lock"));
    std::string why;
    std::optional<LockHolder> holder;
    EXPECT_TRUE(FolderLock::acquire(dir.string(), "x.lock", "after", why, holder)) << why;
    ::close(ready[0]);
    ::close(ready[1]);
}

}  // namespace
}  // namespace hg::io
