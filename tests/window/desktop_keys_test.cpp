// The desktop's keys (garden/desktop/desktop_keys.*): GLFW presses become
// the documented commands; the tool keys and the wheel become tool intents
// that change the session's ToolSettings and the selected sculpture; Ctrl+Z
// and Ctrl+Shift+Z undo and redo a real stroke made with the mouse; a move
// drag with the mouse is one undo, and so is a burst of wheel notches.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include "../garden/session_garden.h"
#include "garden/app/garden_session.h"
#include "garden/window/desktop_keys.h"
#include "tests/render/headless_imgui.h"
#include "garden/sculpt/sculpture_edits.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;

DesktopKeys press(int key, int mods = 0) {
    DesktopKeys k;
    EXPECT_TRUE(addKeyPress(k, key, mods)) << key;
    return k;
}

TEST(DesktopKeys, KeysMapToTheDocumentedCommands) {
    const Kind digits[] = {Kind::None,    Kind::Carve,   Kind::Add,  Kind::Melt,   Kind::Perturb,
                           Kind::Impacts, Kind::Move,    Kind::Sketch, Kind::Smooth, Kind::Inflate};
    for (int d = 0; d <= 9; ++d) {
        EXPECT_EQ(press(GLFW_KEY_0 + d).tool, digits[d]) << d;
        EXPECT_EQ(press(GLFW_KEY_KP_0 + d).tool, digits[d]) << "keypad " << d;
    }
    DesktopKeys none;
    EXPECT_FALSE(addKeyPress(none, GLFW_KEY_J, 0));
    EXPECT_FALSE(none.tool);
    EXPECT_FALSE(addKeyPress(none, GLFW_KEY_K, 0));
    EXPECT_EQ(press(GLFW_KEY_RIGHT_BRACKET).sizeSteps, 1);
    EXPECT_EQ(press(GLFW_KEY_LEFT_BRACKET).sizeSteps, -1);
    EXPECT_TRUE(press(GLFW_KEY_R).reverse);
    EXPECT_TRUE(press(GLFW_KEY_M).mirror);
    const DesktopKeys undo = press(GLFW_KEY_Z, GLFW_MOD_CONTROL);
    EXPECT_TRUE(undo.undo);
    EXPECT_FALSE(undo.redo);
    const DesktopKeys redo = press(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT);
    EXPECT_TRUE(redo.redo);
    EXPECT_FALSE(redo.undo);
    EXPECT_TRUE(press(GLFW_KEY_Y, GLFW_MOD_CONTROL).redo);
    EXPECT_FALSE(addKeyPress(none, GLFW_KEY_1, GLFW_MOD_CONTROL)) << "Ctrl+1 picks no tool";
    EXPECT_FALSE(none.tool);
    EXPECT_TRUE(press(GLFW_KEY_SPACE).fly);
    EXPECT_TRUE(press(GLFW_KEY_O).orbit);
    EXPECT_TRUE(press(GLFW_KEY_G).detail);
    EXPECT_TRUE(press(GLFW_KEY_F12).screenshot);
    EXPECT_TRUE(press(GLFW_KEY_ESCAPE).escape);
    EXPECT_TRUE(press(GLFW_KEY_F3).stats);
    EXPECT_TRUE(press(GLFW_KEY_F9).headset);
    EXPECT_TRUE(press(GLFW_KEY_C).clayView);
    EXPECT_TRUE(press(GLFW_KEY_X).wireframe);
    EXPECT_TRUE(press(GLFW_KEY_1, GLFW_MOD_SHIFT).tool) << "Shift (held to turn) leaves the keys as they are";
    EXPECT_FALSE(addKeyPress(none, GLFW_KEY_W, 0)) << "walking keys are held, polled each frame";
    // Presses add up between frames: two ] and a [ are one step up.
    DesktopKeys k;
    addKeyPress(k, GLFW_KEY_RIGHT_BRACKET, 0);
    addKeyPress(k, GLFW_KEY_RIGHT_BRACKET, 0);
    addKeyPress(k, GLFW_KEY_LEFT_BRACKET, 0);
    EXPECT_EQ(k.sizeSteps, 1);
}

