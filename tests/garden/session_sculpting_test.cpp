// Sculpting in the running garden (garden/app/session_sculpting.cpp and the
// replay's sculpting commands): the tool hand carves where its ray meets a
// sculpture, each edit changes the grid within the frame, undo and redo on
// the hand's buttons restore it exactly, and bad input changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/quaternion.hpp>

#include "garden/app/garden_session.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionSculptingTest : public test::SmallGarden {};


void frame(GardenSession& s, const Hands& h) {
    s.frame(FrameInput(h, 1.0 / 90.0));
}

TEST_F(SessionSculptingTest, TheToolHandCarvesAndItsButtonsUndoAndRedoExactly) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int c = s.findSculpture("c");  // a ball of radius 0.6 about (2, 0.5, 1.1547)
    const voxel::Volume original = s.sculptures()[static_cast<std::size_t>(c)].volume->clone();
    s.tool().kind = ToolSettings::Kind::Carve;
    s.tool().radius = 0.1;
    Hands h;
    h.tool.tracked = true;
    h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    const auto hit = s.toolHit(Pose{glm::vec3(2.0f, 0.5f, 4.0f), h.tool.aim.orientation});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->first, c);
    EXPECT_NEAR(hit->second.z, 1.1547f + 0.6f, 0.05f);
    h.tool.trigger = 1.0f;
    for (int f = 0; f < 6; ++f) {
        h.tool.aim.position = glm::vec3(1.85f + 0.05f * static_cast<float>(f), 0.5f, 4.0f);
        frame(s, h);
    }
    h.tool.trigger = 0.0f;
    frame(s, h);
    ASSERT_EQ(s.editCount(c), 1u);
    Sculpture& st = s.sculptures()[static_cast<std::size_t>(c)];
    EXPECT_GT(test::differingVoxels(*st.volume, original), 100);
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    // Where the ray met the surface is now outside, and the morph did not move.
    const voxel::VolumeFrame& fr = st.volume->frame;
    const int i = fr.indexOf(0, 0.0), j = fr.indexOf(1, 0.5), k = fr.indexOf(2, 0.55);
    EXPECT_GT(original.value(i, j, k), 0.0f);
    EXPECT_LT(st.volume->value(i, j, k), 0.0f);
    const voxel::Volume carved = st.volume->clone();
    // Undo on the tool hand's button: the grid of a session that never carved.
    h.tool.buttons = kButtonUndo;
    frame(s, h);
    h.tool.buttons = 0;
    frame(s, h);
    EXPECT_EQ(s.editCount(c), 0u);
    EXPECT_EQ(test::differingVoxels(*st.volume, original), 0);
    h.tool.buttons = kButtonRedo;
    frame(s, h);
    EXPECT_EQ(test::differingVoxels(*st.volume, carved), 0);
    // The carved chunks were remeshed.
    for (int f = 0; f < 200 && !s.idle(); ++f) frame(s, Hands{});
    EXPECT_TRUE(s.idle());
}

// A replay's "action" command is a journal's action, word for word: a
// journalled session's actions pasted into a script rebuild its grids.
TEST_F(SessionSculptingTest, ReplayActionCommandsAreTheJournalsActions) {
    const std::string garden = writeGarden();
    GardenSession s(loadGarden(garden), test::smallSessionSettings());
    test::ActionList journal;
    s.setJournal(&journal);
    const int b = s.findSculpture("b");
    ASSERT_EQ(s.applyStroke(b, StrokeTool::Carve, {{-2.1, 0.8, 1.0}, {-1.9, 0.7, 1.2}}, 0.08), "");
    ASSERT_EQ(s.applyPerturbation(b, QuadricShape::Torus, {-2.0, 0.9, 1.15}, {0.15, 0.05, 0.0}, 2.0), "");
    ASSERT_TRUE(s.undo());
    std::string commands;
    for (const Action& a : journal.actions) commands += std::string(commands.empty() ? "" : ", ") + "{\"action\": " + actionJson(a) + "}";
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [)" + commands +
                                                      R"(]}, {"until_idle": true, "frames": 2000}]})",
                                                  "actions.json", "");
    GardenSession played(loadGarden(garden), test::smallSessionSettings());
    const ReplayResult r = runReplay(script, played, nullptr, {});
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(played.editCount(b), 1u);
    EXPECT_EQ(test::differingVoxels(*s.sculptures()[static_cast<std::size_t>(b)].volume,
                                    *played.sculptures()[static_cast<std::size_t>(b)].volume),
              0);
    // A bad action is reported at its JSON path.
    try {
        parseReplayScript(R"({"garden": "g.json", "steps": [{"commands": [
            {"action": {"action": "stroke", "sculpture": "b", "tool": "chisel", "radius": 0.1, "path": [[0, 0, 0]]}}]}]})",
                          "bad.json", "");
        ADD_FAILURE() << "an unknown tool was read";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.steps[0].commands[0].action.tool");
    }
}

