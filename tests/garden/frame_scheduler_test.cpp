// The frame scheduler: stages are timed and add up to at most the frame,
// the morph gets at most its share of what is left, allowances shrink as
// the frame goes on and never drop below the minimum, and each frame lands
// in the history.
#include <gtest/gtest.h>

#include <thread>

#include "garden/app/frame_scheduler.h"

namespace hg::garden {
namespace {

void spin(double ms) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double, std::milli>(ms);
    while (std::chrono::steady_clock::now() < end) {}
}

TEST(FrameScheduler, TimesStagesAndSharesTheBudget) {
    SchedulerSettings s;
    s.budgetMs = 20.0;
    s.morphShare = 0.5;
    FrameScheduler f(s);
    f.beginFrame();
    f.beginStage(Stage::Input);
    spin(2.0);
    f.beginStage(Stage::Morph);
    const double morph = f.allowanceMs(Stage::Morph), remesh = f.allowanceMs(Stage::Remesh);
    EXPECT_LE(morph, 0.5 * (20.0 - s.marginMs - 2.0) + 1e-9) << "the margin stays free";
    EXPECT_GT(remesh, morph);
    spin(3.0);
    EXPECT_LT(f.allowanceMs(Stage::Remesh), remesh - 2.5);
    f.beginStage(Stage::Render);
    spin(1.0);
    const FrameStats& st = f.endFrame();
    double sum = 0;
    for (double t : st.stageMs) sum += t;
    EXPECT_GE(st.stageMs[static_cast<int>(Stage::Input)], 2.0);
    EXPECT_GE(st.stageMs[static_cast<int>(Stage::Morph)], 3.0);
    EXPECT_LE(sum, st.totalMs + 1e-6);
    EXPECT_GE(st.totalMs, 6.0);
    ASSERT_EQ(f.history().frames().size(), 1u);
    EXPECT_EQ(f.history().last()->frame, 0u);

    // Next frame: the render reserve comes off the remesh allowance.
    f.beginFrame();
    EXPECT_LE(f.allowanceMs(Stage::Remesh), 20.0 - s.marginMs - st.stageMs[static_cast<int>(Stage::Render)] + 1e-6);
    spin(25.0);
    EXPECT_EQ(f.allowanceMs(Stage::Remesh), s.minimumMs) << "over budget: only the minimum";
    f.endFrame();
    EXPECT_EQ(f.history().frames().size(), 2u);
}

TEST(FrameHistory, KeepsTheLastFrames) {
    FrameHistory h(3);
    for (std::uint64_t i = 0; i < 5; ++i) {
        FrameStats s;
        s.frame = i;
        h.push(s);
    }
    ASSERT_EQ(h.frames().size(), 3u);
    EXPECT_EQ(h.frames().front().frame, 2u);
    EXPECT_EQ(h.last()->frame, 4u);
    EXPECT_STREQ(stageName(Stage::Remesh), "remesh");
}

}  // namespace
}  // namespace hg::garden
