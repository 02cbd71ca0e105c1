// Sculptures hidden behind nearer ones (garden/render/visibility_queries.h,
// the view's use in garden/window/garden_view.cpp): left out of the scene
// pass once an occlusion query found their box hidden, and the picture is
// the same as with every sculpture drawn, frame by frame, while the eye
// walks out from behind a wall and the hidden sculptures come into view,
// shadows included (a hidden sculpture still casts).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "../render/gl_fixture.h"
#include "garden/action/action.h"
#include "garden/app/garden_session.h"
#include "garden/render/visibility_queries.h"
#include "garden/window/garden_view.h"
#include "tests/test_folder.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

// A wall 3 m wide, 2 m tall and 0.3 m deep.
const char* const kWall =
    "wall(x[3], a[1]) {\n"
    "  wall = (1.5 - x[1]) & (1.5 + x[1]) & x[2] & (2 - x[2]) & (0.15 - x[3]) & (0.15 + x[3]);\n"
    "}\n";
// A stem and a cap, 1.45 m tall.
const char* const kMushroom =
    "mushroom(x[3], a[1]) {\n"
    "  stem = 0.09 - (x[1]^2 + x[3]^2);\n"
    "  stem = stem & x[2] & (1.2 - x[2]);\n"
    "  cap = 0.25 - (x[1]^2 + (x[2] - 1.2)^2 + x[3]^2);\n"
    "  mushroom = stem | cap;\n"
    "}\n";

class HiddenSculpturesTest : public test::GlTest {
protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        folder_ = std::make_unique<hg::test::TestFolder>("hg_hidden_sculptures");
        fs::create_directories(folder_->path);
        std::ofstream(folder_->path / "wall.hf") << kWall;
        std::ofstream(folder_->path / "mushroom.hf") << kMushroom;
        // The sun low from the -x side: the mushrooms' shadows reach out past the wall's end.
        std::ofstream out(folder_->path / "garden.json");
        out << R"({"version": 1, "name": "hidden", "materials": {"grey": {"color": [0.6, 0.6, 0.6]},)"
            << R"( "red": {"color": [0.85, 0.12, 0.1]}},)"
            << R"( "lights": [{"type": "directional", "direction": [0.85, -0.45, 0.25], "intensity": 1.0},)"
            << R"( {"type": "ambient", "color": [1, 1, 1], "intensity": 0.25}], "sculptures": [)"
            << R"({"name": "wall", "file": "wall.hf", "resolution": 48, "material": "grey",)"
            << R"( "box": {"min": [-1.6, -0.05, -0.25], "max": [1.6, 2.1, 0.25]}, "placement": {"position": [0, 0, 0]}})";
        for (int i = 0; i < 3; ++i)
            out << R"(, {"name": "m)" << i << R"(", "file": "mushroom.hf", "resolution": 40, "material": "red",)"
                << R"( "box": {"min": [-0.55, -0.05, -0.55], "max": [0.55, 1.5, 0.55]},)"
                << R"( "placement": {"position": [)" << (i - 1) * 0.9 << ", 0, -2.5]}}";
        out << "]}";
    }
    void TearDown() override {
        folder_.reset();
        test::GlTest::TearDown();
    }

    SessionSettings settings() const {
        SessionSettings s;
        s.chunkSize = 16;
        s.maxLevel = 1;
        s.viewportHeight = kHeight;
        s.fovY = glm::radians(double(kFovY));
        s.remeshChunksPerFrame = 4096;
        return s;
    }

    // The garden with the eye 6 m in front of the wall, flying.
    std::unique_ptr<GardenSession> openInFrontOfTheWall() const {
        auto session = std::make_unique<GardenSession>(loadGarden((folder_->path / "garden.json").string()), settings());
        session->navigator().setMode(NavigationMode::Fly);
        session->navigator().setPose({0.0f, 1.2f, 6.0f}, 0.0f, 0.0f);
        return session;
    }
    // Frames until every sculpture is sampled and meshed.
    static void settle(GardenSession& session) {
        for (int f = 0; f < 3000 && !session.idle(); ++f) session.frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(session.idle());
    }

    RenderStats draw(Renderer& renderer, GardenView& view, const GardenSession& session, const glm::vec3& eye,
                     const glm::vec3& at) {
        target_->bind();
        const glm::mat4 v = glm::lookAt(eye, at, glm::vec3(0, 1, 0));
        const glm::mat4 p = glm::perspective(glm::radians(kFovY), float(kWidth) / float(kHeight), kNear, kFar);
        view.render(session, {kWidth, kHeight}, v, p, eye);
        const RenderStats stats = renderer.endFrame();
        read();
        return stats;
    }

    // Renders the view from `eye` with culling (into `picture`) and with
    // everything drawn (left in color_); returns the culled frame's stats.
    RenderStats drawBoth(Renderer& everything, GardenView& culled, GardenView& all, const GardenSession& session,
                         const glm::vec3& eye, const glm::vec3& at, std::vector<std::uint8_t>& picture) {
        const RenderStats c = draw(*renderer_, culled, session, eye, at);
        picture = color_;
        draw(everything, all, session, eye, at);
        return c;
    }

    static int redPixels(const std::vector<std::uint8_t>& rgba) {
        int red = 0;
        for (std::size_t i = 0; i < rgba.size(); i += 4) red += rgba[i] > rgba[i + 1] + 40 && rgba[i] > rgba[i + 2] + 40;
        return red;
    }

    std::unique_ptr<hg::test::TestFolder> folder_;
};

