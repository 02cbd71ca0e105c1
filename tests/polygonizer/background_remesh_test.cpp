// Meshing off the frame thread (RemeshQueue::processInBackground with a
// MeshingWorker): the meshes it settles on are bit for bit those of the
// grid meshed from scratch, also when the grid changes while a job is under
// way; every state on show is one closed surface; a call never waits for
// the worker; a queue may go away with its job under way, and a worker with
// jobs queued.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/polygonizer/chunk_union.h"
#include "sample_program.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/realtime/meshing_worker.h"
#include "polygonizer/realtime/remesh_queue.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

frep::Model sphere(double r2, double cx) {
    return ::hg::test::modelFromSource("q(x[3], a[2]) { q = a[1] - ((x[1] - a[2])^2 + x[2]^2 + x[3]^2); }", {r2, cx});
}

// Calls until nothing is pending, as frames would; every state shown is closed.
int settle(RemeshQueue& q, MeshingWorker& worker, const RemeshBudget& budget) {
    int calls = 0;
    std::uint64_t seen = q.shownGeneration();
    for (; q.pending() > 0 && calls < 100000; ++calls) {
        q.processInBackground(worker, budget);
        if (q.shownGeneration() != seen) {
            seen = q.shownGeneration();
            const MeshReport now = validateMesh(weldByPosition(test::shownUnion(q)));
            EXPECT_EQ(now.boundaryEdges, 0u) << "after call " << calls;
            if (now.boundaryEdges != 0) break;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));  // a frame's other stages
    }
    EXPECT_EQ(q.pending(), 0u);
    EXPECT_FALSE(q.meshing());
    return calls;
}

void expectFromScratch(const RemeshQueue& q, const LodPyramid& pyramid, const ChunkLayout& layout,
                       const std::vector<int>& levels) {
    const std::vector<ChunkLod> lods = chunkLods(layout, levels);
    for (std::size_t i = 0; i < q.count(); ++i) {
        const Mesh scratch = meshChunk(pyramid, layout, i, lods[i]);
        ASSERT_TRUE(q.mesh(i)) << "chunk " << i;
        EXPECT_EQ(q.shownLod(i), lods[i]) << "chunk " << i;
        EXPECT_EQ(q.mesh(i)->positions, scratch.positions) << "chunk " << i;
        EXPECT_EQ(q.mesh(i)->indices, scratch.indices) << "chunk " << i;
        EXPECT_EQ(q.mesh(i)->normals, scratch.normals) << "chunk " << i;
    }
}

// Levels 0 at -x, 1 in the middle, 2 at +x: transition faces between.
std::vector<int> rampLevels(const ChunkLayout& layout) {
    std::vector<int> levels(layout.count());
    for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = std::min(2, layout.key(i).x - layout.key(0).x);
    return levels;
}

TEST(BackgroundRemesh, GatheredSamplesMeshAsThePyramidDoes) {
    voxel::Volume v = test::sampleInUnitCube(sphere(0.3, 0.1), 64);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    const std::vector<ChunkLod> lods = chunkLods(layout, rampLevels(layout));
    std::size_t transitions = 0;
    for (std::size_t i = 0; i < layout.count(); ++i) {
        const ChunkSamples s = gatherChunk(pyramid, layout, i, lods[i]);
        for (int f = 0; f < kChunkFaces; ++f)
            EXPECT_EQ(s.fine[f].values.empty(), !(lods[i].transitionFaces & (1 << f))) << "chunk " << i;
        transitions += lods[i].transitionFaces != 0;
        // Meshed from the copy after the grid is gone from under it.
        const Mesh direct = meshChunk(pyramid, layout, i, lods[i]);
        const Mesh fromCopy = meshChunk(s);
        EXPECT_EQ(fromCopy.positions, direct.positions) << "chunk " << i;
        EXPECT_EQ(fromCopy.indices, direct.indices) << "chunk " << i;
    }
    EXPECT_GT(transitions, 0u) << "the levels must give transition faces to test";
    EXPECT_THROW(gatherChunk(pyramid, layout, 0, ChunkLod{3, 0}), std::invalid_argument);
    EXPECT_THROW(gatherChunk(pyramid, layout, 0, ChunkLod{0, 1}), std::invalid_argument);
}