TEST_F(SessionSculptingTest, ReplayCommandsSculptUndoAndRedo) {
    const std::string garden = writeGarden();
    const ReplayScript script = parseReplayScript(R"({
      "garden": ")" + garden + R"(",
      "steps": [
        {"commands": [{"stroke": {"sculpture": "a", "tool": "carve", "radius": 0.08,
                                  "path": [[-0.3, 0.6, -1.8], [0.3, 0.6, -1.8]]}}]},
        {"commands": [{"stroke": {"sculpture": "a", "tool": "melt", "radius": 0.1, "softness": 2,
                                  "path": [[0, 0.9, -2.3], [0, 0.95, -2.0]]}}]},
        {"commands": [{"perturb": {"sculpture": "b", "shape": "torus", "center": [-2, 0.9, 1.15],
                                   "radii": [0.15, 0.05, 0], "strength": 2}}]},
        {"commands": [{"stroke": {"sculpture": "c", "tool": "add", "radius": 0.1,
                                  "path": [[2.6, 0.5, 1.15], [2.8, 0.6, 1.15]]}}]},
        {"commands": [{"undo": 2}]},
        {"commands": [{"redo": 1}]},
        {"until_idle": true, "frames": 2000}
      ]})", "sculpt.json", "");
    GardenSession s(loadGarden(garden), test::smallSessionSettings());
    const ReplayResult r = runReplay(script, s, nullptr, {});
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(s.editCount(s.findSculpture("a")), 2u);
    EXPECT_EQ(s.editCount(s.findSculpture("b")), 1u);
    EXPECT_EQ(s.editCount(s.findSculpture("c")), 0u);  // undone, not redone
    for (const char* name : {"a", "b"}) {
        const Sculpture& st = s.sculptures()[static_cast<std::size_t>(s.findSculpture(name))];
        EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0) << name;
    }
}

TEST_F(SessionSculptingTest, EditsOnTheMorphResultPersistWhenTheWeightsChangeAndCanBeDiscarded) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int m = s.findSculpture("metamorphosis");
    for (int f = 0; f < 2000 && !s.idle(); ++f) frame(s, Hands{});
    const glm::vec3 c = s.sculptures()[static_cast<std::size_t>(m)].worldCentre();
    ASSERT_EQ(s.applyStroke(m, StrokeTool::Carve, {{c.x - 0.4, c.y + 0.1, c.z}, {c.x + 0.4, c.y + 0.1, c.z}}, 0.12), "");
    ASSERT_EQ(s.applyPerturbation(m, QuadricShape::Ellipsoid, {c.x, c.y + 0.5, c.z}, {0.2, 0.1, 0.2}, 3.0), "");
    s.setMorphWeights({0.6, 0.2, 0.2});
    for (int f = 0; f < 4000 && !s.idle(); ++f) frame(s, Hands{});
    ASSERT_TRUE(s.idle());
    const Sculpture& r = s.sculptures()[static_cast<std::size_t>(m)];
    EXPECT_EQ(s.editCount(m), 2u);
    // The unedited grid is the new blend; the shown grid is that blend with the edits.
    const auto blend = s.blendFromScratch();
    EXPECT_EQ(test::differingVoxels(r.edits->base(), *blend), 0);
    EXPECT_EQ(test::differingVoxels(*r.volume, *r.edits->rebuild()), 0);
    EXPECT_GT(test::differingVoxels(*r.volume, *blend), 100);
    const voxel::Volume edited = r.volume->clone();
    s.discardEdits(m);
    EXPECT_EQ(s.editCount(m), 0u);
    EXPECT_FALSE(s.redo());
    EXPECT_EQ(test::differingVoxels(*r.volume, *blend), 0);
    // And undo brings the edits back over the blend.
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.editCount(m), 2u);
    EXPECT_EQ(test::differingVoxels(*r.volume, edited), 0);
}