// The eye 6 m in front of the wall, then sideways 2 cm a frame out past
// its end, then back behind the wall and out in one jump: every frame is
// the picture with every sculpture drawn (a second renderer in the same
// context, culling off), while at the start the three mushrooms behind the
// wall are left out. (The jump is what a result trusted after the eye
// moved would get wrong.) Then one of them is moved out past the wall's
// end: drawn in the very next frame.
TEST_F(HiddenSculpturesTest, TheWalkOutFromBehindAWallShowsWhatDrawingEverythingShows) {
    const std::unique_ptr<GardenSession> opened = openInFrontOfTheWall();
    GardenSession& session = *opened;
    settle(session);
    if (HasFatalFailure()) return;

    RenderQuality q = test::plainQuality();
    q.shadows = true;
    renderer_->setQuality(q);
    ASSERT_TRUE(renderer_->occlusionCulling()) << "on by default";
    GardenView culled(*renderer_);
    culled.upload(session, 1e9);
    Renderer everything;
    everything.setQuality(q);
    everything.setOcclusionCulling(false);
    GardenView all(everything);
    all.upload(session, 1e9);

    int framesWithHidden = 0, framesCompared = 0, mushroomPixelsSeen = 0;
    std::size_t hiddenAtStart = 0, trianglesCulled = 0, trianglesAll = 0;
    // Three frames standing still first (the queries' results come in),
    // the walk out, three frames back behind the wall, and one jump out.
    std::vector<float> walk = {0.0f, 0.0f, 0.0f};
    for (int step = 0; step <= 200; ++step) walk.push_back(0.02f * static_cast<float>(step));
    walk.insert(walk.end(), {0.0f, 0.0f, 0.0f, 4.0f});
    for (std::size_t step = 0; step < walk.size(); ++step) {
        const float x = walk[step];
        const glm::vec3 eye(x, 1.2f, 6.0f), at(x, 1.0f, 0.0f);
        const RenderStats c = draw(*renderer_, culled, session, eye, at);
        const std::vector<std::uint8_t> picture = color_;
        const RenderStats a = draw(everything, all, session, eye, at);
        EXPECT_EQ(a.sculpturesHidden, 0u);
        if (step == 3) {
            hiddenAtStart = c.sculpturesHidden;
            trianglesCulled = c.trianglesDrawn;
            trianglesAll = a.trianglesDrawn;
        }
        framesWithHidden += c.sculpturesHidden > 0;
        int differ = 0, red = 0;
        for (std::size_t i = 0; i < picture.size(); i += 4) {
            differ += picture[i] != color_[i] || picture[i + 1] != color_[i + 1] || picture[i + 2] != color_[i + 2];
            red += color_[i] > color_[i + 1] + 40 && color_[i] > color_[i + 2] + 40;
        }
        mushroomPixelsSeen = std::max(mushroomPixelsSeen, red);
        ++framesCompared;
        ASSERT_EQ(differ, 0) << "at x = " << x << " m the picture differs from drawing everything (" << c.sculpturesHidden
                             << " left out)";
    }
    // Back behind the wall, and one of the hidden mushrooms moved out past
    // its end: drawn at once, though its last test found it hidden.
    RenderStats behind;
    for (int f = 0; f < 3; ++f) behind = draw(*renderer_, culled, session, {0.0f, 1.2f, 6.0f}, {0.0f, 1.0f, 0.0f});
    ASSERT_EQ(behind.sculpturesHidden, 3u);
    ASSERT_EQ(session.apply(MoveAction{"m2", Placement{{3.2, 0.0, -2.5}, 0.0, 1.0}}), "");
    const RenderStats moved = draw(*renderer_, culled, session, {0.0f, 1.2f, 6.0f}, {0.0f, 1.0f, 0.0f});
    const std::vector<std::uint8_t> picture = color_;
    draw(everything, all, session, {0.0f, 1.2f, 6.0f}, {0.0f, 1.0f, 0.0f});
    EXPECT_EQ(picture, color_) << "the moved mushroom is drawn";
    EXPECT_GT(redPixels(picture), 200) << "and in view past the wall's end";
    // Its neighbours' results were forgotten too (it stood beside them: the
    // test is conservative); tested again, they are left out again.
    EXPECT_LE(moved.sculpturesHidden, 2u);
    RenderStats later;
    for (int f = 0; f < 4; ++f) later = draw(*renderer_, culled, session, {0.0f, 1.2f, 6.0f}, {0.0f, 1.0f, 0.0f});
    EXPECT_EQ(later.sculpturesHidden, 2u) << "the two still behind the wall";

    std::printf("hidden at the start %zu, triangles %zu of %zu; frames with some hidden %d of %d; red pixels at most %d\n",
                hiddenAtStart, trianglesCulled, trianglesAll, framesWithHidden, framesCompared, mushroomPixelsSeen);
    EXPECT_EQ(hiddenAtStart, 3u) << "the three mushrooms behind the wall";
    EXPECT_LT(trianglesCulled, trianglesAll);
    EXPECT_GT(mushroomPixelsSeen, 1000) << "the walk ends with the mushrooms in view";
    EXPECT_LT(framesWithHidden, framesCompared) << "and drawn";
}

