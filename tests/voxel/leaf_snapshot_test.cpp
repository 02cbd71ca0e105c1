// Leaf snapshots (voxel/leaf_snapshot.h): copies of the 8^3 leaves that hold
// a box's voxels (clipped to the frame), values and active states, written
// back exactly; the first copy of a leaf wins, so a box that grows keeps
// the state from before its first part. What is tested, on real sampled
// grids edited through real edit tapes (voxel/edit_region.h):
//  * capture, edit in place, restore: every voxel's value bits and active
//    state are the unedited grid's, around the frame too;
//  * a growing box (a live stroke: capture, edit, capture more, edit ...)
//    restores to the state before the first part, and a snapshot taken
//    after a part restores to that part;
//  * whole leaves come back, and only those: an edit beyond the captured
//    leaves stays;
//  * tiles (a deep inside, the background outside, an active tile) are
//    copied as their values and states, and come back over leaves or over
//    other tiles;
//  * bytes() counts each copied leaf once (clipped to the frame, none for a
//    box outside it); a moved snapshot restores the same.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <array>
#include <cmath>
#include <optional>
#include <set>

#include "edit_tapes.h"
#include "test_models.h"
#include "voxel/edit_region.h"
#include "voxel/leaf_snapshot.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {
namespace {

using test::differingVoxels;
using test::grown;

// A sphere of radius 0.707 in [-1, 1]^3 at 64 voxels.
Volume sphereGrid() {
    VolumeRequest req;
    req.resolution = 64;
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = -1.0;
        b.hi[a] = 1.0;
    }
    req.box = b;
    VoxelizeResult r = voxelize(test::modelFromSource(test::kSphere, {0.5}), req);
    EXPECT_TRUE(r.volume) << r.error;
    return r.volume ? std::move(*r.volume) : Volume();
}

// A carve and a bump about `centre` (model units), radius `r`, in place
// over the voxels of `box`: what a stroke's part does to the grid.
void edit(Volume& v, const IndexBox& box, std::array<double, 3> centre, double r = 0.15) {
    const double scale = 1.0 / (2.0 * r * v.frame.voxelSize);
    const frep::Tape tape = test::ballsTape({{centre, r, false}, {{centre[0] + r, centre[1], centre[2]}, 0.6 * r, true}}, scale);
    applyEditTape(v, v, box, tape);
}

// The box of voxels within `r` (plus two voxels) of a model point.
IndexBox around(const Volume& v, std::array<double, 3> c, double r) {
    IndexBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = v.frame.indexOf(a, c[static_cast<std::size_t>(a)] - r) - 2;
        b.hi[a] = v.frame.indexOf(a, c[static_cast<std::size_t>(a)] + r) + 2;
    }
    return b;
}

// Origins of the leaves holding voxels of each box (clipped to the frame).
std::set<std::array<int, 3>> leavesOf(const Volume& v, std::initializer_list<IndexBox> boxes) {
    std::set<std::array<int, 3>> s;
    for (const IndexBox& box : boxes) {
        const IndexBox clip = intersect(box, v.frame.indexBox);
        if (clip.empty()) continue;
        for (int z = floorMultiple(clip.lo[2], 8); z <= clip.hi[2]; z += 8)
            for (int y = floorMultiple(clip.lo[1], 8); y <= clip.hi[1]; y += 8)
                for (int x = floorMultiple(clip.lo[0], 8); x <= clip.hi[0]; x += 8) s.insert({x, y, z});
    }
    return s;
}

bool inLeaves(const std::set<std::array<int, 3>>& leaves, int i, int j, int k) {
    return leaves.count({floorMultiple(i, 8), floorMultiple(j, 8), floorMultiple(k, 8)}) > 0;
}

TEST(LeafSnapshot, RestoresEveryVoxelOfAnEditedBoxExactly) {
    const Volume base = sphereGrid();
    const IndexBox all = grown(base.frame.indexBox, 3);
    // On the surface, and on the surface where it meets the frame's edge.
    for (const std::array<double, 3> c : {std::array<double, 3>{0.7, 0.05, -0.03}, std::array<double, 3>{0.0, 0.0, 0.71}}) {
        for (const IndexBox& box : {around(base, c, 0.2), grown(base.frame.indexBox, 5)}) {
            Volume v = base.clone();
            LeafSnapshot before;
            before.capture(v, box);
            edit(v, box, c);
            ASSERT_GT(differingVoxels(v, base, all), 100u) << "the edit changed the grid";
            before.restore(v);
            EXPECT_EQ(differingVoxels(v, base, all, "restored"), 0u);
            // Restoring twice changes nothing more.
            before.restore(v);
            EXPECT_EQ(differingVoxels(v, base, all, "restored twice"), 0u);
        }
    }
}

