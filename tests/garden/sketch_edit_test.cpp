// Sketches as edits (garden/sculpt/sketch_edit.h, the SketchAction): an
// outline drawn on a plane is inflated and joined to a sculpture or cut
// from it, within the call, bounded and exactly local (the grid equals a
// rebuild from every edit), undone and redone exactly, mirrored, refused
// with a message when degenerate, journalled and replayed.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include "garden/app/garden_session.h"
#include "garden/export/part_export.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/sketch_edit.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SketchEditTest : public test::SmallGarden {};

// A circle of `r` metres about `centre` in the plane normal to `normal`
// (one of the axes), drawn as `n` points.
std::vector<std::array<double, 3>> circle(const std::array<double, 3>& centre, double r, int axis, int n = 40) {
    std::vector<std::array<double, 3>> out;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * 3.14159265358979323846 * i / n;
        std::array<double, 3> p = centre;
        p[static_cast<std::size_t>(a)] += r * std::cos(t);
        p[static_cast<std::size_t>(b)] += r * std::sin(t);
        out.push_back(p);
    }
    return out;
}

const voxel::Volume& grid(const GardenSession& s, int i) { return *s.sculptures()[static_cast<std::size_t>(i)].volume; }

TEST_F(SketchEditTest, ACircleJoinedAndAnotherCutChangeTheGridExactlyAndUndo) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int c = s.findSculpture("c");  // a ball of radius 0.6 about (2, 0.5, 1.1547)
    const voxel::Volume original = grid(s, c).clone();
    // Towards a corner of the box: a ball of 0.1 m about (0.4, 0.5, 0.4),
    // half out of the surface.
    ASSERT_EQ(s.applySketch(c, SketchMode::Add, circle({2.4, 0.5, 1.5547}, 0.1, 2), {0, 0, 1}), "");
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(c)];
    EXPECT_EQ(s.editCount(c), 1u);
    // Inside the new ball, beyond the old surface: now inside.
    const voxel::Volume& v = grid(s, c);
    const auto inside = [&](double wx, double wy, double wz) {
        const auto m = glm::inverse(sc.modelToWorld()) * glm::vec4(wx, wy, wz, 1.0f);
        return v.value(v.frame.indexOf(0, m.x), v.frame.indexOf(1, m.y), v.frame.indexOf(2, m.z)) > 0.0f;
    };
    EXPECT_FALSE(original.value(original.frame.indexOf(0, 0.45), original.frame.indexOf(1, 0.5),
                                original.frame.indexOf(2, 0.45)) > 0.0f);
    EXPECT_TRUE(inside(2.45, 0.5, 1.1547 + 0.45));
    EXPECT_FALSE(inside(2.55, 0.5, 1.1547 + 0.5));
    EXPECT_EQ(test::differingVoxels(v, *sc.edits->rebuild()), 0) << "the box update is the whole rebuild";
    // On the top: a ball of 0.2 m cut.
    ASSERT_EQ(s.applySketch(c, SketchMode::Cut, circle({2.0, 1.1, 1.1547}, 0.2, 1), {0, 1, 0}), "");
    EXPECT_FALSE(inside(2.0, 1.0, 1.1547));
    EXPECT_TRUE(inside(2.0, 0.5, 1.1547));
    EXPECT_EQ(test::differingVoxels(v, *sc.edits->rebuild()), 0);
    const voxel::Volume both = v.clone();
    ASSERT_TRUE(s.undo());
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(v, original), 0) << "undone exactly";
    ASSERT_TRUE(s.redo());
    ASSERT_TRUE(s.redo());
    EXPECT_EQ(test::differingVoxels(v, both), 0) << "redone exactly";
}

