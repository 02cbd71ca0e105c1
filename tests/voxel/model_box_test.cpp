// The model box when none is given (voxel/model_box.h): bounded sculptures
// written outside the project, on which the interval estimate fails, get a
// box found by sampling the default box [-10, 10]^3 that contains the solid
// and closes in on it; truly unbounded solids are refused with the faces of
// that box they reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "frep/eval/bounds.h"
#include "test_models.h"
#include "voxel/lattice_evaluation.h"
#include "voxel/model_box.h"
#include "voxel/sampler.h"

namespace hg::voxel {
namespace {

// Bounded sculptures in the style of files written outside the project
// (tests/data/bounded): no guard keeps interval bounds tight far away.
const char* const kBoundedFiles[] = {"arc_torus.hf", "figure_on_block.hf", "totem.hf"};

std::string boundedFile(const std::string& name) { return std::string(HG_TEST_DATA_DIR) + "/bounded/" + name; }

// The bounding box of the points of a lattice over `box` (`n` points along
// each axis) where the model is inside (f >= 0, float evaluation as the
// sampler's); `any` false when there is none.
struct InsideHull {
    bool any = false;
    frep::Box3 hull;
};

InsideHull insideHull(const frep::Model& model, const frep::Box3& box, int n) {
    std::array<std::vector<float>, 3> axes;
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i < n; ++i)
            axes[a].push_back(static_cast<float>(box.lo[a] + (box.hi[a] - box.lo[a]) * i / (n - 1)));
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    std::vector<float> f(count);
    evaluateLattice(model, axes, f.data());
    InsideHull h;
    const std::size_t un = static_cast<std::size_t>(n);
    for (std::size_t k = 0; k < un; ++k)
        for (std::size_t j = 0; j < un; ++j)
            for (std::size_t i = 0; i < un; ++i) {
                if (!(f[(k * un + j) * un + i] >= 0.0f)) continue;
                const double p[3] = {axes[0][i], axes[1][j], axes[2][k]};
                for (int a = 0; a < 3; ++a) {
                    h.hull.lo[a] = h.any ? std::min(h.hull.lo[a], p[a]) : p[a];
                    h.hull.hi[a] = h.any ? std::max(h.hull.hi[a], p[a]) : p[a];
                }
                h.any = true;
            }
    return h;
}

frep::Box3 cube(double lo, double hi) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) { b.lo[a] = lo; b.hi[a] = hi; }
    return b;
}

double longestSide(const frep::Box3& b) {
    return std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
}

TEST(ModelBox, BoundedFilesTheIntervalEstimateFailsOnAreSampled) {
    for (const char* name : kBoundedFiles) {
        SCOPED_TRACE(name);
        frep::Model model = test::modelFromFile(boundedFile(name));
        ASSERT_TRUE(model.tape()) << model.fallbackReason();
        // What makes these files the case in point: intervals do not
        // separate them from far space.
        EXPECT_TRUE(frep::estimateBounds(*model.tape()).unbounded);

        ModelBox found;
        ASSERT_EQ(resolveModelBox(model, std::nullopt, found), "");
        EXPECT_EQ(found.origin, BoxOrigin::Sampled);
        EXPECT_NE(found.estimateFailure.find("interval bounds did not separate"), std::string::npos)
            << found.estimateFailure;
        EXPECT_GT(found.samples, 0u);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(found.box.lo[a], -2.5) << "axis " << a;
            EXPECT_LE(found.box.hi[a], 2.5) << "axis " << a;
        }

        // Every inside point of a dense sampling of [-10, 10]^3 (a lattice
        // of 0.125 spacing, not the fallback's 0.156) lies in the box.
        InsideHull wide = insideHull(model, cube(-10.0, 10.0), 161);
        ASSERT_TRUE(wide.any);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(found.box.lo[a], wide.hull.lo[a]) << "axis " << a;
            EXPECT_GE(found.box.hi[a], wide.hull.hi[a]) << "axis " << a;
        }

        // And of a fine sampling around the box (spacing a 200th of it,
        // half a unit beyond it): the box contains the solid and is within
        // a few cells of the second pass (about a 128th of the solid) of
        // it, which is less than one cell of the first pass over the default
        // box (0.16): without the second pass it would be two or three.
        frep::Box3 around = found.box;
        for (int a = 0; a < 3; ++a) { around.lo[a] -= 0.5; around.hi[a] += 0.5; }
        const double spacing = longestSide(around) / 200.0;
        InsideHull fine = insideHull(model, around, 201);
        ASSERT_TRUE(fine.any);
        const double slack = (kSampledBoxMargin + 1) * longestSide(fine.hull) / kSampledBoxResolution + spacing;
        ASSERT_LT(slack, 2.0 * kDefaultBoxHalfSize / kSampledBoxResolution);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(found.box.lo[a], fine.hull.lo[a]) << "axis " << a;
            EXPECT_GE(found.box.hi[a], fine.hull.hi[a]) << "axis " << a;
            EXPECT_GE(found.box.lo[a], fine.hull.lo[a] - slack) << "axis " << a;
            EXPECT_LE(found.box.hi[a], fine.hull.hi[a] + slack) << "axis " << a;
        }
    }
}

