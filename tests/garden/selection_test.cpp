// Selections in a running garden (issue 22, garden/app/session_selection.cpp,
// docs/sketching.md "Selections"): a deformable model sketched around a
// sculpture shrinks onto it; its selection limits edits, bounded and exact
// (the grid equals a rebuild, undo restores it); extractPart makes the part
// a sculpture whose HyperFun is the source's inside the selection; a
// journal of models, deformations, selections, masked edits and an
// extraction plays back to the same meshes and grids; gestures switch the
// sketch tool's use and circling deforms the model.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "../gesture/gesture_shapes.h"
#include "frep/eval/model.h"
#include "garden/app/garden_session.h"
#include "garden/export/hyperfun_export.h"
#include "garden/export/part_export.h"
#include "garden/scene/model_file.h"
#include "garden/sculpt/edit_field.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

// Ball c: radius 0.6 about (2, 0.5, 1.1547) in the world, (0, 0.5, 0) in
// its model frame (one metre per unit).
constexpr double kCx = 2.0, kCy = 0.5, kCz = 1.1547;

// A circle of `r` metres about `centre` in the plane z = centre's z.
std::vector<std::array<double, 3>> circleZ(const std::array<double, 3>& centre, double r, int n = 48) {
    std::vector<std::array<double, 3>> out;
    for (int i = 0; i < n; ++i) {
        const double t = 2.0 * 3.14159265358979323846 * i / n;
        out.push_back({centre[0] + r * std::cos(t), centre[1] + r * std::sin(t), centre[2]});
    }
    return out;
}

class SelectionTest : public test::SmallGarden {
protected:
    void SetUp() override {
        SmallGarden::SetUp();
        session = std::make_unique<GardenSession>(loadGarden(writeGarden()), test::smallSessionSettings());
        session->setJournal(&journal);
        c = session->findSculpture("c");
    }
    // A model named `name` sketched around c as a circle of `r` about `centre`.
    std::string model(const std::string& name, const std::array<double, 3>& centre, double r) {
        const auto a = session->modelFromWorld(c, name, circleZ(centre, r), {0, 0, 1});
        return a.action ? session->apply(*a.action) : a.why;
    }
    double valueAt(const frep::Model& m, double x, double y, double z) {
        frep::PointSampler<double> sampler(m);
        frep::ErrorReport errors;
        double out = 0.0;
        sampler.evaluate(&x, &y, &z, &out, 1, errors);
        return out;
    }
    const voxel::Volume& grid(int i) const { return *session->sculptures()[static_cast<std::size_t>(i)].volume; }
    const GardenSession::ModelView& view(const std::string& name) {
        views = session->models();
        for (const auto& v : views)
            if (v.name == name) return v;
        throw std::runtime_error("no model " + name);
    }
    test::ActionList journal;
    std::unique_ptr<GardenSession> session;
    std::vector<GardenSession::ModelView> views;
    int c = -1;
};

TEST_F(SelectionTest, AModelSketchedAroundABallShrinksOntoItAndSelectsIt) {
    ASSERT_EQ(model("wrap", {kCx, kCy, kCz}, 0.9), "");
    EXPECT_EQ(session->activeModel(), "wrap");
    EXPECT_FALSE(session->selectionOf(c)) << "a model selects nothing until it is deformed or chosen";
    ASSERT_EQ(session->deformModel("wrap", true, 200), "");
    const double voxel = grid(c).frame.voxelSize;
    const auto& m = view("wrap");
    ASSERT_GT(m.vertices->size(), 50u);
    double worst = 0.0;
    for (const glm::dvec3& v : *m.vertices) worst = std::max(worst, std::fabs(glm::length(v - glm::dvec3(0, 0.5, 0)) - 0.6));
    EXPECT_LT(worst, 1.5 * voxel) << "every vertex ends on the ball";
    const auto& sel = session->selectionOf(c);
    ASSERT_TRUE(sel);
    EXPECT_EQ(session->sculptures()[static_cast<std::size_t>(c)].selectionModel, "wrap");
    FieldUnits u = unitsOf(grid(c));
    EXPECT_DOUBLE_EQ(maskWeight(0.0, 0.5, 0.0, *sel, u), 1.0) << "the centre is selected";
    EXPECT_DOUBLE_EQ(maskWeight(0.0, 0.5, 0.9, *sel, u), 0.0) << "beyond the ball is not";
    EXPECT_EQ(session->deformModel("nope", true, 3), "no model named 'nope'");
}

