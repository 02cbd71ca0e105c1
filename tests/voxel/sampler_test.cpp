// The narrow-band sampler: signs agree with direct evaluation, tiles are on
// the right side, the field is about one unit per voxel at the surface, the
// grid does not depend on the thread count, and the dense cache agrees with
// the grid wherever the grid holds an evaluated value.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <random>

#include "test_models.h"
#include "voxel/dense_field.h"
#include "voxel/grid_stats.h"
#include "voxel/sampler.h"
#include "voxel/volume_vdb.h"

namespace hg::voxel {
namespace {

using test::kInterpreterOnly;
using test::kSphere;
using test::kTorusBlock;

Volume sample(const frep::Model& model, int res, std::optional<frep::Box3> box = std::nullopt) {
    VolumeRequest req;
    req.resolution = res;
    req.box = box;
    VoxelizeResult r = voxelize(model, req);
    EXPECT_TRUE(r.volume) << r.error;
    return r.volume ? std::move(*r.volume) : Volume();
}

frep::Box3 box(double lo, double hi) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) { b.lo[a] = lo; b.hi[a] = hi; }
    return b;
}

// f in double at the point the grid sampled (voxel positions are rounded to
// float for the batch evaluator), or NaN where the float evaluation there
// has the other sign: at a discontinuity of f (the clipping `if` of our
// content) rounding decides the sign, and the grid follows the float
// evaluator. Such points are skipped; the tests check they are rare.
double evalDouble(const frep::Model& model, double x, double y, double z) {
    float xf = static_cast<float>(x), yf = static_cast<float>(y), zf = static_cast<float>(z), ff;
    x = xf;
    y = yf;
    z = zf;
    frep::PointSampler<double> s(model);
    frep::PointSampler<float> sf(model);
    double f;
    frep::ErrorReport e;
    s.evaluate(&x, &y, &z, &f, 1, e);
    sf.evaluate(&xf, &yf, &zf, &ff, 1, e);
    if ((ff > 0) != (f > 0)) return std::nan("");
    return f;
}

// Voxel values and active states agree bit for bit over `region`.
void expectSameVoxels(const Volume& a, const Volume& b, const IndexBox& region) {
    std::size_t differ = 0;
    for (int k = region.lo[2]; k <= region.hi[2]; ++k)
        for (int j = region.lo[1]; j <= region.hi[1]; ++j)
            for (int i = region.lo[0]; i <= region.hi[0]; ++i) {
                float va = a.value(i, j, k), vb = b.value(i, j, k);
                if (std::memcmp(&va, &vb, sizeof va) != 0 || a.active(i, j, k) != b.active(i, j, k)) {
                    if (differ++ < 5)
                        ADD_FAILURE() << "voxel (" << i << "," << j << "," << k << "): " << va << " vs " << vb;
                }
            }
    EXPECT_EQ(differ, 0u);
}

struct Subject {
    const char* name;
    frep::Model model;
    std::optional<frep::Box3> box;
    bool culls;  // intervals prove whole leaves (the interpreter has none)
};

std::vector<Subject> subjects() {
    std::vector<Subject> s;
    s.push_back({"sphere", test::modelFromSource(kSphere, {0.5}), std::nullopt, true});
    s.push_back({"torus+block", test::modelFromSource(kTorusBlock), std::nullopt, true});
    frep::Box3 dancerBox;
    dancerBox.lo[0] = -0.8; dancerBox.lo[1] = -0.15; dancerBox.lo[2] = -0.5;
    dancerBox.hi[0] = 0.8; dancerBox.hi[1] = 2.3; dancerBox.hi[2] = 0.5;
    s.push_back({"dancer", test::modelFromFile(test::contentFile("dancer.hf"), {0.4}), dancerBox, true});
    s.push_back({"interpreter", test::modelFromSource(kInterpreterOnly), box(-1.2, 1.2), false});
    return s;
}

