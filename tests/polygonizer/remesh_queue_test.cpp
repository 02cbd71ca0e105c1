// The incremental meshing queue: after a region of the grid changes, the
// meshes it shows once drained are exactly the meshes of the changed grid
// meshed from scratch, and only chunks that read the region were remeshed;
// budgets hold; while an update is half done the old meshes stay and the
// surface on screen stays closed; explicit priority goes first, then the
// nearest chunk; level changes remesh the chunks whose level or transition
// faces changed.
#include <gtest/gtest.h>

#include "tests/polygonizer/chunk_union.h"
#include "sample_program.h"
#include "polygonizer/realtime/lod_selection.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/realtime/remesh_queue.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

frep::Model sphere(double r2, double cx) {
    return ::hg::test::modelFromSource("q(x[3], a[2]) { q = a[1] - ((x[1] - a[2])^2 + x[2]^2 + x[3]^2); }", {r2, cx});
}

voxel::Volume sample(const frep::Model& m, int res) { return test::sampleInUnitCube(m, res); }

// Levels 0 near -x, coarser towards +x, balanced.
std::vector<int> rampLevels(const ChunkLayout& layout) {
    std::vector<int> levels(layout.count());
    for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = std::min(2, (layout.key(i).x - layout.key(0).x) / 1);
    return levels;
}

void drain(RemeshQueue& q) {
    for (int guard = 0; q.pending() > 0 && guard < 1000; ++guard) q.process(RemeshBudget{0.0, 7});
    ASSERT_EQ(q.pending(), 0u);
}

TEST(RemeshQueue, RemeshAfterARegionChangeEqualsMeshingFromScratch) {
    frep::Model small = sphere(0.2, 0.0), moved = sphere(0.3, 0.25);
    voxel::Volume v = sample(small, 96);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    const std::vector<int> levels = rampLevels(layout);
    RemeshQueue q(pyramid, layout, levels);
    drain(q);
    std::vector<std::uint64_t> before(q.count());
    for (std::size_t i = 0; i < q.count(); ++i) before[i] = q.version(i);

    const voxel::IndexBox region = voxel::IndexBox::fromCorners(40, 30, 35, 80, 66, 62);
    voxel::resampleRegion(v, moved, region);
    pyramid.update(region);
    q.markChanged(region);
    drain(q);

    const std::vector<ChunkLod> lods = chunkLods(layout, levels);
    std::size_t remeshed = 0;
    for (std::size_t i = 0; i < q.count(); ++i) {
        Mesh scratch = meshChunk(pyramid, layout, i, lods[i]);
        ASSERT_TRUE(q.mesh(i));
        EXPECT_EQ(q.mesh(i)->positions, scratch.positions) << "chunk " << i;
        EXPECT_EQ(q.mesh(i)->indices, scratch.indices) << "chunk " << i;
        EXPECT_EQ(q.mesh(i)->normals, scratch.normals) << "chunk " << i;
        if (q.version(i) == before[i]) continue;
        ++remeshed;
        // Only chunks whose samples (with their gradient halo) reach the region.
        const voxel::IndexBox c = layout.voxels(i);
        const int cell = 1 << lods[i].level;
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(region.hi[a], c.lo[a] - cell) << "chunk " << i;
            EXPECT_LE(region.lo[a], c.hi[a] + 1 + cell) << "chunk " << i;
        }
    }
    EXPECT_GT(remeshed, 0u);
    EXPECT_LT(remeshed, q.count() / 2);
    MeshReport r = validateMesh(weldByPosition(test::shownUnion(q)));
    EXPECT_EQ(r.boundaryEdges, 0u);
}