class DesktopKeysSession : public test::FlyingBeforeBallC {
protected:
    // One frame of the window: these keys pressed, the mouse at `mouse`,
    // the left button as given.
    void frame(const DesktopKeys& keys, glm::vec2 mouse, bool leftButton, float wheel = 0.0f) {
        DesktopInput in;
        in.viewport = kViewport;
        in.mouse = mouse;
        in.toolButton = leftButton;
        in.wheel = wheel;
        const Hands h = desktopHands(in, keys, *session, projection, kDt, carry);
        lastSpeed = h.speedScale;
        session->frame(FrameInput(h, kDt));
    }
    void frame(const DesktopKeys& keys) { frame(keys, kCentre, false); }
    // Half a second of frames with nothing pressed: longer than a burst.
    void pause() {
        for (int f = 0; f < 45; ++f) frame({});
    }
    Sculpture& ball() { return session->sculptures()[static_cast<std::size_t>(c)]; }

    static constexpr double kDt = 1.0 / 90.0;
    DesktopCarry carry;
    float lastSpeed = 1.0f;
};

// Esc closes what is open first (a drop-down, the help), then quits,
// asking first only when work is not saved; Home frames the garden, F1
// the key list.
TEST(DesktopKeys, EscClosesWhatIsOpenFirstAndAsksOnlyWhenUnsaved) {
    EXPECT_TRUE(press(GLFW_KEY_HOME).frameGarden);
    EXPECT_TRUE(press(GLFW_KEY_F1).help);
    EXPECT_EQ(escapeDoes(true, true, true), EscapeDoes::ClosePopup);
    EXPECT_EQ(escapeDoes(false, true, true), EscapeDoes::CloseHelp);
    EXPECT_EQ(escapeDoes(false, false, true), EscapeDoes::AskToQuit);
    EXPECT_EQ(escapeDoes(false, false, false), EscapeDoes::Quit);
    EXPECT_FALSE(popupOpen());  // no ImGui context: nothing to close
    createHeadlessImGui(ImVec2(800, 600));
    // A panel's drop-down, open in the last frame, is what Esc closes.
    bool shown = false;
    const auto frame = [&](bool open) {
        ImGui::NewFrame();
        ImGui::Begin("panel");
        if (open) ImGui::OpenPopup("choices");
        shown = ImGui::BeginPopup("choices");
        if (shown) {
            ImGui::TextUnformatted("a");
            ImGui::EndPopup();
        }
        ImGui::End();
        ImGui::Render();
    };
    frame(false);
    EXPECT_FALSE(popupOpen());
    frame(true);
    EXPECT_TRUE(popupOpen());
    frame(false);
    EXPECT_TRUE(shown) << "it stays open by itself";
    closePopups();
    EXPECT_FALSE(popupOpen());
    frame(false);
    EXPECT_FALSE(shown) << "Esc closed it";
    ImGui::DestroyContext();
}

TEST_F(DesktopKeysSession, WorkIsUnsavedWithoutAJournalOrWithAFailedOne) {
    EXPECT_FALSE(unsavedWork(*session)) << "nothing done yet";
    session->select(c);
    frame(press(GLFW_KEY_1));
    frame({}, kCentre, true);
    frame({}, kCentre, false);
    ASSERT_EQ(session->editCount(c), 1u);
    EXPECT_TRUE(unsavedWork(*session)) << "a stroke and no session folder";
    EXPECT_NE(unsavedWhat(*session).find("1 action made in this run"), std::string::npos) << unsavedWhat(*session);
    struct FailingJournal : test::ActionList {
        bool failed = false;
        SaveStatus saveStatus() const override {
            SaveStatus s;
            if (failed) {
                s.state = SaveStatus::State::NotSaved;
                s.unsaved = 1;
                s.reason = "disk full";
            }
            return s;
        }
    } journal;
    session->setJournal(&journal);
    EXPECT_FALSE(unsavedWork(*session)) << "every action of a session folder is on disk";
    journal.failed = true;
    EXPECT_TRUE(unsavedWork(*session));
    EXPECT_NE(unsavedWhat(*session).find("disk full"), std::string::npos);
    session->setJournal(nullptr);
}

