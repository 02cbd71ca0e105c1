// Measured level errors (polygonizer/realtime/chunk_errors.h) and the level
// selection that uses them: a smooth surface strays little at coarse levels
// and a thin rod much; the errors never fall as the level grows, and a
// chunk far from the surface has none; a local update leaves the changed
// chunks at the voxel-size rule's level until they are measured again, a
// batch at a time, and then equals measuring everything again;
// and selection with errors takes coarser levels where the surface is
// smooth, never finer ones, fewer for the rod, stitches (neighbours
// at most one level apart), and its hierarchical shortcut equals the
// per-chunk selection.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <random>

#include "sample_program.h"
#include "polygonizer/realtime/chunk_errors.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/realtime/lod_selection.h"

namespace hg::poly {
namespace {

// A ball of radius 0.6 (29 voxels at 96^3), and a rod 0.03 across (1.4
// voxels) along x from x = -0.8 to 0.8, its axis off the coarse levels'
// sample lines (on one, the coarse samples would keep it): each a volume of its own (a
// HyperFun union blends the fields between them, which is a real error of
// its own; the test keeps the two cases apart).
const char* const kBall = "q(x[3], a[1]) { q = 0.36 - (x[1]^2 + x[2]^2 + x[3]^2); }";
const char* const kRod =
    "q(x[3], a[1]) { q = (0.015^2 - ((x[2] - 0.05)^2 + (x[3] - 0.03)^2)) & (0.8 - x[1]) & (0.8 + x[1]); }";

struct Sculpture {
    voxel::Volume volume;
    LodPyramid pyramid;
    ChunkLayout layout;
    explicit Sculpture(const char* source)
        : volume(test::sampleInUnitCube(::hg::test::modelFromSource(source, {}), 96)),
          pyramid(volume, 4),
          layout(volume.frame, 16) {}
};

// Whether a chunk lies near the surface: some of its voxels (and the
// samples on its far faces) within 2 voxels of it.
bool holdsSurface(const voxel::Volume& v, const ChunkLayout& layout, std::size_t c) {
    const voxel::IndexBox b = layout.voxels(c);
    for (int k = b.lo[2]; k <= b.hi[2] + 1; ++k)
        for (int j = b.lo[1]; j <= b.hi[1] + 1; ++j)
            for (int i = b.lo[0]; i <= b.hi[0] + 1; ++i)
                if (std::fabs(v.value(i, j, k)) < 2.0f) return true;
    return false;
}

// The largest error over the chunks near the surface, per level; the
// other chunks' errors must be 0.
std::array<float, 4> worstOnTheSurface(const Sculpture& s, const ChunkErrors& e, std::size_t& surfaceChunks) {
    std::array<float, 4> worst{};
    surfaceChunks = 0;
    for (std::size_t c = 0; c < e.count(); ++c) {
        EXPECT_EQ(e.error(c, 0), 0.0f);
        for (int l = 1; l < 4; ++l) {
            EXPECT_GE(e.error(c, l), e.error(c, l - 1)) << "never falls as the level grows";
            EXPECT_LE(e.error(c, l), e.largest(l));
            EXPECT_GE(e.error(c, l), e.smallest(l));
        }
        if (!holdsSurface(s.volume, s.layout, c)) {
            EXPECT_EQ(e.error(c, 3), 0.0f) << "a chunk far from the surface strays by nothing";
            continue;
        }
        ++surfaceChunks;
        for (int l = 1; l < 4; ++l) worst[static_cast<std::size_t>(l)] = std::max(worst[static_cast<std::size_t>(l)], e.error(c, l));
    }
    return worst;
}

TEST(ChunkErrors, ASmoothBallStraysLittleAndAThinRodMuch) {
    const Sculpture ball(kBall), rod(kRod);
    const ChunkErrors ballErrors(ball.pyramid, ball.layout), rodErrors(rod.pyramid, rod.layout);
    ASSERT_EQ(ballErrors.count(), ball.layout.count());
    ASSERT_EQ(ballErrors.levels(), 4);
    std::size_t ballChunks = 0, rodChunks = 0;
    const auto b = worstOnTheSurface(ball, ballErrors, ballChunks);
    const auto r = worstOnTheSurface(rod, rodErrors, rodChunks);
    std::printf("ball: %zu chunks near the surface, worst error at levels 1-3 %.3f %.3f %.3f voxels; "
                "rod: %zu chunks, %.3f %.3f %.3f\n",
                ballChunks, b[1], b[2], b[3], rodChunks, r[1], r[2], r[3]);
    ASSERT_GT(ballChunks, 50u);
    ASSERT_GT(rodChunks, 5u);
    // Level 1 bends from a ball 29 voxels in radius by a few hundredths
    // of a voxel; the samples of levels 2 and 3, 4 and 8 voxels apart,
    // also meet the band's clamp (3 voxels), which pulls the coarse
    // surface further (about 0.4 and 1.4 voxels).
    EXPECT_LT(b[1], 0.1f);
    EXPECT_LT(b[3], 2.0f);
    // The rod, 1.4 voxels across, is gone by level 2 or 3.
    EXPECT_GT(r[3], 1.0f);
    EXPECT_GT(r[2], 2.0f * b[2]);
}

TEST(ChunkErrors, AnUpdateEqualsMeasuringAgain) {
    Sculpture s(kBall);
    ChunkErrors e(s.pyramid, s.layout);
    // Carve a groove into the ball's top: a region resampled from another field.
    const frep::Model grooved = ::hg::test::modelFromSource(
        "q(x[3], a[1]) { ball = 0.36 - (x[1]^2 + x[2]^2 + x[3]^2); groove = 0.02^2 - ((x[2] - 0.6)^2 + x[3]^2); q = ball & -groove; }",
        {});
    const voxel::IndexBox region = voxel::IndexBox::fromCorners(20, 70, 30, 70, 82, 60);
    voxel::resampleRegion(s.volume, grooved, region);
    s.pyramid.update(region);
    const std::uint64_t before = e.version();
    const std::size_t changed = e.update(region);
    EXPECT_GT(changed, 0u);
    EXPECT_LT(changed, s.layout.count() / 2) << "only the chunks near the region";
    EXPECT_EQ(e.unknown(), changed);
    EXPECT_GT(e.version(), before);
    // Unknown until measured: they take the voxel-size rule's level.
    EXPECT_TRUE(std::isinf(e.largest(1)));
    Camera cam;
    cam.position = {0.0, 0.5, 3.0};
    LodSettings lod;
    lod.maxLevel = 3;
    const std::vector<int> measuring = selectLevelsPerChunk(s.layout, cam, lod, &e);
    const voxel::IndexBox grown = voxel::IndexBox::fromCorners(region.lo[0] - 8, region.lo[1] - 8, region.lo[2] - 8,
                                                               region.hi[0] + 8, region.hi[1] + 8, region.hi[2] + 8);
    std::size_t inside = 0;
    for (std::size_t c = 0; c < s.layout.count(); ++c)
        if (grown.contains(s.layout.voxels(c))) {
            ++inside;
            const double d = distanceToChunk(s.layout, c, cam.position);
            EXPECT_LE(measuring[c], levelAtDistance(cam, s.layout.frame().voxelSize, d, lod)) << "chunk " << c;
        }
    EXPECT_GT(inside, 0u);
    // Measured a batch at a time: a short allowance leaves some unknown.
    const std::size_t first = e.refresh(cam.position, 1e-6);
    EXPECT_GT(first, 0u);
    EXPECT_EQ(e.unknown(), changed - first);
    while (e.unknown() > 0) ASSERT_GT(e.refresh(cam.position, 1e-6), 0u);
    EXPECT_EQ(e.refresh(cam.position, 0.0), 0u);
    const ChunkErrors again(s.pyramid, s.layout);
    for (std::size_t c = 0; c < e.count(); ++c)
        for (int l = 1; l < 4; ++l) ASSERT_EQ(e.error(c, l), again.error(c, l)) << "chunk " << c << " level " << l;
    for (int l = 1; l < 4; ++l) {
        EXPECT_EQ(e.largest(l), again.largest(l));
        EXPECT_EQ(e.smallest(l), again.smallest(l));
    }
}

// Levels chosen with the errors over 80 cameras around the volume, 1 to 30
// units away: the same rules every time (never finer than the voxel-size
// rule, neighbours at most one level apart, each chunk within the pixel
// rule or within the error allowed, the shortcut equal to the per-chunk
// selection). Returns the levels gained over the voxel-size rule by the
// chunks near the surface, and how many such chunks were seen.
std::pair<std::size_t, std::size_t> sweep(const Sculpture& s, const ChunkErrors& e, std::size_t& hierarchical) {
    const double h = s.layout.frame().voxelSize;
    std::vector<bool> surface(s.layout.count());
    for (std::size_t c = 0; c < surface.size(); ++c) surface[c] = holdsSurface(s.volume, s.layout, c);
    std::mt19937 rng(5);
    std::size_t coarser = 0, seen = 0;
    for (int n = 0; n < 80; ++n) {
        Camera cam;
        const double distance = std::pow(10.0, std::uniform_real_distribution<double>(0.0, 1.5)(rng));
        const double a = std::uniform_real_distribution<double>(0.0, 6.283)(rng);
        cam.position = {distance * std::cos(a), 0.3, distance * std::sin(a)};
        cam.fovY = 0.9;
        cam.viewportHeight = 1080;
        LodSettings lod;
        lod.maxLevel = 3;
        const std::vector<int> plain = selectLevelsPerChunk(s.layout, cam, lod);
        const std::vector<int> measured = selectLevelsPerChunk(s.layout, cam, lod, &e);
        for (std::size_t c = 0; c < measured.size(); ++c) {
            EXPECT_GE(measured[c], plain[c]) << "never finer than the voxel-size rule";
            for (std::size_t nb : s.layout.faceNeighbours(c)) EXPECT_LE(std::abs(measured[c] - measured[nb]), 1);
            const double d = distanceToChunk(s.layout, c, cam.position);
            if (measured[c] > 0 && projectedVoxelPixels(cam, h, measured[c], d) > lod.pixelError + 1e-9) {
                EXPECT_LE(projectedVoxelPixels(cam, h, measured[c], d), lod.coarsePixels + 1e-9);
                EXPECT_LE(projectedVoxelPixels(cam, h * e.error(c, measured[c]), 0, d), lod.errorPixels + 1e-9);
            }
            if (surface[c]) {
                ++seen;
                coarser += static_cast<std::size_t>(measured[c] - plain[c]);
            }
        }
        if (const auto u = uniformLevel(s.layout, cam, lod, &e)) {
            ++hierarchical;
            for (int l : measured) EXPECT_EQ(l, *u) << "the shortcut equals the per-chunk selection";
        }
        EXPECT_EQ(selectLevels(s.layout, cam, lod, &e), measured);
    }
    return {coarser, seen};
}

TEST(ChunkErrors, SelectionTakesCoarserLevelsWhereSmoothNeverFinerAndFewerForAThinRod) {
    const Sculpture ball(kBall), rod(kRod);
    const ChunkErrors ballErrors(ball.pyramid, ball.layout), rodErrors(rod.pyramid, rod.layout);
    std::size_t ballUniform = 0, rodUniform = 0;
    const auto [ballCoarser, ballSeen] = sweep(ball, ballErrors, ballUniform);
    const auto [rodCoarser, rodSeen] = sweep(rod, rodErrors, rodUniform);
    const double ballGain = double(ballCoarser) / double(ballSeen), rodGain = double(rodCoarser) / double(rodSeen);
    std::printf("levels gained over the voxel-size rule per chunk near the surface: ball %.3f, rod %.3f; "
                "one level for the whole volume: ball %zu, rod %zu of 80 cameras\n",
                ballGain, rodGain, ballUniform, rodUniform);
    EXPECT_GT(ballGain, 0.25) << "a smooth surface goes coarser";
    EXPECT_GT(ballGain, 1.5 * rodGain) << "a thin rod, which coarse levels lose, much less";
    EXPECT_GT(ballUniform, 0u);
}

}  // namespace
}  // namespace hg::poly