TEST_F(SketchEditTest, AMirroredSketchActsOnBothSides) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int c = s.findSculpture("c");
    s.setMirror(c, MirrorPlane{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    ASSERT_EQ(s.applySketch(c, SketchMode::Cut, circle({2.4, 0.5, 1.4547}, 0.12, 2), {0, 0, 1}), "");
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(c)];
    const auto& k = std::get<SketchSolid>(sc.edits->list().edits().back().op);
    EXPECT_EQ(k.reach.size(), 2 * k.solid.pieces.size());
    const voxel::Volume& v = grid(s, c);
    const auto at = [&](double mx, double my, double mz) {
        return v.value(v.frame.indexOf(0, mx), v.frame.indexOf(1, my), v.frame.indexOf(2, mz));
    };
    EXPECT_LT(at(0.4, 0.5, 0.3), 0.0f) << "cut where drawn";
    EXPECT_LT(at(-0.4, 0.5, 0.3), 0.0f) << "and in the mirror";
    EXPECT_GT(at(0.0, 0.5, 0.3), 0.0f) << "not between";
    EXPECT_EQ(test::differingVoxels(v, *sc.edits->rebuild()), 0);
}

TEST_F(SketchEditTest, DegenerateSketchesAreRefusedAndChangeNothing) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int c = s.findSculpture("c");
    EXPECT_NE(s.applySketch(c, SketchMode::Add, {{2.0, 0.5, 1.7}, {2.1, 0.5, 1.7}}, {0, 0, 1}), "");
    // A line drawn back and forth has no area.
    const std::string flat =
        s.applySketch(c, SketchMode::Add, {{1.8, 0.5, 1.7}, {2.0, 0.5, 1.7}, {2.2, 0.5, 1.7}, {2.0, 0.5, 1.7}, {1.8, 0.5, 1.7}},
                      {0, 0, 1});
    EXPECT_NE(flat, "");
    EXPECT_EQ(s.applySketch(c, SketchMode::Add, circle({2.0, 0.5, 1.6547}, 0.15, 2), {0, 0, 0}),
              "the sketch's plane has no normal");
    // A figure eight.
    std::vector<std::array<double, 3>> eight;
    for (int i = 0; i < 80; ++i) {
        const double t = 2.0 * 3.14159265358979323846 * i / 80;
        eight.push_back({2.0 + 0.3 * std::sin(t), 0.5 + 0.15 * std::sin(2.0 * t), 1.7});
    }
    EXPECT_NE(s.applySketch(c, SketchMode::Add, eight, {0, 0, 1}), "");
    EXPECT_EQ(s.editCount(c), 0u);
}

TEST_F(SketchEditTest, ASketchIsJournalledAndAReplayCommandDrawsIt) {
    const std::string garden = writeGarden();
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [
        {"sketch": {"sculpture": "c", "mode": "add", "normal": [0, 0, 1],
                    "points": [[2.15, 0.5, 1.65], [2.0, 0.65, 1.65], [1.85, 0.5, 1.65], [2.0, 0.35, 1.65]]}},
        {"sketch": {"sculpture": "c", "mode": "cut", "normal": [0, 1, 0], "thickness": 0.5,
                    "points": [[1.8, 1.1, 1.0], [2.2, 1.1, 1.0], [2.2, 1.1, 1.3], [1.8, 1.1, 1.3]]}}]},
        {"until_idle": true, "frames": 2000}]})",
                                                  "sketch.json", "");
    GardenSession s(loadGarden(garden), test::smallSessionSettings());
    test::ActionList journal;
    s.setJournal(&journal);
    const ReplayResult r = runReplay(script, s, nullptr, {});
    ASSERT_EQ(r.error, "");
    const int c = s.findSculpture("c");
    EXPECT_EQ(s.editCount(c), 2u);
    ASSERT_EQ(journal.actions.size(), 2u);
    const auto& cut = std::get<SketchAction>(journal.actions[1]);
    EXPECT_EQ(cut.mode, SketchMode::Cut);
    EXPECT_EQ(cut.thickness, 0.5);
    // Through the journal's text and back: the same grid, bit for bit.
    std::vector<Action> read;
    for (const Action& a : journal.actions) read.push_back(parseAction(actionJson(a), "journal"));
    GardenSession again(loadGarden(garden), test::smallSessionSettings());
    ASSERT_EQ(again.restore(read), "");
    EXPECT_EQ(test::differingVoxels(grid(s, c), grid(again, c)), 0);
    // A bad mode is refused at its JSON path.
    try {
        parseReplayScript(R"({"garden": "g.json", "steps": [{"commands": [{"sketch": {"sculpture": "c", "mode": "grow",
            "normal": [0, 0, 1], "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]}]})",
                          "bad.json", "");
        ADD_FAILURE() << "an unknown mode was read";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.steps[0].commands[0].sketch.mode");
    }
}

