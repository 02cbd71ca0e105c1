// Walking follows the head (xr/walking.h): the stick's forward turned to
// where the head looks, on the ground, whatever its pitch.
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "xr/walking.h"

namespace hg::xr {
namespace {

constexpr float kPi = 3.14159265f;

garden::Pose head(float yawRight, float pitchUp) {
    garden::Pose p;
    p.orientation = glm::angleAxis(-yawRight, glm::vec3(0, 1, 0)) * glm::angleAxis(pitchUp, glm::vec3(1, 0, 0));
    return p;
}

void expectNear(const glm::vec2& a, const glm::vec2& b, const char* what = "") {
    EXPECT_NEAR(a.x, b.x, 1e-5f) << what;
    EXPECT_NEAR(a.y, b.y, 1e-5f) << what;
}

TEST(Walking, TheStickFollowsTheHeadsHeading) {
    expectNear(headRelativeStick({0, 1}, head(0, 0)), {0, 1});
    expectNear(headRelativeStick({0, 1}, head(0.5f * kPi, 0)), {1, 0}, "head turned right: forward is the rig's right");
    expectNear(headRelativeStick({0, 1}, head(-0.5f * kPi, 0)), {-1, 0});
    expectNear(headRelativeStick({1, 0}, head(0.5f * kPi, 0)), {0, -1}, "its right is the rig's back");
    expectNear(headRelativeStick({0, 1}, head(kPi, 0)), {0, -1});
}

TEST(Walking, PitchDoesNotChangeTheHeadingNorTheSpeed) {
    for (const float pitch : {-1.2f, -0.5f * kPi, 0.4f, 0.5f * kPi}) {
        const glm::vec2 s = headRelativeStick({0, 1}, head(0.25f * kPi, pitch));
        EXPECT_NEAR(s.x, std::sqrt(0.5f), 1e-4f) << "pitch " << pitch;
        EXPECT_NEAR(s.y, std::sqrt(0.5f), 1e-4f) << "pitch " << pitch;
    }
}

}  // namespace
}  // namespace hg::xr
