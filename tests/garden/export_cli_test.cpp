// `hypergarden export`: a session folder's sculpture written as HyperFun
// (the same text the library writes for that session), and clear errors
// that leave no file for bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "garden/export/hyperfun_export.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "garden/session/open_session.h"
#include "session_garden.h"
#include "tests/cli_fixture.h"

namespace hg::garden {
namespace {

class ExportCliTest : public ::hg::test::CliTest {
protected:
    std::string garden() { return "'" + test::writeSmallGarden(dir / "g") + "'"; }
    std::string read(const std::string& name) const {
        std::ifstream in(dir / name, std::ios::binary);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

TEST_F(ExportCliTest, ASessionsSculptureIsWrittenAsTheLibraryWritesIt) {
    const std::string gardenFile = test::writeSmallGarden(dir / "g");
    const std::string folder = (dir / "session").string();
    std::string expected;
    {
        SessionSettings settings;
        settings.maxLevel = 0;
        OpenedSession o = openSession({folder, gardenFile}, settings);
        ASSERT_EQ(o.error, "");
        GardenSession& s = *o.session;
        const int c = s.findSculpture("c");
        ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{1.7, 0.9, 1.5}, {2.3, 0.9, 1.5}}, 0.1), "");
        ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Torus, {1.5, 0.5, 1.15}, {0.15, 0.05, 0.0}, -2.0), "");
        const HyperFunExport e = exportHyperFun(s, c);
        ASSERT_EQ(e.error, "");
        expected = e.text;
    }
    const ::hg::test::CommandRun r = ::hg::test::runHypergarden("export " + path("session") + " --sculpture c -o " + path("c.hf"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("2 edits"), std::string::npos) << r.output;
    EXPECT_EQ(read("c.hf"), expected);
    // From the garden file: the unedited sculpture.
    const ::hg::test::CommandRun g = ::hg::test::runHypergarden("export '" + gardenFile + "' --sculpture a -o " + path("a.hf"));
    ASSERT_EQ(g.status, 0) << g.output;
    EXPECT_NE(read("a.hf").find("my_model"), std::string::npos);
}

TEST_F(ExportCliTest, BadInputGivesAClearErrorAndNoFile) {
    const std::string g = garden();
    struct Case {
        std::string args, message;
    };
    const Case cases[] = {
        {g + " --sculpture nobody -o " + path("out.hf"), "no sculpture 'nobody'; its sculptures: 'a' 'b' 'c' 'lost' 'metamorphosis'"},
        {g + " --sculpture lost -o " + path("out.hf"), "sculpture 'lost' is missing"},
        {g + " --sculpture a -o " + path("out.xyz"), "unknown format '.xyz'"},
        {g + " --sculpture a -o " + path("out.stl") + " --res 100000", "error:"},
        {g + " --sculpture a -o " + path("out.stl") + " --res 1024 --memory-limit 1", "would fit"},
        {g + " --sculpture a -o " + path("out.glb") + " --box 1,2,3", "error:"},
        {g + " --sculpture a -o " + path("out.stl") + " --mm-per-unit -2", "must not be negative"},
        {g + " --sculpture a -o " + path("missing/out.hf"), "error:"},
        {path("g") + " --sculpture a -o " + path("out.hf"), "is not a session folder"},
        {path("none.json") + " --sculpture a -o " + path("out.hf"), "no such session folder or garden file"},
    };
    for (const Case& c : cases) {
        const ::hg::test::CommandRun r = ::hg::test::runHypergarden("export " + c.args);
        EXPECT_NE(r.status, 0) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(exists("out.hf") || exists("out.xyz") || exists("out.stl") || exists("out.glb") || exists("missing"))
            << c.args;
    }
    // Only the garden's folder is left: no temporary either.
    EXPECT_EQ(entries(), 1u);
}


