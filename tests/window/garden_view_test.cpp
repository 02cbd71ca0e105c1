// The garden drawn: a session of the small garden, settled, rendered by
// GardenView into an offscreen target. The ball in front covers its
// projected disc, its depth is its distance, the ground is below and the
// sky above; uploads happen once per shown mesh.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>

#include "../garden/session_garden.h"
#include "../render/gl_fixture.h"
#include "garden/app/garden_session.h"
#include "garden/render/shapes.h"
#include "garden/window/garden_view.h"

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
    // The small garden, flown 3 m in front of ball c (radius 0.6, centre
    // (2, 0.5, 1.1547)) looking along -z, and settled.
    std::unique_ptr<GardenSession> settledSmallGarden() {
        SessionSettings settings;
        settings.chunkSize = 16;
        settings.maxLevel = 1;
        settings.viewportHeight = kHeight;
        settings.fovY = glm::radians(double(kFovY));
        auto session = std::make_unique<GardenSession>(loadGarden(test::writeSmallGarden(scratch_)), settings);
        session->navigator().setMode(NavigationMode::Fly);
        session->navigator().setPose({2.0f, 0.5f, 4.1547f}, 0.0f, 0.0f);
        for (int f = 0; f < 500 && !session->idle(); ++f) session->frame(FrameInput(Hands{}, 1.0 / 90.0));
        EXPECT_TRUE(session->idle());
        return session;
    }
    std::filesystem::path scratch_;
};

TEST_F(GardenViewTest, TheSettledGardenShowsItsSculpturesAtTheirDepth) {
    // Ball c ahead; ball a shows small to the left, the rest is out of view.
    const std::unique_ptr<GardenSession> settled = settledSmallGarden();
    ASSERT_TRUE(settled->idle());
    GardenSession& session = *settled;

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

// A sculpture without a box whose file changes its solid's extent (a ball
// of radius 0.8 made a flat ellipsoid 1.6 by 0.8 by 0.8) is rebuilt in a
// new frame with other chunks: the view drops the meshes it had uploaded
// for the old ones and shows the new solid, none of the old.
TEST_F(GardenViewTest, ASculptureRebuiltInANewFrameShowsItsNewMeshesOnly) {
    const auto write = [&](const std::string& field) {
        const std::filesystem::path p = scratch_ / "t.hf";
        const bool existed = std::filesystem::exists(p);
        const auto before = existed ? std::filesystem::last_write_time(p) : std::filesystem::file_time_type{};
        std::ofstream(p) << "t(x[3], a[1]) { t = " << field << "; }\n";
        if (existed) std::filesystem::last_write_time(p, before + std::chrono::seconds(1));
    };
    write("0.64 - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2)");
    std::ofstream(scratch_ / "garden.json") << R"({"version": 1, "name": "shrink", "materials": {"red": {"color": [0.9, 0.1, 0.1], "roughness": 0.6}},
        "sculptures": [{"name": "t", "file": "t.hf", "resolution": 32, "material": "red", "placement": {"position": [0, 0, 0]}}],
        "start": {"position": [0, 0.5, 3], "look_at": [0, 0.5, 0]}})";
    SessionSettings settings;
    settings.chunkSize = 16;
    settings.maxLevel = 0;
    settings.viewportHeight = kHeight;
    settings.fovY = glm::radians(double(kFovY));
    GardenSession session(loadGarden((scratch_ / "garden.json").string()), settings);
    session.navigator().setMode(NavigationMode::Fly);
    session.navigator().setPose({0.0f, 0.5f, 3.0f}, 0.0f, 0.0f);
    const auto settle = [&] {
        for (int f = 0; f < 500 && !session.idle(); ++f) session.frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(session.idle());
    };
    const auto redPixels = [&](GardenView& view) {
        view.upload(session, 1e9);
        target_->bind();
        view.render(session, {kWidth, kHeight}, glm::radians(kFovY));
        renderer_->endFrame();
        read();
        int n = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) n += test::reddish(pixel(x, y)) ? 1 : 0;
        return n;
    };
    settle();
    GardenView view(*renderer_);
    const double big = discRadiusPixels(0.8, 3.0);
    EXPECT_NEAR(redPixels(view), test::kPi * big * big, 0.08 * test::kPi * big * big);
    const std::size_t chunksBefore = session.sculptures()[0].queue->count();

    write("0.16 - (x[1]^2 / 4 + (x[2]-0.5)^2 + x[3]^2)");
    ASSERT_EQ(session.reloadChangedSources().size(), 1u);
    const Sculpture& t = session.sculptures()[0];
    ASSERT_LT(t.queue->count(), chunksBefore) << "a flatter frame, fewer chunks";
    settle();
    const double wide = discRadiusPixels(0.8, 3.0), high = discRadiusPixels(0.4, 3.0);
    EXPECT_NEAR(redPixels(view), test::kPi * wide * high, 0.08 * test::kPi * wide * high);
    for (std::size_t c = t.queue->count(); c < chunksBefore; ++c)
        EXPECT_FALSE(renderer_->has(GardenView::chunkId(0, c))) << "old chunk " << c << " dropped";
    for (std::size_t c = 0; c < t.queue->count(); ++c) {
        if (!t.queue->mesh(c)) continue;
        EXPECT_TRUE(renderer_->has(GardenView::chunkId(0, c), t.queue->version(c))) << c;
    }
}

