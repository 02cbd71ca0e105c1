// The garden in a headset (xr/xr_garden.h) against the mock runtime, in
// this process: the session reaches FOCUSED and both views are submitted
// into sRGB swapchains with depth; a scripted right hand carves the same
// grid as the replay of the same script; a lost or ended session keeps its
// finished stroke in the journal; LOCAL stands in for a missing STAGE.
#include "xr_carve_script.h"
#include "xr_garden_fixture.h"

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include "garden/app/garden_session.h"
#include "garden/render/renderer.h"
#include "garden/render/tool_gizmo.h"
#include "garden/replay/replay_runner.h"
#include "garden/session/open_session.h"
#include "voxel/volume.h"
#include "xr/hand_panel.h"
#include "xr/hand_panel_ui.h"
#include "xr/xr_garden.h"
#include "xr/xr_settings.h"

namespace hg::xr::test {
namespace {

TEST_F(XrGarden, ReachesFocusedAndSubmitsBothViews) {
    XrOptions o = framesRun(12);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_EQ(info.framesSubmitted, 12);
    EXPECT_GE(info.focusedFrames, 10) << "focused from the second frame on";
    EXPECT_EQ(info.framesRendered, 11) << "every frame once visible";
    EXPECT_EQ(info.space, "LOCAL_FLOOR") << "XR_EXT_local_floor offered";
    EXPECT_EQ(info.interactionProfile, "/interaction_profiles/oculus/touch_controller");
    EXPECT_TRUE(info.depthSubmitted);
    EXPECT_FALSE(info.lost);
    const nlohmann::json j = readback();
    EXPECT_EQ(j["frames_ended"], 12);
    EXPECT_EQ(j["frames_with_two_views"], 11);
    EXPECT_EQ(j["last_frame"]["views"], 2);
    EXPECT_EQ(j["last_frame"]["depth_views"], 2) << "XR_KHR_composition_layer_depth";
    EXPECT_EQ(j["last_frame"]["layers"], nlohmann::json::array({"projection"}));
    EXPECT_EQ(j["last_frame"]["image_size"], nlohmann::json::array({512, 512}));
    // The left eye: the clear sky above (between the clouds) is blue and no
    // brighter than the horizon's clear colour; the ground below is not sky.
    EXPECT_TRUE(std::filesystem::exists(dir / "readback" / "right.png"));
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load((dir / "readback" / "left.png").c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    ASSERT_EQ(w, 512);
    const auto at = [&](int x, int y, int c) { return static_cast<int>(px[(y * w + x) * 4 + c]); };
    expectClearSkyInRow(px, w, 4);
    EXPECT_GT(std::abs(at(w / 2, h - 4, 2) - at(w / 2, 4, 2)), 40) << "the ground is not sky";
    stbi_image_free(px);
}

TEST_F(XrGarden, ScriptedRightHandCarvesTheGridTheReplayCarves) {
    const std::string s = script(kCarveSteps);
    // The replay path: the same script's hands, headless.
    garden::GardenLoad load = garden::loadGarden(gardenFile);
    ASSERT_TRUE(load.ok()) << load.error;
    garden::GardenSession replay(std::move(load));
    const garden::ReplayScript parsed = garden::loadReplayScript(s);
    const garden::ReplayResult r = garden::runReplay(parsed, replay, nullptr, {});
    ASSERT_TRUE(r.ok()) << r.error;
    const int a = replay.findSculpture("a");
    ASSERT_EQ(replay.editCount(a), 1u) << "the replay carved one stroke";

    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    bool compared = false;
    const int status = runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo& info) {
        EXPECT_GE(info.focusedFrames, parsed.totalFrames());
        ASSERT_EQ(xr.editCount(a), 1u) << "the headset's right hand carved one stroke";
        EXPECT_EQ(garden::test::differingVoxels(*replay.sculptures()[static_cast<std::size_t>(a)].volume,
                                                *xr.sculptures()[static_cast<std::size_t>(a)].volume),
                  0);
        compared = true;
    });
    ASSERT_EQ(status, 0);
    EXPECT_TRUE(compared);
    EXPECT_GE(readback()["haptic_pulses"].get<int>(), 1) << "a pulse when the tool starts touching material";
}

// The headset's gesture button is the navigation hand's trigger: held
// while the tool hand's ray draws a Z (seen from the hand, as on a
// screen), it makes the sketch tool's next outline a deformable model
// (issue 22), as the desktop's middle button does.
TEST_F(XrGarden, TheOtherTriggerDrawsAGestureWithTheToolHand) {
    nlohmann::json steps = nlohmann::json::array();
    const auto at = [](double x, double y) {  // screen-like offsets: x right, y down
        return nlohmann::json{{"position", {0.2, 1.2, -0.3}}, {"direction", {x, -y, -1.0}}};
    };
    const double corners[4][2] = {{-0.15, -0.15}, {0.15, -0.15}, {-0.15, 0.15}, {0.15, 0.15}};
    for (int side = 0; side < 3; ++side)
        for (int i = 0; i < 12; ++i) {
            const double t = i / 12.0;
            const double x = corners[side][0] + t * (corners[side + 1][0] - corners[side][0]);
            const double y = corners[side][1] + t * (corners[side + 1][1] - corners[side][1]);
            steps.push_back({{"frames", 1},
                             {"navigation", {{"aim", {{"position", {-0.2, 1.0, -0.3}}}}, {"trigger", 1}}},
                             {"tool", {{"aim", at(x, y)}}}});
        }
    steps.push_back({{"frames", 1},
                     {"navigation", {{"aim", {{"position", {-0.2, 1.0, -0.3}}}}, {"trigger", 1}}},
                     {"tool", {{"aim", at(0.15, 0.15)}}}});
    steps.push_back({{"frames", 3}, {"tool", {{"aim", at(0.15, 0.15)}}}});
    const std::string s = script(steps.dump());
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    bool checked = false;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) {
                  EXPECT_EQ(xr.tool().kind, garden::ToolSettings::Kind::Sketch) << xr.gestureMessage();
                  EXPECT_EQ(xr.tool().sketchUse, garden::ToolSettings::SketchUse::Model) << xr.gestureMessage();
                  EXPECT_EQ(xr.editCount(xr.findSculpture("a")), 0u) << "the gesture sculpts nothing";
                  checked = true;
              }),
              0);
    EXPECT_TRUE(checked);
}