TEST(ModelBox, VoxelizeUsesTheSampledBoxAndSaysSo) {
    frep::Model model = test::modelFromFile(boundedFile("totem.hf"));
    VolumeRequest req;
    req.resolution = 64;
    VoxelizeResult r = voxelize(model, req);
    ASSERT_TRUE(r.volume) << r.error;
    EXPECT_EQ(r.modelBox.origin, BoxOrigin::Sampled);
    EXPECT_EQ(r.volume->boxOrigin, BoxOrigin::Sampled);
    for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(r.volume->frame.modelBox.lo[a], r.modelBox.box.lo[a]);
        EXPECT_EQ(r.volume->frame.modelBox.hi[a], r.modelBox.box.hi[a]);
    }
    EXPECT_GT(r.volume->activeVoxelCount(), 1000u);
    const std::string said = describeModelBox(r.modelBox);
    EXPECT_NE(said.find("sampled: the interval estimate failed"), std::string::npos) << said;
    EXPECT_NE(said.find("[-10, 10]^3"), std::string::npos) << said;

    // A given box and a successful estimate are said as such.
    VolumeRequest given = req;
    given.box = cube(-1.0, 1.0);
    frep::Model sphere = test::modelFromSource(test::kSphere, {0.5});
    EXPECT_EQ(voxelize(sphere, given).modelBox.origin, BoxOrigin::Given);
    VoxelizeResult estimated = voxelize(sphere, req);
    EXPECT_EQ(estimated.modelBox.origin, BoxOrigin::IntervalEstimate);
    EXPECT_NE(describeModelBox(estimated.modelBox).find("estimated by interval subdivision"), std::string::npos);
    EXPECT_NE(describeModelBox(voxelize(sphere, given).modelBox).find("(given)"), std::string::npos);
}

TEST(ModelBox, InterpreterProgramsAreSampledWithoutIntervals) {
    // 0.8 - x^2 - y^2 - z^2 through a loop the tape cannot flatten: a ball
    // of radius sqrt(0.8).
    frep::Model model = test::modelFromSource(test::kInterpreterOnly);
    ASSERT_FALSE(model.tape());
    ModelBox found;
    ASSERT_EQ(resolveModelBox(model, std::nullopt, found), "");
    EXPECT_EQ(found.origin, BoxOrigin::Sampled);
    EXPECT_NE(found.estimateFailure.find("scalar interpreter"), std::string::npos) << found.estimateFailure;
    const double r = std::sqrt(0.8);
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(found.box.lo[a], -r);
        EXPECT_GE(found.box.hi[a], r);
        EXPECT_GT(found.box.lo[a], -r - 0.1);
        EXPECT_LT(found.box.hi[a], r + 0.1);
    }
}

TEST(ModelBox, UnboundedSolidsAreRefusedWithTheFacesTheyReach) {
    struct Case {
        const char* source;
        std::vector<std::string> reached, notReached;
    } cases[] = {
        // An infinite cylinder along z, thin enough to miss x and y faces.
        {"c(x[3], a[1]) { c = 0.25 - x[1]^2 - x[2]^2; }", {"z = -10", "z = 10"}, {"x = ", "y = "}},
        // The half-space y <= 0.5.
        {"h(x[3], a[1]) { h = 0.5 - x[2]; }", {"x = -10", "x = 10", "y = -10", "z = -10", "z = 10"}, {"y = 10"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.source);
        frep::Model model = test::modelFromSource(c.source);
        ModelBox found;
        std::string why = resolveModelBox(model, std::nullopt, found);
        EXPECT_NE(why.find("the solid is unbounded"), std::string::npos) << why;
        EXPECT_NE(why.find("the default box [-10, 10]^3"), std::string::npos) << why;
        for (const std::string& face : c.reached) EXPECT_NE(why.find(face), std::string::npos) << face << ": " << why;
        for (const std::string& face : c.notReached) EXPECT_EQ(why.find(face), std::string::npos) << face << ": " << why;
        VolumeRequest req;
        req.resolution = 32;
        EXPECT_FALSE(voxelize(model, req).volume);
    }
}

TEST(ModelBox, EmptySolidsAreRefused) {
    // Proven empty by intervals.
    ModelBox found;
    std::string why = resolveModelBox(test::modelFromSource("e(x[3], a[1]) { e = -1; }"), std::nullopt, found);
    EXPECT_NE(why.find("the solid is empty"), std::string::npos) << why;
    // On the interpreter: no sample of the default box is inside.
    const char* emptyLoop =
        "e(x[3], a[1]) {\n"
        "  q = 0; n = 0;\n"
        "  while (n < 2) loop\n"
        "    q = q + x[1] * x[1];\n"
        "    n = n + 1 + 0 * x[2];\n"
        "  endloop;\n"
        "  e = -1 - q;\n"
        "}\n";
    why = resolveModelBox(test::modelFromSource(emptyLoop), std::nullopt, found);
    EXPECT_NE(why.find("the solid is empty as far as sampling shows"), std::string::npos) << why;
}

}  // namespace
}  // namespace hg::voxel
