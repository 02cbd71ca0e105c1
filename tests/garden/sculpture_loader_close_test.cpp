// Closing a session while the background loader samples (garden/app/
// sculpture_loader.h): the sampling under way is cancelled through
// io/progress.h, so the close does not wait for a large sculpture to finish.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

#include "garden/app/sculpture_loader.h"
#include "tests/test_models.h"

namespace hg::garden {
namespace {

using Clock = std::chrono::steady_clock;

TEST(SculptureLoaderClose, ClosingCancelsTheSamplingUnderWay) {
    auto load = std::make_shared<SculptureLoad>();
    load->model = ::hg::test::modelFromSource(::hg::test::kTorusBlock);
    voxel::VolumeRequest request;
    request.box = frep::Box3{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
    request.resolution = 384;

    // How long the sculpture takes to sample whole.
    const auto t0 = Clock::now();
    const voxel::VoxelizeResult whole = voxel::voxelize(*load->model, request);
    const double sampling = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_TRUE(whole.volume) << whole.error;

    SculptureLoader::Job job;
    job.source = load;
    job.request = request;
    const auto t1 = Clock::now();
    {
        SculptureLoader loader({job}, {0.0, 0.0, 0.0});
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        EXPECT_EQ(loader.remaining(), 1u);
    }  // closed with the sampling under way
    const double closing = std::chrono::duration<double>(Clock::now() - t1).count();
    EXPECT_LT(closing, 0.5 * sampling) << "the close waited for the sampling (" << sampling << " s whole)";
}

}  // namespace
}  // namespace hg::garden