// Every action goes through apply() and is journalled in the model frame;
// playing the journal in a fresh session rebuilds every grid bit for bit,
// a mirrored stroke included (it used to come back unmirrored).
TEST_F(SessionSculptingTest, ActionsPlayedFromTheJournalRebuildEveryGridExactly) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    test::ActionList journal;
    s.setJournal(&journal);
    const int c = s.findSculpture("c");
    const int a = s.findSculpture("a");
    s.setMirror(c, MirrorPlane{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    s.setMirror(c, std::nullopt);
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 0.3, 1.7}, {0.1, 0.08, 0.1}, 2.5), "");
    ImpactTool t;
    t.size = 0.05;
    t.volume = 8e-6;
    t.count = 3;
    ASSERT_EQ(s.applyImpacts(c, {2.0, 0.5, 4.0}, {0.0, 0.0, -1.0}, t), "");
    ASSERT_EQ(s.reapplyImpacts(c, a), "");
    const auto picked = s.pickPerturbation(c, {2.0, 0.3, 1.7});
    ASSERT_TRUE(picked);
    ASSERT_EQ(s.editPerturbation(c, *picked, -1.5, {0.12, 0.1, 0.12}), "");
    ASSERT_TRUE(s.undo());
    ASSERT_TRUE(s.redo());
    ASSERT_EQ(journal.actions.size(), 7u);
    EXPECT_TRUE(std::get<StrokeAction>(journal.actions[0]).mirror) << "the stroke's mirror plane is in its action";

    GardenSession again(loadGarden(writeGarden()), test::smallSessionSettings());
    ASSERT_EQ(again.restore(journal.actions), "");
    for (const int i : {a, c}) {
        const auto& mine = *s.sculptures()[static_cast<std::size_t>(i)].volume;
        const auto& played = *again.sculptures()[static_cast<std::size_t>(i)].volume;
        EXPECT_EQ(test::differingVoxels(mine, played), 0) << s.sculptures()[static_cast<std::size_t>(i)].name;
    }
    // The same actions applied one by one (what a replay's "action" does).
    GardenSession third(loadGarden(writeGarden()), test::smallSessionSettings());
    for (const Action& act : journal.actions) ASSERT_EQ(third.apply(act), "") << actionKind(act);
    EXPECT_EQ(test::differingVoxels(*s.sculptures()[static_cast<std::size_t>(c)].volume,
                                    *third.sculptures()[static_cast<std::size_t>(c)].volume),
              0);
    // An action naming no sculpture is refused and changes nothing.
    EXPECT_EQ(third.apply(DiscardAction{"nobody"}), "no sculpture named 'nobody'");
    EXPECT_EQ(third.editCount(c), 3u);
}

TEST_F(SessionSculptingTest, AMirrorPlaneAppliesEachStrokeOnBothSides) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int c = s.findSculpture("c");  // a ball about the model's x = 0 plane, on a lattice symmetric about it
    s.setMirror(c, MirrorPlane{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}});  // normalized on the way in
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.5, 0.3, 1.0}, {0.1, 0.08, 0.1}, 2.5), "");
    const voxel::Volume& v = *s.sculptures()[static_cast<std::size_t>(c)].volume;
    const voxel::IndexBox& b = v.frame.indexBox;
    ASSERT_EQ(b.lo[0] + b.hi[0], 2 * v.frame.indexOf(0, 0.0));
    double worst = 0.0;
    int changed = 0;
    const auto& base = s.sculptures()[static_cast<std::size_t>(c)].edits->base();
    for (int k = b.lo[2]; k <= b.hi[2]; ++k)
        for (int j = b.lo[1]; j <= b.hi[1]; ++j)
            for (int i = b.lo[0]; i <= b.hi[0]; ++i) {
                worst = std::max(worst, static_cast<double>(std::fabs(v.value(i, j, k) - v.value(b.lo[0] + b.hi[0] - i, j, k))));
                changed += v.value(i, j, k) != base.value(i, j, k);
            }
    EXPECT_LT(worst, 1e-3);  // symmetric up to the rounding of mirrored positions
    EXPECT_GT(changed, 200);
    EXPECT_EQ(s.editCount(c), 2u);  // each one edit, undone as one
    ASSERT_TRUE(s.undo());
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(v, base), 0);
}