TEST(LeafSnapshot, AGrowingBoxKeepsTheStateBeforeItsFirstPart) {
    const Volume base = sphereGrid();
    const IndexBox all = grown(base.frame.indexBox, 2);
    Volume v = base.clone();
    LeafSnapshot stroke, fromSecond;
    // Three parts of a stroke along the surface, each box overlapping the last.
    const std::array<double, 3> path[] = {{0.70, 0.0, 0.0}, {0.66, 0.2, 0.0}, {0.55, 0.4, 0.05}};
    std::optional<Volume> afterFirst;
    std::set<std::array<int, 3>> leaves;
    for (int p = 0; p < 3; ++p) {
        const IndexBox box = around(v, path[p], 0.2);
        stroke.capture(v, box);
        if (p == 1) fromSecond.capture(v, around(v, path[1], 0.2));
        if (p == 2) fromSecond.capture(v, box);
        edit(v, box, path[p]);
        if (p == 0) afterFirst = v.clone();
        leaves.merge(leavesOf(v, {box}));
    }
    const Volume edited = v.clone();
    ASSERT_GT(differingVoxels(edited, base, all), 300u);

    Volume undone = edited.clone();
    stroke.restore(undone);
    EXPECT_EQ(differingVoxels(undone, base, all, "the whole stroke undone"), 0u);
    // Taken from the second part on: the first part stays.
    Volume partly = edited.clone();
    fromSecond.restore(partly);
    EXPECT_EQ(differingVoxels(partly, *afterFirst, all, "back to after the first part"), 0u);
    EXPECT_GT(differingVoxels(partly, base, all), 50u);

    // Each leaf was copied once.
    LeafSnapshot one;
    one.capture(base, IndexBox::fromCorners(8, 8, 8, 8, 8, 8));
    ASSERT_GT(one.bytes(), 512u * sizeof(float));
    EXPECT_EQ(stroke.bytes(), leaves.size() * one.bytes());
}

TEST(LeafSnapshot, WholeLeavesComeBackAndOnlyThose) {
    const Volume base = sphereGrid();
    Volume v = base.clone();
    // A box of a few voxels, not on the leaf grid, then an edit far wider.
    const IndexBox small = IndexBox::fromCorners(53, 29, 30, 55, 34, 33);
    LeafSnapshot s;
    s.capture(v, small);
    const std::set<std::array<int, 3>> leaves = leavesOf(v, {small});
    ASSERT_EQ(leaves.size(), 4u);  // x 48, y 24 and 32, z 24 and 32: one leaf on x
    const IndexBox wide = grown(small, 12);
    edit(v, wide, {base.frame.coordinate(0, 54), base.frame.coordinate(1, 31), base.frame.coordinate(2, 31)}, 0.25);
    const Volume edited = v.clone();
    s.restore(v);
    std::size_t restored = 0, kept = 0, changedOutside = 0;
    const IndexBox all = grown(base.frame.indexBox, 2);
    for (int k = all.lo[2]; k <= all.hi[2]; ++k)
        for (int j = all.lo[1]; j <= all.hi[1]; ++j)
            for (int i = all.lo[0]; i <= all.hi[0]; ++i) {
                if (inLeaves(leaves, i, j, k)) {
                    restored += v.value(i, j, k) == base.value(i, j, k) && v.active(i, j, k) == base.active(i, j, k);
                } else {
                    kept += v.value(i, j, k) == edited.value(i, j, k) && v.active(i, j, k) == edited.active(i, j, k);
                    changedOutside += edited.value(i, j, k) != base.value(i, j, k);
                }
            }
    EXPECT_EQ(restored, leaves.size() * 512u) << "every voxel of the copied leaves, inside the box or not";
    EXPECT_EQ(kept, all.volume() - leaves.size() * 512u) << "the rest keeps the edit";
    EXPECT_GT(changedOutside, 500u) << "the edit reached beyond the copied leaves";
}

