// The morph blend: from scratch, and as budgeted partial updates that drain
// to the same grid bit for bit, report every change, go coarse-first then
// nearest-first, and restart with new weights.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "garden/morph/morph_blend.h"
#include "morph_blend_fixture.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "voxel/volume_vdb.h"

namespace hg::garden {
namespace {

using namespace test;

TEST_F(MorphBlend, FromScratchIsTheClampedWeightedSumOfUnclampedSources) {
    voxel::Volume r = blendMorph(*sources, w1);
    const float band = sources->frame.band;
    const float w[3] = {static_cast<float>(w1.w[0]), static_cast<float>(w1.w[1]), static_cast<float>(w1.w[2])};
    Snapshot s = snapshot(r);
    std::size_t inside = 0, surface = 0, beyondBand = 0;
    for (int k = s.box.lo[2]; k <= s.box.hi[2]; ++k)
        for (int j = s.box.lo[1]; j <= s.box.hi[1]; ++j)
            for (int i = s.box.lo[0]; i <= s.box.hi[0]; ++i) {
                const std::size_t o = s.at(i, j, k);
                if (!sources->frame.indexBox.contains(i, j, k)) {
                    ASSERT_EQ(s.value[o], -band);
                    ASSERT_FALSE(s.on[o]);
                    continue;
                }
                const float f[3] = {sources->fields[0].value(i, j, k), sources->fields[1].value(i, j, k),
                                    sources->fields[2].value(i, j, k)};
                const float raw = w[0] * f[0] + w[1] * f[1] + w[2] * f[2];
                const float expected = std::min(std::max(raw, -band), band);
                ASSERT_EQ(bits(s.value[o]), bits(expected)) << i << " " << j << " " << k;
                ASSERT_EQ(s.on[o] != 0, std::fabs(expected) < band);
                inside += expected > 0.0f;
                surface += s.on[o] != 0;
                // Somewhere a source is beyond the band while the blend is
                // inside it: clamped sources would have given another value.
                for (float source : f) beyondBand += std::fabs(source) > band && std::fabs(raw) < band;
            }
    EXPECT_GT(inside, 1000u);
    EXPECT_GT(surface, 1000u);
    EXPECT_GT(beyondBand, 100u);
    // A corner of the triangle is that source alone, clamped.
    voxel::Volume corner = blendMorph(*sources, weightsFromBarycentric({0, 1, 0}));
    const voxel::IndexBox& b = sources->frame.indexBox;
    for (int k = b.lo[2]; k <= b.hi[2]; k += 3)
        for (int j = b.lo[1]; j <= b.hi[1]; j += 3)
            for (int i = b.lo[0]; i <= b.hi[0]; i += 3) {
                float f = sources->fields[1].value(i, j, k);
                ASSERT_EQ(corner.value(i, j, k), std::min(std::max(f, -band), band));
            }
}

TEST_F(MorphBlend, SmallBudgetDrainsToTheFromScratchBlend) {
    voxel::Volume result = makeMorphVolume(*sources);
    MorphBlender blender(*sources, result);
    EXPECT_TRUE(blender.done());  // nothing to do before restart()
    blender.restart(w1, viewer);
    const std::uint64_t total = blender.totalSamples();
    EXPECT_EQ(total, sources->frame.indexBox.volume() + [&] {
        std::uint64_t coarse = 0;
        for (const auto& it : blender.workList()) coarse += it.pass == BlendPass::Coarse ? it.samples : 0;
        return coarse;
    }());
    BlendBudget budget;
    budget.maxSamples = 777;  // not a multiple of anything: steps stop mid-block
    std::uint64_t samples = 0;
    int steps = 0;
    while (!blender.done()) {
        BlendStep s = blender.step(budget);
        ASSERT_LE(s.samples, 777u);
        ASSERT_GT(s.samples, 0u);
        samples += s.samples;
        EXPECT_EQ(blender.remainingSamples(), total - samples);
        ++steps;
        ASSERT_LT(steps, 100000);
    }
    EXPECT_EQ(samples, total);
    EXPECT_EQ(static_cast<std::uint64_t>(steps), (total + 776) / 777);
    voxel::Volume scratch = blendMorph(*sources, w1);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
    EXPECT_EQ(result.leafCount(), scratch.leafCount());
    EXPECT_EQ(result.activeVoxelCount(), scratch.activeVoxelCount());
    // Drained: another step does nothing.
    BlendStep idle = blender.step(budget);
    EXPECT_EQ(idle.samples, 0u);
    EXPECT_TRUE(idle.done);
}

TEST_F(MorphBlend, ChangedBoxesCoverEveryChangeAndKeepAPyramidUpToDate) {
    voxel::Volume result = blendMorph(*sources, w1);
    poly::LodPyramid pyramid(result, 4);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    BlendBudget budget;
    budget.maxSamples = 5000;
    std::uint64_t changedTotal = 0;
    while (!blender.done()) {
        Snapshot before = snapshot(result);
        BlendStep step = blender.step(budget);
        Snapshot after = snapshot(result);
        std::size_t changed = 0;
        for (int k = before.box.lo[2]; k <= before.box.hi[2]; ++k)
            for (int j = before.box.lo[1]; j <= before.box.hi[1]; ++j)
                for (int i = before.box.lo[0]; i <= before.box.hi[0]; ++i) {
                    const std::size_t o = before.at(i, j, k);
                    if (bits(before.value[o]) == bits(after.value[o]) && before.on[o] == after.on[o]) continue;
                    ++changed;
                    bool covered = false;
                    for (const auto& b : step.changed) covered |= b.contains(i, j, k);
                    ASSERT_TRUE(covered) << "voxel " << i << " " << j << " " << k << " changed outside the boxes";
                }
        EXPECT_EQ(step.changedVoxels, changed);
        changedTotal += changed;
        // Each box lies in one block.
        for (const auto& b : step.changed)
            for (int a = 0; a < 3; ++a)
                ASSERT_EQ(std::floor(b.lo[a] / 8.0), std::floor(b.hi[a] / 8.0));
        for (const auto& b : step.changed) pyramid.update(b);
    }
    EXPECT_GT(changedTotal, 1000u);
    voxel::Volume scratch = blendMorph(*sources, w2);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
    // The same leaves: blocks that left the band became tiles again, blocks
    // that entered it became leaves (both happen between these weights).
    EXPECT_EQ(leafOrigins(result), leafOrigins(scratch));
    std::set<std::array<int, 3>> before = leafOrigins(blendMorph(*sources, w1)), after = leafOrigins(scratch);
    std::size_t gone = 0, added = 0;
    for (const auto& o : before) gone += after.count(o) == 0;
    for (const auto& o : after) added += before.count(o) == 0;
    EXPECT_GT(gone, 0u);
    EXPECT_GT(added, 0u);
    // The pyramid followed the reported boxes to the rebuilt one's values.
    expectPyramidOf(pyramid, scratch, sources->frame.indexBox);
}

TEST_F(MorphBlend, CoarseLatticeFirstThenNearestBlocksFirst) {
    voxel::Volume result = blendMorph(*sources, w1);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    const auto& list = blender.workList();
    const voxel::VolumeFrame& f = sources->frame;
    const double vi[3] = {(viewer[0] - f.modelBox.lo[0]) / f.voxelSize, (viewer[1] - f.modelBox.lo[1]) / f.voxelSize,
                          (viewer[2] - f.modelBox.lo[2]) / f.voxelSize};
    // Distance from the viewer to the centre of the region-aligned cube
    // holding the item's block.
    auto distance = [&](const BlendItem& it, int region) {
        double d = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            int lo = static_cast<int>(std::floor(it.origin[a] / static_cast<double>(region))) * region;
            d += std::pow(lo + 0.5 * (region - 1) - vi[a], 2);
        }
        return d;
    };
    // Every coarse item before every fine one. The fine pass goes nearest
    // block first; the coarse pass nearest 32^3 region first, and inside a
    // region in z, y, x order.
    std::size_t coarse = 0;
    std::uint64_t coarseSamples = 0;
    while (coarse < list.size() && list[coarse].pass == BlendPass::Coarse) coarseSamples += list[coarse++].samples;
    ASSERT_GT(coarse, 0u);
    for (std::size_t i = coarse; i < list.size(); ++i) ASSERT_EQ(list[i].pass, BlendPass::Fine);
    for (std::size_t i = coarse + 1; i < list.size(); ++i)
        ASSERT_LE(distance(list[i - 1], kBlendBlock), distance(list[i], kBlendBlock)) << i;
    for (std::size_t i = 1; i < coarse; ++i) {
        double a = distance(list[i - 1], kCoarseRegion), b = distance(list[i], kCoarseRegion);
        ASSERT_LE(a, b) << i;
        if (a == b) {
            auto zyx = [](const BlendItem& it) { return std::array<int, 3>{it.origin[2], it.origin[1], it.origin[0]}; };
            ASSERT_LT(zyx(list[i - 1]), zyx(list[i])) << i;
        }
    }
    // The coarse pass is the voxels whose indices are multiples of 4.
    std::uint64_t lattice = 0;
    for (int k = f.indexBox.lo[2]; k <= f.indexBox.hi[2]; ++k)
        for (int j = f.indexBox.lo[1]; j <= f.indexBox.hi[1]; ++j)
            for (int i = f.indexBox.lo[0]; i <= f.indexBox.hi[0]; ++i)
                lattice += i % 4 == 0 && j % 4 == 0 && k % 4 == 0;
    EXPECT_EQ(coarseSamples, lattice);

