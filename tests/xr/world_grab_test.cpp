// Two-handed manipulation of the world (xr/world_grab.h): the grabbed point
// stays under the hand, both hands scale about their midpoint and turn the
// world about the vertical, the scale is clamped and never zero or negative.
#include <gtest/gtest.h>

#include <cmath>

#include "xr/world_grab.h"

namespace hg::xr {
namespace {

constexpr float kEps = 1e-4f;

void expectNear(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, kEps);
    EXPECT_NEAR(a.y, b.y, kEps);
    EXPECT_NEAR(a.z, b.z, kEps);
}

StageRig someRig() {
    StageRig r;
    r.origin = glm::vec3(3.0f, 0.5f, -2.0f);
    r.yaw = 0.7f;
    r.scale = 1.5f;
    return r;
}

TEST(StageRig, YawTurnsLikeTheNavigator) {
    StageRig r;
    r.yaw = 0.5f;  // the navigator looks along (sin yaw, 0, -cos yaw)
    expectNear(r.toWorld(glm::vec3(0, 0, -1)), glm::vec3(std::sin(0.5f), 0.0f, -std::cos(0.5f)));
}

TEST(StageRig, ViewOfAnEyeLooksFromItsWorldPosition) {
    const StageRig r = someRig();
    garden::Pose eye;
    eye.position = glm::vec3(0.2f, 1.6f, 0.1f);
    const glm::mat4 v = r.viewOf(eye);
    const glm::vec4 atEye = v * glm::vec4(r.toWorld(eye.position), 1.0f);
    expectNear(glm::vec3(atEye), glm::vec3(0.0f));
    // A point ahead of the eye in the stage is ahead (-z) in view space.
    const glm::vec4 ahead = v * glm::vec4(r.toWorld(eye.position + glm::vec3(0, 0, -1)), 1.0f);
    EXPECT_NEAR(ahead.z, -r.scale, kEps);
}

TEST(StageRig, RecenteringPutsTheHeadAtTheStartLookingItsWay) {
    const StageRig r = someRig();
    garden::Pose head;
    head.position = glm::vec3(0.7f, 1.6f, -0.4f);
    head.orientation = glm::angleAxis(0.9f, glm::vec3(0, 1, 0));  // turned left in the stage
    const glm::vec3 start(2.0f, 1.7f, 5.0f);
    const StageRig c = r.recentered(head, start, 1.7f, 0.3f);
    const glm::vec3 at = c.toWorld(head.position);
    EXPECT_NEAR(at.x, start.x, kEps);
    EXPECT_NEAR(at.z, start.z, kEps);
    EXPECT_NEAR(at.y, start.y - 1.7f + c.scale * head.position.y, kEps) << "heights stay the tracked ones";
    const glm::vec3 f = c.toWorld(head).forward();
    EXPECT_NEAR(std::atan2(f.x, -f.z), 0.3f, kEps) << "looking along the start's heading";
    EXPECT_EQ(c.scale, r.scale);
}

TEST(WorldGrab, NoSqueezeLeavesTheRig) {
    WorldGrab g;
    const StageRig r = someRig();
    const StageRig out = g.update(r, std::nullopt, glm::vec3(1, 1, 1));  // the tool hand alone does not grab
    expectNear(out.origin, r.origin);
    EXPECT_EQ(out.scale, r.scale);
    EXPECT_FALSE(g.grabbing());
}

TEST(WorldGrab, OneHandKeepsTheGrabbedPointUnderIt) {
    WorldGrab g;
    const StageRig r = someRig();
    const glm::vec3 a0(0.2f, 1.0f, -0.3f);
    const glm::vec3 grabbed = r.toWorld(a0);
    StageRig now = g.update(r, a0, std::nullopt);
    EXPECT_TRUE(g.grabbing());
    const glm::vec3 a1(-0.4f, 1.3f, 0.2f);
    now = g.update(now, a1, std::nullopt);
    expectNear(now.toWorld(a1), grabbed);
    EXPECT_EQ(now.scale, r.scale);
    EXPECT_EQ(now.yaw, r.yaw);
}

TEST(WorldGrab, TwoHandsScaleAboutTheirMidpoint) {
    WorldGrab g;
    const StageRig r = someRig();
    const glm::vec3 a0(-0.2f, 1.0f, -0.3f), b0(0.2f, 1.0f, -0.3f);
    const glm::vec3 middle = r.toWorld(0.5f * (a0 + b0));
    StageRig now = g.update(r, a0, b0);
    EXPECT_TRUE(g.scaling());
    // Hands twice as far apart: the world seems twice as big, so the rig's
    // scale (world metres per stage metre) halves.
    const glm::vec3 a1(-0.4f, 1.1f, -0.2f), b1(0.4f, 1.1f, -0.2f);
    now = g.update(now, a1, b1);
    EXPECT_NEAR(now.scale, r.scale * 0.5f, kEps);
    expectNear(now.toWorld(0.5f * (a1 + b1)), middle);
    EXPECT_NEAR(now.yaw, r.yaw, kEps);
}

TEST(WorldGrab, TwoHandsTurnTheWorldAboutTheVerticalOnly) {
    WorldGrab g;
    const StageRig r = someRig();
    const glm::vec3 a0(-0.3f, 1.0f, 0.0f), b0(0.3f, 1.0f, 0.0f);
    const glm::vec3 middle = r.toWorld(0.5f * (a0 + b0));
    StageRig now = g.update(r, a0, b0);
    // The hands turn a quarter about the vertical, one also lifts: the
    // world turns with them about the vertical through the midpoint.
    const glm::vec3 a1(0.0f, 0.9f, 0.3f), b1(0.0f, 1.1f, -0.3f);
    now = g.update(now, a1, b1);
    expectNear(now.toWorld(0.5f * (a1 + b1)), middle);
    // The world direction of the hands' span (horizontal part) is kept.
    const glm::vec3 before = r.toWorld(b0) - r.toWorld(a0), after = now.toWorld(b1) - now.toWorld(a1);
    EXPECT_NEAR(std::atan2(before.x, -before.z), std::atan2(after.x, -after.z), kEps);
    // Up stays up: the rig only ever turns about y.
    expectNear(now.rotation() * glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
}

TEST(WorldGrab, ScaleIsClampedAndNeverZeroOrNegative) {
    WorldGrab g;
    StageRig r = someRig();
    StageRig now = g.update(r, glm::vec3(-0.5f, 1, 0), glm::vec3(0.5f, 1, 0));
    now = g.update(now, glm::vec3(-50, 1, 0), glm::vec3(50, 1, 0));  // hands 100x apart
    EXPECT_EQ(now.scale, kMinRigScale);
    WorldGrab g2;
    now = g2.update(r, glm::vec3(-0.5f, 1, 0), glm::vec3(0.5f, 1, 0));
    now = g2.update(now, glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));  // hands together
    EXPECT_GT(now.scale, 0.0f);
    EXPECT_LE(now.scale, kMaxRigScale);
    now = g2.update(now, glm::vec3(0.001f, 1, 0), glm::vec3(-0.001f, 1, 0));  // crossed, nearly together
    EXPECT_EQ(now.scale, kMaxRigScale);
    EXPECT_GT(now.scale, 0.0f);
}

TEST(WorldGrab, LettingGoOfOneHandStartsAOneHandGrabWhereTheHandsAre) {
    WorldGrab g;
    const StageRig r = someRig();
    StageRig now = g.update(r, glm::vec3(-0.2f, 1, 0), glm::vec3(0.2f, 1, 0));
    now = g.update(now, glm::vec3(-0.4f, 1, 0), glm::vec3(0.4f, 1, 0));
    const float scaled = now.scale;
    const glm::vec3 a(-0.4f, 1, 0), grabbed = now.toWorld(a);
    now = g.update(now, a, std::nullopt);  // the tool hand lets go
    now = g.update(now, glm::vec3(-0.1f, 1.2f, 0.1f), std::nullopt);
    EXPECT_EQ(now.scale, scaled);
    expectNear(now.toWorld(glm::vec3(-0.1f, 1.2f, 0.1f)), grabbed);
}

}  // namespace
}  // namespace hg::xr