TEST(BackgroundRemesh, SettlesOnTheMeshesOfTheGridAsItIsWhenItChangesUnderAJob) {
    voxel::Volume v = test::sampleInUnitCube(sphere(0.2, 0.0), 96);
    LodPyramid pyramid(v, 3);
    ChunkLayout layout(v.frame, 16);
    const std::vector<int> levels = rampLevels(layout);
    RemeshQueue q(pyramid, layout, levels);
    MeshingWorker worker;
    settle(q, worker, RemeshBudget{0.0, 5});
    expectFromScratch(q, pyramid, layout, levels);

    // The grid changes while a job meshes its old samples: that job's
    // meshes of the changed chunks are stale and must not stay on show.
    const voxel::IndexBox region = voxel::IndexBox::fromCorners(40, 30, 35, 80, 66, 62);
    q.markChanged(v.frame.indexBox);
    q.processInBackground(worker, RemeshBudget{0.0, 0});
    ASSERT_TRUE(q.meshing());
    voxel::resampleRegion(v, sphere(0.3, 0.25), region);
    pyramid.update(region);
    q.markChanged(region);
    const int calls = settle(q, worker, RemeshBudget{0.0, 5});
    EXPECT_GT(calls, 1);
    expectFromScratch(q, pyramid, layout, levels);

    // New levels while a job is under way.
    std::vector<int> coarser(layout.count(), 1);
    q.markChanged(v.frame.indexBox);
    q.processInBackground(worker, RemeshBudget{0.0, 0});
    q.setLevels(coarser);
    settle(q, worker, RemeshBudget{0.0, 0});
    expectFromScratch(q, pyramid, layout, coarser);

    // process() in the frame takes a job under way first.
    q.setLevels(levels);
    q.processInBackground(worker, RemeshBudget{0.0, 3});
    ASSERT_TRUE(q.meshing());
    while (q.pending() > 0) q.process(RemeshBudget{0.0, 7});
    EXPECT_FALSE(q.meshing());
    expectFromScratch(q, pyramid, layout, levels);
}

TEST(BackgroundRemesh, ACallNeverWaitsForTheWorker) {
    // A long job first (every chunk of a fine grid at level 0), then a
    // second queue's: the worker takes jobs in turn, so while the first is
    // under way the second's cannot be done, and its calls must return
    // without its meshes.
    voxel::Volume big = test::sampleInUnitCube(sphere(0.3, 0.0), 224);
    LodPyramid bigPyramid(big, 1);
    ChunkLayout bigLayout(big.frame, 16);
    RemeshQueue longOne(bigPyramid, bigLayout, std::vector<int>(bigLayout.count(), 0));
    voxel::Volume v = test::sampleInUnitCube(sphere(0.3, 0.0), 48);
    LodPyramid pyramid(v, 2);
    ChunkLayout layout(v.frame, 16);
    RemeshQueue q(pyramid, layout, std::vector<int>(layout.count(), 1));

    MeshingWorker worker;
    longOne.processInBackground(worker, RemeshBudget{0.0, bigLayout.count()});
    ASSERT_TRUE(longOne.meshing());
    const RemeshReport first = q.processInBackground(worker, RemeshBudget{0.0, 0});
    const RemeshReport second = q.processInBackground(worker, RemeshBudget{0.0, 0});
    ASSERT_GE(worker.backlog(), 1u) << "the long job ended before the test could look: make it longer";
    EXPECT_EQ(first.meshed, 0u);
    EXPECT_EQ(second.meshed, 0u) << "the call waited for its job";
    EXPECT_TRUE(q.meshing());
    for (std::size_t i = 0; i < q.count(); ++i) EXPECT_FALSE(q.mesh(i)) << "nothing meshed can be on show yet";
    settle(q, worker, RemeshBudget{0.0, 0});
    expectFromScratch(q, pyramid, layout, std::vector<int>(layout.count(), 1));
}

