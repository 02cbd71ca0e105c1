// `hypergarden voxelize` as a user runs it: a good run writes a readable
// grid and reports its statistics; bad inputs give a clear message, a
// non-zero exit status and no output file.
#include <gtest/gtest.h>

#include <fstream>

#include "../cli_fixture.h"
#include "test_models.h"
#include "voxel/vdb_io.h"

namespace hg::voxel {
namespace {

namespace fs = std::filesystem;
using ::hg::test::CommandRun;

CommandRun run(const std::string& args) { return ::hg::test::runHypergarden(args); }

class VoxelizeCli : public ::hg::test::CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        if (!IsSkipped()) std::ofstream(dir / "torus.hf") << test::kTorusBlock;
    }
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

TEST_F(VoxelizeCli, BoundedFilesVoxelizeWithoutABox) {
    // Sculptures written outside the project (tests/data/bounded) that the
    // interval estimate cannot bound: sampled for their box, which the
    // output and the grid's metadata say.
    for (const char* name : {"arc_torus", "figure_on_block", "totem"}) {
        SCOPED_TRACE(name);
        const std::string hf = "'" + std::string(HG_TEST_DATA_DIR) + "/bounded/" + name + ".hf'";
        CommandRun r = run("voxelize " + hf + " --res 48 -o " + path("b.vdb"));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("model box: ["), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("(sampled: the interval estimate failed: interval bounds did not separate"),
                  std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find("the default box [-10, 10]^3 was sampled"), std::string::npos) << r.output;
        Volume v;
        ASSERT_EQ(readVolume((dir / "b.vdb").string(), v), "");
        EXPECT_EQ(v.boxOrigin, BoxOrigin::Sampled);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GT(v.frame.modelBox.lo[a], -2.5) << "axis " << a;
            EXPECT_LT(v.frame.modelBox.hi[a], 2.5) << "axis " << a;
        }
        EXPECT_GT(v.activeVoxelCount(), 1000u);

        // --dense finds the same box.
        r = run("voxelize " + hf + " --res 48 --dense -o " + path("d.vdb"));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("(sampled: the interval estimate failed"), std::string::npos) << r.output;
        Volume d;
        ASSERT_EQ(readVolume((dir / "d.vdb").string(), d), "");
        EXPECT_EQ(d.boxOrigin, BoxOrigin::Sampled);
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(d.frame.modelBox.lo[a], v.frame.modelBox.lo[a]);
            EXPECT_EQ(d.frame.modelBox.hi[a], v.frame.modelBox.hi[a]);
        }
    }
}

TEST_F(VoxelizeCli, UnboundedSolidsNameTheFacesTheyReach) {
    // The half-space y <= 0.3: every face of the default box but y = 10.
    std::ofstream(dir / "ground.hf") << "ground(x[3], a[1]) { ground = 0.3 - x[2]; }\n";
    CommandRun r = run("voxelize " + path("ground.hf") + " --res 32 -o " + path("o.vdb"));
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("the solid is unbounded"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("reaching x = -10, x = 10, y = -10, z = -10, z = 10;"), std::string::npos) << r.output;
    EXPECT_FALSE(exists("o.vdb"));
}

}  // namespace
}  // namespace hg::voxel
