// The morph selector: barycentric weights from sub-triangle areas, balancing
// factors, normalization to 1, clamping to the triangle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "garden/morph/morph_weights.h"

namespace hg::garden {
namespace {

// An equilateral triangle about the origin (side sqrt(3)), as in seed 004,
// and a scalene one in the other winding.
const MorphTriangle kEquilateral{{Point2{0.0, 1.0}, Point2{-std::sqrt(3.0) / 2, -0.5}, Point2{std::sqrt(3.0) / 2, -0.5}}};
const MorphTriangle kScalene{{Point2{-1.0, 0.2}, Point2{2.5, -0.7}, Point2{0.3, 3.1}}};

double sum(const std::array<double, 3>& w) { return w[0] + w[1] + w[2]; }

TEST(MorphWeights, CornersSelectOneSource) {
    for (const MorphTriangle& t : {kEquilateral, kScalene})
        for (std::size_t i = 0; i < 3; ++i) {
            MorphWeights m = morphWeights(t, t.corners[i], {0.3, 2.0, 5.0});
            for (std::size_t j = 0; j < 3; ++j) {
                EXPECT_EQ(m.barycentric[j], i == j ? 1.0 : 0.0);
                EXPECT_EQ(m.w[j], i == j ? 1.0 : 0.0);  // exactly, whatever the balance
            }
            EXPECT_FALSE(m.clamped);
        }
}

TEST(MorphWeights, CentreWithEqualBalanceGivesThirds) {
    for (const MorphTriangle& t : {kEquilateral, kScalene}) {
        MorphWeights m = morphWeights(t, t.centroid());
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_NEAR(m.barycentric[i], 1.0 / 3.0, 1e-12);
            EXPECT_NEAR(m.w[i], 1.0 / 3.0, 1e-12);
        }
        EXPECT_NEAR(sum(m.w), 1.0, 1e-15);
    }
}

TEST(MorphWeights, BalanceScalesThenNormalizes) {
    MorphWeights m = morphWeights(kEquilateral, kEquilateral.centroid(), {2.0, 1.0, 1.0});
    EXPECT_NEAR(m.w[0], 0.5, 1e-12);
    EXPECT_NEAR(m.w[1], 0.25, 1e-12);
    EXPECT_NEAR(m.w[2], 0.25, 1e-12);
    EXPECT_EQ(m.balance[0], 2.0);
}

TEST(MorphWeights, AreasReproduceThePoint) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 200; ++n) {
        // A random point inside, from random barycentric coordinates.
        double a = u(rng), b = u(rng);
        if (a + b > 1) { a = 1 - a; b = 1 - b; }
        const auto& c = kScalene.corners;
        Point2 p{(1 - a - b) * c[0][0] + a * c[1][0] + b * c[2][0], (1 - a - b) * c[0][1] + a * c[1][1] + b * c[2][1]};
        auto l = barycentric(kScalene, p);
        EXPECT_NEAR(l[0], 1 - a - b, 1e-12);
        EXPECT_NEAR(l[1], a, 1e-12);
        EXPECT_NEAR(l[2], b, 1e-12);
        EXPECT_NEAR(sum(l), 1.0, 1e-15);
    }
}

TEST(MorphWeights, OutsidePointsClampToTheTriangle) {
    // Beyond a corner: that corner.
    MorphWeights m = morphWeights(kEquilateral, {0.0, 5.0});
    EXPECT_TRUE(m.clamped);
    EXPECT_NEAR(m.w[0], 1.0, 1e-12);
    EXPECT_NEAR(m.point[1], 1.0, 1e-12);
    // Straight out from the middle of an edge: the edge's midpoint, the
    // opposite corner weighs nothing.
    m = morphWeights(kEquilateral, {0.0, -3.0});
    EXPECT_TRUE(m.clamped);
    EXPECT_NEAR(m.point[0], 0.0, 1e-12);
    EXPECT_NEAR(m.point[1], -0.5, 1e-12);
    EXPECT_NEAR(m.w[0], 0.0, 1e-12);
    EXPECT_NEAR(m.w[1], 0.5, 1e-12);
    EXPECT_NEAR(m.w[2], 0.5, 1e-12);
    // Random outside points: the nearest point of the triangle, found by
    // brute force over a fine sampling of the edges; weights still sum to 1.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-6.0, 6.0);
    int outside = 0;
    for (int n = 0; n < 300; ++n) {
        Point2 p{u(rng), u(rng)};
        MorphWeights w = morphWeights(kScalene, p, {1.0, 3.0, 0.5});
        EXPECT_NEAR(sum(w.w), 1.0, 1e-12);
        for (double v : w.w) EXPECT_GE(v, 0.0);
        if (!w.clamped) continue;
        ++outside;
        double best = INFINITY;
        for (std::size_t e = 0; e < 3; ++e)
            for (int s = 0; s <= 2000; ++s) {
                const Point2& a = kScalene.corners[e];
                const Point2& b = kScalene.corners[(e + 1) % 3];
                double t = s / 2000.0;
                double dx = a[0] + t * (b[0] - a[0]) - p[0], dz = a[1] + t * (b[1] - a[1]) - p[1];
                best = std::min(best, std::sqrt(dx * dx + dz * dz));
            }
        double got = std::hypot(w.point[0] - p[0], w.point[1] - p[1]);
        EXPECT_LE(got, best + 1e-12);
        EXPECT_GE(got, best - 5e-3);
        // The clamped point is inside (or on) the triangle: no negative area.
        auto l = barycentric(kScalene, w.point);
        for (double v : l) EXPECT_GE(v, 0.0);
    }
    EXPECT_GT(outside, 100);
}

TEST(MorphWeights, BalancingFactorsMakeUnitGradients) {
    std::array<double, 3> g{0.1, 6.0, 1.0};
    auto b = balancingFactors(g);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(b[i] * g[i], 1.0);
    // A source without a surface keeps factor 1.
    EXPECT_EQ(balancingFactors({0.0, 1.0, 1.0})[0], 1.0);
}

}  // namespace
}  // namespace hg::garden
