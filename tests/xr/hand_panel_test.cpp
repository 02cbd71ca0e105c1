// The panel on the navigation hand (xr/hand_panel.h): where the tool's ray
// meets the board (image order: top left (0, 0)), the trigger the panel's
// only for a pull that starts on the board, nothing from behind or while
// the navigation hand is untracked; the hand panel's layout points on the
// board, in order.
#include <gtest/gtest.h>

#include <iterator>
#include <utility>

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

// The layout's points (what tests and hands aim at) are on the board, the
// options of a choice side by side, left to right, below the page buttons.
TEST(HandPanel, ThePagesWidgetsLieOnTheBoardInOrder) {
    const auto onBoard = [](const glm::vec2& p) { return p.x > 0.0f && p.x < 1.0f && p.y > 0.0f && p.y < 1.0f; };
    const float pagesBottom = panelPageCenter(PanelPage::Tool).y;
    for (const auto& [choice, options] : {std::pair<PanelChoice, int>{PanelChoice::PerturbShape, 2},
                                          {PanelChoice::ImpactShape, 3},
                                          {PanelChoice::ImpactSpread, 3},
                                          {PanelChoice::SnapAngle, static_cast<int>(std::size(kSnapAngles))}}) {
        for (int i = 0; i < options; ++i) {
            const glm::vec2 p = panelChoiceCenter(choice, i);
            EXPECT_TRUE(onBoard(p)) << static_cast<int>(choice) << " " << i;
            EXPECT_GT(p.y, pagesBottom);
            if (i > 0) {
                EXPECT_GT(p.x, panelChoiceCenter(choice, i - 1).x);
                EXPECT_EQ(p.y, panelChoiceCenter(choice, i - 1).y);
            }
        }
    }
    for (const PanelToggle t : {PanelToggle::LeftHanded, PanelToggle::Seated, PanelToggle::SmoothTurn, PanelToggle::Mirror})
        EXPECT_TRUE(onBoard(panelToggleCenter(t)) && panelToggleCenter(t).y > pagesBottom) << static_cast<int>(t);
    for (const PanelAction a : {PanelAction::PreviousSculpture, PanelAction::NextSculpture, PanelAction::DiscardEdits})
        EXPECT_TRUE(onBoard(panelActionCenter(a)) && panelActionCenter(a).y > pagesBottom) << static_cast<int>(a);
    EXPECT_LT(panelSeatedOffsetPoint(0.0).x, panelSeatedOffsetPoint(kMaxSeatedHeightOffset).x);
    EXPECT_TRUE(onBoard(panelSeatedOffsetPoint(0.0)) && onBoard(panelSeatedOffsetPoint(kMaxSeatedHeightOffset)));
    // The page buttons below every tool button, side by side.
    for (int b = 0; b < static_cast<int>(PanelButton::Count); ++b)
        EXPECT_LT(panelButtonCenter(static_cast<PanelButton>(b)).y, pagesBottom);
    EXPECT_LT(panelPageCenter(PanelPage::Tool).x, panelPageCenter(PanelPage::Sculpture).x);
    EXPECT_LT(panelPageCenter(PanelPage::Sculpture).x, panelPageCenter(PanelPage::Settings).x);
}

}  // namespace
}  // namespace hg::xr
