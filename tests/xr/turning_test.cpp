// Turning on the navigation stick (xr/turning.h): one snap (of the angle
// given) per push, a smooth turn proportional to the tilt, switched while
// running, and the stick's x never strafes.
#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "xr/turning.h"

namespace hg::xr {
namespace {

garden::Hands stick(float x) {
    garden::Hands h;
    h.navigation.tracked = true;
    h.navigation.thumbstick = glm::vec2(x, 0.3f);
    return h;
}

TEST(Turning, SnapsOncePerPush) {
    Turning t;
    garden::Hands h = stick(0.9f);
    EXPECT_FLOAT_EQ(t.apply(h, 0.011), kSnapTurn);
    EXPECT_EQ(h.navigation.thumbstick.x, 0.0f) << "no strafing";
    EXPECT_EQ(h.navigation.thumbstick.y, 0.3f) << "walking stays";
    h = stick(0.95f);
    EXPECT_EQ(t.apply(h, 0.011), 0.0f) << "held: no second snap";
    h = stick(0.1f);
    EXPECT_EQ(t.apply(h, 0.011), 0.0f);
    h = stick(-0.8f);
    EXPECT_FLOAT_EQ(t.apply(h, 0.011), -kSnapTurn);
}

TEST(Turning, SnapsTheAngleItIsGivenAndSwitchesWhenSet) {
    const float quarter = glm::radians(90.0f);
    Turning t(false, quarter);
    garden::Hands h = stick(-0.9f);
    EXPECT_FLOAT_EQ(t.apply(h, 0.011), -quarter);
    // Switched to smooth while held: turns at once, proportionally.
    t.set(true, quarter);
    h = stick(-1.0f);
    EXPECT_NEAR(t.apply(h, 0.5), -kSmoothTurnRate * 0.5f, 1e-6f);
    // And back to snaps of 15 degrees.
    t.set(false, glm::radians(15.0f));
    h = stick(0.0f);
    t.apply(h, 0.011);
    h = stick(0.9f);
    EXPECT_FLOAT_EQ(t.apply(h, 0.011), glm::radians(15.0f));
}

TEST(Turning, SmoothTurnsWithTheTilt) {
    Turning t(true);
    garden::Hands h = stick(1.0f);
    EXPECT_NEAR(t.apply(h, 0.5), kSmoothTurnRate * 0.5f, 1e-6f);
    h = stick(-1.0f);
    EXPECT_NEAR(t.apply(h, 0.5), -kSmoothTurnRate * 0.5f, 1e-6f);
    h = stick(0.1f);
    EXPECT_EQ(t.apply(h, 0.5), 0.0f) << "dead zone";
    EXPECT_EQ(h.navigation.thumbstick.x, 0.0f);
}

}  // namespace
}  // namespace hg::xr
