// Predictable tools (issue 23): a stroke edits the sculpture its press met
// and only that one, which becomes the selection; a press that meets none
// does nothing (the tool panel says why) even when the held ray then
// sweeps onto a sculpture; each tool keeps its own reverse and radius; the
// tools start sized to the sculpture in view.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "garden/app/garden_session.h"
#include "garden/app/tool_defaults.h"
#include "garden/app/tool_intents.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;

class ToolTargeting : public test::SmallGardenSession {
protected:
    // One frame with the tool hand at (x, 0.5, 4) pointing along -z.
    void frame(float x, bool trigger, const ToolIntents& intents = {}) {
        Hands h;
        h.tool.tracked = true;
        h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
        h.tool.aim.position = glm::vec3(x, 0.5f, 4.0f);
        h.tool.trigger = trigger ? 1.0f : 0.0f;
        h.intents = intents;
        session->frame(FrameInput(h, 1.0 / 90.0));
    }
    voxel::Volume grid(int i) { return session->sculptures()[static_cast<std::size_t>(i)].volume->clone(); }
};

TEST_F(ToolTargeting, APressInTheAirDoesNothingEvenWhenTheRaySweepsOntoASculpture) {
    session->tool().kind = Kind::Carve;
    session->tool().radius = 0.1;
    const voxel::Volume before = grid(c);
    // x = 1 passes between ball c (x 1.4 to 2.6) and ball a (x -0.5 to 0.5).
    ASSERT_FALSE(session->toolHit(Pose{{1.0f, 0.5f, 4.0f}, glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0))}));
    frame(1.0f, true);
    EXPECT_NE(session->toolMessage().find("met no sculpture"), std::string::npos) << session->toolMessage();
    for (float x = 1.0f; x <= 2.0f; x += 0.1f) frame(x, true);  // held, onto ball c
    frame(2.0f, false);
    EXPECT_EQ(session->editCount(c), 0u);
    EXPECT_EQ(test::differingVoxels(grid(c), before), 0) << "the ray met c after the press: nothing is carved";
    EXPECT_EQ(session->selected(), -1);
    // A press on c carves c and selects it; the message goes.
    frame(2.0f, true);
    frame(2.1f, true);
    frame(2.1f, false);
    EXPECT_EQ(session->editCount(c), 1u);
    EXPECT_EQ(session->selected(), c);
    EXPECT_TRUE(session->toolMessage().empty());
}

TEST_F(ToolTargeting, AStrokeEditsOnlyTheSculptureItsPressMet) {
    session->tool().kind = Kind::Carve;
    session->tool().radius = 0.1;
    const int a = session->findSculpture("a");
    const voxel::Volume aBefore = grid(a);
    frame(2.0f, true);  // on c
    // Dragged across to x = 0, where the ray meets ball a 4 m behind.
    for (float x = 2.0f; x >= 0.0f; x -= 0.1f) frame(x, true);
    ASSERT_TRUE(session->toolHit(Pose{{0.0f, 0.5f, 4.0f}, glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0))}));
    frame(0.0f, false);
    EXPECT_EQ(session->editCount(c), 1u);
    EXPECT_EQ(session->editCount(a), 0u);
    EXPECT_EQ(test::differingVoxels(grid(a), aBefore), 0) << "ball a, under the ray at the end, is untouched";
    EXPECT_EQ(session->selected(), c);
}

TEST_F(ToolTargeting, EachToolKeepsItsOwnReverseAndRadius) {
    ToolIntents pick;
    ToolIntents reverse;
    reverse.reverse = true;
    ToolIntents larger;
    larger.size = 2.0;
    pick.tool = ToolChoice::Carve;
    frame(0.0f, false, pick);
    const double r = session->tool().radius;
    frame(0.0f, false, reverse);  // carve reversed: adds
    frame(0.0f, false, larger);
    EXPECT_TRUE(session->tool().reverse);
    EXPECT_DOUBLE_EQ(session->tool().radius, 2.0 * r);
    pick.tool = ToolChoice::Perturb;
    frame(0.0f, false, pick);
    EXPECT_FALSE(session->tool().reverse) << "perturb has its own reverse: it pulls";
    frame(0.0f, false, reverse);  // perturb pushes
    EXPECT_LT(session->tool().perturbStrength(), 0.0);
    pick.tool = ToolChoice::Melt;
    frame(0.0f, false, pick);
    EXPECT_FALSE(session->tool().reverse);
    EXPECT_DOUBLE_EQ(session->tool().radius, 2.0 * r) << "melt never held: it takes the radius in hand";
    frame(0.0f, false, larger);
    pick.tool = ToolChoice::Carve;
    frame(0.0f, false, pick);
    EXPECT_TRUE(session->tool().reverse) << "carve is still reversed";
    EXPECT_DOUBLE_EQ(session->tool().radius, 2.0 * r) << "carve's own radius, not melt's";
    pick.tool = ToolChoice::Perturb;
    frame(0.0f, false, pick);
    EXPECT_TRUE(session->tool().reverse) << "and perturb still pushes";
    pick.tool = ToolChoice::Melt;
    frame(0.0f, false, pick);
    EXPECT_DOUBLE_EQ(session->tool().radius, 4.0 * r);
}

TEST_F(ToolTargeting, ToolsStartSizedToTheSculptureInView) {
    // Looking straight at ball c from 3 m.
    session->navigator().setMode(NavigationMode::Fly);
    session->navigator().setPose({2.0f, 0.5f, 4.1547f}, 0.0f, 0.0f);
    EXPECT_EQ(sculptureInView(*session), c);
    sizeToolsToView(*session);
    // c's box is 1.2 m across each way: a diagonal of 1.2 sqrt(3) m.
    const double diagonal = 1.2 * std::sqrt(3.0);
    EXPECT_NEAR(session->tool().radius, kStartRadiusShare * diagonal, 1e-6);
    EXPECT_NEAR(session->tool().impactSize, kStartImpactShare * diagonal, 1e-6);
    EXPECT_NEAR(session->tool().perturbRadii()[0], kStartPerturbShare * diagonal, 1e-6);
    // Scaled up four times, the sculpture gets a tool four times larger.
    Placement p = session->sculptures()[static_cast<std::size_t>(c)].placement;
    p.scale = 4.0;
    ASSERT_EQ(session->moveSculpture(c, p), "");
    session->navigator().setPose({2.0f, 2.0f, 8.0f}, 0.0f, 0.0f);  // its centre, 2 m up now, straight ahead
    ASSERT_EQ(sculptureInView(*session), c);
    sizeToolsToView(*session);
    EXPECT_NEAR(session->tool().radius, 4.0 * kStartRadiusShare * diagonal, 1e-6);
    // Looking at the sky over the garden's edge, away from every sculpture: unchanged.
    session->navigator().setPose({0.0f, 0.5f, 20.0f}, 3.14159265f, 0.0f);
    EXPECT_EQ(sculptureInView(*session), -1);
}

}  // namespace
}  // namespace hg::garden
