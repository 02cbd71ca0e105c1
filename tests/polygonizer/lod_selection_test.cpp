// View-dependent level selection: every chunk meets the pixel error, face
// neighbours differ by at most one level (for many cameras, near, far and
// inside), the nearest chunk is at full detail and a far camera sees all
// coarse, and the detail sphere and the tool force full detail around them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygonizer/lod_selection.h"

namespace hg::poly {
namespace {

voxel::VolumeFrame frame(int res) {
    frep::Box3 box;
    box.lo[0] = -1; box.lo[1] = 0; box.lo[2] = -0.5;
    box.hi[0] = 1; box.hi[1] = 2; box.hi[2] = 0.5;
    voxel::VolumeFrame f;
    EXPECT_EQ(voxel::makeFrame(box, res, 3.0f, f), "");
    return f;
}

void expectValid(const ChunkLayout& layout, const Camera& cam, const LodSettings& s, const std::vector<int>& levels) {
    ASSERT_EQ(levels.size(), layout.count());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        ASSERT_GE(levels[i], 0);
        ASSERT_LE(levels[i], s.maxLevel);
        for (std::size_t n : layout.faceNeighbours(i)) ASSERT_LE(std::abs(levels[i] - levels[n]), 1) << i << " vs " << n;
        double d = distanceToChunk(layout, i, cam.position);
        if (levels[i] > 0) {
            ASSERT_LE(projectedVoxelPixels(cam, layout.frame().voxelSize, levels[i], d), s.pixelError + 1e-9);
        }
    }
}

TEST(LodSelection, NeighboursDifferByAtMostOneAndEveryChunkMeetsThePixelError) {
    std::mt19937 rng(3);
    for (int size : {16, 32}) {
        ChunkLayout layout(frame(512), size);
        for (int n = 0; n < 60; ++n) {
            Camera cam;
            std::uniform_real_distribution<double> u(-20, 20);
            double scale = std::pow(10.0, std::uniform_real_distribution<double>(-2, 1)(rng));
            cam.position = {u(rng) * scale, u(rng) * scale, u(rng) * scale};
            cam.fovY = std::uniform_real_distribution<double>(0.3, 1.8)(rng);
            cam.viewportHeight = 600 + static_cast<int>(rng() % 1600);
            LodSettings s;
            s.pixelError = std::uniform_real_distribution<double>(0.5, 4)(rng);
            s.maxLevel = size == 32 ? 3 : 2;
            expectValid(layout, cam, s, selectLevels(layout, cam, s));
        }
    }
}

TEST(LodSelection, NearIsFineAndFarIsCoarse) {
    ChunkLayout layout(frame(512), 32);
    Camera cam;
    cam.position = {0, 1, -0.6};  // just in front of the model, looking along +z
    cam.fovY = 1.0;
    cam.viewportHeight = 1080;
    LodSettings s;
    s.pixelError = 1.0;
    std::vector<int> levels = selectLevels(layout, cam, s);
    expectValid(layout, cam, s, levels);
    std::vector<std::pair<double, int>> byDistance;
    for (std::size_t i = 0; i < levels.size(); ++i) byDistance.push_back({distanceToChunk(layout, i, cam.position), levels[i]});
    std::sort(byDistance.begin(), byDistance.end());
    EXPECT_EQ(byDistance.front().second, 0) << "the nearest chunk is at full detail";
    // A camera far away sees everything coarse.
    cam.position = {0, 1, -400};
    std::vector<int> far = selectLevels(layout, cam, s);
    for (int l : far) EXPECT_EQ(l, s.maxLevel);
}

TEST(LodSelection, DetailSphereAndToolForceFullDetail) {
    ChunkLayout layout(frame(512), 32);
    Camera cam;
    cam.position = {0, 1, -300};
    LodSettings s;
    s.detail = Sphere{{0.5, 1.5, 0.0}, 0.1};
    s.tool = Sphere{{-0.8, 0.2, 0.2}, 0.05};
    std::vector<int> levels = selectLevels(layout, cam, s);
    expectValid(layout, cam, s, levels);
    int forced = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        bool inDetail = distanceToChunk(layout, i, s.detail->center) <= s.detail->radius;
        bool inTool = distanceToChunk(layout, i, s.tool->center) <= s.tool->radius;
        if (inDetail || inTool) {
            EXPECT_EQ(levels[i], 0);
            ++forced;
        }
    }
    EXPECT_GT(forced, 1);
    // Away from both, the far camera keeps chunks coarse.
    EXPECT_EQ(*std::max_element(levels.begin(), levels.end()), s.maxLevel);
}

TEST(ChunkLayout, ChunksCoverTheIndexBoxAlignedWithLeaves) {
    voxel::VolumeFrame f = frame(100);
    for (int size : {16, 32}) {
        ChunkLayout layout(f, size);
        std::size_t covered = 0;
        for (std::size_t i = 0; i < layout.count(); ++i) {
            voxel::IndexBox b = layout.voxels(i);
            for (int a = 0; a < 3; ++a) EXPECT_EQ(((b.lo[a] % 8) + 8) % 8, 0);
            EXPECT_EQ(layout.index(layout.key(i)), i);
            covered += voxel::intersect(b, f.indexBox).volume();
        }
        EXPECT_EQ(covered, f.indexBox.volume());
    }
    EXPECT_THROW(ChunkLayout(f, 24), std::invalid_argument);
}

}  // namespace
}  // namespace hg::poly