TEST(LeafSnapshot, TilesAndEmptySpaceAreCopiedAsTheirValues) {
    Volume base = sphereGrid();
    const float band = base.frame.band;
    // An active tile of one 16^3 block near a corner, as a grid may hold.
    vdb(base).tree().fill(openvdb::CoordBBox(openvdb::Coord(0, 0, 48), openvdb::Coord(15, 15, 63)), 1.25f, true);
    const IndexBox inside = IndexBox::fromCorners(24, 24, 24, 39, 39, 39);    // deep inside: +band
    const IndexBox corner = IndexBox::fromCorners(-4, -4, -4, 11, 11, 11);    // outside: -band
    const IndexBox activeTile = IndexBox::fromCorners(0, 0, 48, 15, 15, 63);
    ASSERT_EQ(base.value(30, 30, 30), band);
    ASSERT_FALSE(base.active(30, 30, 30));
    ASSERT_EQ(base.value(0, 0, 0), -band);
    ASSERT_TRUE(base.active(3, 3, 50));
    ASSERT_EQ(vdb(base).tree().probeConstLeaf(openvdb::Coord(24, 24, 24)), nullptr) << "a tile, not a leaf";

    Volume v = base.clone();
    LeafSnapshot s;
    for (const IndexBox& b : {inside, corner, activeTile}) s.capture(v, b);
    LeafSnapshot one;
    one.capture(v, IndexBox::fromCorners(30, 30, 30, 30, 30, 30));
    EXPECT_EQ(s.bytes(), leavesOf(v, {inside, corner, activeTile}).size() * one.bytes());
    // Leaves where the tiles were, other tiles where there were leaves.
    for (const IndexBox& b : {inside, corner, activeTile})
        edit(v, b, {base.frame.coordinate(0, (b.lo[0] + b.hi[0]) / 2), base.frame.coordinate(1, (b.lo[1] + b.hi[1]) / 2),
                    base.frame.coordinate(2, (b.lo[2] + b.hi[2]) / 2)},
             0.3);
    vdb(v).tree().fill(openvdb::CoordBBox(openvdb::Coord(8, 8, 8), openvdb::Coord(15, 15, 15)), 2.0f, true);
    const IndexBox all = grown(base.frame.indexBox, 2);
    ASSERT_GT(differingVoxels(v, base, all), 1000u);
    s.restore(v);
    EXPECT_EQ(differingVoxels(v, base, all, "tiles restored"), 0u);
    EXPECT_TRUE(v.active(3, 3, 50));
    EXPECT_EQ(v.value(3, 3, 50), 1.25f);
}

TEST(LeafSnapshot, ClippedToTheFrameAndMovable) {
    const Volume base = sphereGrid();
    const IndexBox& frame = base.frame.indexBox;
    LeafSnapshot none;
    none.capture(base, IndexBox::fromCorners(frame.hi[0] + 1, 0, 0, frame.hi[0] + 40, 30, 30));
    none.capture(base, IndexBox());
    EXPECT_EQ(none.bytes(), 0u);
    Volume v = base.clone();
    none.restore(v);
    EXPECT_EQ(v.leafCount(), base.leafCount());

    // Half outside the frame: only the leaves of its part inside.
    const IndexBox half = IndexBox::fromCorners(frame.hi[0] - 3, 20, 20, frame.hi[0] + 30, 35, 35);
    LeafSnapshot s, one;
    s.capture(base, half);
    one.capture(base, IndexBox::fromCorners(20, 20, 20, 20, 20, 20));
    EXPECT_EQ(s.bytes(), leavesOf(base, {half}).size() * one.bytes());
    EXPECT_EQ(leavesOf(base, {half}).size(), (frame.hi[0] / 8 - (frame.hi[0] - 3) / 8 + 1) * 3u * 3u);

    // Moved, it restores the same.
    const std::array<double, 3> c{0.7, 0.0, 0.0};
    const IndexBox box = around(base, c, 0.2);
    LeafSnapshot taken;
    taken.capture(v, box);
    edit(v, box, c);
    LeafSnapshot moved(std::move(taken));
    LeafSnapshot assigned;
    assigned = std::move(moved);
    ASSERT_GT(differingVoxels(v, base, grown(frame, 2)), 100u);
    assigned.restore(v);
    EXPECT_EQ(differingVoxels(v, base, grown(frame, 2), "moved snapshot"), 0u);
}

}  // namespace
}  // namespace hg::voxel