TEST_F(SelectionTest, EditsActOnlyInsideTheSelectionExactlyAndUndo) {
    // A model of 0.25 m about the ball's top, chosen as it is (not deformed).
    ASSERT_EQ(model("cap", {kCx, kCy + 0.6, kCz}, 0.25), "");
    ASSERT_EQ(session->selectWithModel("c", "cap"), "");
    // A copy: the selection is cleared below, and the test goes on using it.
    const std::optional<SelectionMask> sel = session->selectionOf(c);
    ASSERT_TRUE(sel);
    const voxel::Volume before = grid(c).clone();
    // A carve straight across the ball's top, far wider than the cap.
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{kCx - 0.7, kCy + 0.55, kCz}, {kCx + 0.7, kCy + 0.55, kCz}}, 0.12),
              "");
    const voxel::Volume& after = grid(c);
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(c)];
    EXPECT_EQ(test::differingVoxels(after, *s.edits->rebuild()), 0) << "the masked update is the whole rebuild";
    const FieldUnits u = unitsOf(after);
    // Voxels changed inside the selection, and beyond its reach (where the
    // limited tool is at its floor: more than the band outside the balls).
    const auto changes = [&]() {
        std::pair<int, int> n{0, 0};
        const voxel::IndexBox box = after.frame.indexBox;
        for (int i = box.lo[0]; i <= box.hi[0]; ++i)
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
                for (int k = box.lo[2]; k <= box.hi[2]; ++k) {
                    if (after.value(i, j, k) == before.value(i, j, k)) continue;
                    const auto p = after.frame.position(i, j, k);
                    const double m = maskVoxels(p[0], p[1], p[2], *sel, u);
                    if (m > 0.0) ++n.first;
                    if (m < -u.band) ++n.second;
                }
        return n;
    };
    const auto masked = changes();
    EXPECT_GT(masked.first, 20);
    EXPECT_EQ(masked.second, 0) << "nothing changes beyond the selection's reach";
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(test::differingVoxels(after, before), 0) << "undone exactly";
    // The same stroke without the selection cuts the ball's top far beyond it.
    ASSERT_EQ(session->selectWithModel("c", ""), "");
    EXPECT_FALSE(session->selectionOf(c));
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{kCx - 0.7, kCy + 0.55, kCz}, {kCx + 0.7, kCy + 0.55, kCz}}, 0.12),
              "");
    EXPECT_GT(changes().second, 20) << "unmasked, the stroke reaches beyond the selection";
    EXPECT_EQ(session->selectWithModel("a", "cap"), "model 'cap' surrounds 'c', not 'a'");
}

TEST_F(SelectionTest, TheExtractedPartIsTheSourceInsideTheSelection) {
    ASSERT_EQ(model("wrap", {kCx + 0.3, kCy + 0.3, kCz}, 0.45), "");
    ASSERT_EQ(session->deformModel("wrap", true, 60), "");
    const auto sel = session->selectionOf(c);
    ASSERT_TRUE(sel);
    const std::size_t before = session->sculptures().size();
    ASSERT_EQ(extractPart(*session, "c", "wrap", "piece"), "");
    ASSERT_EQ(session->sculptures().size(), before + 1);
    const int p = session->findSculpture("piece");
    ASSERT_GE(p, 0);
    EXPECT_TRUE(std::holds_alternative<AddAction>(journal.actions.back())) << "journalled as an added sculpture";
    // Its HyperFun is the source's grid field inside the mask, exactly.
    const HyperFunExport part = exportHyperFun(*session, p);
    ASSERT_EQ(part.error, "");
    const ModelFile partModel = modelFromText(part.text, "piece.hf", "", {});
    ASSERT_TRUE(partModel.ok()) << partModel.error;
    const HyperFunExport source = exportHyperFun(*session, c);
    const ModelFile sourceModel = modelFromText(source.text, "c.hf", "", {});
    ASSERT_TRUE(sourceModel.ok()) << sourceModel.error;
    const FieldUnits u = unitsOf(grid(c));
    const double normalization = grid(c).normalization;
    int inside = 0;
    for (int n = 0; n < 200; ++n) {
        const double x = -0.1 + 0.7 * std::fmod(n * 0.618033, 1.0), y = 0.4 + 0.7 * std::fmod(n * 0.414213, 1.0),
                     z = -0.3 + 0.6 * std::fmod(n * 0.732050, 1.0);
        const double f = editops::clamp<double>(valueAt(*sourceModel.model, x, y, z) * normalization, -u.band, u.band);
        const double expected = insideMask<double>(f, x, y, z, *sel, u);
        EXPECT_EQ(valueAt(*partModel.model, x, y, z), expected) << "at " << x << ", " << y << ", " << z;
        if (expected > 0.0) ++inside;
    }
    EXPECT_GT(inside, 5) << "some samples fall in the part";
    // The part's grid: solid at the selected surface's inside, empty far away.
    const voxel::Volume& g = grid(p);
    EXPECT_GT(g.value(g.frame.indexOf(0, 0.3), g.frame.indexOf(1, 0.8), g.frame.indexOf(2, 0.0)), 0.0f);
    ASSERT_TRUE(session->undo());
    EXPECT_LT(session->findSculpture("piece"), 0) << "undo takes the part away";
}