    // After exactly the coarse pass, every voxel on the coarse lattice (and
    // so LOD levels 2 and 3) already shows the new weights.
    BlendBudget budget;
    budget.maxSamples = coarseSamples;
    BlendStep s = blender.step(budget);
    EXPECT_TRUE(s.coarseDone);
    EXPECT_FALSE(s.done);
    voxel::Volume scratch = blendMorph(*sources, w2);
    poly::LodPyramid early(result, 4), target(scratch, 4);
    std::size_t fineDiffer = 0;
    for (int k = f.indexBox.lo[2]; k <= f.indexBox.hi[2]; ++k)
        for (int j = f.indexBox.lo[1]; j <= f.indexBox.hi[1]; ++j)
            for (int i = f.indexBox.lo[0]; i <= f.indexBox.hi[0]; ++i) {
                bool onLattice = i % 4 == 0 && j % 4 == 0 && k % 4 == 0;
                if (onLattice) ASSERT_EQ(bits(result.value(i, j, k)), bits(scratch.value(i, j, k)));
                else fineDiffer += bits(result.value(i, j, k)) != bits(scratch.value(i, j, k));
            }
    EXPECT_GT(fineDiffer, 1000u);  // the fine voxels are still the old blend
    for (int level = 2; level < 4; ++level)
        for (int k = f.indexBox.lo[2] >> level; k <= f.indexBox.hi[2] >> level; ++k)
            for (int j = f.indexBox.lo[1] >> level; j <= f.indexBox.hi[1] >> level; ++j)
                for (int i = f.indexBox.lo[0] >> level; i <= f.indexBox.hi[0] >> level; ++i)
                    ASSERT_EQ(bits(early.value(level, i, j, k)), bits(target.value(level, i, j, k)));

