// The move tool and live moves (garden/app/session_moving.cpp): a drag shows
// at once and becomes one undoable, journalled move when it ends; the tool
// hand selects a sculpture, drags it on a horizontal plane, turns it with
// the secondary button or by its ring, and a click on nothing deselects.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include <glm/gtc/quaternion.hpp>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionMovingTest : public test::SmallGardenSession {
protected:
    void SetUp() override {
        test::SmallGardenSession::SetUp();
        session->setJournal(&sink);
    }
    const Placement& placementOf(int i) const { return session->sculptures()[static_cast<std::size_t>(i)].placement; }
    int moves() const {
        int n = 0;
        for (const Action& r : journal) n += std::holds_alternative<MoveAction>(r);
        return n;
    }
    void frame(const Hands& h) {
        session->frame(FrameInput(h, 1.0 / 90.0));
    }
    // The tool hand at `from`, pointing along `dir`, trigger as given.
    static Hands hand(const glm::vec3& from, const glm::vec3& dir, bool trigger, bool secondary = false) {
        Hands h;
        h.tool.tracked = true;
        h.tool.aim.position = from;
        const glm::vec3 up = std::fabs(dir.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        h.tool.aim.orientation = glm::quatLookAt(glm::normalize(dir), up);
        h.tool.trigger = trigger ? 1.0f : 0.0f;
        if (secondary) h.tool.buttons |= kButtonSecondary;
        return h;
    }
    test::ActionList sink;
    std::vector<Action>& journal = sink.actions;
};

TEST_F(SessionMovingTest, ALiveMoveIsOneUndoableJournalledMove) {
    const Placement start = placementOf(c);
    Placement p = start;
    for (int k = 1; k <= 5; ++k) {
        p.position[0] = start.position[0] + 0.1 * k;
        p.yawDegrees = 3.0 * k;
        ASSERT_EQ(session->moveSculptureLive(c, p), "");
        EXPECT_TRUE(session->movingLive());
        EXPECT_EQ(placementOf(c).position[0], p.position[0]) << "shown at once";
    }
    EXPECT_EQ(moves(), 0) << "nothing journalled during the drag";
    session->endLiveMove();
    EXPECT_FALSE(session->movingLive());
    ASSERT_EQ(moves(), 1);
    const MoveAction& m = std::get<MoveAction>(journal.back());
    EXPECT_EQ(m.sculpture, "c");
    EXPECT_EQ(m.placement.position[0], p.position[0]);
    EXPECT_EQ(m.placement.yawDegrees, 15.0);
    // One undo takes the whole drag back; redo brings its end.
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(placementOf(c).position, start.position);
    EXPECT_EQ(placementOf(c).yawDegrees, start.yawDegrees);
    EXPECT_FALSE(session->undo()) << "the drag was one action";
    ASSERT_TRUE(session->redo());
    EXPECT_EQ(placementOf(c).position[0], p.position[0]);
    EXPECT_EQ(placementOf(c).yawDegrees, 15.0);
}

TEST_F(SessionMovingTest, ADragBackToItsStartAddsNothingAndBadPlacementsAreRefused) {
    const Placement start = placementOf(c);
    Placement p = start;
    p.position[2] += 1.0;
    ASSERT_EQ(session->moveSculptureLive(c, p), "");
    ASSERT_EQ(session->moveSculptureLive(c, start), "");
    session->endLiveMove();
    EXPECT_EQ(moves(), 0);
    EXPECT_FALSE(session->undo());
    Placement bad = start;
    bad.position[1] = std::nan("");
    EXPECT_NE(session->moveSculptureLive(c, bad), "");
    bad = start;
    bad.scale = 0.0;
    EXPECT_NE(session->moveSculptureLive(c, bad), "");
    EXPECT_NE(session->moveSculptureLive(99, start), "");
    EXPECT_FALSE(session->movingLive());
    EXPECT_EQ(placementOf(c).position, start.position);
}

TEST_F(SessionMovingTest, UndoDuringALiveMoveEndsItFirst) {
    const Placement start = placementOf(c);
    Placement p = start;
    p.position[0] += 0.5;
    ASSERT_EQ(session->moveSculptureLive(c, p), "");
    ASSERT_TRUE(session->undo()) << "the drag ended, then was undone";
    EXPECT_FALSE(session->movingLive());
    EXPECT_EQ(placementOf(c).position, start.position);
    EXPECT_EQ(moves(), 1);
}

