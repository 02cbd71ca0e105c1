// Morph sources: the shared frame, normalized unclamped caches, the surface
// gradient they are balanced by, and the garden's morph set-up.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "garden/morph/garden_morph.h"
#include "garden/morph/morph_blend.h"
#include "garden_test_util.h"
#include "voxel/dense_field.h"

namespace hg::garden {
namespace {

// Radius 1, f = 1 - r^2 (|grad f| = 2 at the surface), and radius 0.6 with
// f a hundred times steeper (|grad f| = 120): the same kind of shape on very
// different scales.
constexpr const char* kWide = "wide(x[3], a[1]) { wide = 1 - (x[1]^2 + x[2]^2 + x[3]^2); }";
constexpr const char* kSteep = "steep(x[3], a[1]) { steep = 100 * (0.36 - (x[1]^2 + x[2]^2 + x[3]^2)); }";

frep::Box3 cube(double h) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) { b.lo[a] = -h; b.hi[a] = h; }
    return b;
}

// Where the blend crosses zero going out along +x from the centre, in model
// units (linear interpolation between the voxels around the sign change).
double radiusAlongX(const voxel::Volume& v) {
    const voxel::VolumeFrame& f = v.frame;
    const int c = f.indexOf(0, 0.0);
    for (int i = c; i < f.indexBox.hi[0]; ++i) {
        float a = v.value(i, c, c), b = v.value(i + 1, c, c);
        if (a >= 0.0f && b < 0.0f) return f.coordinate(0, i) + f.voxelSize * static_cast<double>(a / (a - b));
    }
    return -1.0;
}

TEST(MorphSources, BalancingFactorsEqualizeGradientsOfSpheresOfDifferentScale) {
    frep::Model wide = test::modelFromSource(kWide), steep = test::modelFromSource(kSteep);
    voxel::VolumeFrame frame;
    ASSERT_EQ(voxel::makeFrame(cube(1.2), 48, 3.0f, frame), "");
    const double h = frame.voxelSize;
    // Raw f (scale 1): the fields rise at very different rates.
    const frep::Model* models[3] = {&wide, &steep, &wide};
    std::array<voxel::DenseField, 3> dense;
    for (std::size_t i = 0; i < 3; ++i) {
        voxel::DenseResult d = voxel::sampleDense(*models[i], frame, 1.0, frame.indexBox);
        ASSERT_TRUE(d.error.empty()) << d.error;
        dense[i] = std::move(d.field);
    }
    MorphSources s = morphSourcesFromDense(frame, dense);
    EXPECT_EQ(checkSources(s), "");
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(s.surfaceGradient[i], surfaceGradient(dense[i]));
        // The blocked copy holds the same values.
        for (int k = frame.indexBox.lo[2]; k <= frame.indexBox.hi[2]; k += 5)
            for (int j = frame.indexBox.lo[1]; j <= frame.indexBox.hi[1]; j += 3)
                for (int n = frame.indexBox.lo[0]; n <= frame.indexBox.hi[0]; ++n)
                    ASSERT_EQ(s.fields[i].value(n, j, k), dense[i].value(n, j, k));
    }
    EXPECT_NEAR(s.surfaceGradient[0], 2.0 * h, 0.05 * 2.0 * h);
    EXPECT_NEAR(s.surfaceGradient[1], 120.0 * h, 0.05 * 120.0 * h);
    std::array<double, 3> b = balancingFactors(s.surfaceGradient);
    // Balanced, both rise by one unit per voxel across their surfaces.
    EXPECT_NEAR(b[0] * s.surfaceGradient[0], 1.0, 1e-12);
    EXPECT_NEAR(b[1] * s.surfaceGradient[1], 1.0, 1e-12);
    EXPECT_NEAR(b[0] / b[1], 60.0, 3.0);
    // Half way between them: balanced, the surface lies between the two
    // spheres ((1 - r^2)/2 + (0.36 - r^2)/1.2 = 0: r = sqrt(0.6)); without
    // balance the steep one wins (r = sqrt(37/101)).
    voxel::Volume balanced = blendMorph(s, weightsFromBarycentric({0.5, 0.5, 0.0}, b));
    voxel::Volume raw = blendMorph(s, weightsFromBarycentric({0.5, 0.5, 0.0}));
    EXPECT_NEAR(radiusAlongX(balanced), std::sqrt(0.6), 0.02);
    EXPECT_NEAR(radiusAlongX(raw), std::sqrt(37.0 / 101.0), 0.02);
}

