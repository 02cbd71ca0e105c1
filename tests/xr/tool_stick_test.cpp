// The tool thumbstick (xr/tool_stick.h): up grows the tool, right makes it
// stronger, the dead zone does nothing, and sizes stay in range.
#include <gtest/gtest.h>

#include "xr/tool_stick.h"

namespace hg::xr {
namespace {

TEST(ToolStick, FullTiltUpDoublesTheSizeInASecond) {
    garden::ToolSettings t;
    t.radius = 0.05;
    t.radii = {0.08, 0.04, 0.08};
    for (int i = 0; i < 90; ++i) adjustTool(t, glm::vec2(0.0f, 1.0f), 1.0 / 90.0);
    EXPECT_NEAR(t.radius, 0.10, 1e-9);
    EXPECT_NEAR(t.radii[1], 0.08, 1e-9);
    EXPECT_EQ(t.strength, garden::ToolSettings{}.strength) << "y leaves the strength";
}

TEST(ToolStick, LeftWeakensAPushWithoutTurningItIntoAPull) {
    garden::ToolSettings t;
    t.strength = -4.0;
    for (int i = 0; i < 90; ++i) adjustTool(t, glm::vec2(-1.0f, 0.0f), 1.0 / 90.0);
    EXPECT_NEAR(t.strength, -2.0, 1e-9);
    EXPECT_EQ(t.radius, garden::ToolSettings{}.radius) << "x leaves the size";
}

TEST(ToolStick, DeadZoneAndRangesHold) {
    garden::ToolSettings t;
    const garden::ToolSettings before = t;
    adjustTool(t, glm::vec2(0.1f, -0.14f), 1.0);
    EXPECT_EQ(t.radius, before.radius);
    EXPECT_EQ(t.strength, before.strength);
    adjustTool(t, glm::vec2(1.0f, 1.0f), 100.0);
    EXPECT_EQ(t.radius, kMaxToolSize);
    EXPECT_EQ(t.strength, kMaxToolStrength);
    adjustTool(t, glm::vec2(-1.0f, -1.0f), 100.0);
    EXPECT_EQ(t.radius, kMinToolSize);
    EXPECT_EQ(t.strength, kMinToolStrength);
}

}  // namespace
}  // namespace hg::xr