// The sketch tool: held on a sculpture, the hand's ray draws on the plane
// facing it; released, the outline is joined (reverse: cut), one action.
TEST_F(SketchEditTest, TheSketchToolDrawsWithTheToolHand) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    test::ActionList journal;
    s.setJournal(&journal);
    const int c = s.findSculpture("c");  // ball of 0.6 about (2, 0.5, 1.1547): its front at z 1.7547
    s.tool().kind = ToolSettings::Kind::Sketch;
    const glm::vec3 eye(2.0f, 0.5f, 4.0f);
    Hands h;
    h.tool.tracked = true;
    h.tool.aim.position = eye;
    const auto aimAt = [&](const glm::vec3& p) {
        h.tool.aim.orientation = glm::quatLookAt(glm::normalize(p - eye), glm::vec3(0, 1, 0));
    };
    const auto frame = [&] { s.frame(FrameInput(h, 1.0 / 90.0)); };
    // Pressed off every sculpture and let go at once: a sketch in the air
    // of one point, refused with the reason; nothing is made.
    const std::size_t count = s.sculptures().size();
    aimAt({0.0f, 3.0f, 0.0f});
    h.tool.trigger = 1.0f;
    frame();
    EXPECT_EQ(s.sketchPath().size(), 1u);
    h.tool.trigger = 0.0f;
    frame();
    EXPECT_NE(s.sketchMessage().find("3 points"), std::string::npos) << s.sketchMessage();
    EXPECT_TRUE(s.sketchPath().empty());
    EXPECT_EQ(s.sculptures().size(), count);
    // A circle of 0.15 m on the ball's front, drawn round once.
    const int n = 40;
    for (int i = 0; i <= n; ++i) {
        const float t = 2.0f * 3.14159265f * static_cast<float>(i) / n;
        aimAt({2.0f + 0.15f * std::cos(t), 0.5f + 0.15f * std::sin(t), 1.74f});
        h.tool.trigger = 1.0f;
        frame();
    }
    EXPECT_GT(s.sketchPath().size(), 30u) << "the outline so far, for the gizmo";
    EXPECT_EQ(s.editCount(c), 0u) << "nothing until the button is let go";
    h.tool.trigger = 0.0f;
    frame();
    EXPECT_EQ(s.sketchMessage(), "");
    EXPECT_TRUE(s.sketchPath().empty());
    ASSERT_EQ(s.editCount(c), 1u);
    ASSERT_EQ(journal.actions.size(), 1u);
    const auto& a = std::get<SketchAction>(journal.actions[0]);
    EXPECT_EQ(a.mode, SketchMode::Add);
    EXPECT_NEAR(a.normal[2], 1.0, 1e-2) << "the plane faces the hand";
    // Reversed: a cut.
    s.tool().reverse = true;
    for (int i = 0; i <= n; ++i) {
        const float t = 2.0f * 3.14159265f * static_cast<float>(i) / n;
        aimAt({2.2f + 0.1f * std::cos(t), 0.5f + 0.1f * std::sin(t), 1.7f});
        h.tool.trigger = 1.0f;
        frame();
    }
    h.tool.trigger = 0.0f;
    frame();
    ASSERT_EQ(journal.actions.size(), 2u);
    EXPECT_EQ(std::get<SketchAction>(journal.actions[1]).mode, SketchMode::Cut);
    EXPECT_EQ(s.editCount(c), 2u);
}

