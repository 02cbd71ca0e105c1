// View-dependent level selection: every chunk meets the pixel error, face
// neighbours differ by at most one level (for many cameras, near, far and
// inside), the nearest chunk is at full detail and a far camera sees all
// coarse, and the detail sphere and the tool force full detail around them.
// The hierarchical selection equals the per-chunk one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "polygonizer/realtime/lod_selection.h"

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

// Each chunk takes the coarsest level that its own pixel rule and its
// neighbours allow, and no finer: level[i] = min over chunks j of (j's own
// level + face steps from j to i), computed here the slow way over every
// pair, for random cameras and spheres.
TEST(LodSelection, EachChunkTakesTheCoarsestLevelItsNeighboursAllow) {
    std::mt19937 rng(11);
    ChunkLayout layout(frame(256), 16);
    const std::size_t n = layout.count();
    std::uniform_real_distribution<double> u(-3, 3);
    int refined = 0;
    for (int c = 0; c < 24; ++c) {
        // Near and far (so that a sphere's level 0 sits among coarse chunks).
        const double far = std::pow(10.0, std::uniform_real_distribution<double>(0, 2.5)(rng));
        Camera cam;
        cam.position = {u(rng) * far, 1.0 + u(rng) * far, u(rng) * far};
        cam.viewportHeight = 1080;
        LodSettings s;
        s.maxLevel = 3;
        s.pixelError = std::uniform_real_distribution<double>(0.5, 3)(rng);
        if (c % 3 == 1) s.detail = Sphere{{u(rng) / 3, 1.0 + u(rng) / 3, u(rng) / 6}, 0.2};
        if (c % 3 == 2) s.tool = Sphere{{u(rng) / 3, 1.0 + u(rng) / 3, u(rng) / 6}, 0.1};
        std::vector<int> own(n);
        for (std::size_t i = 0; i < n; ++i) {
            own[i] = levelAtDistance(cam, layout.frame().voxelSize, distanceToChunk(layout, i, cam.position), s);
            for (const auto& sphere : {s.detail, s.tool})
                if (sphere && distanceToChunk(layout, i, sphere->center) <= sphere->radius) own[i] = 0;
        }
        const std::vector<int> levels = selectLevelsPerChunk(layout, cam, s);
        ASSERT_EQ(levels.size(), n);
        for (std::size_t i = 0; i < n; ++i) {
            const ChunkKey a = layout.key(i);
            int expected = own[i];
            for (std::size_t j = 0; j < n; ++j) {
                const ChunkKey b = layout.key(j);
                expected = std::min(expected, own[j] + std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z));
            }
            ASSERT_EQ(levels[i], expected) << "camera " << c << ", chunk " << i;
            refined += expected < own[i];
        }
    }
    EXPECT_GT(refined, 100) << "the neighbour rule lowered chunks";
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

// The hierarchical selection (the layout's bound first) against every chunk
// tested: a camera walking from inside the model to 600 units away on
// several lines, with and without a detail sphere, always gets the same
// levels; far cameras take the shortcut, near ones do not.
TEST(LodSelection, HierarchicalSelectionEqualsPerChunkSelectionOnACameraSweep) {
    for (int size : {16, 32}) {
        ChunkLayout layout(frame(256), size);
        int uniform = 0, perChunk = 0;
        for (const std::array<double, 3>& dir : {std::array<double, 3>{0, 0, 1}, {0.6, 0.1, -0.8}, {-1, 0.3, 0.2}}) {
            for (double t = 0.0; t < 600.0; t = t * 1.07 + 0.05) {
                Camera cam;
                cam.position = {dir[0] * t, 1.0 + dir[1] * t, dir[2] * t};
                cam.viewportHeight = 1080;
                for (bool sphere : {false, true}) {
                    LodSettings s;
                    s.maxLevel = size == 32 ? 3 : 2;
                    if (sphere) s.detail = Sphere{{0.9, 1.9, 0.4}, 0.3};
                    const std::vector<int> flat = selectLevelsPerChunk(layout, cam, s);
                    ASSERT_EQ(selectLevels(layout, cam, s), flat) << "camera at distance " << t;
                    if (const std::optional<int> l = uniformLevel(layout, cam, s)) {
                        ++uniform;
                        for (int f : flat) ASSERT_EQ(f, *l) << "camera at distance " << t;
                    } else {
                        ++perChunk;
                    }
                }
            }
        }
        EXPECT_GT(uniform, 20) << "far cameras select for the whole layout at once";
        EXPECT_GT(perChunk, 20) << "near cameras and the detail sphere visit the chunks";
    }
}

TEST(LodSelection, NoUniformLevelWhereASphereReachesTheLayout) {
    ChunkLayout layout(frame(256), 32);
    Camera cam;
    cam.position = {0, 1, -400};
    LodSettings s;
    ASSERT_EQ(uniformLevel(layout, cam, s), s.maxLevel);
    s.tool = Sphere{{1.05, 1.0, 0.0}, 0.1};  // just outside the model box, within reach of its last chunks
    EXPECT_EQ(uniformLevel(layout, cam, s), std::nullopt);
    s.tool = Sphere{{5.0, 1.0, 0.0}, 0.1};
    EXPECT_EQ(uniformLevel(layout, cam, s), s.maxLevel);
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