TEST(MorphSources, BuiltSourcesAreNormalizedToTheSharedFrame) {
    test::ThreeModels m;
    MorphSources s = test::threeSources(m, 32);
    EXPECT_EQ(checkSources(s), "");
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_TRUE(s.fields[i].box() == s.frame.indexBox);
        // Each source rises by about one unit per voxel: balance about 1.
        EXPECT_NEAR(s.surfaceGradient[i], 1.0, 0.2) << i;
        EXPECT_NEAR(balancingFactors(s.surfaceGradient)[i], 1.0, 0.25) << i;
    }
    // Unclamped: far from the surface the values go well past the band.
    float lowest = 0.0f;
    const voxel::IndexBox& b = s.frame.indexBox;
    for (int k = b.lo[2]; k <= b.hi[2]; ++k)
        for (int j = b.lo[1]; j <= b.hi[1]; ++j)
            for (int i = b.lo[0]; i <= b.hi[0]; ++i) lowest = std::min(lowest, s.fields[2].value(i, j, k));
    EXPECT_LT(lowest, -3.0f * s.frame.band);
}

class GardenMorph : public test::ScratchDir {};

TEST_F(GardenMorph, SetsUpFromAGardenFile) {
    write("ball.hf", "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n");
    nlohmann::json j = nlohmann::json::parse(R"({
      "version": 1,
      "sculptures": [
        {"name": "a", "file": "ball.hf", "a": [0.25], "box": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]},
         "placement": {"position": [0, 0, -2]}},
        {"name": "b", "file": "ball.hf", "a": [0.16], "box": {"min": [-0.4, 0.1, -0.4], "max": [0.4, 0.9, 0.4]},
         "placement": {"position": [-1.7, 0, 1]}},
        {"name": "c", "file": "ball.hf", "a": [0.36], "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]},
         "placement": {"position": [1.7, 0, 1]}}
      ],
      "morph": {"sources": ["a", "b", "c"], "result": {"resolution": 32}}
    })");
    std::string path = write("g.json", j.dump());
    GardenLoad load = loadGarden(path);
    ASSERT_TRUE(load.ok()) << load.error;
    MorphTriangle t = morphTriangle(*load.garden, 0);
    EXPECT_EQ(t.corners[1][0], -1.7);
    EXPECT_EQ(t.corners[0][1], -2.0);
    frep::Box3 box;
    ASSERT_EQ(morphModelBox(load, 0, box), "");
    EXPECT_EQ(box.lo[1], -0.1);
    EXPECT_EQ(box.hi[0], 0.6);
    // Boxes a session already resolved are used as they are (here one wider
    // than the file's, to see it taken).
    ResolvedBoxes resolved(3);
    frep::Box3 wide;
    for (int a = 0; a < 3; ++a) { wide.lo[a] = -2.0; wide.hi[a] = 2.0; }
    resolved[1] = wide;
    frep::Box3 withResolved;
    ASSERT_EQ(morphModelBox(load, 0, withResolved, resolved), "");
    EXPECT_EQ(withResolved.lo[0], -2.0);
    EXPECT_EQ(withResolved.hi[1], 2.0);
    MorphSourcesResult r = buildGardenMorphSources(load, 0);
    ASSERT_TRUE(r.sources) << r.error;
    EXPECT_EQ(r.sources->frame.resolution, 32);
    std::array<double, 3> b = morphBalance(load.garden->morphs[0], *r.sources);
    for (double v : b) EXPECT_NEAR(v, 1.0, 0.25);
    // Given factors win.
    j["morph"]["balance"] = {1, 2, 3};
    GardenLoad given = loadGarden(write("g2.json", j.dump()));
    ASSERT_TRUE(given.ok()) << given.error;
    EXPECT_EQ(morphBalance(given.garden->morphs[0], *r.sources)[2], 3.0);
    // A missing source: no morph, and the garden still opens.
    j["sculptures"][1]["file"] = "gone.hf";
    GardenLoad missing = loadGarden(write("g3.json", j.dump()));
    ASSERT_TRUE(missing.ok());
    EXPECT_FALSE(buildGardenMorphSources(missing, 0).sources.has_value());
    EXPECT_NE(buildGardenMorphSources(missing, 0).error.find("'b' is missing"), std::string::npos);
}

}  // namespace
}  // namespace hg::garden