TEST_F(DesktopKeysSession, HomeTakesTheViewBackToTheGardensStart) {
    // The small garden starts the visitor at (0, 1.7, 8) looking at (0, 0.5, 0).
    session->navigator().setMode(NavigationMode::Fly);
    session->navigator().setPose(glm::vec3(3.0f, 4.0f, -2.0f), 1.0f, 0.3f);
    session->resetView();
    EXPECT_EQ(session->navigator().eye(), glm::vec3(0.0f, 1.7f, 8.0f));
    EXPECT_FLOAT_EQ(session->navigator().yaw(), 0.0f);
    EXPECT_NEAR(session->navigator().pitch(), std::asin(-1.2f / std::sqrt(1.44f + 64.0f)), 1e-6);
    EXPECT_EQ(session->navigator().mode(), NavigationMode::Walk);
}

TEST_F(DesktopKeysSession, ToolKeysPickToolsAndScaleTheirSizes) {
    ToolSettings& t = session->tool();
    frame(press(GLFW_KEY_1));
    EXPECT_EQ(t.kind, Kind::Carve);
    const double r = t.radius;
    frame(press(GLFW_KEY_RIGHT_BRACKET));
    EXPECT_DOUBLE_EQ(t.radius, r * 1.25);
    DesktopKeys twoDown;
    addKeyPress(twoDown, GLFW_KEY_LEFT_BRACKET, 0);
    addKeyPress(twoDown, GLFW_KEY_LEFT_BRACKET, 0);
    frame(twoDown);
    EXPECT_DOUBLE_EQ(t.radius, r / 1.25);
    frame(press(GLFW_KEY_4));
    EXPECT_EQ(t.kind, Kind::Perturb);
    const auto radii = t.radii;
    frame(press(GLFW_KEY_RIGHT_BRACKET));
    EXPECT_DOUBLE_EQ(t.perturbScale, 1.25) << "perturb: the global scale";
    EXPECT_EQ(t.radii, radii) << "the radii themselves stay";
    EXPECT_DOUBLE_EQ(t.perturbRadii()[1], radii[1] * 1.25);
    EXPECT_DOUBLE_EQ(t.radius, r / 1.25) << "the stroke radius is another tool's";
    frame(press(GLFW_KEY_5));
    EXPECT_EQ(t.kind, Kind::Impacts);
    const double size = t.impactSize;
    frame(press(GLFW_KEY_RIGHT_BRACKET));
    EXPECT_DOUBLE_EQ(t.impactSize, size * 1.25);
    // Sizes stay in their bounds however often a key is pressed.
    for (int i = 0; i < 100; ++i) frame(press(GLFW_KEY_RIGHT_BRACKET));
    EXPECT_EQ(t.impactSize, kMaxImpactSize);
    frame(press(GLFW_KEY_2));
    EXPECT_EQ(t.kind, Kind::Add);
    frame(press(GLFW_KEY_3));
    EXPECT_EQ(t.kind, Kind::Melt);
    frame(press(GLFW_KEY_6));
    EXPECT_EQ(t.kind, Kind::Move);
    frame(press(GLFW_KEY_0));
    EXPECT_EQ(t.kind, Kind::None);
    // R toggles the reverse.
    EXPECT_FALSE(t.reverse);
    frame(press(GLFW_KEY_R));
    EXPECT_TRUE(t.reverse);
    frame(press(GLFW_KEY_R));
    EXPECT_FALSE(t.reverse);
}

TEST_F(DesktopKeysSession, MTogglesTheSelectedSculpturesMirrorThroughItsBoxCentre) {
    frame(press(GLFW_KEY_M));
    for (const Sculpture& s : session->sculptures()) EXPECT_FALSE(s.mirror) << "nothing selected: nothing mirrored";
    session->select(c);
    frame(press(GLFW_KEY_M));
    ASSERT_TRUE(ball().mirror);
    const frep::Box3& box = ball().volume->frame.modelBox;
    EXPECT_DOUBLE_EQ(ball().mirror->point[1], 0.5 * (box.lo[1] + box.hi[1]));
    EXPECT_DOUBLE_EQ(ball().mirror->normal[0], 1.0);
    frame(press(GLFW_KEY_M));
    EXPECT_FALSE(ball().mirror);
}