    // Then the block nearest to the viewer is finished first: it is the
    // nearest of all blocks (brute force), and after its samples it is right.
    const BlendItem first = list[coarse];
    double best = INFINITY;
    for (const auto& it : list) best = std::min(best, distance(it, kBlendBlock));
    EXPECT_EQ(distance(first, kBlendBlock), best);
    budget.maxSamples = first.samples;
    s = blender.step(budget);
    EXPECT_EQ(s.blocksFinished, 1u);
    for (int k = first.origin[2]; k < first.origin[2] + 8; ++k)
        for (int j = first.origin[1]; j < first.origin[1] + 8; ++j)
            for (int i = first.origin[0]; i < first.origin[0] + 8; ++i)
                ASSERT_EQ(bits(result.value(i, j, k)), bits(scratch.value(i, j, k)));
}

TEST_F(MorphBlend, NewWeightsMidUpdateRestartTheList) {
    voxel::Volume result = blendMorph(*sources, w1);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    BlendBudget budget;
    budget.maxSamples = 3001;
    for (int i = 0; i < 12; ++i) blender.step(budget);  // through the coarse pass, into the fine one
    EXPECT_TRUE(blender.coarseDone());
    EXPECT_FALSE(blender.done());
    blender.restart(w3, {-2.0, 0.0, 0.0});
    EXPECT_EQ(blender.cursor(), 0u);
    EXPECT_FALSE(blender.coarseDone());
    EXPECT_EQ(blender.remainingSamples(), blender.totalSamples());
    EXPECT_EQ(blender.weights().w[1], w3.w[1]);
    while (!blender.done()) blender.step(budget);
    voxel::Volume scratch = blendMorph(*sources, w3);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
    EXPECT_EQ(result.leafCount(), scratch.leafCount());
}

TEST_F(MorphBlend, ViewerMovesMidUpdate) {
    voxel::Volume result = makeMorphVolume(*sources);
    MorphBlender blender(*sources, result);
    blender.restart(w3, viewer);
    BlendBudget budget;
    budget.maxSamples = 1500;
    for (int i = 0; i < 3; ++i) blender.step(budget);
    const std::array<double, 3> elsewhere{-1.5, -1.0, 1.3};
    blender.setViewer(elsewhere);
    // The items not yet started are nearest-first from the new point.
    const auto& list = blender.workList();
    const voxel::VolumeFrame& f = sources->frame;
    auto distance = [&](const BlendItem& it) {
        const int region = it.pass == BlendPass::Coarse ? kCoarseRegion : kBlendBlock;
        double d = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            int lo = static_cast<int>(std::floor(it.origin[a] / static_cast<double>(region))) * region;
            d += std::pow(lo + 0.5 * (region - 1) - (elsewhere[a] - f.modelBox.lo[a]) / f.voxelSize, 2);
        }
        return d;
    };
    for (std::size_t i = blender.cursor() + 2; i < list.size(); ++i)
        if (list[i - 1].pass == list[i].pass) {
            ASSERT_LE(distance(list[i - 1]), distance(list[i]));
        }
    while (!blender.done()) blender.step(budget);
    voxel::Volume scratch = blendMorph(*sources, w3);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
}

TEST_F(MorphBlend, TimeBudgetMakesProgressAndDrains) {
    voxel::Volume result = makeMorphVolume(*sources);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    BlendBudget budget;
    budget.maxSamples = 0;
    budget.maxMilliseconds = 0.2;
    int steps = 0;
    while (!blender.done()) {
        BlendStep s = blender.step(budget);
        EXPECT_GT(s.samples, 0u);
        ASSERT_LT(++steps, 100000);
    }
    voxel::Volume scratch = blendMorph(*sources, w2);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
}

TEST_F(MorphBlend, RefusesAResultInAnotherFrame) {
    voxel::Volume other;
    ASSERT_EQ(voxel::makeFrame(sources->frame.modelBox, 24, 3.0f, other.frame), "");
    EXPECT_THROW(MorphBlender(*sources, other), std::invalid_argument);
    MorphSources broken;
    broken.frame = sources->frame;
    EXPECT_THROW(blendMorph(broken, w1), std::invalid_argument);
}

}  // namespace
}  // namespace hg::garden
