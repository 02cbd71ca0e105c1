// io/progress.h, the one progress-and-cancel interface: ranges map a
// stage's fractions into its parent's, cancel is shared and sticky, and
// reports from many threads reach report() one at a time, rising, ending
// at 1.
#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "io/progress.h"
#include "tests/progress_recorder.h"

namespace hg::io {
namespace {

TEST(Progress, ARangeMapsItsFractionsIntoItsParents) {
    test::RecordingProgress whole;
    {
        ProgressRange first(&whole, 0.0, 1.0 / 3.0);
        EXPECT_FALSE(first.interrupted(0.0));
        EXPECT_FALSE(first.interrupted(1.0));
    }
    ProgressRange second(&whole, 1.0 / 3.0, 2.0 / 3.0);
    second.interrupted(0.5);
    // A stage of a stage: the second half of stage 2.
    ProgressRange inner(&second, 0.5, 1.0);
    inner.interrupted(0.5);
    inner.interrupted(1.0);
    ASSERT_EQ(whole.fractions().size(), 5u);
    EXPECT_DOUBLE_EQ(whole.fractions()[0], 0.0);
    EXPECT_DOUBLE_EQ(whole.fractions()[1], 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(whole.fractions()[2], 0.5);
    EXPECT_DOUBLE_EQ(whole.fractions()[3], 1.0 / 3.0 + 0.75 / 3.0);
    EXPECT_DOUBLE_EQ(whole.fractions()[4], 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(whole.fraction(), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(inner.fraction(), 1.0);
}

TEST(Progress, OnlyLargerFractionsAreShownAndAskingReportsNothing) {
    test::RecordingProgress p;
    EXPECT_DOUBLE_EQ(p.fraction(), 0.0);
    p.interrupted(0.4);
    p.interrupted(0.2);  // late, from a slower thread: not shown
    p.interrupted(-1.0);
    p.interrupted(std::numeric_limits<double>::quiet_NaN());
    p.interrupted();
    p.interrupted(7.0);  // past the end: shown as 1
    p.interrupted(1.0);
    ASSERT_EQ(p.fractions().size(), 2u);
    EXPECT_DOUBLE_EQ(p.fractions()[0], 0.4);
    EXPECT_DOUBLE_EQ(p.fractions()[1], 1.0);
}

TEST(Progress, CancelIsSharedWithRangesAndSticky) {
    NullProgress root;
    ProgressRange stage(&root, 0.2, 0.8);
    ProgressRange step(&stage, 0.0, 0.5);
    EXPECT_FALSE(step.interrupted(0.5));
    EXPECT_FALSE(root.cancelled());
    root.cancel();  // the Cancel button
    EXPECT_TRUE(stage.cancelled());
    EXPECT_TRUE(step.cancelled());
    EXPECT_TRUE(step.interrupted(0.9));
    EXPECT_TRUE(root.interrupted());
    EXPECT_DOUBLE_EQ(root.fraction(), 0.2 + 0.25 * 0.6) << "nothing is reported once cancelled";

    // A range's cancel stops the whole work; a range with no parent has a flag of its own.
    NullProgress other;
    ProgressRange part(&other, 0.0, 1.0);
    part.cancel();
    EXPECT_TRUE(other.cancelled());
    ProgressRange alone(nullptr, 0.0, 0.5);
    EXPECT_FALSE(alone.interrupted(0.3));
    alone.cancel();
    EXPECT_TRUE(alone.interrupted());
}

TEST(Progress, AReportThatSaysStopCancels) {
    test::RecordingProgress p(0.5);
    ProgressRange half(&p, 0.5, 1.0);
    EXPECT_FALSE(p.interrupted(0.25));
    EXPECT_TRUE(half.interrupted(0.0)) << "0.5 of the whole: the display said stop";
    EXPECT_TRUE(p.cancelled());
    EXPECT_TRUE(half.cancelled());
}

// The sampler and the meshers report from TBB workers, out of order.
TEST(Progress, ReportsFromManyThreadsAreShownOneAtATimeRisingToOne) {
    test::RecordingProgress whole;
    ProgressRange stage(&whole, 0.5, 1.0);
    whole.interrupted(0.5);
    constexpr std::size_t kSteps = 20000;
    tbb::parallel_for(std::size_t{0}, kSteps, [&](std::size_t i) {
        stage.interrupted(static_cast<double>(i + 1) / kSteps);
        EXPECT_FALSE(stage.cancelled());
    });
    EXPECT_FALSE(whole.overlapped()) << "report() was entered by two threads at once";
    EXPECT_TRUE(whole.risesTo(1.0));
    EXPECT_GT(whole.fractions().size(), 2u);
    EXPECT_DOUBLE_EQ(stage.fraction(), 1.0);

    // A cancel from another thread is seen by every worker's cheap check.
    NullProgress shared;
    std::atomic<std::size_t> afterCancel{0};
    tbb::parallel_for(std::size_t{0}, kSteps, [&](std::size_t i) {
        if (i == kSteps / 10) shared.cancel();
        if (shared.cancelled()) ++afterCancel;
    });
    EXPECT_TRUE(shared.cancelled());
    EXPECT_GT(afterCancel.load(), 0u);
}

}  // namespace
}  // namespace hg::io