TEST_F(SessionSculptingTest, MovesAreUndoneAndRedoneAndTheirScaleIsChecked) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int a = s.findSculpture("a");
    const Placement before = s.sculptures()[static_cast<std::size_t>(a)].placement;
    Placement p = before;
    p.position = {0.5, 0.0, -3.0};
    p.yawDegrees = 45.0;
    p.scale = 2.0;
    ASSERT_EQ(s.moveSculpture(a, p), "");
    const Sculpture& sa = s.sculptures()[static_cast<std::size_t>(a)];
    EXPECT_EQ(sa.scale(), 2.0);
    const glm::vec3 centre = sa.worldCentre();
    EXPECT_NEAR(centre.y, 1.0f, 1e-4f);  // the ball's model centre (0, 0.5, 0) doubled
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(sa.placement.position, before.position);
    EXPECT_EQ(sa.scale(), before.scale);
    ASSERT_TRUE(s.redo());
    EXPECT_EQ(sa.placement.yawDegrees, 45.0);
    Placement bad = p;
    bad.scale = -1.0;
    EXPECT_NE(s.moveSculpture(a, bad), "");
    bad.scale = 1.0;
    bad.position[1] = std::numeric_limits<double>::infinity();
    EXPECT_NE(s.moveSculpture(a, bad), "");
    EXPECT_EQ(sa.placement.scale, 2.0);
}

// The solid's volume: each voxel counts the part of it inside, read from
// the stored field (about one unit per voxel across the surface).
double solidVolume(const voxel::Volume& v) {
    const voxel::IndexBox& b = v.frame.indexBox;
    double n = 0.0;
    for (int k = b.lo[2]; k <= b.hi[2]; ++k)
        for (int j = b.lo[1]; j <= b.hi[1]; ++j)
            for (int i = b.lo[0]; i <= b.hi[0]; ++i) n += std::clamp(0.5 + static_cast<double>(v.value(i, j, k)), 0.0, 1.0);
    return n * v.frame.voxelSize * v.frame.voxelSize * v.frame.voxelSize;
}

TEST_F(SessionSculptingTest, ImpactsRemoveTheirCompactionVolumeAndFireAgainAtAnotherSculpture) {
    // Finer balls, so that a few cubic centimetres are many voxels.
    GardenSession s(loadGarden(writeGarden(nlohmann::json::parse(
                        R"({"sculptures": [{"name": "a", "file": "ball.hf", "a": [0.25], "resolution": 96,
                              "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}, "placement": {"position": [0, 0, -2.3094]}},
                            {"name": "c", "file": "ball.hf", "a": [0.36], "resolution": 96,
                              "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}, "placement": {"position": [2, 0, 1.1547]}}],
                            "morph": null})"))),
                    test::smallSessionSettings());
    const int c = s.findSculpture("c");
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(c)];
    const double before = solidVolume(*sc.volume);
    ImpactTool t;
    t.shape = ImpactShape::Sphere;
    t.size = 0.04;
    t.volume = 8e-6;  // 8 cm^3 each
    t.count = 12;
    t.spreadSize = 0.25;
    t.seed = 7;
    // From above the ball (radius 0.6 about (2, 0.5, 1.1547)), straight down.
    ASSERT_EQ(s.applyImpacts(c, {2.0, 2.0, 1.1547}, {0.0, -1.0, 0.0}, t), "");
    ASSERT_EQ(s.editCount(c), 1u);
    const auto& series = std::get<ImpactSeries>(sc.edits->list().edits()[0].op);
    EXPECT_EQ(series.impacts.size(), 12u);
    const double removed = before - solidVolume(*sc.volume);
    // Twelve dents of 8 cm^3 on a gently curved top, overlapping a little.
    EXPECT_GT(removed, 0.5 * 12 * 8e-6);
    EXPECT_LT(removed, 1.5 * 12 * 8e-6);
    EXPECT_EQ(test::differingVoxels(*sc.volume, *sc.edits->rebuild()), 0);
    // The same rays fired at the other ball.
    const int a = s.findSculpture("a");
    ASSERT_EQ(s.reapplyImpacts(c, a), "");
    const auto& again = std::get<ImpactSeries>(s.sculptures()[static_cast<std::size_t>(a)].edits->list().edits()[0].op);
    EXPECT_GT(again.impacts.size(), 6u);
    EXPECT_EQ(again.rayOrigins, series.rayOrigins);
    // One undo takes the whole series away.
    ASSERT_TRUE(s.undo());
    ASSERT_TRUE(s.undo());
    EXPECT_NEAR(solidVolume(*sc.volume), before, 1e-12);
    EXPECT_NE(s.applyImpacts(c, {2.0, 5.0, 9.0}, {0.0, 1.0, 0.0}, t), "");  // pointing away: nothing met
}

TEST_F(SessionSculptingTest, APickedPerturbationIsReplacedNotStacked) {
    const std::string garden = writeGarden();
    GardenSession s(loadGarden(garden), test::smallSessionSettings());
    const int c = s.findSculpture("c");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 1.1, 1.15}, {0.15, 0.1, 0.15}, 2.0), "");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{2.5, 0.5, 1.5}, {2.5, 0.7, 1.5}}, 0.08), "");
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(c)];
    const voxel::Volume first = sc.volume->clone();
    EXPECT_FALSE(s.pickPerturbation(c, {2.5, 0.5, 1.5}));  // under the stroke, no bump
    const auto picked = s.pickPerturbation(c, {2.0, 1.12, 1.15});
    ASSERT_TRUE(picked);
    EXPECT_EQ(*picked, 0u);
    ASSERT_EQ(s.editPerturbation(c, *picked, -3.0, {0.2, 0.12, 0.2}), "");
    EXPECT_EQ(s.editCount(c), 2u);
    EXPECT_EQ(test::differingVoxels(*sc.volume, *sc.edits->rebuild()), 0);
    // The same as a session that made the changed bump in the first place.
    GardenSession other(loadGarden(garden), test::smallSessionSettings());
    ASSERT_EQ(other.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 1.1, 1.15}, {0.2, 0.12, 0.2}, -3.0), "");
    ASSERT_EQ(other.applyStroke(c, StrokeTool::Carve, {{2.5, 0.5, 1.5}, {2.5, 0.7, 1.5}}, 0.08), "");
    EXPECT_EQ(test::differingVoxels(*sc.volume, *other.sculptures()[static_cast<std::size_t>(c)].volume), 0);
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(*sc.volume, first), 0);
    ASSERT_TRUE(s.redo());
    EXPECT_EQ(test::differingVoxels(*sc.volume, *other.sculptures()[static_cast<std::size_t>(c)].volume), 0);
    EXPECT_NE(s.editPerturbation(c, 1, 1.0, {0.1, 0.1, 0.1}), "");  // edit 1 is the stroke
}