TEST_F(XrGarden, CarvingWhileTheLeftHandHoldsTheWorldMovedEqualsTheReplay) {
    // The left hand grabs the world and pulls it half a metre nearer, then
    // holds it there while the right hand carves. In the world, the right
    // hand is then half a metre further along -z than in the stage: the
    // replay of the same strokes gets those world positions. (The numbers
    // are exact in floats, so the grids must match voxel for voxel.)
    const char* carve = R"([-0.35, -0.6, -1.3], [-0.15, -0.6, -1.3], [0.05, -0.65, -1.3])";
    const nlohmann::json directions = nlohmann::json::parse(std::string("[") + carve + "]");
    const auto steps = [&](double toolZ, bool withNavigation) {
        nlohmann::json j = nlohmann::json::array();
        j.push_back({{"frames", 2}, {"commands", {{{"sculpt_tool", {{"kind", "carve"}, {"radius", 0.12}}}}}}});
        const auto nav = [](double z) {
            return nlohmann::json{{"aim", {{"position", {-0.3, 1.0, z}}}}, {"squeeze", 1}};
        };
        nlohmann::json grab1 = {{"frames", 3}}, grab2 = {{"frames", 3}};
        if (withNavigation) {
            grab1["navigation"] = nav(-1.0);
            grab2["navigation"] = nav(-0.5);
        }
        j.push_back(grab1);
        j.push_back(grab2);
        for (const auto& d : directions) {
            nlohmann::json st = {{"frames", 5},
                                 {"tool", {{"aim", {{"position", {0.3, 1.2, toolZ}}, {"direction", d}}}, {"trigger", 1}}}};
            if (withNavigation) st["navigation"] = nav(-0.5);
            j.push_back(st);
        }
        j.push_back({{"frames", 3}});
        return j.dump();
    };
    // The replay: world positions.
    const std::string replayScript = script(steps(-1.0, false));
    garden::GardenLoad load = garden::loadGarden(gardenFile);
    ASSERT_TRUE(load.ok()) << load.error;
    garden::GardenSession replay(std::move(load));
    const garden::ReplayResult r = garden::runReplay(garden::loadReplayScript(replayScript), replay, nullptr, {});
    ASSERT_TRUE(r.ok()) << r.error;
    const int a = replay.findSculpture("a");
    ASSERT_EQ(replay.editCount(a), 1u);
    // The headset: stage positions, the world moved by the left hand.
    const std::string xrScript = (dir / "xr.json").string();
    std::ofstream(xrScript) << R"({"garden": "garden.json", "steps": )" << steps(-0.5, true) << "}";
    ::setenv("HG_MOCK_XR_SCRIPT", xrScript.c_str(), 1);
    XrOptions o;
    o.script = xrScript;
    o.mirror = false;
    bool compared = false;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) {
                  EXPECT_NEAR(xr.navigator().eye().z, -0.5f, 1e-6f) << "the world was moved";
                  ASSERT_EQ(xr.editCount(a), 1u);
                  EXPECT_EQ(garden::test::differingVoxels(*replay.sculptures()[static_cast<std::size_t>(a)].volume,
                                                          *xr.sculptures()[static_cast<std::size_t>(a)].volume),
                            0);
                  compared = true;
              }),
              0);
    EXPECT_TRUE(compared);
}