TEST_F(SessionMovingTest, TheMoveToolSelectsAndDragsKeepingTheHeight) {
    session->tool().kind = ToolSettings::Kind::Move;
    const Placement start = placementOf(c);
    // From 3 m in front of the ball at its centre's height, looking along -z.
    const glm::vec3 dir(0, 0, -1);
    frame(hand({2.0f, 0.5f, 4.0f}, dir, true));
    EXPECT_EQ(session->selected(), c);
    // The hand moves 0.4 m right and 0.1 m down: the ray meets the plane
    // y = 0.5 again 0.4 m to the right; height is kept.
    frame(hand({2.2f, 0.5f, 4.0f}, dir, true));
    frame(hand({2.4f, 0.5f, 4.0f}, dir, true));
    EXPECT_NEAR(placementOf(c).position[0], start.position[0] + 0.4, 1e-5);
    EXPECT_EQ(placementOf(c).position[1], start.position[1]);
    EXPECT_NEAR(placementOf(c).position[2], start.position[2], 1e-5);
    EXPECT_EQ(moves(), 0);
    frame(hand({2.4f, 0.5f, 4.0f}, dir, false));
    EXPECT_EQ(moves(), 1);
    EXPECT_EQ(session->editCount(c), 0u) << "a move is no edit of the grid";
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(placementOf(c).position, start.position);
    EXPECT_FALSE(session->undo());
}

TEST_F(SessionMovingTest, TheSecondaryButtonOrTheRingTurnsAboutThePivot) {
    session->tool().kind = ToolSettings::Kind::Move;
    const Placement start = placementOf(c);
    const glm::vec3 pivot(2.0f, 0.0f, 1.1547f);
    // Held with the secondary button: the ray meets the ball at (2, 0.5,
    // 1.7547), 0.6 m in front of the pivot; 0.3 m to the right is
    // atan(0.3 / 0.6) counter-clockwise seen from above.
    frame(hand({2.0f, 0.5f, 4.0f}, {0, 0, -1}, true, true));
    frame(hand({2.3f, 0.5f, 4.0f}, {0, 0, -1}, true, true));
    const double expected = std::atan2(0.3, 0.6) * 180.0 / 3.14159265358979323846;
    EXPECT_NEAR(placementOf(c).yawDegrees, start.yawDegrees + expected, 0.05);
    EXPECT_EQ(placementOf(c).position, start.position) << "turned, not moved";
    frame(hand({2.3f, 0.5f, 4.0f}, {0, 0, -1}, false));
    EXPECT_EQ(moves(), 1);

    // Pointing straight down on the ring, beside the ball: a turn too.
    const MoveRing ring = moveRing(session->sculptures()[static_cast<std::size_t>(c)]);
    EXPECT_NEAR(ring.radius, 1.1 * std::hypot(0.6, 0.6), 1e-4);
    const double yaw = placementOf(c).yawDegrees;
    const glm::vec3 down(0, -1, 0);
    frame(hand(pivot + glm::vec3(ring.radius, 3.0f, 0.0f), down, true));
    frame(hand(pivot + glm::vec3(0.0f, 3.0f, -ring.radius), down, true));
    EXPECT_NEAR(placementOf(c).yawDegrees, yaw + 90.0, 0.05) << "a quarter turn counter-clockwise";
    frame(hand(pivot + glm::vec3(0.0f, 3.0f, -ring.radius), down, false));
    EXPECT_EQ(moves(), 2);
    EXPECT_EQ(session->selected(), c);
    // A click on bare ground, off the ring, selects nothing.
    frame(hand(pivot + glm::vec3(2.5f * ring.radius, 3.0f, 0.0f), down, true));
    frame(hand(pivot + glm::vec3(2.5f * ring.radius, 3.0f, 0.0f), down, false));
    EXPECT_EQ(session->selected(), -1);
    EXPECT_EQ(moves(), 2);
    ASSERT_TRUE(session->undo());
    ASSERT_TRUE(session->undo());
    EXPECT_NEAR(placementOf(c).yawDegrees, start.yawDegrees, 1e-9);
}

TEST_F(SessionMovingTest, CentralMirrorGoesThroughTheModelBoxCentre) {
    const MirrorPlane m = centralMirror(session->sculptures()[static_cast<std::size_t>(c)]);
    // The small garden's box: [-0.6, 0.6] x [-0.1, 1.1] x [-0.6, 0.6].
    EXPECT_NEAR(m.point[0], 0.0, 1e-12);
    EXPECT_NEAR(m.point[1], 0.5, 1e-12);
    EXPECT_NEAR(m.point[2], 0.0, 1e-12);
    EXPECT_EQ(m.normal[0], 1.0);
    EXPECT_EQ(m.normal[1], 0.0);
}

}  // namespace
}  // namespace hg::garden