TEST_F(DesktopKeysSession, CtrlZAndCtrlShiftZUndoAndRedoAStrokeMadeWithTheMouse) {
    const voxel::Volume original = ball().volume->clone();
    frame(press(GLFW_KEY_1));
    // Carve across the ball with the left button held.
    for (int f = 0; f < 6; ++f) frame({}, kCentre + glm::vec2(10.0f * static_cast<float>(f), 0.0f), true);
    frame({}, kCentre, false);
    ASSERT_EQ(session->editCount(c), 1u);
    const voxel::Volume carved = ball().volume->clone();
    EXPECT_GT(test::differingVoxels(carved, original), 50);

    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_EQ(session->editCount(c), 0u);
    EXPECT_EQ(test::differingVoxels(*ball().volume, original), 0) << "exactly the unedited grid";
    frame({});
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT));
    EXPECT_EQ(session->editCount(c), 1u);
    EXPECT_EQ(test::differingVoxels(*ball().volume, carved), 0);
    frame({});
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    frame({});
    frame(press(GLFW_KEY_Y, GLFW_MOD_CONTROL));
    EXPECT_EQ(test::differingVoxels(*ball().volume, carved), 0) << "Ctrl+Y redoes too";
    // Held keys repeat no action: one press, one undo (the hands' button edge).
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_EQ(session->editCount(c), 0u);
    EXPECT_FALSE(session->undo()) << "two frames held: one undo, nothing left";
}

TEST_F(DesktopKeysSession, AMoveDragWithTheMouseIsOneUndo) {
    const Placement start = ball().placement;
    frame(press(GLFW_KEY_6));
    frame({}, kCentre, true);
    EXPECT_EQ(session->selected(), c) << "the click selected the ball";
    for (int f = 1; f <= 10; ++f) frame({}, kCentre + glm::vec2(10.0f * static_cast<float>(f), 0.0f), true);
    // 100 pixels right at 2.4 m: about 0.38 m right (the grabbed point stays
    // under the mouse at its distance), height kept.
    EXPECT_NEAR(ball().placement.position[0], start.position[0] + 0.38, 0.03);
    EXPECT_EQ(ball().placement.position[1], start.position[1]);
    frame({}, kCentre + glm::vec2(100.0f, 0.0f), false);
    const Placement moved = ball().placement;

    // The wheel scales the selection with the move tool: one action, and
    // the walking speed is left alone.
    frame({}, kCentre, false, 1.0f);
    EXPECT_DOUBLE_EQ(ball().placement.scale, start.scale * 1.25);
    EXPECT_EQ(lastSpeed, 1.0f);
    pause();  // the burst ends: the next press is another move
    frame(press(GLFW_KEY_LEFT_BRACKET));
    pause();
    EXPECT_DOUBLE_EQ(ball().placement.scale, start.scale);
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_DOUBLE_EQ(ball().placement.scale, start.scale * 1.25);
    frame({});
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_EQ(ball().placement.position, moved.position);
    EXPECT_DOUBLE_EQ(ball().placement.scale, start.scale);
    frame({});
    // The whole drag goes in one undo.
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_EQ(ball().placement.position, start.position);
    EXPECT_FALSE(session->undo());
}