TEST_F(XrGarden, SessionLossKeepsTheStrokeInTheJournal) {
    // The trigger is still held when the runtime loses the session.
    const std::string s = script(R"([
      {"frames": 1, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.12}}]},
      {"frames": 200, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1}}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    ::setenv("HG_MOCK_XR_EVENTS", "12:loss", 1);
    XrOptions o;
    o.script = s;
    o.session = (dir / "session").string();
    o.mirror = false;
    std::unique_ptr<voxel::Volume> carved;
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo& i) {
                  info = i;
                  carved = std::make_unique<voxel::Volume>(
                      xr.sculptures()[static_cast<std::size_t>(xr.findSculpture("a"))].volume->clone());
              }),
              0);
    EXPECT_TRUE(info.lost);
    EXPECT_LT(info.framesSubmitted, 20) << "the run ended at the loss, not at the script's end";
    ASSERT_TRUE(carved);
    // Reopened, the session has the stroke and the same grid.
    garden::OpenedSession reopened = garden::openSession({o.session, gardenFile}, {});
    ASSERT_TRUE(reopened.error.empty()) << reopened.error;
    const int a = reopened.session->findSculpture("a");
    EXPECT_EQ(reopened.session->editCount(a), 1u);
    EXPECT_EQ(garden::test::differingVoxels(*carved, *reopened.session->sculptures()[static_cast<std::size_t>(a)].volume), 0);
}

TEST_F(XrGarden, ExitRaisedByTheRuntimeEndsTheRunWithTheStrokeJournalled) {
    // The carve, then a long wait the runtime's exit cuts short.
    nlohmann::json steps = nlohmann::json::parse(kCarveSteps);
    steps.push_back({{"frames", 400}});
    const std::string s = script(steps.dump());
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    ::setenv("HG_MOCK_XR_EVENTS", "30:exit", 1);
    XrOptions o;
    o.session = (dir / "session").string();
    o.garden = gardenFile;
    o.mirror = false;
    o.script = s;  // the app runs its commands (the carve tool), the runtime plays its hands
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_FALSE(info.lost);
    EXPECT_EQ(info.endReason, "the session ended");
    EXPECT_LE(info.framesSubmitted, 30);
    garden::OpenedSession reopened = garden::openSession({o.session, gardenFile}, {});
    ASSERT_TRUE(reopened.error.empty()) << reopened.error;
    EXPECT_EQ(reopened.session->editCount(reopened.session->findSculpture("a")), 1u);
}