// The eye stands still behind the wall and the wall changes instead: a
// hole carved through it, then the wall moved aside. Each time the
// mushrooms it hid are drawn in the very first frame that shows the
// change (the results behind a changed sculpture are forgotten, tests in
// flight included), not when the results grow too old to trust.
TEST_F(HiddenSculpturesTest, WhatAChangedOccluderHidIsDrawnInTheNextFrame) {
    const std::unique_ptr<GardenSession> opened = openInFrontOfTheWall();
    GardenSession& session = *opened;
    settle(session);
    if (HasFatalFailure()) return;
    renderer_->setQuality(test::plainQuality());
    GardenView culled(*renderer_);
    Renderer everything;
    everything.setQuality(test::plainQuality());
    everything.setOcclusionCulling(false);
    GardenView all(everything);
    const glm::vec3 eye(0.0f, 1.2f, 6.0f), at(0.0f, 1.0f, 0.0f);
    std::vector<std::uint8_t> picture;
    const auto show = [&] {
        culled.upload(session, 1e9);
        all.upload(session, 1e9);
        return drawBoth(everything, culled, all, session, eye, at, picture);
    };
    RenderStats stats;
    for (int f = 0; f < 4; ++f) stats = show();
    ASSERT_EQ(stats.sculpturesHidden, 3u);
    ASSERT_EQ(picture, color_);
    ASSERT_EQ(redPixels(picture), 0) << "the wall hides every mushroom";

    // A hole 0.3 m across through the wall, in front of the middle mushroom's cap.
    ASSERT_EQ(session.apply(StrokeAction{"wall", StrokeTool::Carve, 0.15, 2.0, {{0.0, 1.15, 0.45}, {0.0, 1.15, -0.45}}, {},
                                         1.0, Falloff::Smooth, {}}),
              "");
    settle(session);
    stats = show();
    EXPECT_EQ(picture, color_) << "the frame after the carve equals drawing everything";
    EXPECT_GT(redPixels(picture), 100) << "the middle mushroom shows through the hole";
    EXPECT_LT(stats.sculpturesHidden, 3u);
    for (int f = 0; f < 4; ++f) stats = show();
    EXPECT_EQ(picture, color_);
    EXPECT_EQ(stats.sculpturesHidden, 2u) << "the other two are still behind the wall, and left out again";

    ASSERT_EQ(session.apply(MoveAction{"wall", Placement{{5.0, 0.0, 0.0}, 0.0, 1.0}}), "");
    settle(session);
    stats = show();
    EXPECT_EQ(picture, color_) << "the frame after the wall moved aside equals drawing everything";
    EXPECT_EQ(stats.sculpturesHidden, 0u);
    EXPECT_GT(redPixels(picture), 1000) << "all three mushrooms in view";
}