TEST(RemeshQueue, BudgetsHoldAndHalfDoneUpdatesShowTheOldClosedSurface) {
    voxel::Volume v = sample(sphere(0.3, 0.0), 96);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    std::vector<int> levels(layout.count(), 1);
    RemeshQueue q(pyramid, layout, levels);
    RemeshReport first = q.process(RemeshBudget{0.0, 3});
    EXPECT_EQ(first.meshed, 3u);
    EXPECT_EQ(first.shown, 0u) << "one connected group: nothing shows until all of it is meshed";
    for (std::size_t i = 0; i < q.count(); ++i) EXPECT_FALSE(q.mesh(i));
    EXPECT_EQ(q.shownGeneration(), 0u) << "nothing shown yet";
    drain(q);
    const std::uint64_t generation = q.shownGeneration();
    EXPECT_GT(generation, 0u);
    q.process(RemeshBudget{0.0, 3});
    EXPECT_EQ(q.shownGeneration(), generation) << "nothing new shown, same generation";
    const MeshReport coarse = validateMesh(weldByPosition(test::shownUnion(q)));
    ASSERT_EQ(coarse.boundaryEdges, 0u);

    // Walk close: levels change; every partial state shows a closed surface.
    Camera cam;
    cam.position = {-0.35, 0.0, 0.0};
    cam.viewportHeight = 300;
    LodSettings s;
    s.maxLevel = 2;
    q.setViewer(cam.position);
    q.setLevels(selectLevels(layout, cam, s));
    ASSERT_GT(q.pending(), 0u);
    const std::vector<ChunkLod> want = chunkLods(layout, selectLevels(layout, cam, s));
    int calls = 0;
    while (q.pending() > 0 && calls < 1000) {
        RemeshReport r = q.process(RemeshBudget{0.0, 2});
        EXPECT_LE(r.meshed, 2u);
        ++calls;
        MeshReport now = validateMesh(weldByPosition(test::shownUnion(q)));
        ASSERT_EQ(now.boundaryEdges, 0u) << "after call " << calls;
        // The running counts agree with the slots.
        std::size_t triangles = 0, unchanged = 0;
        for (std::size_t i = 0; i < q.count(); ++i) {
            if (q.mesh(i)) triangles += q.mesh(i)->triangleCount();
            unchanged += q.shownLod(i) == want[i] ? 1 : 0;
        }
        ASSERT_EQ(q.shownTriangles(), triangles) << "after call " << calls;
        ASSERT_GE(q.pending(), q.count() - unchanged) << "a chunk not yet at its level is pending";
    }
    EXPECT_GT(calls, 1);
    EXPECT_EQ(q.pending(), 0u);
    // A millisecond budget stops the call once spent (at least one batch runs).
    q.markChanged(v.frame.indexBox);
    RemeshReport timed = q.process(RemeshBudget{1e-6, 0});
    EXPECT_GE(timed.meshed, 1u);
    EXPECT_LT(timed.meshed, q.count());
}

TEST(RemeshQueue, PriorityFirstThenNearestThenCoarser) {
    voxel::Volume v = sample(sphere(0.3, 0.0), 64);
    LodPyramid pyramid(v, 2);
    ChunkLayout layout(v.frame, 16);
    std::vector<int> levels(layout.count(), 0);
    RemeshQueue q(pyramid, layout, levels);
    const std::size_t urgent = layout.count() / 2, nearest = layout.count() - 1;
    double lo[3], hi[3];
    layout.modelBox(nearest, lo, hi);
    q.setViewer({hi[0] + 0.01, hi[1] + 0.01, hi[2] + 0.01});
    q.setPriority(urgent, 5);
    std::vector<std::size_t> taken;
    while (q.pending() > 0) {
        RemeshReport r = q.process(RemeshBudget{0.0, 1});
        ASSERT_EQ(r.chunks.size(), r.meshed);
        taken.insert(taken.end(), r.chunks.begin(), r.chunks.end());
        if (r.meshed == 0) break;
    }
    ASSERT_EQ(taken.size(), layout.count());
    EXPECT_EQ(taken[0], urgent);
    EXPECT_EQ(taken[1], nearest);
    for (std::size_t k = 2; k < taken.size(); ++k)
        EXPECT_LE(distanceToChunk(layout, taken[k - 1], {hi[0] + 0.01, hi[1] + 0.01, hi[2] + 0.01}),
                  distanceToChunk(layout, taken[k], {hi[0] + 0.01, hi[1] + 0.01, hi[2] + 0.01}) + 1e-12);
}

TEST(RemeshQueue, LevelChangesRemeshOnlyChunksWhoseLevelOrTransitionsChanged) {
    voxel::Volume v = sample(sphere(0.3, 0.0), 64);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    std::vector<int> levels(layout.count(), 1);
    RemeshQueue q(pyramid, layout, levels);
    drain(q);
    std::vector<int> changed = levels;
    const std::size_t fine = layout.count() / 2;
    changed[fine] = 0;
    const std::vector<ChunkLod> before = chunkLods(layout, levels), after = chunkLods(layout, changed);
    q.setLevels(changed);
    std::size_t expected = 0;
    for (std::size_t i = 0; i < layout.count(); ++i) expected += before[i] != after[i];
    EXPECT_EQ(q.pending(), expected);
    EXPECT_EQ(expected, 1u + layout.faceNeighbours(fine).size()) << "the chunk and its face neighbours";
    drain(q);
    for (std::size_t i = 0; i < layout.count(); ++i) EXPECT_EQ(q.shownLod(i), after[i]);
}

}  // namespace
}  // namespace hg::poly
