// The hand panel's pages (xr/hand_panel_ui.h) worked through the mock
// runtime by a scripted right hand, as a user would: the perturb tool's
// shape and the impact tool's shape and spread change the session's
// ToolSettings; the sculpture page selects a sculpture, sets its mirror
// plane and discards its edits (journalled: a reopened session has none);
// the settings page's snap angle, smooth turning and seated height are
// written to the settings file, and a second run without flags turns the
// way they say.
#include "xr_garden_fixture.h"

#include <cmath>
#include <memory>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "garden/app/garden_session.h"
#include "garden/session/open_session.h"
#include "garden/sculpt/sculpture_edits.h"
#include "voxel/volume.h"
#include "xr/hand_panel_ui.h"
#include "xr/xr_garden.h"
#include "xr/xr_settings.h"

namespace hg::xr::test {
namespace {

using Kind = garden::ToolSettings::Kind;

// Degrees from yaw `from` to yaw `to` (radians), either way round.
float turnedDegrees(float from, float to) {
    return glm::degrees(std::fabs(std::remainder(to - from, 2.0f * glm::pi<float>())));
}

class HandPanelPages : public XrGarden {
protected:
    // Runs `steps` (a JSON list) as the script, hands and commands; `atEnd`
    // sees the session.
    void run(const std::string& steps, const std::function<void(garden::GardenSession&)>& atEnd = {}) {
        const std::string s = script(steps);
        ::setenv("HG_MOCK_XR_SCRIPT", s.c_str(), 1);
        options.script = s;
        ASSERT_EQ(runXrGarden(options, [&](garden::GardenSession& xr, const XrRunInfo&) {
                      if (atEnd) atEnd(xr);
                  }),
                  0);
    }
    static std::string press(const glm::vec2& uv) { return pressPanel(kPanelHand, uv); }
    void SetUp() override {
        XrGarden::SetUp();
        options.mirror = false;
        options.settingsFile = (dir / "config" / "xr.json").string();
    }
    XrOptions options;
};

TEST_F(HandPanelPages, PerturbShapeChosenOnThePanel) {
    garden::ToolSettings tool;
    run("[" + press(panelButtonCenter(PanelButton::Perturb)) + ", " + press(panelChoiceCenter(PanelChoice::PerturbShape, 1)) +
            R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) { tool = xr.tool(); });
    EXPECT_EQ(tool.kind, Kind::Perturb);
    EXPECT_EQ(tool.shape, garden::QuadricShape::Torus);
    // And back to the ellipsoid, the first option.
    run("[" + press(panelButtonCenter(PanelButton::Perturb)) + ", " + press(panelChoiceCenter(PanelChoice::PerturbShape, 1)) +
            ", " + press(panelChoiceCenter(PanelChoice::PerturbShape, 0)) + R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) { tool = xr.tool(); });
    EXPECT_EQ(tool.shape, garden::QuadricShape::Ellipsoid);
}

TEST_F(HandPanelPages, TheMoveToolSelectsWhatTheHandPointsAtAndTheStickScalesIt) {
    // The panel's move button; the ray on sculpture 'a', a pull and a let
    // go (no drag): 'a' is selected, nothing moved. Then the tool stick up
    // for half a second grows it live, one undoable move.
    const std::string aim = R"("aim": {"position": [0.1, 1.2, -1.0], "direction": [0.05, -0.65, -1.3]})";
    Kind kind = Kind::None;
    int selected = -1;
    double scale = 0.0, undone = 0.0, start = -1.0;
    run("[" + press(panelButtonCenter(PanelButton::Move)) + R"(, {"frames": 3, "tool": {)" + aim + R"(, "trigger": 1}},
         {"frames": 2, "tool": {)" + aim + R"(, "trigger": 0}},
         {"frames": 45, "tool": {)" + aim + R"(, "thumbstick": [0, 1]}},
         {"frames": 3, "tool": {)" + aim + "}}]",
        [&](garden::GardenSession& xr) {
            kind = xr.tool().kind;
            const int a = xr.findSculpture("a");
            selected = xr.selected() == a ? 0 : xr.selected();
            start = garden::Placement{}.scale;  // the small garden gives its balls no scale
            scale = xr.sculptures()[static_cast<std::size_t>(a)].placement.scale;
            xr.undo();
            undone = xr.sculptures()[static_cast<std::size_t>(a)].placement.scale;
        });
    EXPECT_EQ(kind, Kind::Move);
    EXPECT_EQ(selected, 0) << "sculpture 'a', pointed at, is selected";
    // Full tilt doubles in a second: about 2^0.5 in 45 frames at 90 Hz.
    EXPECT_NEAR(scale / start, std::sqrt(2.0), 0.05);
    EXPECT_EQ(undone, start) << "one undo takes the whole push back";
}