// Meshes come from the exported FRep: an edited session's sculpture as STL
// (at a resolution finer than its grid), OBJ, glTF and VDB; the STL is
// closed and outward, in millimetres of the sculpture's true size, and the
// carve shows as lost volume against the unedited sculpture's export.
TEST_F(ExportCliTest, AnEditedSculptureIsMeshedFromItsExportedFRepInEveryFormat) {
    const std::string gardenFile = test::writeSmallGarden(dir / "g");
    const std::string folder = (dir / "session").string();
    {
        SessionSettings settings;
        settings.maxLevel = 0;
        OpenedSession o = openSession({folder, gardenFile}, settings);
        ASSERT_EQ(o.error, "");
        const int a = o.session->findSculpture("a");
        ASSERT_EQ(o.session->applyStroke(a, StrokeTool::Carve, {{-0.3, 1.0, -2.3094}, {0.3, 1.0, -2.3094}}, 0.1), "");
    }
    for (const char* ext : {"stl", "obj", "glb", "vdb"}) {
        const ::hg::test::CommandRun r = ::hg::test::runHypergarden("export " + path("session") + " --sculpture a --res 64 -o " +
                                                                    path(std::string("carved.") + ext));
        ASSERT_EQ(r.status, 0) << ext << "\n" << r.output;
        EXPECT_TRUE(exists(std::string("carved.") + ext)) << ext;
    }
    const ::hg::test::CommandRun plain =
        ::hg::test::runHypergarden("export '" + gardenFile + "' --sculpture a --res 64 -o " + path("plain.stl"));
    ASSERT_EQ(plain.status, 0) << plain.output;
    const auto volumeOf = [&](const std::string& name) {
        const poly::StlReadResult r = poly::readStl((dir / name).string());
        EXPECT_EQ(r.error, "");
        const poly::MeshReport m = poly::validateMesh(poly::weldByPosition(r.mesh));
        EXPECT_TRUE(m.ok()) << name << "\n" << poly::describe(m);
        // Millimetres at the sculpture's true size: the ball is 1 m across.
        EXPECT_NEAR(m.boxMax[1] - m.boxMin[1], 1000.0, 40.0) << name;
        return m.volume;
    };
    const double carved = volumeOf("carved.stl"), whole = volumeOf("plain.stl");
    // A ball of radius 0.5 m; the groove (radius 0.1 m across its top) takes about 1.5%.
    EXPECT_NEAR(whole, 4.0 / 3.0 * 3.14159265358979 * 0.125e9, 0.02 * whole);
    EXPECT_LT(carved, whole * 0.995);
    EXPECT_GT(carved, whole * 0.95);
}


// `mesh` and `export` agree on units: a file meshed by `mesh` at its
// defaults and the same sculpture exported from a garden at scale 1 are STLs
// of the same size in millimetres, and each report states its sizes in the
// file's units (mm for STL, m for OBJ).
TEST_F(ExportCliTest, MeshAndExportWriteTheSameSizeAndReportInTheFilesUnits) {
    const std::string g = garden();  // ball c: radius 0.6 units at 1 m per unit
    ::hg::test::CommandRun e = ::hg::test::runHypergarden("export " + g + " --sculpture c --res 48 -o " + path("e.stl"));
    ASSERT_EQ(e.status, 0) << e.output;
    ::hg::test::CommandRun m = ::hg::test::runHypergarden("mesh " + path("g/ball.hf") +
                                                          " --a 0.36 --box -0.6,-0.1,-0.6,0.6,1.1,0.6 --res 48 -o " + path("m.stl"));
    ASSERT_EQ(m.status, 0) << m.output;
    EXPECT_NE(m.output.find("STL in mm, 1000 mm per model unit: model units as metres"), std::string::npos) << m.output;
    poly::MeshReport sizes[2];
    int k = 0;
    for (const char* name : {"e.stl", "m.stl"}) {
        const poly::StlReadResult stl = poly::readStl((dir / name).string());
        ASSERT_EQ(stl.error, "") << name;
        sizes[k++] = poly::validateMesh(poly::weldByPosition(stl.mesh));
    }
    for (int a = 0; a < 3; ++a) {
        const double exported = sizes[0].boxMax[a] - sizes[0].boxMin[a], meshed = sizes[1].boxMax[a] - sizes[1].boxMin[a];
        EXPECT_NEAR(exported, 1200.0, 30.0) << "axis " << a << ": the ball's 1.2 m in mm";
        EXPECT_NEAR(meshed, exported, 30.0) << "axis " << a << ": within a voxel (25 mm) of each other";
    }
    // Each report in its file's units: the STL's 1.2 m as about 1200 mm,
    // the OBJ's as about 1.2 m.
    EXPECT_NE(e.output.find("size 1199.9"), std::string::npos) << e.output;
    EXPECT_NE(e.output.find(" mm\n"), std::string::npos) << e.output;
    EXPECT_NE(m.output.find("size: 1199.9"), std::string::npos) << m.output;
    ::hg::test::CommandRun o = ::hg::test::runHypergarden("export " + g + " --sculpture c --res 48 -o " + path("e.obj"));
    ASSERT_EQ(o.status, 0) << o.output;
    EXPECT_NE(o.output.find(" m\n"), std::string::npos) << o.output;
    EXPECT_NE(o.output.find("size 1.1"), std::string::npos) << o.output;
}

}  // namespace
}  // namespace hg::garden