TEST_F(SelectionTest, AJournalPlaysBackToTheSameModelsSelectionsAndGrids) {
    ASSERT_EQ(model("wrap", {kCx, kCy + 0.3, kCz}, 0.5), "");
    ASSERT_EQ(session->deformModel("wrap", true, 17), "");
    ASSERT_EQ(session->deformModel("wrap", true, 23), "");
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Add, {{kCx - 0.5, kCy + 0.5, kCz + 0.3}, {kCx + 0.5, kCy + 0.5, kCz + 0.3}},
                                   0.08),
              "");
    ASSERT_EQ(session->deformModel("wrap", false, 5), "");
    ASSERT_EQ(extractPart(*session, "c", "wrap", ""), "");
    const auto& m = view("wrap");
    const std::vector<glm::dvec3> vertices = *m.vertices;
    const int part = session->findSculpture("c-part");
    ASSERT_GE(part, 0);

    GardenSession replayed(loadGarden(writeGarden()), test::smallSessionSettings());
    ASSERT_EQ(replayed.restore(journal.actions), "");
    std::vector<glm::dvec3> again;
    for (const auto& v : replayed.models())
        if (v.name == "wrap") again = *v.vertices;
    EXPECT_EQ(again, vertices) << "the model's mesh bit for bit";
    ASSERT_TRUE(replayed.selectionOf(replayed.findSculpture("c")));
    EXPECT_EQ(test::differingVoxels(*replayed.sculptures()[static_cast<std::size_t>(replayed.findSculpture("c"))].volume,
                                    grid(c)),
              0);
    const int part2 = replayed.findSculpture("c-part");
    ASSERT_GE(part2, 0);
    EXPECT_EQ(test::differingVoxels(*replayed.sculptures()[static_cast<std::size_t>(part2)].volume, grid(part)), 0);
}

TEST_F(SelectionTest, GesturesSwitchTheSketchToolAndCirclingDeformsTheModel) {
    using test::archShape;
    ASSERT_EQ(session->applyGesture(test::vShape()), "") << session->gestureMessage();
    EXPECT_EQ(session->tool().kind, ToolSettings::Kind::Sketch);
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::New);
    ASSERT_EQ(session->applyGesture(test::uShape()), "") << session->gestureMessage();
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::Join);
    ASSERT_EQ(session->applyGesture(archShape()), "") << session->gestureMessage();
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::Cut);
    // A loop with no model yet: told so.
    ASSERT_EQ(session->applyGesture(test::loopShape(true)), "");
    EXPECT_NE(session->gestureMessage().find("no model"), std::string::npos) << session->gestureMessage();
    ASSERT_EQ(session->applyGesture(test::zShape()), "") << session->gestureMessage();
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::Model);
    ASSERT_EQ(model("wrap", {kCx, kCy, kCz}, 0.9), "");
    ASSERT_EQ(session->applyGesture(test::loopShape(true)), "") << session->gestureMessage();
    const int afterShrink = view("wrap").iterations;
    EXPECT_GE(afterShrink, 10) << "a clockwise loop shrinks: about 20 iterations a turn";
    EXPECT_TRUE(std::holds_alternative<DeformAction>(journal.actions.back()));
    EXPECT_TRUE(std::get<DeformAction>(journal.actions.back()).shrink);
    ASSERT_EQ(session->applyGesture(test::loopShape(false)), "") << session->gestureMessage();
    EXPECT_FALSE(std::get<DeformAction>(journal.actions.back()).shrink) << "counter-clockwise grows";
    EXPECT_NE(session->applyGesture(test::lineShape()), "") << "a straight line is no gesture";
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::Model) << "and changes nothing";
}