// The garden's chunks placed in a later page while other meshes filled the
// first, and those meshes then gone: the view's upload stage empties the
// sparse page into the first a budget at a time (defragmented in the
// background), and the garden looks the same. With a budget of 0 nothing moves.
TEST_F(GardenViewTest, TheUploadStageEmptiesASparsePageAndTheGardenLooksTheSame) {
    const std::unique_ptr<GardenSession> settled = settledSmallGarden();
    ASSERT_TRUE(settled->idle());
    GardenSession& session = *settled;

    // Meshes under ids no garden uses fill the first page.
    const ChunkArena& arena = renderer_->arena();
    const poly::Mesh filler = uvSphereMesh(0.1f, 40, 20);
    ChunkId id = ChunkId{0xFFFFFFF0u} << 32;
    std::vector<ChunkId> fillers;
    while (fillers.empty() || arena.slot(fillers.back())->page == 0) {
        fillers.push_back(id++);
        renderer_->upload(fillers.back(), 1, filler);
    }
    renderer_->drop(fillers.back());
    fillers.pop_back();
    GardenView view(*renderer_);
    view.setArenaCompactBytes(0);
    auto picture = [&] {
        view.upload(session, 1e9);
        target_->bind();
        view.render(session, {kWidth, kHeight}, glm::radians(kFovY));
        const RenderStats stats = renderer_->endFrame();
        read();
        return std::make_pair(color_, stats.drawCalls);
    };
    const auto [before, callsBefore] = picture();
    std::size_t later = 0;
    for (std::size_t c = 0; c < session.sculptures()[0].queue->count(); ++c)
        if (const ArenaSlot* s = arena.slot(GardenView::chunkId(0, c))) later += s->page > 0 ? 1 : 0;
    ASSERT_GT(later, 0u) << "the garden's chunks went to a later page";

    for (ChunkId f : fillers) renderer_->drop(f);
    const std::size_t pages = arena.livePages();
    ASSERT_GT(pages, 1u);
    picture();
    EXPECT_EQ(arena.chunksMoved(), 0u) << "a budget of 0 moves nothing";

    view.setArenaCompactBytes(64 << 10);
    for (int f = 0; f < 200 && arena.livePages() == pages; ++f) EXPECT_EQ(picture().first, before) << "frame " << f;
    EXPECT_GT(arena.chunksMoved(), 0u);
    EXPECT_LT(arena.livePages(), pages) << "the sparse page emptied and let go";
    const auto [after, callsAfter] = picture();
    EXPECT_EQ(after, before);
    EXPECT_LE(callsAfter, callsBefore);
}

}  // namespace
}  // namespace hg::garden
