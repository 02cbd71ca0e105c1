// The morph blend off the frame thread (MorphBlender::stepInBackground and
// its BlendJob): a thread computes each batch from the sources, the frame
// writes it at a later step without waiting, and the list drains to the
// from-scratch blend bit for bit, whatever happens meanwhile (new weights,
// a viewer that moves, a thread that stops, a switch back to the frame).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "garden/morph/morph_blend.h"
#include "../jobs/gate_job.h"
#include "jobs/job_thread.h"
#include "morph_blend_fixture.h"
#include "polygonizer/realtime/lod_pyramid.h"

namespace hg::garden {
namespace {

using namespace test;
using jobs::test::Gate;

// A budget of time only, as the session's morph stage gives.
BlendBudget timed(double ms) {
    BlendBudget b;
    b.maxSamples = 0;
    b.maxMilliseconds = ms;
    return b;
}

// Steps until drained, yielding between steps as frames would; returns the
// samples written.
std::uint64_t drain(MorphBlender& blender, const BlendBudget& budget, jobs::JobThread& thread) {
    std::uint64_t written = 0;
    for (int steps = 0; !blender.done(); ++steps) {
        written += blender.stepInBackground(budget, thread).samples;
        EXPECT_LT(steps, 1000000);
        if (steps >= 1000000) break;
        std::this_thread::yield();
    }
    return written;
}

class BlendJobTest : public MorphBlend {};

TEST_F(BlendJobTest, DrainsToTheFromScratchBlendWithEveryChangeReported) {
    voxel::Volume result = blendMorph(*sources, w1);
    poly::LodPyramid pyramid(result, 4);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    const std::uint64_t total = blender.totalSamples();
    jobs::JobThread thread;
    BlendBudget budget = timed(0.3);
    budget.commit = [&](const std::vector<voxel::IndexBox>& boxes) {
        for (const auto& b : boxes) pyramid.update(b);
    };
    std::uint64_t changed = 0;
    std::uint64_t remaining = blender.remainingSamples();
    std::uint64_t written = 0;
    for (int steps = 0; !blender.done(); ++steps) {
        const BlendStep s = blender.stepInBackground(budget, thread);
        written += s.samples;
        changed += s.changedVoxels;
        // What is written leaves the count; what a job holds does not.
        EXPECT_EQ(blender.remainingSamples(), remaining - s.samples);
        remaining = blender.remainingSamples();
        ASSERT_LT(steps, 1000000);
        std::this_thread::yield();
    }
    EXPECT_EQ(written, total);
    EXPECT_EQ(blender.remainingSamples(), 0u);
    EXPECT_FALSE(blender.inBackground());
    EXPECT_GT(changed, 1000u);
    const voxel::Volume scratch = blendMorph(*sources, w2);
    EXPECT_EQ(differences(snapshot(result), snapshot(scratch)), 0u);
    EXPECT_EQ(leafOrigins(result), leafOrigins(scratch));
    EXPECT_EQ(result.activeVoxelCount(), scratch.activeVoxelCount());
    // The pyramid followed the reported boxes.
    expectPyramidOf(pyramid, scratch, sources->frame.indexBox);
    // Drained: a step writes nothing and hands nothing over.
    const BlendStep idle = blender.stepInBackground(budget, thread);
    EXPECT_EQ(idle.samples, 0u);
    EXPECT_TRUE(idle.done);
    EXPECT_EQ(thread.backlog(), 0u);
}

TEST_F(BlendJobTest, TheFrameNeverWaitsForTheThread) {
    voxel::Volume result = blendMorph(*sources, w1);
    const Snapshot before = snapshot(result);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    jobs::JobThread thread;
    auto gate = std::make_shared<Gate>();
    thread.submit(gate);
    BlendBudget budget = timed(0.3);
    // The first step hands the thread a job, which waits behind the gate;
    // the steps after it return at once with nothing written.
    for (int frame = 0; frame < 20; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        const BlendStep s = blender.stepInBackground(budget, thread);
        EXPECT_EQ(s.samples, 0u);
        EXPECT_FALSE(s.done);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    }
    EXPECT_TRUE(blender.inBackground());
    EXPECT_EQ(thread.backlog(), 2u) << "the gate and one blend job, not one per step";
    EXPECT_EQ(differences(snapshot(result), before), 0u) << "nothing is written before the job is done";
    gate->open();
    drain(blender, budget, thread);
    EXPECT_EQ(differences(snapshot(result), snapshot(blendMorph(*sources, w2))), 0u);
}

// Waits until the thread has nothing left, as frames would.
void settle(const jobs::JobThread& thread) {
    while (thread.backlog() > 0) std::this_thread::yield();
}

TEST_F(BlendJobTest, NewWeightsDropTheJobUnderWay) {
    voxel::Volume result = blendMorph(*sources, w1);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    jobs::JobThread thread;
    BlendBudget budget = timed(0.2);
    blender.stepInBackground(budget, thread);  // the coarse pass, as one job
    settle(thread);
    // Its values are written (some of them) while the next job waits behind a gate.
    auto gate = std::make_shared<Gate>();
    thread.submit(gate);
    while (!gate->entered) std::this_thread::yield();
    EXPECT_GT(blender.stepInBackground(budget, thread).samples, 0u);
    ASSERT_EQ(thread.queued(), 1u);
    // New weights: the queued job (for w2) is never written.
    blender.restart(w3, {-2.0, 0.0, 0.0});
    EXPECT_EQ(blender.remainingSamples(), blender.totalSamples());
    EXPECT_EQ(blender.cursor(), 0u);
    EXPECT_FALSE(blender.coarseDone());
    EXPECT_FALSE(blender.inBackground());
    gate->open();
    settle(thread);
    const BlendStep dropped = blender.stepInBackground(budget, thread);
    EXPECT_EQ(dropped.samples, 0u) << "the old weights' job is dropped, and one for the new is handed over";
    EXPECT_TRUE(blender.inBackground());
    drain(blender, budget, thread);
    EXPECT_EQ(differences(snapshot(result), snapshot(blendMorph(*sources, w3))), 0u);
    EXPECT_EQ(leafOrigins(result), leafOrigins(blendMorph(*sources, w3)));
}

TEST_F(BlendJobTest, AViewerThatMovesKeepsTheJobsItems) {
    voxel::Volume result = makeMorphVolume(*sources);
    MorphBlender blender(*sources, result);
    blender.restart(w3, viewer);
    jobs::JobThread thread;
    BlendBudget budget = timed(0.1);
    const std::array<std::array<double, 3>, 3> places{{{-1.5, -1.0, 1.3}, {0.0, 2.0, 0.0}, {1.5, 1.1, -1.0}}};
    for (int steps = 0; !blender.done(); ++steps) {
        blender.setViewer(places[static_cast<std::size_t>(steps / 7) % places.size()]);
        blender.stepInBackground(budget, thread);
        ASSERT_LT(steps, 1000000);
        std::this_thread::yield();
    }
    EXPECT_EQ(differences(snapshot(result), snapshot(blendMorph(*sources, w3))), 0u);
}

TEST_F(BlendJobTest, AJobDroppedByAThreadThatStopsIsBlendedAgain) {
    voxel::Volume result = blendMorph(*sources, w1);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    BlendBudget budget = timed(0.2);
    {
        auto stopping = std::make_unique<jobs::JobThread>();
        auto gate = std::make_shared<Gate>();
        stopping->submit(gate);
        while (!gate->entered) std::this_thread::yield();
        blender.stepInBackground(budget, *stopping);  // its job waits behind the gate
        ASSERT_TRUE(blender.inBackground());
        // The thread stops: it takes the queued job off its queue (and
        // marks it done, not run) and then waits for the gate, the job under
        // way. The object lives until the gate opens, so it can be asked.
        jobs::JobThread* raw = stopping.get();
        std::thread stop([&stopping] { stopping.reset(); });
        while (raw->queued() > 0) std::this_thread::yield();
        gate->open();
        stop.join();
    }
    EXPECT_TRUE(blender.inBackground());
    jobs::JobThread thread;
    drain(blender, budget, thread);
    EXPECT_EQ(differences(snapshot(result), snapshot(blendMorph(*sources, w2))), 0u);
}

TEST_F(BlendJobTest, BackToTheFrameMidwayStartsTheListAgain) {
    voxel::Volume result = blendMorph(*sources, w1);
    MorphBlender blender(*sources, result);
    blender.restart(w2, viewer);
    jobs::JobThread thread;
    const BlendBudget timedBudget = timed(0.2);
    blender.stepInBackground(timedBudget, thread);
    settle(thread);
    auto gate = std::make_shared<Gate>();
    thread.submit(gate);
    while (!gate->entered) std::this_thread::yield();
    blender.stepInBackground(timedBudget, thread);  // writes part of the coarse pass; the next job waits
    ASSERT_TRUE(blender.inBackground());
    // The frame blends itself now, without waiting for the job behind the gate.
    BlendBudget counted;
    counted.maxSamples = 4099;
    blender.step(counted);
    EXPECT_FALSE(blender.inBackground());
    while (!blender.done()) blender.step(counted);
    EXPECT_EQ(differences(snapshot(result), snapshot(blendMorph(*sources, w2))), 0u);
    EXPECT_EQ(leafOrigins(result), leafOrigins(blendMorph(*sources, w2)));
    gate->open();
}

}  // namespace
}  // namespace hg::garden
