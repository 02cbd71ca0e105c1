// SculptureEdits' spread updates (appendSpread, extendLastStrokeSpread,
// advance): an edit is in the list at once and its grid update lands cell
// by cell over later calls; any other change settles what waits first, so
// the grid always ends equal to the same edits applied whole, bit for bit.
// And the session that spreads them (SessionSettings::spreadEdits): the
// action is journalled and undoable at once, the grid whole once idle.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "garden/app/garden_session.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/stroke_segments.h"
#include "garden_test_util.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

constexpr double kForever = std::numeric_limits<double>::infinity();

Edit perturbation(const ModelPoint& centre, double radius, double strength) {
    Perturbation p;
    p.center = centre;
    p.radii = {radius, 0.7 * radius, 0.9 * radius};
    p.strength = strength;
    Edit e;
    e.op = p;
    return e;
}

// A stroke's first point, as a live stroke or a replay's whole stroke begins.
Edit strokeStart(StrokeTool tool, double radius, const ModelPoint& first, const FieldUnits& units) {
    Stroke s;
    s.tool = tool;
    s.radius = radius;
    if (tool == StrokeTool::Inflate) s.strength = 1.5;
    s.path = {first};
    extendStrokeSegments(s, 0, units);
    Edit e;
    e.op = s;
    return e;
}

TEST(SculptureEditsSpread, AnEditLandsCellByCellAndEndsEqualToTheWholeEdit) {
    voxel::Volume whole = test::ballVolume();
    voxel::Volume spread = whole.clone();
    const voxel::Volume before = whole.clone();
    SculptureEdits a(whole), b(spread);
    const double v = whole.frame.voxelSize;
    a.append(perturbation({0.0, 0.45, 0.0}, 14 * v, 3.0));
    b.appendSpread(perturbation({0.0, 0.45, 0.0}, 14 * v, 3.0));
    // In the list at once; on the grid not yet.
    EXPECT_EQ(b.list().size(), 1u);
    EXPECT_TRUE(b.late());
    EXPECT_EQ(test::differingVoxels(spread, before), 0);
    // What an export of the grid reads is the whole edit already.
    EXPECT_EQ(test::differingVoxels(b.settledGrid(), whole), 0);
    int calls = 0;
    std::size_t cells = 0;
    while (b.late()) {
        // The least time there is: one cell a call.
        const std::vector<voxel::IndexBox> changed = b.advance(1e-9);
        ASSERT_EQ(changed.size(), 1u) << "call " << calls;
        cells += changed.size();
        ++calls;
        ASSERT_LT(calls, 1000);
    }
    EXPECT_GT(calls, 3) << "a perturbation 28 voxels across spans several cells of 16";
    EXPECT_EQ(test::differingVoxels(spread, whole), 0);
    EXPECT_EQ(test::differingVoxels(spread, *b.rebuild()), 0);
    EXPECT_GT(test::differingVoxels(spread, before), 100);
    // Nothing waits: no time asked, nothing done.
    EXPECT_TRUE(b.advance(kForever).empty());
}

TEST(SculptureEditsSpread, EveryOtherChangeSettlesWhatWaitsFirst) {
    voxel::Volume whole = test::ballVolume();
    voxel::Volume spread = whole.clone();
    SculptureEdits a(whole), b(spread);
    const double v = whole.frame.voxelSize;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-0.45, 0.45);
    const StrokeTool tools[] = {StrokeTool::Carve, StrokeTool::Add, StrokeTool::Melt, StrokeTool::Smooth,
                                StrokeTool::Inflate};
    for (int i = 0; i < 30; ++i) {
        const ModelPoint p{u(rng), u(rng), u(rng)};
        if (i % 3 == 0) {
            a.append(perturbation(p, 6 * v, i % 2 ? 2.0 : -2.0));
            b.appendSpread(perturbation(p, 6 * v, i % 2 ? 2.0 : -2.0));
        } else {
            // A whole stroke as the session plays one: its first point, then
            // the rest of its path (a smooth stroke's fits read the grid,
            // which must be settled for them to come out the same).
            const StrokeTool tool = tools[i % 5];
            const ModelPoint q{p[0] + 0.12, p[1] + 0.04, p[2] - 0.05};
            a.append(strokeStart(tool, (3 + i % 3) * v, p, a.units()));
            a.extendLastStroke({q});
            b.appendSpread(strokeStart(tool, (3 + i % 3) * v, p, b.units()));
            b.extendLastStrokeSpread({q});
        }
        // Some cells land, the rest wait for the next change to settle them.
        if (i % 2) b.advance(1e-9);
        if (i % 7 == 6) {
            ASSERT_TRUE(a.undo());
            ASSERT_TRUE(b.undo());
            EXPECT_EQ(test::differingVoxels(spread, whole), 0) << "undo after edit " << i;
            if (i % 2) {
                a.redo();
                b.redo();
            }
        }
    }
    ASSERT_EQ(a.list().size(), b.list().size());
    b.advance(kForever);
    EXPECT_FALSE(b.late());
    EXPECT_EQ(test::differingVoxels(spread, whole), 0);
    EXPECT_EQ(test::differingVoxels(spread, *b.rebuild()), 0);
    // Undo all the way: the ball again, through the copies taken before each edit.
    while (b.undo()) {}
    EXPECT_EQ(test::differingVoxels(spread, test::ballVolume()), 0);
}

class SessionSpreadEditsTest : public test::SmallGarden {};

TEST_F(SessionSpreadEditsTest, TheActionIsJournalledAtOnceAndTheGridWholeOnceIdle) {
    SessionSettings settings = test::smallSessionSettings();
    settings.remeshChunksPerFrame = 0;  // the allowance: timing mode, as the window runs
    settings.spreadEdits = true;
    GardenSession s(loadGarden(writeGarden()), settings);
    test::ActionList journal;
    s.setJournal(&journal);
    for (int f = 0; f < 400 && !s.idle(); ++f) s.frame(FrameInput{});
    ASSERT_TRUE(s.idle());
    const int c = s.findSculpture("c");  // a ball of radius 0.6 about (2, 0.5, 1.1547)
    Sculpture& st = s.sculptures()[static_cast<std::size_t>(c)];
    const voxel::Volume original = st.volume->clone();
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 1.1, 1.1547}, {0.3, 0.2, 0.3}, 3.0), "");
    EXPECT_EQ(journal.actions.size(), 1u) << "journalled when applied, before its grid update lands";
    EXPECT_EQ(s.editCount(c), 1u);
    EXPECT_FALSE(s.idle());
    for (int f = 0; f < 400 && !s.idle(); ++f) s.frame(FrameInput{});
    ASSERT_TRUE(s.idle());
    EXPECT_GT(test::differingVoxels(*st.volume, original), 100);
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    // A stroke and at once its undo: the grid of before the stroke.
    const voxel::Volume perturbed = st.volume->clone();
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{1.6, 0.5, 1.7}, {2.0, 0.6, 1.75}, {2.4, 0.5, 1.7}}, 0.08), "");
    EXPECT_TRUE(s.undo());
    s.settleEdits();
    EXPECT_EQ(test::differingVoxels(*st.volume, perturbed), 0);
    // Redone and settled: the whole stroke, as a rebuild makes it.
    EXPECT_TRUE(s.redo());
    s.settleEdits();
    EXPECT_GT(test::differingVoxels(*st.volume, perturbed), 50);
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
}

}  // namespace
}  // namespace hg::garden
