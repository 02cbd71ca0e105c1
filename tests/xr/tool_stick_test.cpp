// The tool thumbstick (xr/tool_stick.h) as tool intents: up grows the tool,
// right makes it stronger, full tilt doubles in a second, the dead zone
// does nothing; applied by the session, the stick keeps the bounds every
// device shares (a 3 m desktop radius stays 3 m at the first nudge, issue
// 21), and one push scales the selection in one undo step.
#include <gtest/gtest.h>

#include <cmath>

#include "../garden/session_garden.h"
#include "xr/tool_stick.h"

namespace hg::xr {
namespace {

TEST(ToolStick, FullTiltUpDoublesTheSizeInASecond) {
    double size = 1.0, strength = 1.0;
    for (int i = 0; i < 90; ++i) {
        const garden::ToolIntents in = stickIntents(glm::vec2(0.0f, 1.0f), 1.0 / 90.0);
        size *= in.size;
        strength *= in.strength;
        EXPECT_TRUE(in.held);
        EXPECT_FALSE(in.tool || in.reverse || in.mirror != garden::MirrorIntent::Keep || in.selectionScale != 1.0);
    }
    EXPECT_NEAR(size, 2.0, 1e-9);
    EXPECT_EQ(strength, 1.0) << "y leaves the strength";
}

TEST(ToolStick, LeftHalvesTheStrengthInASecond) {
    double size = 1.0, strength = 1.0;
    for (int i = 0; i < 90; ++i) {
        const garden::ToolIntents in = stickIntents(glm::vec2(-1.0f, 0.0f), 1.0 / 90.0);
        size *= in.size;
        strength *= in.strength;
        EXPECT_FALSE(in.held) << "x is no scale gesture";
    }
    EXPECT_NEAR(strength, 0.5, 1e-9);
    EXPECT_EQ(size, 1.0) << "x leaves the size";
}

TEST(ToolStick, TheDeadZoneAsksNothing) {
    for (glm::vec2 s : {glm::vec2(0.1f, -0.14f), glm::vec2(kStickDeadZone, -kStickDeadZone), glm::vec2(0.0f)})
        EXPECT_FALSE(stickIntents(s, 1.0).any()) << s.x << ", " << s.y;
    // Just past it: a little, growing with the tilt.
    const double a = stickIntents(glm::vec2(0.0f, 0.2f), 1.0).size, b = stickIntents(glm::vec2(0.0f, 0.6f), 1.0).size;
    EXPECT_GT(a, 1.0);
    EXPECT_GT(b, a);
    EXPECT_LT(stickIntents(glm::vec2(0.0f, -0.6f), 1.0).size, 1.0);
}

class ToolStickSession : public garden::test::SmallGardenSession {
protected:
    void frame(glm::vec2 stick) {
        garden::Hands h;
        h.tool.tracked = true;
        h.intents = stickIntents(stick, 1.0 / 90.0);
        session->frame(garden::FrameInput(h, 1.0 / 90.0));
    }
};

// Issue 21: the stick clamped sizes to 1 m, the desktop's keys to 5 m.
TEST_F(ToolStickSession, AThreeMetreDesktopRadiusStaysThreeMetresAtTheFirstNudge) {
    garden::ToolSettings& t = session->tool();
    t.kind = garden::ToolSettings::Kind::Carve;
    t.radius = 3.0;
    frame(glm::vec2(0.0f, 0.3f));
    EXPECT_GT(t.radius, 3.0);
    EXPECT_LT(t.radius, 3.01);
    for (int i = 0; i < 900; ++i) frame(glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(t.radius, garden::kMaxToolSize) << "the shared bound";
    // The stick sizes the tool in hand only, the perturbation by its scale.
    t.kind = garden::ToolSettings::Kind::Perturb;
    const auto radii = t.radii;
    for (int i = 0; i < 90; ++i) frame(glm::vec2(0.0f, 1.0f));
    EXPECT_NEAR(t.perturbScale, 2.0, 1e-9);
    EXPECT_EQ(t.radii, radii);
    EXPECT_EQ(t.radius, garden::kMaxToolSize);
}

TEST_F(ToolStickSession, OnePushScalesTheSelectionInOneUndoStep) {
    session->tool().kind = garden::ToolSettings::Kind::Move;
    session->select(c);
    const double start = session->sculptures()[static_cast<std::size_t>(c)].placement.scale;
    for (int i = 0; i < 45; ++i) frame(glm::vec2(0.0f, 1.0f));
    EXPECT_TRUE(session->movingLive());
    frame(glm::vec2(0.0f));
    EXPECT_FALSE(session->movingLive());
    EXPECT_NEAR(session->sculptures()[static_cast<std::size_t>(c)].placement.scale, start * std::sqrt(2.0), 1e-9);
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(session->sculptures()[static_cast<std::size_t>(c)].placement.scale, start);
    EXPECT_FALSE(session->undo());
}

}  // namespace
}  // namespace hg::xr