TEST_F(HandPanelPages, ImpactShapeAndSpreadChosenOnThePanel) {
    garden::ToolSettings tool;
    run("[" + press(panelButtonCenter(PanelButton::Impacts)) + ", " + press(panelChoiceCenter(PanelChoice::ImpactShape, 2)) +
            ", " + press(panelChoiceCenter(PanelChoice::ImpactSpread, 2)) + R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) { tool = xr.tool(); });
    EXPECT_EQ(tool.kind, Kind::Impacts);
    EXPECT_EQ(tool.impactShape, garden::ImpactShape::Square);
    EXPECT_EQ(tool.spread, garden::ImpactSpread::Cone);
    EXPECT_EQ(tool.spreadSize, garden::ToolSettings{}.spreadSize) << "the size kept, now read as the cone's half-angle";
    run("[" + press(panelButtonCenter(PanelButton::Impacts)) + ", " + press(panelChoiceCenter(PanelChoice::ImpactSpread, 1)) +
            R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) { tool = xr.tool(); });
    EXPECT_EQ(tool.spread, garden::ImpactSpread::Gaussian);
    EXPECT_EQ(tool.impactShape, garden::ImpactShape::Sphere) << "a new run starts from the defaults";
}

// The headset's history page (issue 23: the desktop's history panel where
// it applies): after a carve on 'a', the page's "undo on a" takes back that
// sculpture's last action alone, journalled as an undo naming it.
TEST_F(HandPanelPages, TheHistoryPageUndoesTheSelectedSculpturesLastAction) {
    std::size_t edits = 1;
    std::vector<garden::HistoryItem> history;
    run("[" + press(panelButtonCenter(PanelButton::Carve)) + R"(,
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1}},
      {"frames": 2}, )" + press(panelPageCenter(PanelPage::History)) + ", " +
            press(panelActionCenter(PanelAction::UndoSelected)) + R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) {
            edits = xr.editCount(xr.findSculpture("a"));
            history = xr.history();
        });
    EXPECT_EQ(edits, 0u) << "undone on the history page";
    ASSERT_EQ(history.size(), 1u);
    EXPECT_TRUE(history[0].undone) << "the carve waits in the redo list";
    EXPECT_EQ(history[0].name, "a");
}

// The inflate and smooth buttons choose those tools, and a partial pull of
// the trigger (0.75: half way past the press threshold) inflates with the
// pressure it gives, 0.1 + 0.9 * 0.5 of the tool's strength, read once the
// pull has settled; a full pull smooths at the tool's whole strength.
TEST_F(HandPanelPages, InflateAndSmoothButtonsAndTheTriggersPressure) {
    std::vector<garden::Stroke> strokes;
    run("[" + press(panelButtonCenter(PanelButton::Inflate)) + R"(,
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 0.75}},
      {"frames": 2}, )" + press(panelButtonCenter(PanelButton::Smooth)) + R"(,
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.3, -0.6, -1.3]}, "trigger": 1}},
      {"frames": 2}])",
        [&](garden::GardenSession& xr) {
            for (const garden::Edit& e : xr.sculptures()[static_cast<std::size_t>(xr.findSculpture("a"))].edits->list().edits())
                if (const auto* st = std::get_if<garden::Stroke>(&e.op)) strokes.push_back(*st);
        });
    ASSERT_EQ(strokes.size(), 2u);
    EXPECT_EQ(strokes[0].tool, garden::StrokeTool::Inflate);
    EXPECT_NEAR(strokes[0].strength, garden::ToolSettings{}.inflateStrength * 0.55, 1e-6);
    EXPECT_EQ(strokes[1].tool, garden::StrokeTool::Smooth);
    EXPECT_NEAR(strokes[1].strength, garden::ToolSettings{}.smoothStrength, 1e-6);
    EXPECT_EQ(strokes[1].fits.size(), strokes[1].segments.size());
}

