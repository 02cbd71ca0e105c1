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

TEST(SculptureLoaderClose, ClosingCancelsTheSamplingUnderWay) {
    auto load = std::make_shared<SculptureLoad>();
    load->model = ::hg::test::modelFromSource(::hg::test::kTorusBlock);
    SculptureLoader::Job job;
    job.source = load;
    job.request.box = frep::Box3{{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}};
    job.request.resolution = 1024;  // seconds to sample whole: the close comes far before its end

    SculptureLoader loader({job}, {0.0, 0.0, 0.0});
    // Until the sampling has reported some progress: it is under way.
    for (int i = 0; i < 60000 && loader.fractionUnderWay() <= 0.0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ASSERT_GT(loader.fractionUnderWay(), 0.0) << "the sampling never started";
    EXPECT_EQ(loader.remaining(), 1u);
    EXPECT_TRUE(loader.close()) << "the sampling under way ran to its end";
    EXPECT_TRUE(loader.take().empty()) << "a cancelled sampling is nobody's grid";
}

}  // namespace
}  // namespace hg::garden