TEST_F(XrGarden, LeftHandMovesTheWorldAndBothHandsScaleIt) {
    // The left hand squeezes and pulls half a metre towards the user: the
    // world comes with it, so the rig (the user) moves half a metre along
    // -z in the world. Then both hands squeeze
    // and spread from 0.4 m to 0.8 m apart: the world seems twice as big.
    const std::string s = script(R"([
      {"frames": 3, "navigation": {"aim": {"position": [-0.3, 1.0, -0.8]}, "squeeze": 1}},
      {"frames": 3, "navigation": {"aim": {"position": [-0.3, 1.0, -0.3]}, "squeeze": 1}},
      {"frames": 2},
      {"frames": 3, "navigation": {"aim": {"position": [-0.2, 1.0, -0.5]}, "squeeze": 1},
                    "tool": {"aim": {"position": [0.2, 1.0, -0.5]}, "squeeze": 1}},
      {"frames": 3, "navigation": {"aim": {"position": [-0.4, 1.0, -0.5]}, "squeeze": 1},
                    "tool": {"aim": {"position": [0.4, 1.0, -0.5]}, "squeeze": 1}}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    glm::vec3 eye(0.0f);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo& i) {
                  eye = xr.navigator().eye();
                  info = i;
              }),
              0);
    EXPECT_NEAR(info.worldScale, 0.5f, 1e-5f);
    // The one-hand grab moved the rig by -0.5 in z; the scaling about the
    // hands' midpoint (0, 1, -0.5) keeps that point: the rig's origin goes
    // to midpoint - 0.5 * (midpoint - origin).
    const glm::vec3 origin1(0.0f, 0.0f, -0.5f), middle = origin1 + glm::vec3(0.0f, 1.0f, -0.5f);
    const glm::vec3 origin2 = middle - 0.5f * glm::vec3(0.0f, 1.0f, -0.5f);
    EXPECT_NEAR(eye.x, origin2.x, 1e-4f);
    EXPECT_NEAR(eye.y - 1.7f, origin2.y, 1e-4f);
    EXPECT_NEAR(eye.z, origin2.z, 1e-4f);
}

TEST_F(XrGarden, MenuOnTheLeftHandRecenters) {
    // A grab moves the user half a metre; the menu button brings the head
    // back to the garden's start.
    const std::string s = script(R"([
      {"frames": 3, "navigation": {"aim": {"position": [-0.3, 1.0, -0.8]}, "squeeze": 1}},
      {"frames": 3, "navigation": {"aim": {"position": [-0.3, 1.0, -0.3]}, "squeeze": 1}},
      {"frames": 2, "navigation": {"aim": {"position": [-0.3, 1.0, -0.3]}}},
      {"frames": 2, "navigation": {"aim": {"position": [-0.3, 1.0, -0.3]}, "buttons": ["menu"]}},
      {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    glm::vec3 eye(1e9f);
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { eye = xr.navigator().eye(); }), 0);
    // The mock's head stands at the stage's origin: the rig is back where it began.
    EXPECT_NEAR(eye.x, 0.0f, 1e-4f);
    EXPECT_NEAR(eye.y, 1.7f, 1e-4f);
    EXPECT_NEAR(eye.z, 0.0f, 1e-4f);
}