// content/replays/sketching_session.json (the README's sketching replay)
// plays on the default garden: a leaf and a ball joined to a column, a
// groove cut in its capital, the groove undone.
TEST(SketchingReplay, TheContentReplayPlays) {
    const ReplayScript script =
        loadReplayScript(std::string(HG_SOURCE_DIR) + "/content/replays/sketching_session.json");
    SessionSettings settings = test::smallSessionSettings();
    settings.sculptureResolution = 48;
    settings.morphResolution = 32;
    settings.remeshChunksPerFrame = 0;
    GardenSession s(loadGarden(script.garden), settings);
    ReplayOptions options;
    options.extractor = extractPart;
    const ReplayResult r = runReplay(script, s, nullptr, options);
    ASSERT_EQ(r.error, "");
    EXPECT_GE(s.findSculpture("pebble"), 0) << "a new sculpture drawn in the air";
    const int column = s.findSculpture("column east");
    ASSERT_GE(column, 0);
    EXPECT_EQ(s.editCount(column), 2u) << "two joined; the cut undone (redoable)";
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(column)];
    EXPECT_EQ(sc.edits->redoCount(), 1u);
    // The west column's capital selected with a shrunk model, and extracted.
    const int west = s.findSculpture("column west");
    ASSERT_TRUE(s.selectionOf(west));
    const int capital = s.findSculpture("capital");
    ASSERT_GE(capital, 0);
    const frep::Box3& box = s.sculptures()[static_cast<std::size_t>(capital)].volume->frame.modelBox;
    EXPECT_GT(box.lo[1], 0.6) << "the capital only, not the shaft below it";
    EXPECT_LT(box.hi[1], 1.3);
}

}  // namespace
}  // namespace hg::garden

namespace hg::garden {
namespace {

// Begun in the air, the outline lies on a plane 1.5 m along the ray and
// becomes a new sculpture there, selected, one journalled AddAction.
TEST_F(SketchEditTest, ASketchBegunInTheAirMakesANewSculpture) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    test::ActionList journal;
    s.setJournal(&journal);
    s.tool().kind = ToolSettings::Kind::Sketch;
    const glm::vec3 eye(0.0f, 1.5f, 8.0f);
    Hands h;
    h.tool.tracked = true;
    h.tool.aim.position = eye;
    const std::size_t count = s.sculptures().size();
    // A circle of 0.2 m about (0, 1.5, 6.5), seen from the eye.
    for (int i = 0; i <= 40; ++i) {
        const float t = 2.0f * 3.14159265f * static_cast<float>(i) / 40.0f;
        const glm::vec3 p(0.2f * std::cos(t), 1.5f + 0.2f * std::sin(t), 6.5f);
        h.tool.aim.orientation = glm::quatLookAt(glm::normalize(p - eye), glm::vec3(0, 1, 0));
        h.tool.trigger = 1.0f;
        s.frame(FrameInput(h, 1.0 / 90.0));
    }
    h.tool.trigger = 0.0f;
    s.frame(FrameInput(h, 1.0 / 90.0));
    ASSERT_EQ(s.sketchMessage(), "");
    ASSERT_EQ(s.sculptures().size(), count + 1);
    const int made = static_cast<int>(count);
    EXPECT_EQ(s.selected(), made);
    EXPECT_EQ(s.sculptures()[count].name, "sketch");
    ASSERT_EQ(journal.actions.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<AddAction>(journal.actions[0]));
    // It stands where it was drawn: the tool's ray through the circle's
    // centre meets it about 0.2 m before the plane.
    Pose aim;
    aim.position = eye;
    aim.orientation = glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    const auto hit = s.toolHit(aim);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->first, made);
    EXPECT_NEAR(hit->second.z, 6.7f, 0.03f);
    // Undo takes it away again.
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.findSculpture("sketch"), -1);
}

}  // namespace
}  // namespace hg::garden