TEST(BackgroundRemesh, AQueueMayGoAwayWithItsJobUnderWay) {
    auto worker = std::make_unique<MeshingWorker>();
    for (int round = 0; round < 3; ++round) {
        auto v = std::make_unique<voxel::Volume>(test::sampleInUnitCube(sphere(0.3, 0.0), 64));
        auto pyramid = std::make_unique<LodPyramid>(*v, 2);
        auto layout = std::make_unique<ChunkLayout>(v->frame, 16);
        auto q = std::make_unique<RemeshQueue>(*pyramid, *layout, std::vector<int>(layout->count(), 0));
        q->processInBackground(*worker, RemeshBudget{0.0, layout->count()});
        EXPECT_TRUE(q->meshing());
        // The job owns its samples: the grid, pyramid and layout may go with the queue.
        q.reset();
        layout.reset();
        pyramid.reset();
        v.reset();
    }
    worker.reset();
}

TEST(BackgroundRemesh, AWorkerThatStopsDropsTheJobsItHasNotStarted) {
    // A long job under way, a short one behind it; the worker stops.
    voxel::Volume big = test::sampleInUnitCube(sphere(0.3, 0.0), 192);
    LodPyramid bigPyramid(big, 1);
    ChunkLayout bigLayout(big.frame, 16);
    auto worker = std::make_unique<MeshingWorker>();
    auto longJob = std::make_shared<MeshingJob>();
    for (std::size_t i = 0; i < bigLayout.count(); ++i) {
        longJob->chunks.push_back(i);
        longJob->lods.push_back(ChunkLod{});
        longJob->stamps.push_back(0);
        longJob->samples.push_back(gatherChunk(bigPyramid, bigLayout, i, ChunkLod{}));
    }
    voxel::Volume v = test::sampleInUnitCube(sphere(0.3, 0.0), 64);
    LodPyramid pyramid(v, 2);
    ChunkLayout layout(v.frame, 16);
    RemeshQueue q(pyramid, layout, std::vector<int>(layout.count(), 0));
    worker->submit(longJob);
    while (worker->queued() > 0) std::this_thread::yield();  // the worker has taken it
    q.processInBackground(*worker, RemeshBudget{0.0, layout.count()});
    auto handMade = std::make_shared<MeshingJob>();
    handMade->chunks.push_back(0);
    handMade->lods.push_back(ChunkLod{});
    handMade->stamps.push_back(0);
    handMade->samples.push_back(gatherChunk(pyramid, layout, 0, ChunkLod{}));
    worker->submit(handMade);
    ASSERT_EQ(worker->queued(), 2u) << "the long job ended before the test could look: make it longer";
    ASSERT_FALSE(longJob->done());
    worker.reset();  // finishes the long job, drops the two behind it
    EXPECT_TRUE(longJob->done());
    EXPECT_EQ(longJob->meshes.size(), bigLayout.count());
    EXPECT_TRUE(handMade->done()) << "nobody waits for ever on a dropped job";
    EXPECT_TRUE(handMade->meshes.empty());
    EXPECT_TRUE(q.meshing()) << "the queue takes its job back at its next call";
    // The dropped job came back without meshes: its chunks are meshed again.
    const RemeshReport r = q.process(RemeshBudget{});
    EXPECT_EQ(r.meshed, layout.count());
    EXPECT_FALSE(q.meshing());
    expectFromScratch(q, pyramid, layout, std::vector<int>(layout.count(), 0));
}

}  // namespace
}  // namespace hg::poly
