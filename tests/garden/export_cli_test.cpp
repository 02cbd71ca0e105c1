// `hypergarden export`: a session folder's sculpture written as HyperFun
// (the same text the library writes for that session), and clear errors
// that leave no file for bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "garden/export/hyperfun_export.h"
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
        OpenedSession o = openSession(folder, gardenFile, settings);
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
        {g + " --sculpture a -o " + path("out.stl"), "export to .stl is not built yet"},
        {g + " --sculpture a -o " + path("out.glb"), "export to .glb is not built yet"},
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

}  // namespace
}  // namespace hg::garden