TEST_F(XrGarden, ThePanelsLabelledButtonsChooseTheToolAndUndo) {
    // The right hand presses the panel's carve button (above the left
    // hand), carves sculpture 'a', then presses undo. With no tool chosen
    // the trigger would only pick the (absent) morph.
    const std::string s = script("[" + pressPanel(kPanelHand, panelButtonCenter(PanelButton::Carve)) + R"(,
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1}},
      {"frames": 2}, )" + pressPanel(kPanelHand, panelButtonCenter(PanelButton::Undo)) + R"(, {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    std::size_t edits = 1, redone = 0;
    bool carving = false;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) {
                  const int a = xr.findSculpture("a");
                  edits = xr.editCount(a);
                  carving = xr.tool().kind == garden::ToolSettings::Kind::Carve;
                  xr.redo();
                  redone = xr.editCount(a);
              }),
              0);
    EXPECT_TRUE(carving);
    EXPECT_EQ(edits, 0u) << "undone from the panel";
    EXPECT_EQ(redone, 1u) << "the stroke the panel undid";
}

TEST_F(XrGarden, ThePanelsMorphTriangleSetsTheWeights) {
    gardenFile = writeGarden(nlohmann::json::parse(R"({"start": {"position": [0, 1.7, 0], "look_at": [0, 1.7, -1]}})"));
    const glm::vec3 want(0.6f, 0.25f, 0.15f);
    const std::string s = script("[" + atPanel(kPanelHand, panelMorphPoint(want), false, 2) + ", " +
                                 atPanel(kPanelHand, panelMorphPoint(want), true, 3) + R"(, {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    std::optional<garden::MorphWeights> w;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { w = xr.morphWeights(); }), 0);
    ASSERT_TRUE(w.has_value());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(w->barycentric[static_cast<std::size_t>(i)], want[i], 0.02) << "corner " << i;
}

TEST_F(XrGarden, LeftHandedSwitchedOnThePanelIsKeptForTheNextRun) {
    const std::string settings = (dir / "config" / "xr.json").string();
    // Run 1: the right hand opens the settings page on the panel over the
    // left hand and ticks left-handed.
    std::string s = script("[" + pressPanel(kPanelHand, panelPageCenter(PanelPage::Settings)) + ", " +
                           pressPanel(kPanelHand, panelToggleCenter(PanelToggle::LeftHanded)) + R"(, {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    o.settingsFile = settings;
    ASSERT_EQ(runXrGarden(o), 0);
    std::string warning;
    EXPECT_TRUE(loadXrSettings(settings, warning).leftHanded);
    EXPECT_EQ(warning, "");
    // Run 2, no flag: the left controller (the script's navigation hand) carves.
    s = script(R"([
      {"frames": 2, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.12}}]},
      {"frames": 6, "navigation": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1},
                    "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [0.35, -0.6, -1.3]}}},
      {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    o.script = s;
    std::size_t edits = 0;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { edits = xr.editCount(xr.findSculpture("a")); }), 0);
    EXPECT_EQ(edits, 1u) << "left-handed from the settings";
    // The flag wins for its run, and the file is left as it was.
    o.leftHanded = false;
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { edits = xr.editCount(xr.findSculpture("a")); }), 0);
    EXPECT_EQ(edits, 0u) << "right-handed for this run: the left hand only points";
    EXPECT_TRUE(loadXrSettings(settings, warning).leftHanded);
}

// The left stick held forward for 20 frames.
constexpr const char* kWalkForward =
    R"([{"frames": 20, "navigation": {"aim": {"position": [-0.2, 1.0, -0.4]}, "thumbstick": [0, 1]}}])";

// The script `s` (kWalkForward) with the head turned 90 degrees right when
// the session began: where the eye ends, and the run.
std::pair<glm::vec3, XrRunInfo> walkWithTheHeadTurned(const std::string& s) {
    ::setenv("HG_MOCK_XR_HEAD_YAW", "90", 1);
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    std::pair<glm::vec3, XrRunInfo> out;
    EXPECT_EQ(runXrGarden(o,
                          [&](garden::GardenSession& xr, const XrRunInfo& i) {
                              out = {xr.navigator().eye(), i};
                          }),
              0);
    return out;
}

