// The mouse as events (garden/hands/pointer_events.h): a click shorter
// than a frame is still a click (a stroke on the sculpture under it), and a
// move in the frame of a right-button press, made before the press, does
// not turn the view; scripted event sequences through the desktop's hands
// into a real session.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "../garden/session_garden.h"
#include "garden/app/garden_session.h"
#include "garden/window/desktop_keys.h"
#include "garden/hands/pointer_events.h"

namespace hg::garden {
namespace {

using Kind = PointerEvent::Kind;

PointerEvent move(glm::vec2 p) { return {Kind::Move, PointerButton::Tool, p}; }
PointerEvent press(PointerButton b, glm::vec2 p) { return {Kind::Press, b, p}; }
PointerEvent release(PointerButton b, glm::vec2 p) { return {Kind::Release, b, p}; }

TEST(PointerEvents, APressAndReleaseInOneFrameIsOneFrameHeldAtThePress) {
    PointerState state;
    const PointerFrame f = foldPointerEvents({move({10, 10}), press(PointerButton::Tool, {10, 10}), move({30, 10}),
                                              release(PointerButton::Tool, {30, 10})},
                                             state);
    EXPECT_TRUE(f.toolButton) << "the click is seen";
    EXPECT_TRUE(f.toolPressed);
    EXPECT_EQ(f.toolPosition, glm::vec2(10, 10)) << "the tool acts where the button went down";
    EXPECT_FALSE(state.toolDown);
    EXPECT_EQ(state.position, glm::vec2(30, 10));
    const PointerFrame next = foldPointerEvents({}, state);
    EXPECT_FALSE(next.toolButton) << "and released the frame after";
    EXPECT_EQ(next.toolPosition, glm::vec2(30, 10));
    // Held over frames: held until its release, the tool following the mouse.
    EXPECT_TRUE(foldPointerEvents({press(PointerButton::Tool, {30, 10})}, state).toolButton);
    const PointerFrame held = foldPointerEvents({move({40, 12})}, state);
    EXPECT_TRUE(held.toolButton);
    EXPECT_FALSE(held.toolPressed);
    EXPECT_EQ(held.toolPosition, glm::vec2(40, 12));
    EXPECT_FALSE(foldPointerEvents({release(PointerButton::Tool, {40, 12})}, state).toolButton);
}

TEST(PointerEvents, OnlyMovesWithTheLookButtonDownLook) {
    PointerState state;
    state.position = {100, 100};
    PointerFrame f = foldPointerEvents({move({160, 100}), press(PointerButton::Look, {160, 100})}, state);
    EXPECT_TRUE(f.lookButton);
    EXPECT_EQ(f.lookDelta, glm::vec2(0.0f)) << "the move came before the press";
    f = foldPointerEvents({move({170, 95}), move({175, 95})}, state);
    EXPECT_EQ(f.lookDelta, glm::vec2(15, -5));
    f = foldPointerEvents({move({180, 95}), release(PointerButton::Look, {180, 95}), move({300, 95})}, state);
    EXPECT_FALSE(f.lookButton);
    EXPECT_EQ(f.lookDelta, glm::vec2(5, 0)) << "moves after the release do not look";
    // A right click inside one frame: held for the frame, nothing turned.
    f = foldPointerEvents({press(PointerButton::Look, {300, 95}), release(PointerButton::Look, {300, 95})}, state);
    EXPECT_TRUE(f.lookButton);
    EXPECT_EQ(f.lookDelta, glm::vec2(0.0f));
}

class PointerSession : public test::FlyingBeforeBallC {
protected:
    void SetUp() override {
        test::FlyingBeforeBallC::SetUp();
        pointer.position = kCentre;
    }
    // One window frame with these pointer events (the desktop loop's path).
    void frame(const std::vector<PointerEvent>& events, const DesktopKeys& keys = {}) {
        DesktopInput in;
        in.viewport = kViewport;
        applyPointer(in, foldPointerEvents(events, pointer), glm::vec2(1.0f), true);
        session->frame(FrameInput(desktopHands(in, keys, *session, projection, kDt, carry), kDt));
    }
    static constexpr double kDt = 1.0 / 12.0;  // a slow software-GL frame
    PointerState pointer;
    DesktopCarry carry;
};

TEST_F(PointerSession, AClickShorterThanAFrameIsAStroke) {
    test::ActionList journal;
    session->setJournal(&journal);
    DesktopKeys carve;
    addKeyPress(carve, GLFW_KEY_1, 0);
    frame({}, carve);
    frame({press(PointerButton::Tool, kCentre), release(PointerButton::Tool, kCentre)});
    frame({});
    EXPECT_EQ(session->editCount(c), 1u) << "the click carved ball c";
    ASSERT_EQ(journal.actions.size(), 1u);
    const auto* stroke = std::get_if<StrokeAction>(&journal.actions[0]);
    ASSERT_NE(stroke, nullptr);
    EXPECT_EQ(stroke->sculpture, "c");
    // Polled once a frame the same click was never seen: the button is up
    // at both frames' starts. Two clicks in two frames are two strokes.
    frame({press(PointerButton::Tool, kCentre), move(kCentre + glm::vec2(20, 0)),
           release(PointerButton::Tool, kCentre + glm::vec2(20, 0))});
    frame({});
    EXPECT_EQ(session->editCount(c), 2u);
    session->setJournal(nullptr);
}

TEST_F(PointerSession, AMoveInTheFrameOfARightPressDoesNotTurnTheView) {
    const float yaw = session->navigator().yaw(), pitch = session->navigator().pitch();
    frame({move(kCentre + glm::vec2(200, 80)), press(PointerButton::Look, kCentre + glm::vec2(200, 80))});
    EXPECT_EQ(session->navigator().yaw(), yaw);
    EXPECT_EQ(session->navigator().pitch(), pitch);
    // Dragged with the button down, it does.
    frame({move(kCentre + glm::vec2(250, 80))});
    EXPECT_NE(session->navigator().yaw(), yaw);
    const float turned = session->navigator().yaw();
    frame({release(PointerButton::Look, kCentre + glm::vec2(250, 80)), move(kCentre)});
    EXPECT_EQ(session->navigator().yaw(), turned) << "released, moving does not look";
}

}  // namespace
}  // namespace hg::garden
