// Scanned volumes (voxel/scalar_volume.h): raw u8 and u16 samples and a
// float grid of a .vdb give a level set whose zero crossing is the
// iso-surface (a ball of known radius: within half a voxel), the same bits
// every time; bad files, grids and iso-values are refused with reasons.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "tests/scan_volumes.h"
#include "voxel/scalar_volume.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {
namespace {

namespace fs = std::filesystem;

struct ScanFiles : ::testing::Test {
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("hg_scan_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string file(const std::string& name) const { return (dir / name).string(); }
};

RawVolumeLayout layoutOf(const test::ScanBall& b, bool sixteen) {
    RawVolumeLayout l;
    l.dims = {b.n, b.n, b.n};
    l.type = sixteen ? SampleType::U16 : SampleType::U8;
    l.spacing = {b.spacing, b.spacing, b.spacing};
    return l;
}

// The largest distance, in voxels, between the ball's sphere and where the
// stored values put the surface, over the voxels next to the surface
// (|value| < 1: the value is a true distance there). Also checks the sign
// far inside and outside.
double worstSurfaceError(const Volume& v, const test::ScanBall& b, int& nearSurface) {
    double worst = 0.0;
    nearSurface = 0;
    const IndexBox& box = v.frame.indexBox;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const auto p = v.frame.position(i, j, k);
                const double r = std::sqrt((p[0] - b.centre[0]) * (p[0] - b.centre[0]) +
                                           (p[1] - b.centre[1]) * (p[1] - b.centre[1]) +
                                           (p[2] - b.centre[2]) * (p[2] - b.centre[2]));
                const double truth = (b.radius - r) / v.frame.voxelSize;  // voxels, positive inside
                const float stored = v.value(i, j, k);
                if (std::fabs(stored) < 1.0f) {
                    ++nearSurface;
                    worst = std::max(worst, std::fabs(truth - stored));
                } else if (truth > 2.0) {
                    EXPECT_GT(stored, 0.0f) << i << " " << j << " " << k;
                } else if (truth < -2.0) {
                    EXPECT_LT(stored, 0.0f) << i << " " << j << " " << k;
                }
            }
    return worst;
}

void expectBall(const Volume& v, const test::ScanBall& b) {
    int near = 0;
    const double worst = worstSurfaceError(v, b, near);
    EXPECT_GT(near, 500);
    EXPECT_LT(worst, 0.5) << "the zero crossing is within half a voxel of the sphere";
    EXPECT_DOUBLE_EQ(v.normalization, 1.0 / v.frame.voxelSize);
    // The invariants of every sculpture's grid: outside is the background.
    EXPECT_EQ(v.value(v.frame.indexBox.lo[0] - 5, 0, 0), -v.frame.band);
    const openvdb::FloatGrid& g = vdb(v);
    for (auto it = g.cbeginValueOn(); it; ++it) ASSERT_LT(std::fabs(*it), v.frame.band);
    for (auto it = g.cbeginValueOff(); it; ++it) ASSERT_EQ(std::fabs(*it), v.frame.band);
}

void writeGrids(const std::string& path, openvdb::GridPtrVec grids) {
    openvdb::io::File f(path);
    f.write(grids);
    f.close();
}

IsoSurfaceRequest requestAt(double iso, int resolution = 64) {
    IsoSurfaceRequest r;
    r.iso = iso;
    r.resolution = resolution;
    return r;
}

TEST_F(ScanFiles, RawU8BallIsASphereWithinHalfAVoxel) {
    test::ScanBall b;
    b.write(file("ball.raw"), false);
    ScalarVolume s;
    ASSERT_EQ(readRawVolume(file("ball.raw"), layoutOf(b, false), s), "");
    EXPECT_EQ(s.minValue, 0.0f);
    EXPECT_EQ(s.maxValue, 255.0f);
    VoxelizeResult r = levelSetFromScalar(s, requestAt(b.iso));
    ASSERT_TRUE(r.volume) << r.error;
    expectBall(*r.volume, b);
    // The box is the inside samples' bounds grown by a sample: about the ball.
    EXPECT_EQ(r.modelBox.origin, BoxOrigin::Sampled);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(r.modelBox.box.lo[a], b.centre[static_cast<std::size_t>(a)] - b.radius, 2 * b.spacing);
        EXPECT_NEAR(r.modelBox.box.hi[a], b.centre[static_cast<std::size_t>(a)] + b.radius, 2 * b.spacing);
    }
}

TEST_F(ScanFiles, RawU16LittleEndianBallIsASphere) {
    test::ScanBall b;
    b.iso = 30000;
    b.slope = 3000;
    b.top = 65535;
    b.write(file("ball16.raw"), true);
    ScalarVolume s;
    ASSERT_EQ(readRawVolume(file("ball16.raw"), layoutOf(b, true), s), "");
    EXPECT_GT(s.maxValue, 40000.0f) << "the high byte is read second";
    VoxelizeResult r = levelSetFromScalar(s, requestAt(b.iso));
    ASSERT_TRUE(r.volume) << r.error;
    expectBall(*r.volume, b);
}

TEST_F(ScanFiles, InsideBelowTakesTheLowSamples) {
    test::ScanBall b;
    b.inverted = true;
    b.write(file("hollow.raw"), false);
    ScalarVolume s;
    ASSERT_EQ(readRawVolume(file("hollow.raw"), layoutOf(b, false), s), "");
    IsoSurfaceRequest req = requestAt(255.0 - b.iso);
    req.insideAbove = false;
    VoxelizeResult r = levelSetFromScalar(s, req);
    ASSERT_TRUE(r.volume) << r.error;
    expectBall(*r.volume, b);
}