TEST(Sampler, SignAgreesWithDirectEvaluationAwayFromTheSurface) {
    for (const Subject& s : subjects()) {
        SCOPED_TRACE(s.name);
        Volume v = sample(s.model, 64, s.box);
        std::mt19937 rng(7);
        const IndexBox& ib = v.frame.indexBox;
        int checked = 0, inside = 0, discontinuous = 0;
        for (int n = 0; n < 4000; ++n) {
            int p[3];
            for (int a = 0; a < 3; ++a) p[a] = std::uniform_int_distribution<int>(ib.lo[a], ib.hi[a])(rng);
            auto pos = v.frame.position(p[0], p[1], p[2]);
            double f = evalDouble(s.model, pos[0], pos[1], pos[2]) * v.normalization;
            if (std::isnan(f)) {
                ++discontinuous;
                continue;
            }
            if (std::fabs(f) < 0.25) continue;  // float evaluation may round either way
            ++checked;
            inside += f > 0;
            float g = v.value(p[0], p[1], p[2]);
            ASSERT_EQ(g > 0, f > 0) << "voxel " << p[0] << "," << p[1] << "," << p[2] << ": grid " << g << ", f*scale " << f;
        }
        EXPECT_GT(checked, 3000);
        EXPECT_LT(discontinuous, 40);
        EXPECT_GT(inside, 20) << "the test should see inside voxels too";
        // Off the lattice: trilinear interpolation agrees where the field
        // is more than two voxels from zero.
        openvdb::FloatGrid::ConstAccessor acc = vdb(v).getConstAccessor();
        for (int n = 0; n < 2000; ++n) {
            double q[3];
            for (int a = 0; a < 3; ++a)
                q[a] = std::uniform_real_distribution<double>(ib.lo[a], ib.hi[a])(rng);
            auto pos = std::array<double, 3>{v.frame.coordinate(0, 0) + q[0] * v.frame.voxelSize,
                                             v.frame.coordinate(1, 0) + q[1] * v.frame.voxelSize,
                                             v.frame.coordinate(2, 0) + q[2] * v.frame.voxelSize};
            double f = evalDouble(s.model, pos[0], pos[1], pos[2]) * v.normalization;
            if (std::isnan(f) || std::fabs(f) < 2.0) continue;
            int i0[3];
            double t[3];
            for (int a = 0; a < 3; ++a) {
                i0[a] = static_cast<int>(std::floor(q[a]));
                t[a] = q[a] - i0[a];
            }
            double g = 0;
            for (int c = 0; c < 8; ++c) {
                int d[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
                double w = 1;
                for (int a = 0; a < 3; ++a) w *= d[a] ? t[a] : 1 - t[a];
                g += w * static_cast<double>(acc.getValue(openvdb::Coord(i0[0] + d[0], i0[1] + d[1], i0[2] + d[2])));
            }
            ASSERT_EQ(g > 0, f > 0) << "model point " << pos[0] << "," << pos[1] << "," << pos[2];
        }
    }
}

TEST(Sampler, TilesAndInactiveVoxelsHoldTheClampedValueOnTheRightSide) {
    for (const Subject& s : subjects()) {
        SCOPED_TRACE(s.name);
        Volume v = sample(s.model, 64, s.box);
        const float band = v.frame.band;
        std::mt19937 rng(11);
        std::size_t tiles = 0, inactive = 0;
        for (auto it = vdb(v).tree().cbeginValueOff(); it; ++it) {
            const float value = *it;
            ASSERT_EQ(std::fabs(value), band) << "inactive values are clamped";
            openvdb::CoordBBox bb;
            it.getBoundingBox(bb);
            IndexBox cells = intersect(toIndexBox(bb), v.frame.indexBox);
            if (cells.empty()) continue;
            it.isVoxelValue() ? ++inactive : ++tiles;
            // Tiles: a few random voxels; inactive voxels: one in sixteen.
            int probes = it.isVoxelValue() ? (rng() % 16 == 0) : 4;
            for (int n = 0; n < probes; ++n) {
                int p[3];
                for (int a = 0; a < 3; ++a)
                    p[a] = std::uniform_int_distribution<int>(cells.lo[a], cells.hi[a])(rng);
                auto pos = v.frame.position(p[0], p[1], p[2]);
                double f = evalDouble(s.model, pos[0], pos[1], pos[2]);
                if (std::isnan(f)) continue;
                ASSERT_EQ(f > 0, value > 0) << (it.isVoxelValue() ? "voxel " : "tile ") << p[0] << "," << p[1] << ","
                                            << p[2] << " holds " << value << " but f = " << f;
            }
        }
        if (s.culls) {
            EXPECT_GT(tiles, 0u) << "culling should make tiles";
        }
        EXPECT_GT(inactive, 0u);
        for (auto it = vdb(v).tree().cbeginValueOn(); it; ++it) ASSERT_LT(std::fabs(*it), band);
    }
}

TEST(Sampler, NormalizedGradientIsAboutOnePerVoxel) {
    for (const Subject& s : subjects()) {
        SCOPED_TRACE(s.name);
        Volume v = sample(s.model, 96, s.box);
        GridStats g = measureGrid(v);
        EXPECT_GT(g.surfaceVoxels, 100u);
        EXPECT_NEAR(g.medianGradient, 1.0, 0.2);
    }
}

TEST(Sampler, GridIsTheSameWithOneAndTwoThreads) {
    for (const Subject& s : subjects()) {
        SCOPED_TRACE(s.name);
        std::optional<Volume> one, two;
        tbb::task_arena(1).execute([&] { one = sample(s.model, 80, s.box); });
        tbb::task_arena(2).execute([&] { two = sample(s.model, 80, s.box); });
        EXPECT_EQ(one->normalization, two->normalization);
        EXPECT_EQ(one->leafCount(), two->leafCount());
        EXPECT_EQ(one->activeVoxelCount(), two->activeVoxelCount());
        expectSameVoxels(*one, *two, one->frame.indexBox);
    }
}

TEST(Sampler, RegionResampleEqualsAFullResampleBitForBit) {
    // The sphere grows: resample a region of the small sphere's grid from the
    // large sphere's program, with the same frame and normalization.
    frep::Model small = test::modelFromSource(kSphere, {0.3});
    frep::Model large = test::modelFromSource(kSphere, {0.5});
    VolumeRequest req;
    req.resolution = 72;
    req.box = box(-1, 1);
    VoxelizeResult a = voxelize(small, req);
    ASSERT_TRUE(a.volume);
    // The full resample of `large` in the same frame, with a's normalization.
    Volume full = a.volume->clone();
    SampleStats all = resampleRegion(full, large, full.frame.indexBox);
    EXPECT_EQ(all.voxels, full.frame.indexBox.volume());
    const IndexBox regions[] = {IndexBox::fromCorners(13, 5, 20, 57, 40, 71),   // unaligned, inside
                                IndexBox::fromCorners(-9, 30, 30, 10, 33, 90),  // reaches past the frame
                                IndexBox::fromCorners(36, 36, 36, 36, 36, 36),  // one voxel
                                IndexBox::fromCorners(0, 0, 0, 31, 31, 31)};    // leaf-aligned
    for (const IndexBox& region : regions) {
        Volume part = a.volume->clone();
        SampleStats st = resampleRegion(part, large, region);
        EXPECT_LE(st.samples, region.volume());
        IndexBox in = intersect(region, part.frame.indexBox);
        expectSameVoxels(part, full, in);
        // Outside the region nothing changed: compare a shell around it.
        IndexBox around = intersect(IndexBox::fromCorners(region.lo[0] - 3, region.lo[1] - 3, region.lo[2] - 3,
                                                          region.hi[0] + 3, region.hi[1] + 3, region.hi[2] + 3),
                                    part.frame.indexBox);
        for (int k = around.lo[2]; k <= around.hi[2]; ++k)
            for (int j = around.lo[1]; j <= around.hi[1]; ++j)
                for (int i = around.lo[0]; i <= around.hi[0]; ++i)
                    if (!region.contains(i, j, k)) {
                        ASSERT_EQ(part.value(i, j, k), a.volume->value(i, j, k)) << i << "," << j << "," << k;
                        ASSERT_EQ(part.active(i, j, k), a.volume->active(i, j, k));
                    }
    }
    // A resample of the whole frame from the same program gives back exactly
    // what voxelize stored.
    Volume self = a.volume->clone();
    resampleRegion(self, small, IndexBox::fromCorners(-20, -20, -20, 100, 100, 100));
    expectSameVoxels(self, *a.volume, self.frame.indexBox);
}

TEST(Sampler, DenseCacheIsTheUnclampedField) {
    frep::Model model = test::modelFromSource(kTorusBlock);
    VolumeRequest req;
    req.resolution = 48;
    VoxelizeResult r = voxelize(model, req);
    ASSERT_TRUE(r.volume);
    const Volume& v = *r.volume;
    DenseResult d = sampleDense(model, v.frame, v.normalization, v.frame.indexBox);
    ASSERT_TRUE(d.error.empty()) << d.error;
    float lo = 0, hi = 0;
    std::size_t compared = 0;
    for (int k = v.frame.indexBox.lo[2]; k <= v.frame.indexBox.hi[2]; ++k)
        for (int j = v.frame.indexBox.lo[1]; j <= v.frame.indexBox.hi[1]; ++j)
            for (int i = v.frame.indexBox.lo[0]; i <= v.frame.indexBox.hi[0]; ++i) {
                float f = d.field.value(i, j, k);
                lo = std::min(lo, f);
                hi = std::max(hi, f);
                if (!v.active(i, j, k)) continue;
                ++compared;
                ASSERT_EQ(v.value(i, j, k), std::clamp(f, -v.frame.band, v.frame.band));
            }
    EXPECT_EQ(compared, v.activeVoxelCount());
    EXPECT_LT(lo, -3 * v.frame.band) << "the cache is not clamped";
    EXPECT_GT(hi, 0.0f);
}

TEST(Sampler, CullingSkipsMostOfTheBox) {
    // On a given box: how much the estimate trims off the box is not what
    // this measures.
    frep::Model model = test::modelFromSource(kSphere, {0.5});
    VolumeRequest req;
    req.resolution = 128;
    req.box = box(-1.0, 1.0);
    VoxelizeResult r = voxelize(model, req);
    ASSERT_TRUE(r.volume);
    EXPECT_GT(r.stats.boxesCulled, 0u);
    EXPECT_LT(r.stats.evaluatedFraction(), 0.3);
    EXPECT_GE(r.stats.samples, r.volume->activeVoxelCount());
}

TEST(Sampler, BadRequestsSayWhatIsWrong) {
    frep::Model sphere = test::modelFromSource(kSphere, {0.5});
    VolumeRequest req;
    req.resolution = 0;
    EXPECT_NE(voxelize(sphere, req).error.find("resolution 0 is out of range"), std::string::npos);
    req.resolution = 1000000;
    EXPECT_NE(voxelize(sphere, req).error.find("out of range"), std::string::npos);
    req.resolution = 32;
    req.band = 0.0f;
    EXPECT_NE(voxelize(sphere, req).error.find("band"), std::string::npos);
    req.band = 3.0f;
    frep::Model plane = test::modelFromSource("p(x[3], a[1]) { p = x[2]; }");
    EXPECT_NE(voxelize(plane, req).error.find("unbounded"), std::string::npos);
    // A bad resolution is refused before any model box is searched for.
    frep::Model wavy = test::modelFromSource(kInterpreterOnly);
    req.resolution = 2;
    EXPECT_NE(voxelize(wavy, req).error.find("resolution 2 is out of range"), std::string::npos);
    req.resolution = 32;
    frep::Model empty = test::modelFromSource("e(x[3], a[1]) { e = -1; }");
    EXPECT_NE(voxelize(empty, req).error.find("empty"), std::string::npos);
}

TEST(MemoryGuard, RefusesWhatWouldNotFitAndSaysWhatWould) {
    frep::Model sphere = test::modelFromSource(kSphere, {0.5});
    VolumeRequest req;
    req.resolution = 512;
    SampleOptions opts;
    opts.memoryLimit = std::uint64_t{2} << 20;  // 2 MiB
    VoxelizeResult r = voxelize(sphere, req, opts);
    EXPECT_FALSE(r.volume);
    EXPECT_NE(r.error.find("the narrow-band grid at resolution 512 needs about"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("or less would fit"), std::string::npos) << r.error;

    // A 2048^3 dense cache (32 GiB) against the default limit of this machine.
    VolumeFrame frame;
    ASSERT_EQ(makeFrame(box(-1, 1), 2048, 3.0f, frame), "");
    DenseResult d = sampleDense(sphere, frame, 1.0, frame.indexBox, std::uint64_t{16} << 30);
    EXPECT_TRUE(d.field.values.empty());
    EXPECT_NE(d.error.find("needs about 32."), std::string::npos) << d.error;
    EXPECT_NE(d.error.find("would fit"), std::string::npos) << d.error;
}

}  // namespace
}  // namespace hg::voxel
