// What Monado (the open-source OpenXR runtime, docs/xr.md) does that the
// mock did not, played by the mock and met by the program: a predicted
// display period that grows while the app is slower than the display (the
// frame budget stays the display's period, from XR_FB_display_refresh_rate
// or else the smallest period seen), eyes of another size than the mock's
// (the level selection follows the eye's height) and not square (the mirror
// keeps the aspect).
#include "xr_garden_fixture.h"

#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb/stb_image.h>

#include "garden/app/frame_stats.h"
#include "garden/app/garden_session.h"
#include "garden/render/renderer.h"
#include "xr/mirror_fit.h"
#include "xr/xr_garden.h"

namespace hg::xr::test {
namespace {

constexpr double kDisplayPeriodMs = 11.111111;  // the mock's 90 Hz

class MonadoLike : public XrGarden {
protected:
    void TearDown() override {
        ::unsetenv("HG_MOCK_XR_APP_PERIODS");
        ::unsetenv("HG_MOCK_XR_VIEW_SIZE");
        ::unsetenv("HG_MOCK_XR_NO_REFRESH_RATE");
        ::unsetenv("HG_MOCK_XR_NO_DEPTH24");
        ::unsetenv("HG_MOCK_XR_BLEND_MODE");
        ::unsetenv("HG_MOCK_XR_EVENTS");
        XrGarden::TearDown();
    }
};

TEST_F(MonadoLike, TheBudgetIsTheDisplaysPeriodWhileTheRuntimePacesASlowApp) {
    // As Monado: a 16 ms placeholder first, then each frame paced to three
    // display periods; the display's 90 Hz through XR_FB_display_refresh_rate.
    ::setenv("HG_MOCK_XR_APP_PERIODS", "3", 1);
    XrOptions o = framesRun(10);
    std::vector<double> budgets;
    o.onFrame = [&](const garden::FrameStats& s, int) { budgets.push_back(s.budgetMs); };
    ASSERT_EQ(runXrGarden(o), 0);
    ASSERT_GE(budgets.size(), 8u);
    for (double b : budgets) EXPECT_NEAR(b, kDisplayPeriodMs, 0.01) << "not the paced period, 3 x 11.1 ms";
}

TEST_F(MonadoLike, WithoutTheRefreshRateTheBudgetIsTheSmallestPeriodSeen) {
    ::setenv("HG_MOCK_XR_NO_REFRESH_RATE", "1", 1);
    XrOptions o = framesRun(6);
    std::vector<double> budgets;
    o.onFrame = [&](const garden::FrameStats& s, int) { budgets.push_back(s.budgetMs); };
    ASSERT_EQ(runXrGarden(o), 0);
    ASSERT_FALSE(budgets.empty());
    for (double b : budgets) EXPECT_NEAR(b, kDisplayPeriodMs, 0.01);
}

TEST_F(MonadoLike, EyesThatAreNotSquareAreDrawnWhole) {
    // Monado's simulated headset under its main compositor: 1280 x 720
    // split side by side.
    ::setenv("HG_MOCK_XR_VIEW_SIZE", "640x720", 1);
    XrOptions o = framesRun(6);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_EQ(info.framesRendered, 5);
    const nlohmann::json j = readback();
    EXPECT_EQ(j["last_frame"]["image_size"], nlohmann::json::array({640, 720}));
    EXPECT_EQ(j["last_frame"]["depth_views"], 2);
    // The whole image is drawn: sky (or a cloud) at the top corners,
    // ground at the bottom ones, and the clear sky along the top blue and
    // no brighter than the horizon's clear colour.
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load((dir / "readback" / "left.png").c_str(), &w, &h, &n, 4);
    ASSERT_NE(px, nullptr);
    ASSERT_EQ(w, 640);
    ASSERT_EQ(h, 720);
    const auto at = [&](int x, int y, int c) { return static_cast<int>(px[(y * w + x) * 4 + c]); };
    for (int x : {4, w - 5}) {
        EXPECT_GT(at(x, 4, 0) + at(x, 4, 1) + at(x, 4, 2), 400) << "top, x " << x << ": the bright sky, drawn";
        EXPECT_GT(at(x, 4, 2) - at(x, h - 4, 2), 40) << "bottom, x " << x << ": the ground";
    }
    expectClearSkyInRow(px, w, 4);
    stbi_image_free(px);
}

TEST_F(MonadoLike, LevelsAreChosenForTheEyesOwnHeight) {
    // Monado's null compositor recommends 128 x 128 per eye.
    ::setenv("HG_MOCK_XR_VIEW_SIZE", "128x128", 1);
    XrOptions o = framesRun(4);
    int height = 0;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession& s, const XrRunInfo&) { height = s.settings().viewportHeight; }), 0);
    EXPECT_EQ(height, 128);
    EXPECT_EQ(readback()["last_frame"]["image_size"], nlohmann::json::array({128, 128}));
}