TEST_F(SessionSculptingTest, BadInputIsRefusedAndChangesNothing) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const int a = s.findSculpture("a");
    const voxel::Volume original = s.sculptures()[static_cast<std::size_t>(a)].volume->clone();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(s.applyStroke(a, StrokeTool::Carve, {{0, 0.5, -2.3}}, -0.1), "");
    EXPECT_NE(s.applyStroke(a, StrokeTool::Carve, {{0, 0.5, -2.3}}, 1e-6), "");  // under half a voxel
    EXPECT_NE(s.applyStroke(a, StrokeTool::Carve, {{nan, 0.5, -2.3}}, 0.1), "");
    EXPECT_NE(s.applyPerturbation(a, QuadricShape::Torus, {0, 0.5, -2.3}, {0.05, 0.1, 0.0}, 2.0), "");
    EXPECT_NE(s.applyPerturbation(a, QuadricShape::Ellipsoid, {0, 0.5, -2.3}, {0.05, 0.1, 0.1}, nan), "");
    EXPECT_NE(s.applyStroke(s.findSculpture("lost"), StrokeTool::Carve, {{6, 0.5, 6}}, 0.1).find("missing"),
              std::string::npos);
    EXPECT_FALSE(s.undo());
    EXPECT_EQ(s.editCount(a), 0u);
    EXPECT_EQ(test::differingVoxels(*s.sculptures()[static_cast<std::size_t>(a)].volume, original), 0);

    // A replay stops at a bad command with its JSON path.
    try {
        parseReplayScript(R"({"garden": "g.json", "steps": [{"commands": [
            {"stroke": {"sculpture": "a", "tool": "chisel", "radius": 0.1, "path": [[0, 0, 0]]}}]}]})",
                          "bad.json", "");
        ADD_FAILURE() << "an unknown tool was read";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.steps[0].commands[0].stroke.tool");
    }
    const std::string garden = writeGarden();
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [
        {"stroke": {"sculpture": "nobody", "tool": "carve", "radius": 0.1, "path": [[0, 0, 0]]}}]}]})",
                                                  "bad.json", "");
    GardenSession s2(loadGarden(garden), test::smallSessionSettings());
    const ReplayResult r = runReplay(script, s2, nullptr, {});
    EXPECT_NE(r.error.find("$.steps[0].commands[0]: no sculpture named 'nobody'"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace hg::garden
