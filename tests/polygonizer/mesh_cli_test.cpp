// `hypergarden mesh` as a user runs it: a HyperFun file or one of our grids
// becomes an STL that admesh finds nothing to fix in; bad inputs give a
// clear message, a non-zero exit status and no output file.
#include <gtest/gtest.h>

#include <fstream>

#include "../cli_fixture.h"
#include "polygonizer/mesh_validation.h"
#include "polygonizer/stl_io.h"

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

}  // namespace
}  // namespace hg::poly
