// `hypergarden voxelize` as a user runs it: a good run writes a readable
// grid and reports its statistics; bad inputs give a clear message, a
// non-zero exit status and no output file.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "test_models.h"
#include "voxel/vdb_io.h"

namespace hg::voxel {
namespace {

namespace fs = std::filesystem;

struct CommandRun {
    int status = -1;
    std::string output;  // stdout and stderr together
};

CommandRun run(const std::string& args) {
#ifndef HG_HYPERGARDEN_EXE
    (void)args;
    return {};
#else
    CommandRun r;
    std::string cmd = std::string("'") + HG_HYPERGARDEN_EXE + "' " + args + " 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    int st = ::pclose(pipe);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
#endif
}

class VoxelizeCli : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef HG_HYPERGARDEN_EXE
        GTEST_SKIP() << "the hypergarden executable is not built (HG_BUILD_APP=OFF)";
#endif
        dir = fs::temp_directory_path() / ("hg_cli_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
        std::ofstream(dir / "torus.hf") << test::kTorusBlock;
    }
    void TearDown() override {
        if (!dir.empty()) fs::remove_all(dir);
    }
    std::string path(const std::string& name) const { return "'" + (dir / name).string() + "'"; }
    bool exists(const std::string& name) const { return fs::exists(dir / name); }
    std::size_t entries() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
    }
    fs::path dir;
};

TEST_F(VoxelizeCli, WritesAGridAndReportsStatistics) {
    CommandRun r = run("voxelize " + path("torus.hf") + " --res 48 --stats -o " + path("t.vdb"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("estimated by interval subdivision"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("|grad| of the stored field"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("median"), std::string::npos);
    EXPECT_NE(r.output.find("90th percentile"), std::string::npos);
    Volume v;
    ASSERT_EQ(readVolume((dir / "t.vdb").string(), v), "");
    EXPECT_EQ(v.frame.resolution, 48);
    EXPECT_EQ(v.source.body, "tb");
    EXPECT_GT(v.activeVoxelCount(), 1000u);

    r = run("voxelize " + path("torus.hf") + " --res 32 --levelset -o " + path("ls.vdb"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(exists("ls.vdb"));
    r = run("voxelize " + path("torus.hf") + " --res 32 --dense -o " + path("dense.vdb"));
    ASSERT_EQ(r.status, 0) << r.output;
    ASSERT_EQ(readVolume((dir / "dense.vdb").string(), v), "");
    EXPECT_EQ(v.kind, VolumeKind::DenseSource);
    EXPECT_EQ(v.activeVoxelCount(), v.frame.indexBox.volume());
}

TEST_F(VoxelizeCli, BadInputsSayWhatIsWrongAndWriteNothing) {
    struct Case {
        std::string args;
        std::string message;
    } cases[] = {
        {"voxelize " + path("missing.hf") + " --res 32 -o " + path("o.vdb"), "missing.hf"},
        {"voxelize " + path("torus.hf") + " --body nope --res 32 -o " + path("o.vdb"), "no body named 'nope'"},
        {"voxelize " + path("torus.hf") + " --res 0 -o " + path("o.vdb"), "resolution 0 is out of range"},
        {"voxelize " + path("torus.hf") + " --res 5000000 -o " + path("o.vdb"), "out of range"},
        {"voxelize " + path("torus.hf") + " --res 32 -o " + path("no/dir/o.vdb"), "cannot write"},
        {"voxelize " + path("torus.hf") + " --res 32 --box 1,2,3 -o " + path("o.vdb"), "six numbers"},
        {"voxelize " + path("torus.hf") + " --res 2048 --memory-limit 1 -o " + path("o.vdb"), "would fit"},
        {"voxelize " + path("torus.hf") + " --res 1024 --dense --memory-limit 64 -o " + path("o.vdb"),
         "dense cache"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        CommandRun r = run(c.args);
        EXPECT_NE(r.status, 0) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_EQ(entries(), 1u) << "only the input file remains";
    }
    // A syntax error is reported with its line and column.
    std::ofstream(dir / "bad.hf") << "m(x[3], a[1]) {\n  m = 1 +;\n}\n";
    CommandRun r = run("voxelize " + path("bad.hf") + " --res 32 -o " + path("o.vdb"));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("bad.hf:2:"), std::string::npos) << r.output;
    EXPECT_FALSE(exists("o.vdb"));
}

}  // namespace
}  // namespace hg::voxel
