// The sampler's progress and cancel (io/progress.h): reports from its
// workers reach the display rising to 1, and a cancel part way stops the
// sampling at once (the boxes left are skipped) with a cancelled outcome
// and no volume.
#include <gtest/gtest.h>

#include "test_models.h"
#include "tests/progress_recorder.h"
#include "voxel/sampler.h"

namespace hg::voxel {
namespace {

VolumeRequest request(int resolution) {
    VolumeRequest r;
    r.resolution = resolution;
    return r;
}

TEST(SamplerProgress, ReportsRiseToOneFromTheWorkers) {
    const frep::Model model = test::modelFromSource(test::kTorusBlock);
    ::hg::test::RecordingProgress progress;
    SampleOptions options;
    options.progress = &progress;
    const VoxelizeResult r = voxelize(model, request(192), options);
    ASSERT_TRUE(r.volume) << r.error;
    EXPECT_FALSE(r.cancelled);
    EXPECT_FALSE(progress.overlapped());
    EXPECT_TRUE(progress.risesTo(1.0));
    EXPECT_GT(progress.fractions().size(), 20u);
}

TEST(SamplerProgress, CancelledPartWayItStopsPromptlyWithACancelledOutcome) {
    const frep::Model model = test::modelFromSource(test::kTorusBlock);
    // Cancelled by the display once a fifth is done: the boxes under way
    // finish (one per worker), the rest are skipped.
    ::hg::test::RecordingProgress progress(0.2);
    SampleOptions options;
    options.progress = &progress;
    const VoxelizeResult r = voxelize(model, request(256), options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.volume);
    EXPECT_EQ(r.error, io::kCancelled);
    ASSERT_FALSE(progress.fractions().empty());
    EXPECT_GE(progress.fractions().back(), 0.2);
    EXPECT_LT(progress.fraction(), 0.5) << "the sampling went on after the cancel";

    // Cancelled before it starts (the session closing): nothing is sampled.
    io::NullProgress closed;
    closed.cancel();
    options.progress = &closed;
    const VoxelizeResult none = voxelize(model, request(256), options);
    EXPECT_TRUE(none.cancelled);
    EXPECT_FALSE(none.volume);
    EXPECT_EQ(closed.fraction(), 0.0);

    // The same request uncancelled still samples as before.
    const VoxelizeResult whole = voxelize(model, request(64));
    ASSERT_TRUE(whole.volume) << whole.error;
    EXPECT_FALSE(whole.cancelled);
}

}  // namespace
}  // namespace hg::voxel
