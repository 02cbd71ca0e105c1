// A session remembers the view (issue 23): DIR/view.json written from the
// navigator and read back into another, the pose the same; a session
// without one opens at the garden's start; a broken one is named with its
// place and changes nothing.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>

#include "garden/app/navigator.h"
#include "garden/session/session_view.h"
#include "garden_test_util.h"

namespace hg::garden {
namespace {

class SessionViewTest : public test::ScratchDir {};

TEST_F(SessionViewTest, TheViewIsWrittenAndReadBack) {
    Navigator left;
    left.setMode(NavigationMode::Fly);
    left.setPose({1.25f, 2.5f, -3.75f}, 0.7f, -0.3f);
    ASSERT_EQ(writeSessionView(dir.string(), left), "");
    Navigator reopened;
    std::string warning;
    ASSERT_TRUE(readSessionView(dir.string(), reopened, warning)) << warning;
    EXPECT_EQ(warning, "");
    EXPECT_EQ(reopened.mode(), NavigationMode::Fly);
    EXPECT_NEAR(reopened.eye().x, 1.25f, 1e-5f);
    EXPECT_NEAR(reopened.eye().y, 2.5f, 1e-5f);
    EXPECT_NEAR(reopened.eye().z, -3.75f, 1e-5f);
    EXPECT_NEAR(reopened.yaw(), 0.7f, 1e-5f);
    EXPECT_NEAR(reopened.pitch(), -0.3f, 1e-5f);

    // Walking stays walking (at eye height).
    left.setMode(NavigationMode::Walk);
    ASSERT_EQ(writeSessionView(dir.string(), left), "");
    ASSERT_TRUE(readSessionView(dir.string(), reopened, warning));
    EXPECT_EQ(reopened.mode(), NavigationMode::Walk);
}

TEST_F(SessionViewTest, NoViewOpensAtTheStartAndABrokenOneIsNamed) {
    Navigator n;
    n.setPose({4.0f, 1.7f, 4.0f}, 0.1f, 0.0f);
    std::string warning = "stale";
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_EQ(warning, "") << "a session without a view yet is not a fault";
    write(kSessionViewFile, R"({"mode": "fly", "eye": [1, 2], "yaw": 0, "pitch": 0})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("view.json"), std::string::npos) << warning;
    EXPECT_NE(warning.find("$.eye"), std::string::npos) << warning;
    EXPECT_NEAR(n.eye().x, 4.0f, 1e-6f) << "left as it was";
    write(kSessionViewFile, R"({"mode": "swim", "eye": [1, 2, 3], "yaw": 0, "pitch": 0})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("$.mode"), std::string::npos) << warning;
    write(kSessionViewFile, "{\"mode\": \"fly\",");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning));
    EXPECT_NE(warning.find("view.json"), std::string::npos) << warning;
}

// The tool in hand comes back with the view (issue 23): kind, sizes,
// shapes, the reverse and what the sketch tool makes; a view written
// before tools were kept gives none, and a bad tool is named by its path.
TEST_F(SessionViewTest, TheToolAndItsSettingsComeBack) {
    Navigator n;
    ToolSettings t;
    selectTool(t, ToolSettings::Kind::Impacts);
    t.radius = 0.3;
    t.radii = {0.2, 0.1, 0.05};
    t.perturbScale = 1.5;
    t.shape = QuadricShape::Torus;
    t.strength = -4.0;
    t.reverse = true;
    t.impactShape = ImpactShape::Chisel;
    t.impactSize = 0.04;
    t.compactionCm3 = 2.0;
    t.spread = ImpactSpread::Cone;
    t.spreadSize = 12.0;
    t.impactCount = 7;
    t.sketchUse = ToolSettings::SketchUse::Model;
    t.smoothStrength = 0.35;
    t.inflateStrength = 1.75;
    t.falloff = Falloff::Sharp;
    ASSERT_EQ(writeSessionView(dir.string(), n, &t), "");
    std::optional<ToolSettings> back;
    std::string warning;
    ASSERT_TRUE(readSessionView(dir.string(), n, warning, &back)) << warning;
    ASSERT_TRUE(back);
    EXPECT_EQ(back->kind, ToolSettings::Kind::Impacts);
    EXPECT_EQ(back->radius, 0.3);
    EXPECT_EQ(back->radii, t.radii);
    EXPECT_EQ(back->perturbScale, 1.5);
    EXPECT_EQ(back->shape, QuadricShape::Torus);
    EXPECT_EQ(back->strength, -4.0);
    EXPECT_TRUE(back->reverse);
    EXPECT_EQ(back->impactShape, ImpactShape::Chisel);
    EXPECT_EQ(back->impactSize, 0.04);
    EXPECT_EQ(back->compactionCm3, 2.0);
    EXPECT_EQ(back->spread, ImpactSpread::Cone);
    EXPECT_EQ(back->spreadSize, 12.0);
    EXPECT_EQ(back->impactCount, 7);
    EXPECT_EQ(back->sketchUse, ToolSettings::SketchUse::Model);
    EXPECT_EQ(back->smoothStrength, 0.35);
    EXPECT_EQ(back->inflateStrength, 1.75);
    EXPECT_EQ(back->falloff, Falloff::Sharp);
    // Written before tools were kept: the view, and no tool.
    ASSERT_EQ(writeSessionView(dir.string(), n), "");
    ASSERT_TRUE(readSessionView(dir.string(), n, warning, &back)) << warning;
    EXPECT_FALSE(back);
    write(kSessionViewFile, R"({"mode": "fly", "eye": [1, 2, 3], "yaw": 0, "pitch": 0, "tool": {"kind": "chainsaw"}})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning, &back));
    EXPECT_NE(warning.find("$.tool.kind"), std::string::npos) << warning;
    write(kSessionViewFile, R"({"mode": "fly", "eye": [1, 2, 3], "yaw": 0, "pitch": 0, "tool": {"falloff": "soft"}})");
    EXPECT_FALSE(readSessionView(dir.string(), n, warning, &back));
    EXPECT_NE(warning.find("$.tool.falloff"), std::string::npos) << warning;
}

// The desktop's panel layout (ImGui's ini text) goes in "panels" and comes
// back as written; a file without it (written before layouts were kept)
// reads fine and gives none; a layout that is not a string is named.
TEST_F(SessionViewTest, ThePanelLayoutIsKeptAndOldFilesWithoutItReadFine) {
    Navigator n;
    const std::string layout = "[Window][Garden]\nPos=131,47\nSize=300,400\nCollapsed=1\n\n";
    ASSERT_EQ(writeSessionView(dir.string(), n, nullptr, &layout), "");
    std::string warning;
    std::optional<std::string> panels;
    ASSERT_TRUE(readSessionView(dir.string(), n, warning, nullptr, &panels)) << warning;
    ASSERT_TRUE(panels);
    EXPECT_EQ(*panels, layout);

    std::ofstream(dir / kSessionViewFile) << R"({"mode": "walk", "eye": [0, 1.7, 5], "yaw": 0, "pitch": 0})";
    ASSERT_TRUE(readSessionView(dir.string(), n, warning, nullptr, &panels)) << warning;
    EXPECT_FALSE(panels);

    std::ofstream(dir / kSessionViewFile) << R"({"mode": "walk", "eye": [0, 1.7, 5], "yaw": 0, "pitch": 0, "panels": 3})";
    EXPECT_FALSE(readSessionView(dir.string(), n, warning, nullptr, &panels));
    EXPECT_NE(warning.find("$.panels"), std::string::npos) << warning;
}

}  // namespace
}  // namespace hg::garden
