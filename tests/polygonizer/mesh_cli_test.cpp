// `hypergarden mesh` as a user runs it: a HyperFun file or one of our grids
// becomes an STL that admesh finds nothing to fix in; bad inputs give a
// clear message, a non-zero exit status and no output file.
#include <gtest/gtest.h>

#include <fstream>

#include "../cli_fixture.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"

namespace hg::poly {
namespace {

using test::CommandRun;
using test::runHypergarden;

constexpr const char* kRing =
    "ring(x[3], a[1]) { array c[3]; c = [0, 0, 0]; ring = hfTorusY(x, c, 0.6, 0.2); }\n";

class MeshCli : public test::CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        if (!IsSkipped()) std::ofstream(dir / "ring.hf") << kRing;
    }
};

TEST_F(MeshCli, WritesAWatertightStlInMillimetres) {
    CommandRun r = runHypergarden("mesh " + path("ring.hf") + " --res 64 --mm-per-unit 100 -o " + path("ring.stl"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("verdict: watertight and manifold"), std::string::npos) << r.output;
    StlReadResult stl = readStl((dir / "ring.stl").string());
    ASSERT_EQ(stl.error, "");
    MeshReport rep = validateMesh(weldByPosition(stl.mesh));
    EXPECT_TRUE(rep.ok()) << describe(rep);
    const double torus = 2 * 3.14159265358979 * 3.14159265358979 * 60.0 * 20.0 * 20.0;  // mm^3
    EXPECT_NEAR(rep.volume, torus, 0.02 * torus);

    // From a grid written by voxelize, as ASCII.
    r = runHypergarden("voxelize " + path("ring.hf") + " --res 48 -o " + path("ring.vdb"));
    ASSERT_EQ(r.status, 0) << r.output;
    r = runHypergarden("mesh " + path("ring.vdb") + " --ascii -o " + path("ring_ascii.stl"));
    ASSERT_EQ(r.status, 0) << r.output;
    stl = readStl((dir / "ring_ascii.stl").string());
    ASSERT_EQ(stl.error, "");
    EXPECT_TRUE(stl.ascii);
    EXPECT_TRUE(validateMesh(weldByPosition(stl.mesh)).ok());

    ASSERT_EQ(std::system("command -v admesh > /dev/null 2>&1"), 0) << "admesh is not installed (scripts/install-deps.sh)";
    FILE* pipe = ::popen(("admesh " + path("ring.stl") + " 2>&1").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
    ::pclose(pipe);
    for (const char* label : {"Edges fixed", "Facets removed", "Facets added", "Facets reversed", "Backwards edges",
                              "Degenerate facets"}) {
        std::size_t at = out.find(label);
        ASSERT_NE(at, std::string::npos) << label << " in:\n" << out;
        std::size_t colon = out.find(':', at);
        EXPECT_EQ(std::stol(out.substr(colon + 1)), 0) << label << " in:\n" << out;
    }
}

TEST_F(MeshCli, BadInputsSayWhatIsWrongAndWriteNothing) {
    std::ofstream(dir / "not_ours.vdb") << "not a vdb";
    struct Case {
        std::string args, message;
    } cases[] = {
        {"mesh " + path("ring.hf") + " -o " + path("o.stl"), "--res N is required"},
        {"mesh " + path("missing.hf") + " --res 32 -o " + path("o.stl"), "missing.hf"},
        {"mesh " + path("not_ours.vdb") + " -o " + path("o.stl"), "not_ours.vdb"},
        {"mesh " + path("ring.hf") + " --res 32 --mm-per-unit 0 -o " + path("o.stl"), "--mm-per-unit must be positive"},
        {"mesh " + path("ring.hf") + " --res 32 -o " + path("no/dir/o.stl"), "cannot write"},
        {"mesh " + path("ring.hf") + " --res 0 -o " + path("o.stl"), "--res N is required"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        CommandRun r = runHypergarden(c.args);
        EXPECT_NE(r.status, 0) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(exists("o.stl"));
    }
    EXPECT_EQ(entries(), 2u) << "only the inputs remain";
}

TEST_F(MeshCli, BoundedFilesMeshWithoutABox) {
    // Sculptures written outside the project (tests/data/bounded) that the
    // interval estimate cannot bound: the box is found by sampling, said so,
    // and the mesh is the same solid as over a given box around it.
    for (const char* name : {"arc_torus", "figure_on_block", "totem"}) {
        SCOPED_TRACE(name);
        const std::string hf = "'" + std::string(HG_TEST_DATA_DIR) + "/bounded/" + name + ".hf'";
        CommandRun r = runHypergarden("mesh " + hf + " --res 64 -o " + path("found.stl"));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("model box: ["), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("(sampled: the interval estimate failed"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("the default box [-10, 10]^3"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("verdict: watertight and manifold"), std::string::npos) << r.output;
        StlReadResult found = readStl((dir / "found.stl").string());
        ASSERT_EQ(found.error, "");
        MeshReport rep = validateMesh(weldByPosition(found.mesh));
        EXPECT_TRUE(rep.ok()) << describe(rep);

        r = runHypergarden("mesh " + hf + " --res 64 --box -2.5,-2.5,-2.5,2.5,2.5,2.5 -o " + path("given.stl"));
        ASSERT_EQ(r.status, 0) << r.output;
        EXPECT_NE(r.output.find("(given)"), std::string::npos) << r.output;
        StlReadResult given = readStl((dir / "given.stl").string());
        ASSERT_EQ(given.error, "");
        MeshReport ref = validateMesh(weldByPosition(given.mesh));
        // The given box's voxels are about twice as large: within a few of
        // them (0.08 units, 80 mm at the default 1000 mm per unit) of each
        // other, and of the same volume.
        EXPECT_NEAR(rep.volume, ref.volume, 0.03 * ref.volume);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(rep.boxMin[a], ref.boxMin[a], 100.0) << "axis " << a;
            EXPECT_NEAR(rep.boxMax[a], ref.boxMax[a], 100.0) << "axis " << a;
        }
    }

    // A truly unbounded solid (an infinite cylinder along y) is refused with
    // the faces of the default box it reaches, and nothing is written.
    std::ofstream(dir / "pillar.hf") << "pillar(x[3], a[1]) { pillar = 0.3 - x[1]^2 - x[3]^2; }\n";
    CommandRun r = runHypergarden("mesh " + path("pillar.hf") + " --res 32 -o " + path("o.stl"));
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("the solid is unbounded"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("reaching y = -10, y = 10;"), std::string::npos) << r.output;
    EXPECT_FALSE(exists("o.stl"));
}

}  // namespace
}  // namespace hg::poly
