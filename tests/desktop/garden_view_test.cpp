// The garden drawn: a session of the small garden, settled, rendered by
// GardenView into an offscreen target. The ball in front covers its
// projected disc, its depth is its distance, the ground is below and the
// sky above; uploads happen once per shown mesh.
#include <filesystem>

#include "../garden/session_garden.h"
#include "../render/gl_fixture.h"
#include "garden/app/garden_session.h"
#include "garden/desktop/garden_view.h"

namespace hg::garden {
namespace {

class GardenViewTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        scratch_ = std::filesystem::temp_directory_path() / ("hg_view_" + std::to_string(::getpid()));
        std::filesystem::create_directories(scratch_);
    }
    void TearDown() override {
        std::filesystem::remove_all(scratch_);
        test::GlTest::TearDown();
    }
    std::filesystem::path scratch_;
};

TEST_F(GardenViewTest, TheSettledGardenShowsItsSculpturesAtTheirDepth) {
    SessionSettings settings;
    settings.chunkSize = 16;
    settings.maxLevel = 1;
    settings.viewportHeight = kHeight;
    settings.fovY = glm::radians(double(kFovY));
    GardenSession session(loadGarden(test::writeSmallGarden(scratch_)), settings);
    // Fly 3 m in front of ball c (radius 0.6, centre (2, 0.5, 1.1547)),
    // looking along -z: ball a shows small to the left, the rest is out of view.
    session.navigator().setMode(NavigationMode::Fly);
    session.navigator().setPose({2.0f, 0.5f, 4.1547f}, 0.0f, 0.0f);
    for (int f = 0; f < 500 && !session.idle(); ++f) {
        session.frame(FrameInput(Hands{}, 1.0 / 90.0));
    }
    ASSERT_TRUE(session.idle());

    GardenView view(*renderer_);
    const ViewUpload first = view.upload(session, 1e9);
    EXPECT_GT(first.bytes, 0u);
    EXPECT_EQ(first.pending, 0u);
    EXPECT_EQ(view.upload(session, 1e9).bytes, 0u) << "nothing changed: nothing uploaded again";
    target_->bind();
    view.render(session, {kWidth, kHeight}, glm::radians(kFovY));
    const RenderStats stats = renderer_->endFrame();
    EXPECT_GT(stats.trianglesDrawn, 500u);
    read();

    // Coverage: the red disc of ball c around the image centre, and no red
    // in a ring just outside the disc.
    const double r = discRadiusPixels(0.6, 3.0);
    int inDisc = 0, inRing = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double d = std::hypot(x + 0.5 - kWidth / 2.0, y + 0.5 - kHeight / 2.0);
            if (!test::reddish(pixel(x, y))) continue;
            if (d <= 1.05 * r) ++inDisc;
            else if (d <= 1.2 * r) ++inRing;
        }
    EXPECT_NEAR(inDisc, test::kPi * r * r, 0.06 * test::kPi * r * r);
    EXPECT_LT(inRing, 0.02 * test::kPi * r * r);
    EXPECT_TRUE(test::reddish(pixel(kWidth / 2, kHeight / 2)));
    // Depth: the ball's front at 2.4 m, the ground below, the sky above.
    EXPECT_NEAR(eyeDepth(depth(kWidth / 2, kHeight / 2)), 2.4, 0.04);
    EXPECT_LT(depth(kWidth / 2, kHeight - 2), 1.0f) << "ground at the bottom";
    EXPECT_GT(eyeDepth(depth(kWidth / 2, kHeight - 2)), 0.3);
    EXPECT_EQ(depth(kWidth / 2, 2), 1.0f) << "sky at the top";
    EXPECT_FALSE(test::reddish(pixel(kWidth / 2, kHeight - 2)));

    // Facing away from every sculpture: no chunk passes the frustum test.
    session.navigator().setPose({2.0f, 0.5f, 9.0f}, glm::pi<float>(), 0.0f);
    target_->bind();
    view.render(session, {kWidth, kHeight}, glm::radians(kFovY));
    const RenderStats away = renderer_->endFrame();
    EXPECT_LT(away.trianglesDrawn, 16u) << "the ground at most";
    read();
    EXPECT_EQ(count(test::reddish), 0);
}

}  // namespace
}  // namespace hg::garden