TEST_F(ScanFiles, VdbFloatGridBallIsASphere) {
    test::ScanBall b;
    b.iso = 0.5;
    b.slope = 0.15;
    b.top = 1.0;
    openvdb::initialize();
    // A fog volume as other tools write one: background 0, density where
    // it is not, in its own transform.
    openvdb::FloatGrid::Ptr fog = openvdb::FloatGrid::create(0.0f);
    fog->setName("density");
    fog->setTransform(openvdb::math::Transform::createLinearTransform(b.spacing));
    auto acc = fog->getAccessor();
    for (int k = 0; k < b.n; ++k)
        for (int j = 0; j < b.n; ++j)
            for (int i = 0; i < b.n; ++i)
                if (const double v = b.value(i, j, k); v > 0.0) acc.setValue(openvdb::Coord(i, j, k), static_cast<float>(v));
    openvdb::Vec3SGrid::Ptr other = openvdb::Vec3SGrid::create();
    other->setName("velocity");
    writeGrids(file("ball.vdb"), {other, fog});
    ScalarVolume s;
    ASSERT_EQ(readScalarVdb(file("ball.vdb"), "", s), "") << "the first float grid is taken";
    VoxelizeResult r = levelSetFromScalar(s, requestAt(b.iso));
    ASSERT_TRUE(r.volume) << r.error;
    expectBall(*r.volume, b);

    ScalarVolume named;
    ASSERT_EQ(readScalarVdb(file("ball.vdb"), "density", named), "");
    std::string why = readScalarVdb(file("ball.vdb"), "dens", named);
    EXPECT_NE(why.find("no grid named 'dens' (its grids: "), std::string::npos) << why;
    EXPECT_NE(why.find("'velocity' (vec3s)"), std::string::npos) << why;
    EXPECT_NE(why.find("'density' (float)"), std::string::npos) << why;
    why = readScalarVdb(file("ball.vdb"), "velocity", named);
    EXPECT_NE(why.find("grid 'velocity' holds vec3s values, not float"), std::string::npos) << why;
    writeGrids(file("none.vdb"), {other});
    why = readScalarVdb(file("none.vdb"), "", named);
    EXPECT_NE(why.find("no float grid (its grids: 'velocity' (vec3s))"), std::string::npos) << why;
    // A grid whose background is inside has no end.
    IsoSurfaceRequest below = requestAt(b.iso);
    below.insideAbove = false;
    const VoxelizeResult unbounded = levelSetFromScalar(s, below);
    EXPECT_FALSE(unbounded.volume);
    EXPECT_NE(unbounded.error.find("would have no end"), std::string::npos) << unbounded.error;
}

TEST_F(ScanFiles, TheSameInputGivesTheSameBits) {
    test::ScanBall b;
    b.centre = {0.9, 1.1, 1.0};
    b.write(file("ball.raw"), false);
    ScalarVolume s;
    ASSERT_EQ(readRawVolume(file("ball.raw"), layoutOf(b, false), s), "");
    VoxelizeResult one = levelSetFromScalar(s, requestAt(b.iso, 80));
    VoxelizeResult two = levelSetFromScalar(s, requestAt(b.iso, 80));
    ASSERT_TRUE(one.volume && two.volume);
    const IndexBox& box = one.volume->frame.indexBox;
    int differ = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i)
                differ += one.volume->value(i, j, k) != two.volume->value(i, j, k) ||
                          one.volume->active(i, j, k) != two.volume->active(i, j, k);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(one.volume->leafCount(), two.volume->leafCount());
}

TEST_F(ScanFiles, BadFilesAndRequestsAreRefusedWithReasons) {
    test::ScanBall b;
    b.write(file("ball.raw"), false);
    ScalarVolume s;
    RawVolumeLayout wrong = layoutOf(b, false);
    wrong.dims[2] = 41;
    std::string why = readRawVolume(file("ball.raw"), wrong, s);
    EXPECT_NE(why.find("64000 bytes, but dims 40 x 40 x 41 of u8 need 65600 bytes"), std::string::npos) << why;
    why = readRawVolume(file("ball.raw"), layoutOf(b, true), s);
    EXPECT_NE(why.find("of u16 need 128000 bytes"), std::string::npos) << why;
    why = readRawVolume(file("missing.raw"), layoutOf(b, false), s);
    EXPECT_NE(why.find("missing.raw: cannot open: No such file or directory"), std::string::npos) << why;

    ASSERT_EQ(readRawVolume(file("ball.raw"), layoutOf(b, false), s), "");
    for (double iso : {0.0, 255.0, 300.0, -1.0}) {
        const VoxelizeResult r = levelSetFromScalar(s, requestAt(iso));
        EXPECT_FALSE(r.volume);
        EXPECT_NE(r.error.find("is outside the data's range (0 to 255)"), std::string::npos) << r.error;
    }
    IsoSurfaceRequest huge = requestAt(b.iso, 4096);
    huge.memoryLimit = std::uint64_t{64} << 20;
    const VoxelizeResult r = levelSetFromScalar(s, huge);
    EXPECT_FALSE(r.volume);
    EXPECT_NE(r.error.find("the level set of the scanned volume at resolution 4096 needs about"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("or less would fit"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace hg::voxel
