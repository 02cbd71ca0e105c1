// The panel on the navigation hand (xr/hand_panel.h): where the tool's ray
// meets the board (image order: top left (0, 0)), the trigger the panel's
// only for a pull that starts on the board, nothing from behind or while
// the navigation hand is untracked.
#include <gtest/gtest.h>

#include "xr/hand_panel.h"
#include "xr/hand_panel_ui.h"

namespace hg::xr {
namespace {

garden::HandState handAt(const glm::vec3& p) {
    garden::HandState h;
    h.tracked = true;
    h.grip.position = p;
    h.aim.position = p;
    return h;
}

// A ray along -z from in front of board point `uv` (the hand at `hand`).
garden::HandState rayAt(const HandPanel& p, const glm::vec2& uv, float fromZ = 0.3f) {
    return handAt(p.at(uv) + glm::vec3(0.0f, 0.0f, fromZ));
}

void expectNear(const std::optional<glm::vec2>& got, const glm::vec2& want) {
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->x, want.x, 1e-4f);
    EXPECT_NEAR(got->y, want.y, 1e-4f);
}

TEST(HandPanel, FindsTheBoardPointUnderTheRay) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 1.0f);
    ASSERT_TRUE(p.shown());
    // The board above the hand: its top left corner up and to the left.
    const glm::vec3 topLeft = p.at({0.0f, 0.0f});
    EXPECT_NEAR(topLeft.x, -0.5f * HandPanel::kWidth, 1e-6f);
    EXPECT_NEAR(topLeft.y, HandPanel::kAboveHand + 0.5f * HandPanel::kHeight, 1e-6f);
    expectNear(p.pointedAt(rayAt(p, {0.1f, 0.75f}).aim), {0.1f, 0.75f});
    expectNear(p.pointedAt(rayAt(p, panelButtonCenter(PanelButton::Carve)).aim), panelButtonCenter(PanelButton::Carve));
    EXPECT_EQ(p.pointedAt(rayAt(p, {1.2f, 0.5f}).aim), std::nullopt) << "beside the board";
    EXPECT_EQ(p.pointedAt(rayAt(p, {0.5f, 0.5f}, -0.3f).aim), std::nullopt) << "from behind";
}

TEST(HandPanel, ScalesWithTheWorld) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 2.0f);
    garden::HandState t = handAt(glm::vec3(-0.8f * HandPanel::kWidth, 2.0f * HandPanel::kAboveHand + 0.5f * HandPanel::kHeight, 0.5f));
    expectNear(p.pointedAt(t.aim), {0.1f, 0.25f});
}

TEST(HandPanel, TheTriggerIsThePanelsOnlyForAPullStartedOnIt) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 1.0f);
    garden::HandState t = rayAt(p, {0.5f, 0.5f});
    p.update(t);
    EXPECT_TRUE(p.ownsTrigger());
    EXPECT_FALSE(p.pressing());
    t.trigger = 1.0f;
    p.update(t);
    EXPECT_TRUE(p.pressing());
    // Dragged off the board while held: still the panel's (a slider).
    t.aim.position.x += 1.0f;
    p.update(t);
    EXPECT_TRUE(p.pressing());
    EXPECT_TRUE(p.ownsTrigger());
    t.trigger = 0.0f;
    p.update(t);
    EXPECT_FALSE(p.ownsTrigger());
    // A pull that starts off the board (a stroke) and sweeps onto it does not press.
    t.trigger = 1.0f;
    p.update(t);
    t = rayAt(p, {0.5f, 0.5f});
    t.trigger = 1.0f;
    p.update(t);
    EXPECT_FALSE(p.pressing());
    p.place(garden::HandState{}, 1.0f);  // the navigation hand is lost
    p.update(t);
    EXPECT_FALSE(p.ownsTrigger());
}

}  // namespace
}  // namespace hg::xr