TEST_F(MonadoLike, DepthIsSubmittedWithoutA24BitFormat) {
    // Monado's GL client offers 32-bit float and 16-bit depth, never GL_DEPTH_COMPONENT24.
    ::setenv("HG_MOCK_XR_NO_DEPTH24", "1", 1);
    XrOptions o = framesRun(4);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0);
    EXPECT_TRUE(info.depthSubmitted);
    const nlohmann::json j = readback();
    EXPECT_EQ(j["last_frame"]["depth_views"], 2);
    EXPECT_EQ(j["last_frame"]["depth_format"], 0x8CAC) << "GL_DEPTH_COMPONENT32F";
}

TEST_F(MonadoLike, TheBudgetFollowsTheDisplaysRefreshRateWhenItChanges) {
    // XR_FB_display_refresh_rate's event: the display goes from 90 to 60 Hz.
    ::setenv("HG_MOCK_XR_EVENTS", "5:refresh_60", 1);
    XrOptions o = framesRun(10);
    std::vector<double> budgets;
    o.onFrame = [&](const garden::FrameStats& s, int) { budgets.push_back(s.budgetMs); };
    ASSERT_EQ(runXrGarden(o), 0);
    ASSERT_GE(budgets.size(), 8u);
    EXPECT_NEAR(budgets.front(), kDisplayPeriodMs, 0.01);
    EXPECT_NEAR(budgets.back(), 1000.0 / 60.0, 0.01);
}

TEST_F(MonadoLike, ASeeThroughHeadsetGetsFramesInItsBlendMode) {
    // Monado's simulated headset offers OPAQUE only; another may offer only ADDITIVE.
    ::setenv("HG_MOCK_XR_BLEND_MODE", "additive", 1);
    XrOptions o = framesRun(5);
    XrRunInfo info;
    ASSERT_EQ(runXrGarden(o, [&](garden::GardenSession&, const XrRunInfo& i) { info = i; }), 0)
        << "xrEndFrame refuses OPAQUE";
    EXPECT_EQ(info.framesSubmitted, 5);
    EXPECT_EQ(readback()["frames_with_two_views"], 4);
}

TEST(MirrorFit, KeepsTheEyesAspectCentred) {
    // Monado's 640 x 720 eye in the 640 x 640 mirror: bars left and right.
    MirrorRect r = fitMirror({640, 720}, {640, 640});
    EXPECT_EQ(r.size, glm::ivec2(569, 640));
    EXPECT_EQ(r.offset, glm::ivec2(35, 0));
    // A wide eye: bars above and below.
    r = fitMirror({1000, 500}, {640, 640});
    EXPECT_EQ(r.size, glm::ivec2(640, 320));
    EXPECT_EQ(r.offset, glm::ivec2(0, 160));
    // The window's own aspect fills it.
    r = fitMirror({512, 512}, {640, 640});
    EXPECT_EQ(r.size, glm::ivec2(640, 640));
    EXPECT_EQ(r.offset, glm::ivec2(0, 0));
    r = fitMirror({1280, 720}, {1920, 1080});
    EXPECT_EQ(r.size, glm::ivec2(1920, 1080));
    EXPECT_EQ(r.offset, glm::ivec2(0, 0));
}

TEST(MirrorFit, NothingToShowGivesAnEmptyRectangle) {
    EXPECT_EQ(fitMirror({0, 720}, {640, 640}).size, glm::ivec2(0));
    EXPECT_EQ(fitMirror({640, 720}, {0, 0}).size, glm::ivec2(0));
}

}  // namespace
}  // namespace hg::xr::test