// The gesture button held while the tool hand's ray circles: the model
// deforms frame by frame while the circling goes on, stops when the hand
// stops, and the release journals the iterations run as one action.
TEST_F(SelectionTest, CirclingWithTheGestureButtonDeformsLiveAndJournalsOnce) {
    ASSERT_EQ(model("wrap", {kCx, kCy, kCz}, 0.9), "");
    session->tool().kind = ToolSettings::Kind::Sketch;
    session->tool().sketchUse = ToolSettings::SketchUse::Model;
    const std::size_t journalled = journal.actions.size();
    const glm::vec3 eye(static_cast<float>(kCx), 1.0f, 6.0f);
    const glm::vec3 ahead(0.0f, 0.0f, -1.0f), up(0.0f, 1.0f, 0.0f), right(1.0f, 0.0f, 0.0f);
    Hands h;
    h.tool.tracked = true;
    h.tool.aim.position = eye;
    h.tool.buttons = kButtonGesture;
    const auto aimAt = [&](float t) {  // clockwise on the screen: right, then down
        const glm::vec3 d = glm::normalize(ahead + 0.1f * (std::cos(t) * right - std::sin(t) * up));
        h.tool.aim.orientation = glm::quatLookAt(d, up);
    };
    std::vector<int> iterations;
    for (int i = 0; i <= 120; ++i) {  // two turns, 60 frames each
        aimAt(2.0f * 3.14159265f * static_cast<float>(i) / 60.0f);
        session->frame(FrameInput(h, 1.0 / 90.0));
        iterations.push_back(view("wrap").iterations);
    }
    EXPECT_TRUE(session->gestureDrawing());
    EXPECT_GT(iterations[60], 0) << "deforming while circling";
    EXPECT_GT(iterations[120], iterations[60] + 10) << "and going on with it";
    const int moving = iterations.back();
    for (int i = 0; i < 10; ++i) session->frame(FrameInput(h, 1.0 / 90.0));  // held still
    EXPECT_LE(view("wrap").iterations, moving + GardenSession::kLiveDeformIterations) << "stops when the hand stops";
    EXPECT_EQ(journal.actions.size(), journalled) << "nothing journalled while circling";
    h.tool.buttons = 0;
    session->frame(FrameInput(h, 1.0 / 90.0));
    ASSERT_EQ(journal.actions.size(), journalled + 1);
    const auto* d = std::get_if<DeformAction>(&journal.actions.back());
    ASSERT_NE(d, nullptr);
    EXPECT_TRUE(d->shrink) << "clockwise shrinks";
    EXPECT_EQ(d->iterations, view("wrap").iterations) << "one action of every iteration run";
    EXPECT_TRUE(session->selectionOf(c));
    EXPECT_EQ(session->tool().sketchUse, ToolSettings::SketchUse::Model) << "a loop is not a mode switch";
}

// Sketching on the morph result works like any edit there (issue 22): a
// sketch joined to the blend, a model shrunk onto it and a stroke inside
// its selection, all over the blend, which a new weight recomputes under
// them; each time the grid equals the blend with every edit applied.
TEST_F(SelectionTest, SketchesAndSelectionsOnTheMorphResult) {
    const int m = session->findSculpture("metamorphosis");
    ASSERT_GE(m, 0);
    for (int f = 0; f < 2000 && !session->idle(); ++f) session->frame(FrameInput(Hands{}, 1.0 / 90.0));
    ASSERT_TRUE(session->idle());
    const glm::vec3 centre = session->sculptures()[static_cast<std::size_t>(m)].worldCentre();
    const std::array<double, 3> at{centre.x, centre.y + 0.2, centre.z + 0.3};
    ASSERT_EQ(session->applySketch(m, SketchMode::Add, circleZ(at, 0.15), {0, 0, 1}), "");
    const auto a = session->modelFromWorld(m, "blend", circleZ({centre.x, centre.y, centre.z}, 0.8), {0, 0, 1});
    ASSERT_TRUE(a.action) << a.why;
    ASSERT_EQ(session->apply(*a.action), "");
    ASSERT_EQ(session->deformModel("blend", true, 80), "");
    ASSERT_TRUE(session->selectionOf(m));
    ASSERT_EQ(session->applyStroke(m, StrokeTool::Carve, {{centre.x - 0.5, centre.y, centre.z}, {centre.x + 0.5, centre.y, centre.z}},
                                   0.1),
              "");
    EXPECT_EQ(session->editCount(m), 2u);
    const Sculpture& r = session->sculptures()[static_cast<std::size_t>(m)];
    EXPECT_EQ(test::differingVoxels(*r.volume, *r.edits->rebuild()), 0);
    EXPECT_TRUE(r.edits->list().edits().back().mask) << "the stroke carries the selection";
    session->setMorphWeights({0.6, 0.2, 0.2});
    for (int f = 0; f < 4000 && !session->idle(); ++f) session->frame(FrameInput(Hands{}, 1.0 / 90.0));
    ASSERT_TRUE(session->idle());
    EXPECT_EQ(test::differingVoxels(r.edits->base(), *session->blendFromScratch()), 0) << "the new blend underneath";
    EXPECT_EQ(test::differingVoxels(*r.volume, *r.edits->rebuild()), 0) << "with the edits over it";
}

}  // namespace
}  // namespace hg::garden
