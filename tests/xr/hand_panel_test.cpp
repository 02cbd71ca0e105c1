// The panel on the navigation hand (xr/hand_panel.h): which button the
// tool's ray points at, a press on the trigger's way down only, nothing
// from behind or while the hand is untracked.
#include <gtest/gtest.h>

#include "xr/hand_panel.h"

namespace hg::xr {
namespace {

garden::HandState handAt(const glm::vec3& p) {
    garden::HandState h;
    h.tracked = true;
    h.grip.position = p;
    h.aim.position = p;
    return h;
}

// A ray along -z through the board point (u, v) of a panel over a hand at
// the origin (the board spans x in [-0.12, 0.12], y in [0.06, 0.18]).
garden::HandState rayAt(float u, float v, float fromZ = 0.3f) {
    garden::HandState t = handAt(glm::vec3((u - 0.5f) * HandPanel::kWidth,
                                           HandPanel::kAboveHand + (v - 0.5f) * HandPanel::kHeight, fromZ));
    return t;
}

TEST(HandPanel, PointsAtTheButtonUnderTheRay) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 1.0f);
    ASSERT_TRUE(p.shown());
    EXPECT_EQ(p.pointedAt(rayAt(0.1f, 0.75f).aim), PanelButton::ToolNone);
    EXPECT_EQ(p.pointedAt(rayAt(0.375f, 0.75f).aim), PanelButton::Carve);
    EXPECT_EQ(p.pointedAt(rayAt(0.9f, 0.75f).aim), PanelButton::Melt);
    EXPECT_EQ(p.pointedAt(rayAt(0.1f, 0.25f).aim), PanelButton::Perturb);
    EXPECT_EQ(p.pointedAt(rayAt(0.9f, 0.25f).aim), PanelButton::Redo);
    EXPECT_EQ(p.pointedAt(rayAt(1.2f, 0.5f).aim), std::nullopt) << "beside the board";
    EXPECT_EQ(p.pointedAt(rayAt(0.5f, 0.5f, -0.3f).aim), std::nullopt) << "from behind";
}

TEST(HandPanel, ScalesWithTheWorld) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 2.0f);
    garden::HandState t = handAt(glm::vec3(-0.9f * HandPanel::kWidth, 2.0f * HandPanel::kAboveHand + 0.25f * HandPanel::kHeight, 0.5f));
    EXPECT_EQ(p.pointedAt(t.aim), PanelButton::ToolNone) << "twice as big, twice as high";
}

TEST(HandPanel, PressesOnTheTriggersWayDownOnly) {
    HandPanel p;
    p.place(handAt(glm::vec3(0.0f)), 1.0f);
    garden::HandState t = rayAt(0.375f, 0.75f);
    EXPECT_EQ(p.update(t), std::nullopt);
    EXPECT_TRUE(p.pointing());
    t.trigger = 1.0f;
    EXPECT_EQ(p.update(t), PanelButton::Carve);
    EXPECT_EQ(p.update(t), std::nullopt) << "held: one press";
    t.trigger = 0.0f;
    p.update(t);
    p.place(garden::HandState{}, 1.0f);  // the navigation hand is lost
    t.trigger = 1.0f;
    EXPECT_EQ(p.update(t), std::nullopt);
    EXPECT_FALSE(p.pointing());
}

}  // namespace
}  // namespace hg::xr
