// Hands and moving about: the desktop mapping (keys to the navigation
// stick, the mouse ray to the tool's aim, look only while the right button
// is held, the wheel's speed), walking at eye height, flying, orbiting a
// target at a kept distance, toggles on the press only.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "garden/app/navigator.h"
#include "garden/hands/desktop_hands.h"

namespace hg::garden {
namespace {

constexpr float kPi = 3.14159265f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(DesktopHands, TheMouseRayGoesThroughThePixel) {
    const glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(1, 2, 0), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(1.0f, 16.0f / 9.0f, 0.05f, 100.0f);
    Pose centre = rayThroughPixel({640, 360}, {1280, 720}, view, proj);
    expectNear(centre.position, {1, 2, 3});
    expectNear(centre.forward(), {0, 0, -1});
    // The top edge's middle is half the vertical field of view up.
    Pose top = rayThroughPixel({640, 0}, {1280, 720}, view, proj);
    EXPECT_NEAR(std::asin(top.forward().y), 0.5f, 1e-4f);
    expectNear(top.up(), glm::normalize(glm::cross(top.right(), top.forward())));
}

TEST(DesktopHands, KeysMouseAndWheelMapOntoTheHands) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 1.7f, 0), glm::vec3(0, 1.7f, -1), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(1.0f, 1.0f, 0.05f, 100.0f);
    DesktopInput in;
    in.viewport = {800, 800};
    in.mouse = {400, 400};
    in.forward = in.left = true;
    in.toolButton = true;
    in.mouseDelta = {100, 50};
    in.wheel = 2;
    Hands h = mapDesktop(in, view, proj, DesktopMapping{}, 1.0f);
    EXPECT_EQ(h.navigation.thumbstick, glm::vec2(-1, 1));
    EXPECT_EQ(h.tool.trigger, 1.0f);
    expectNear(h.tool.aim.forward(), {0, 0, -1});
    EXPECT_EQ(h.look, glm::vec2(0.0f)) << "no look without the right button";
    EXPECT_NEAR(h.speedScale, 1.5625f, 1e-6f);
    in.lookButton = true;
    h = mapDesktop(in, view, proj, DesktopMapping{}, h.speedScale);
    EXPECT_NEAR(h.look.x, 0.4f, 1e-6f);
    EXPECT_NEAR(h.look.y, -0.2f, 1e-6f);
    EXPECT_NEAR(h.speedScale, 1.5625f * 1.5625f, 1e-5f);
}

TEST(Navigator, WalksAtEyeHeightInTheDirectionItFaces) {
    Navigator nav;
    nav.setPose({0, 5, 0}, 0.0f, 0.3f);
    EXPECT_EQ(nav.eye().y, 1.7f) << "walking keeps eye height";
    Hands h;
    h.navigation.thumbstick = {0, 1};
    nav.update(h, 1.0);
    expectNear(nav.eye(), {0, 1.7f, -1.4f});
    Hands turn;
    turn.look = {kPi / 2, 0};
    nav.update(turn, 0.0);
    nav.update(h, 1.0);
    expectNear(nav.eye(), {1.4f, 1.7f, -1.4f});
    h.speedScale = 2;
    nav.update(h, 0.5);
    expectNear(nav.eye(), {2.8f, 1.7f, -1.4f});
}

TEST(Navigator, FlyToggleActsOnThePressAndFliesAlongTheView) {
    Navigator nav;
    nav.setPose({0, 1.7f, 0}, 0.0f, 0.0f);
    Hands click;
    click.navigation.buttons = kButtonThumbstick;
    nav.update(click, 0.0);
    EXPECT_EQ(nav.mode(), NavigationMode::Fly);
    nav.update(click, 0.0);  // still held: no second toggle
    EXPECT_EQ(nav.mode(), NavigationMode::Fly);
    Hands look;
    look.look = {0, kPi / 4};
    nav.update(look, 0.0);
    Hands go;
    go.navigation.thumbstick = {0, 1};
    nav.update(go, 1.0);
    expectNear(nav.eye(), {0, 1.7f + 3.0f * std::sqrt(0.5f), -3.0f * std::sqrt(0.5f)});
    Hands up;
    up.tool.thumbstick = {0, 1};
    nav.update(up, 1.0);
    EXPECT_NEAR(nav.eye().y, 1.7f + 3.0f * std::sqrt(0.5f) + 3.0f, 1e-4f);
    nav.update(Hands{}, 0.0);
    nav.update(click, 0.0);
    EXPECT_EQ(nav.mode(), NavigationMode::Walk);
    EXPECT_EQ(nav.eye().y, 1.7f);
}

TEST(Navigator, OrbitCirclesTheTargetAtItsDistance) {
    Navigator nav;
    nav.setPose({0, 1.7f, 4}, 0.0f, 0.0f);
    Hands orbit;
    orbit.navigation.buttons = kButtonPrimary;
    nav.update(orbit, 0.0);
    EXPECT_EQ(nav.mode(), NavigationMode::Walk) << "no target: orbit refused";
    nav.update(Hands{}, 0.0);
    const glm::vec3 target(0, 1.7f, 0);
    nav.setOrbitTarget(target);
    nav.update(orbit, 0.0);
    ASSERT_EQ(nav.mode(), NavigationMode::Orbit);
    Hands turn;
    turn.look = {kPi / 2, 0};
    nav.update(turn, 0.0);
    EXPECT_NEAR(glm::length(nav.eye() - target), 4.0f, 1e-4f);
    expectNear(nav.eye(), {-4, 1.7f, 0});
    expectNear(nav.forward(), {1, 0, 0});
    Hands closer;
    closer.navigation.thumbstick = {0, 1};
    nav.update(closer, 0.5);
    EXPECT_NEAR(glm::length(nav.eye() - target), 2.0f, 1e-4f);
}

}  // namespace
}  // namespace hg::garden