TEST_F(HandPanelPages, TheSculpturePageMirrorsAndDiscardsTheSelectedSculpturesEdits) {
    options.session = (dir / "session").string();
    // Run 1: carve 'a' (the carve button, then the trigger on it: the
    // stroke selects what it carves), then on the sculpture page tick its
    // mirror plane.
    int selected = -1;
    std::size_t edits = 0;
    bool mirrored = false;
    run("[" + press(panelButtonCenter(PanelButton::Carve)) + R"(,
      {"frames": 6, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1}},
      {"frames": 2}, )" + press(panelPageCenter(PanelPage::Sculpture)) + ", " + press(panelToggleCenter(PanelToggle::Mirror)) +
            R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) {
            const int a = xr.findSculpture("a");
            selected = xr.selected() == a ? 0 : xr.selected();
            edits = xr.editCount(a);
            mirrored = xr.sculptures()[static_cast<std::size_t>(a)].mirror.has_value();
        });
    ASSERT_EQ(selected, 0);
    ASSERT_EQ(edits, 1u) << "carved through the panel's carve button";
    EXPECT_TRUE(mirrored) << "the mirror plane ticked on the panel";

    // Run 2, the session reopened: select 'a' again and discard its edits.
    std::unique_ptr<voxel::Volume> after;
    bool redone = true;
    std::string lastAction;
    run("[" + press(panelPageCenter(PanelPage::Sculpture)) + ", " + press(panelActionCenter(PanelAction::NextSculpture)) + ", " +
            press(panelActionCenter(PanelAction::DiscardEdits)) + R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) {
            const int a = xr.findSculpture("a");
            edits = xr.editCount(a);
            redone = xr.redo();
            if (!xr.history().empty()) lastAction = xr.history().back().action;
            after = std::make_unique<voxel::Volume>(xr.sculptures()[static_cast<std::size_t>(a)].volume->clone());
        });
    EXPECT_EQ(edits, 0u) << "discarded on the panel";
    EXPECT_FALSE(redone) << "a new action: nothing to redo";
    EXPECT_EQ(lastAction, "discard") << "one action in the history, undoable as on the desktop";
    // The grid is the unedited sculpture's, and the discard is journalled.
    garden::OpenedSession fresh = garden::openSession({(dir / "fresh").string(), gardenFile}, {});
    ASSERT_TRUE(fresh.error.empty()) << fresh.error;
    const int freshA = fresh.session->findSculpture("a");
    ASSERT_TRUE(after);
    EXPECT_EQ(garden::test::differingVoxels(*after, *fresh.session->sculptures()[static_cast<std::size_t>(freshA)].volume), 0);
    garden::OpenedSession reopened = garden::openSession({options.session, gardenFile}, {});
    ASSERT_TRUE(reopened.error.empty()) << reopened.error;
    EXPECT_EQ(reopened.session->editCount(reopened.session->findSculpture("a")), 0u);
}


TEST_F(HandPanelPages, TurningChosenOnTheSettingsPageIsKeptAndTurnsTheNextRun) {
    float startYaw = 0.0f;
    // Run 1: the settings page, a 90-degree snap, the seated height at 0.8 m.
    run("[" + press(panelPageCenter(PanelPage::Settings)) + ", " + press(panelChoiceCenter(PanelChoice::SnapAngle, 3)) + ", " +
            press(panelSeatedOffsetPoint(0.8)) + R"(, {"frames": 2}])",
        [&](garden::GardenSession& xr) { startYaw = xr.navigator().yaw(); });
    std::string warning;
    XrUserSettings kept = loadXrSettings(options.settingsFile, warning);
    EXPECT_EQ(warning, "");
    EXPECT_EQ(kept.snapDegrees, 90);
    EXPECT_FALSE(kept.smoothTurn);
    EXPECT_NEAR(kept.seatedHeightOffset, 0.8, 0.02);

    // Run 2, no flags: one push of the stick turns a quarter.
    const std::string push = R"([{"frames": 18, "navigation": {"aim": {"position": [-0.2, 1.0, -0.4]}, "thumbstick": [1, 0]}},
                                 {"frames": 2}])";
    float yaw = 0.0f;
    run(push, [&](garden::GardenSession& xr) { yaw = xr.navigator().yaw(); });
    EXPECT_NEAR(turnedDegrees(startYaw, yaw), 90.0f, 1e-3f) << "one snap of the kept angle";

    // Run 3: smooth turning ticked.
    run("[" + press(panelPageCenter(PanelPage::Settings)) + ", " + press(panelToggleCenter(PanelToggle::SmoothTurn)) +
        R"(, {"frames": 2}])");
    kept = loadXrSettings(options.settingsFile, warning);
    EXPECT_TRUE(kept.smoothTurn);
    EXPECT_EQ(kept.snapDegrees, 90) << "the other settings kept";

    // Run 4, no flags: the same push turns smoothly, 90 degrees a second at
    // full tilt for 18 frames of 1/90 s: about 18 degrees, not a snap.
    run(push, [&](garden::GardenSession& xr) { yaw = xr.navigator().yaw(); });
    const float turned = turnedDegrees(startYaw, yaw);
    EXPECT_GT(turned, 10.0f);
    EXPECT_LT(turned, 25.0f);

    // Run 5: the flag --smooth-turn over a file that says snap: smooth for
    // its run, the file left as it was.
    XrUserSettings snap = kept;
    snap.smoothTurn = false;
    ASSERT_EQ(saveXrSettings(options.settingsFile, snap), "");
    options.smoothTurn = true;
    run(push, [&](garden::GardenSession& xr) { yaw = xr.navigator().yaw(); });
    EXPECT_LT(turnedDegrees(startYaw, yaw), 25.0f) << "smooth, not a 90-degree snap";
    EXPECT_FALSE(loadXrSettings(options.settingsFile, warning).smoothTurn);
}

}  // namespace
}  // namespace hg::xr::test