TEST_F(XrGarden, TheStickWalksWhereTheHeadLooks) {
    // The head turned 90 degrees right (+x); the navigation stick pushed
    // forward: the rig goes along +x, not the rig's own forward (-z). On
    // the stage: LOCAL_FLOOR would face the head's way (the next test).
    ::setenv("HG_MOCK_XR_NO_LOCAL_FLOOR", "1", 1);
    const auto [eye, info] = walkWithTheHeadTurned(script(kWalkForward));
    EXPECT_EQ(info.space, "STAGE");
    EXPECT_GT(eye.x, 0.1f) << "walked to the head's right of the start";
    EXPECT_NEAR(eye.z, 0.0f, 1e-3f);
    EXPECT_NEAR(eye.y, 1.7f, 1e-3f) << "on the ground's level";
}

// Pixels of an sRGB colour (bytes, within 2) in the left eye's last image.
int pixelsOf(const std::filesystem::path& png, const glm::ivec3& rgb) {
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(png.c_str(), &w, &h, &n, 4);
    if (!px) return -1;
    int count = 0;
    for (int i = 0; i < w * h; ++i)
        if (std::abs(px[i * 4] - rgb.r) <= 2 && std::abs(px[i * 4 + 1] - rgb.g) <= 2 && std::abs(px[i * 4 + 2] - rgb.b) <= 2)
            ++count;
    stbi_image_free(px);
    return count;
}

// Pixels of the panel's background colour in the left eye's last image.
int panelPixels(const std::filesystem::path& png) { return pixelsOf(png, glm::ivec3(31, 26, 51)); }

TEST_F(XrGarden, TheToolIsDrawnWhereTheToolHandPoints) {
    // The right hand aims at sculpture 'a' without pulling: with the carve
    // tool in hand its ray and wire sphere show in the carve colour; with
    // no tool (the morph selector) they do not, and nothing is carved.
    const glm::vec4 carve = garden::toolColor(garden::ToolSettings{garden::ToolSettings::Kind::Carve});
    const glm::ivec3 rgb(glm::round(glm::vec3(carve) * 255.0f));
    for (const char* tool : {"carve", "none"}) {
        const std::string s = script(std::string(R"([{"frames": 2, "commands": [{"sculpt_tool": {"kind": ")") + tool +
                                     R"(", "radius": 0.12}}]},
          {"frames": 6, "tool": {"aim": {"position": [0.1, 1.2, -1.0], "direction": [0.05, -0.65, -1.3]}, "trigger": 0}}])");
        ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
        XrOptions o;
        o.script = s;
        o.mirror = false;
        std::size_t edits = 1;
        ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { edits = xr.editCount(xr.findSculpture("a")); }), 0);
        EXPECT_EQ(edits, 0u);
        const int shown = pixelsOf(dir / "readback" / "left.png", rgb);
        if (std::string(tool) == "carve") EXPECT_GT(shown, 60) << "the ray and the sphere in the carve colour";
        else EXPECT_EQ(shown, 0) << "no tool, nothing drawn";
    }
}

TEST_F(XrGarden, ThePanelIsInTheEyesImage) {
    // The left hand held up in front of the head: the board fills part of
    // the view; without the hand, no panel.
    for (const bool held : {true, false}) {
        const std::string s = script(held ? R"([{"frames": 4, "navigation": {"aim": {"position": [0, 1.45, -0.6]}}}])"
                                          : R"([{"frames": 4}])");
        ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
        XrOptions o;
        o.script = s;
        o.mirror = false;
        ASSERT_EQ(runXrGarden(o), 0);
        const int pixels = panelPixels(dir / "readback" / "left.png");
        if (held) EXPECT_GT(pixels, 2000) << "the board's background";
        else EXPECT_EQ(pixels, 0);
    }
}