// The keys and the wheel become intents, not changes to the session: the
// tool picked, [ and ] as size factors, R and M as toggles; the wheel is a
// selection scale only with the move tool and a selection, else the
// walking speed.
TEST_F(DesktopKeysSession, KeysAndTheWheelBecomeToolIntents) {
    float wheel = 2.0f;
    DesktopCarry carry;
    DesktopKeys keys = press(GLFW_KEY_4);
    addKeyPress(keys, GLFW_KEY_LEFT_BRACKET, 0);
    addKeyPress(keys, GLFW_KEY_R, 0);
    addKeyPress(keys, GLFW_KEY_M, 0);
    ToolIntents i = desktopIntents(keys, wheel, *session, kDt, carry);
    EXPECT_EQ(i.tool, ToolChoice::Perturb);
    EXPECT_DOUBLE_EQ(i.size, 1.0 / kToolSizeStep);
    EXPECT_TRUE(i.reverse);
    EXPECT_EQ(i.mirror, MirrorIntent::Toggle);
    EXPECT_EQ(i.selectionScale, 1.0);
    EXPECT_FALSE(i.held);
    EXPECT_EQ(wheel, 2.0f) << "the wheel is left for the walking speed";
    EXPECT_EQ(session->tool().kind, Kind::None) << "an intent changes nothing by itself";
    i = desktopIntents(DesktopKeys{}, wheel, *session, kDt, carry);
    EXPECT_FALSE(i.any());
    // The move tool picked this frame, with a selection: the wheel scales it.
    session->select(c);
    i = desktopIntents(press(GLFW_KEY_6), wheel, *session, kDt, carry);
    EXPECT_DOUBLE_EQ(i.selectionScale, kToolSizeStep * kToolSizeStep);
    EXPECT_EQ(wheel, 0.0f) << "consumed";
    EXPECT_TRUE(i.held);
}

// A burst of wheel notches (less than kScaleBurstSeconds apart) is one
// gesture: one journalled move, one undo step, like one push of the
// headset's stick; notches farther apart are steps of their own.
TEST_F(DesktopKeysSession, ABurstOfWheelNotchesIsOneUndo) {
    test::ActionList journal;
    session->setJournal(&journal);
    const double start = ball().placement.scale;
    frame(press(GLFW_KEY_6));
    session->select(c);
    for (int notch = 0; notch < 4; ++notch) {
        frame({}, kCentre, false, 1.0f);
        for (int f = 0; f < 10; ++f) frame({});  // 0.11 s between notches
    }
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * std::pow(1.25, 4));
    EXPECT_TRUE(journal.actions.empty()) << "the burst goes on";
    pause();
    EXPECT_EQ(journal.actions.size(), 1u);
    // Two notches half a second apart: two steps.
    frame({}, kCentre, false, -1.0f);
    pause();
    frame({}, kCentre, false, -1.0f);
    pause();
    EXPECT_EQ(journal.actions.size(), 3u);
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * 1.25 * 1.25);
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    frame({});
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_DOUBLE_EQ(ball().placement.scale, start * std::pow(1.25, 4));
    frame({});
    frame(press(GLFW_KEY_Z, GLFW_MOD_CONTROL));
    EXPECT_DOUBLE_EQ(ball().placement.scale, start) << "the burst of four notches, one undo";
    EXPECT_FALSE(session->undo());
    EXPECT_EQ(lastSpeed, 1.0f) << "the walking speed never saw the wheel";
    session->setJournal(nullptr);
}

TEST_F(DesktopKeysSession, DraggingTheOrbitedSculptureDoesNotCarryTheCameraAlong) {
    // Orbiting the ball: were the camera to follow it during the drag, the
    // mouse ray would move with it, and the ball with the ray, frame after
    // frame, with the mouse held still.
    session->select(c);
    frame(press(GLFW_KEY_O));
    ASSERT_EQ(session->navigator().mode(), NavigationMode::Orbit);
    frame(press(GLFW_KEY_6));
    const glm::vec3 eye = session->navigator().eye();
    const Placement start = ball().placement;
    frame({}, kCentre, true);
    for (int f = 1; f <= 5; ++f) frame({}, kCentre + glm::vec2(10.0f * static_cast<float>(f), 0.0f), true);
    const Placement moved = ball().placement;
    EXPECT_GT(moved.position[0], start.position[0] + 0.1) << "dragged right";
    for (int f = 0; f < 10; ++f) frame({}, kCentre + glm::vec2(50.0f, 0.0f), true);
    EXPECT_EQ(ball().placement.position, moved.position) << "held still, it stays";
    EXPECT_EQ(session->navigator().eye(), eye);
    frame({}, kCentre + glm::vec2(50.0f, 0.0f), false);
    // Let go, the orbit takes the new place as its centre.
    frame({});
    EXPECT_NE(session->navigator().eye(), eye);
}

}  // namespace
}  // namespace hg::garden