// A still view held (Renderer::setPictureReuse, the desktop's): the boxes
// are tested against the held picture's depth, so the results stay fresh
// and the hidden mushrooms stay left out; the view is kept frame after
// frame instead of being drawn again each time the results grow too old
// to trust. And the wall moved aside is drawn in the next frame.
TEST_F(HiddenSculpturesTest, AStillViewHeldKeepsWhatItHidesLeftOut) {
    const std::unique_ptr<GardenSession> opened = openInFrontOfTheWall();
    GardenSession& session = *opened;
    settle(session);
    if (HasFatalFailure()) return;
    renderer_->setQuality(test::plainQuality());
    renderer_->setPictureReuse(true);
    GardenView view(*renderer_);
    view.upload(session, 1e9);
    const glm::vec3 eye(0.0f, 1.2f, 6.0f), at(0.0f, 1.0f, 0.0f);
    RenderStats stats;
    for (int f = 0; f < 6; ++f) stats = draw(*renderer_, view, session, eye, at);
    ASSERT_EQ(stats.sculpturesHidden, 3u);
    const std::vector<std::uint8_t> held = color_;
    int kept = 0;
    for (int f = 0; f < 4 * int(VisibilityQueries::kTrustedFrames); ++f) {
        stats = draw(*renderer_, view, session, eye, at);
        EXPECT_EQ(stats.sculpturesHidden, 3u) << "frame " << f;
        kept += int(stats.picturesKept);
        EXPECT_EQ(color_, held);
    }
    EXPECT_EQ(kept, 4 * int(VisibilityQueries::kTrustedFrames)) << "every still frame kept";

    ASSERT_EQ(session.apply(MoveAction{"wall", Placement{{5.0, 0.0, 0.0}, 0.0, 1.0}}), "");
    settle(session);
    view.upload(session, 1e9);
    stats = draw(*renderer_, view, session, eye, at);
    EXPECT_EQ(stats.picturesKept, 0u);
    EXPECT_EQ(stats.sculpturesHidden, 0u);
    EXPECT_GT(redPixels(color_), 1000) << "all three mushrooms in view in the next frame";
}

}  // namespace
}  // namespace hg::garden