TEST_F(XrGarden, InstanceLossEndsTheRun) {
    ::setenv("HG_MOCK_XR_EVENTS", "5:instance_loss", 1);
    XrOptions o;
    o.garden = gardenFile;
    o.frames = 300;  // a guard
    o.mirror = false;
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_TRUE(info.lost);
    EXPECT_NE(info.endReason.find("instance loss"), std::string::npos) << info.endReason;
    EXPECT_LE(info.framesSubmitted, 6);
}

TEST_F(XrGarden, UnfocusedFramesRenderWithoutInput) {
    // The runtime takes focus away for frames 6 to 15 (a system menu, say).
    ::setenv("HG_MOCK_XR_EVENTS", "6:unfocus,16:focus", 1);
    XrOptions o = framesRun(24);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_EQ(info.framesRendered, 23) << "visible all along";
    EXPECT_EQ(info.focusedFrames, 13) << "input read only while focused";
}

TEST_F(XrGarden, LeftHandedTheLeftControllerCarves) {
    // The script's navigation hand is the left controller: left-handed, it
    // holds the tool and carves; the right one (the script's tool hand)
    // only points.
    const std::string s = script(R"([
      {"frames": 2, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.12}}]},
      {"frames": 6, "navigation": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1},
                    "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [0.35, -0.6, -1.3]}}},
      {"frames": 2}])");
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.leftHanded = true;
    o.mirror = false;
    std::size_t edits = 0;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& xr, const XrRunInfo&) { edits = xr.editCount(xr.findSculpture("a")); }), 0);
    EXPECT_EQ(edits, 1u);
}

TEST_F(XrGarden, LocalFloorFacesTheGardenWhereverTheUserFaced) {
    // The head turned 90 degrees right of the stage's forward when the
    // session began: in LOCAL_FLOOR that way is forward, so the garden's
    // start faces the user and the stick walks into the garden (-z).
    const auto [eye, info] = walkWithTheHeadTurned(script(kWalkForward));
    EXPECT_EQ(info.space, "LOCAL_FLOOR");
    EXPECT_LT(eye.z, -0.1f) << "walked into the garden, the way the garden's start looks";
    EXPECT_NEAR(eye.x, 0.0f, 1e-3f);
    EXPECT_NEAR(eye.y, 1.7f, 1e-3f) << "LOCAL_FLOOR's floor is the ground";
}

TEST_F(XrGarden, StageStandsInForAMissingLocalFloorAndLocalForBoth) {
    ::setenv("HG_MOCK_XR_NO_LOCAL_FLOOR", "1", 1);
    for (const char* expected : {"STAGE", "LOCAL"}) {
        if (std::string(expected) == "LOCAL") ::setenv("HG_MOCK_XR_NO_STAGE", "1", 1);
        XrRunInfo info;
        ASSERT_EQ(runXrGarden(framesRun(4), [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
        EXPECT_EQ(info.space, expected);
        EXPECT_EQ(info.framesRendered, 3);
    }
}

TEST_F(XrGarden, TheTwoHandedContentScriptCarvesAndScalesInTheDefaultGarden) {
    // content/replays/xr_two_hands.json, as the README runs it on the mock
    // runtime: the left hand pulls the world nearer, the right carves a
    // groove in column west, then with the move tool picks column east and
    // scales it up with the tool stick.
    const std::string s = std::string(HG_SOURCE_DIR) + "/content/replays/xr_two_hands.json";
    ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
    XrOptions o;
    o.script = s;
    o.mirror = false;
    std::size_t carved = 0;
    double scale = 0.0;
    ASSERT_EQ(runXrGarden(o,
                          [&](garden::GardenSession& xr, const XrRunInfo&) {
                              carved = xr.editCount(xr.findSculpture("column west"));
                              const int east = xr.findSculpture("column east");
                              scale = xr.sculptures()[static_cast<std::size_t>(east)].placement.scale;
                          }),
              0);
    EXPECT_EQ(carved, 1u) << "one groove";
    EXPECT_NEAR(scale, std::sqrt(2.0), 0.05) << "half a second of the stick at full tilt";
}

}  // namespace
}  // namespace hg::xr::test
