// Surface rays (garden/sculpt/surface_ray.h): where a ray in a sculpture's
// model frame first meets the surface of its grid (the trilinear field's
// zero), marching half a voxel at a time through the model box and
// refining between the last two samples; none when it misses the solid in
// the box. What the tools aim with. Tested on sampled grids of balls whose
// surfaces are known exactly:
//  * rays from every side hit the ball within a small fraction of a voxel
//    of the exact intersection, on the grid's own zero (its trilinear
//    value there is about 0), and the first of two balls on the line;
//  * grazing rays: half a voxel inside the ball's silhouette hit, on its
//    surface; beyond it, and rays that point away, start past the ball,
//    miss the model box or have no direction, miss;
//  * t is in units of the direction's length (the session compares t
//    across sculptures in world ray lengths): scaling the direction by 2^n
//    scales t by exactly 2^-n;
//  * a ray that starts inside the solid meets it at 0; one that starts in
//    the box, outside the solid, hits where a ray from outside the box does.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "garden/sculpt/surface_ray.h"
#include "garden_test_util.h"
#include "voxel/sampler.h"

namespace hg::garden {
namespace {

using test::kSphere;

// Ball of radius 0.8 about (0.15, 0.1, 0) in the box [-1.2, 1.2]^3.
constexpr double kRadius = 0.8;
const ModelPoint kCentre{0.15, 0.1, 0.0};

voxel::Volume grid(const std::string& source, std::vector<double> a, int resolution = 64) {
    return test::sampledCube(source, std::move(a), 1.2, resolution);
}

voxel::Volume ball() { return grid(kSphere, {kRadius * kRadius, kCentre[0], kCentre[1], kCentre[2]}); }

ModelPoint at(const ModelPoint& o, const ModelPoint& d, double t) {
    return {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
}
double length(const ModelPoint& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
ModelPoint minus(const ModelPoint& a, const ModelPoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The exact entry into the ball of radius r about c, if the line meets it
// ahead of the origin.
std::optional<double> exactEntry(const ModelPoint& o, const ModelPoint& d, const ModelPoint& c, double r) {
    const ModelPoint oc = minus(o, c);
    const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double b = 2.0 * (oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2]);
    const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
    const double disc = b * b - 4.0 * a * cc;
    if (disc < 0.0) return std::nullopt;
    const double t = (-b - std::sqrt(disc)) / (2.0 * a);
    if (t < 0.0) return std::nullopt;
    return t;
}

// The grid's trilinear field at a model point, in voxel units.
double trilinear(const voxel::Volume& v, const ModelPoint& p) {
    double g[3], value = 0.0;
    int i[3];
    for (int a = 0; a < 3; ++a) {
        g[a] = (p[static_cast<std::size_t>(a)] - v.frame.modelBox.lo[a]) / v.frame.voxelSize;
        i[a] = static_cast<int>(std::floor(g[a]));
        g[a] -= i[a];
    }
    for (int c = 0; c < 8; ++c) {
        const int d[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
        double w = 1.0;
        for (int a = 0; a < 3; ++a) w *= d[a] ? g[a] : 1.0 - g[a];
        value += w * static_cast<double>(v.value(i[0] + d[0], i[1] + d[1], i[2] + d[2]));
    }
    return value;
}

// A unit direction from the seeded generator.
ModelPoint randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> n;
    ModelPoint d{n(rng), n(rng), n(rng)};
    const double l = length(d);
    return {d[0] / l, d[1] / l, d[2] / l};
}

TEST(SurfaceRay, HitsABallWithinAFractionOfAVoxelOnTheGridsZero) {
    const voxel::Volume v = ball();
    const double h = v.frame.voxelSize;
    std::mt19937 rng(12);
    double worst = 0.0, worstField = 0.0;
    int rays = 0;
    for (int n = 0; n < 240; ++n) {
        // From 3 away (outside the model box) towards a point well inside.
        const ModelPoint from = randomDirection(rng), to = randomDirection(rng);
        const ModelPoint o = at(kCentre, from, 3.0), target = at(kCentre, to, 0.6 * kRadius);
        ModelPoint d = minus(target, o);
        if (n % 2) d = {d[0] / length(d), d[1] / length(d), d[2] / length(d)};  // unit and not
        const auto exact = exactEntry(o, d, kCentre, kRadius);
        ASSERT_TRUE(exact);
        const auto t = marchToSurface(v, o, d);
        ASSERT_TRUE(t) << "ray " << n;
        const ModelPoint p = at(o, d, *t);
        worst = std::max(worst, std::fabs(*t - *exact) * length(d) / h);
        worstField = std::max(worstField, std::fabs(trilinear(v, p)));
        ++rays;
    }
    EXPECT_EQ(rays, 240);
    EXPECT_LT(worst, 0.05) << "voxels from the exact ball along the ray";
    EXPECT_LT(worstField, 0.02) << "the grid's trilinear field at the hit";
    // Along the axes, from both sides.
    for (int a = 0; a < 3; ++a)
        for (double s : {-1.0, 1.0}) {
            ModelPoint o = kCentre, d{0.0, 0.0, 0.0};
            o[static_cast<std::size_t>(a)] += 2.5 * s;
            d[static_cast<std::size_t>(a)] = -s;
            const auto t = marchToSurface(v, o, d);
            ASSERT_TRUE(t);
            EXPECT_NEAR(*t, 2.5 - kRadius, 0.1 * h) << "axis " << a << " side " << s;
        }
}

TEST(SurfaceRay, TheFirstOfTwoBallsOnTheLine) {
    // Balls of radius 0.4 about x = -0.6 and x = 0.6.
    const voxel::Volume v = grid(
        "two(x[3], a[1]) { two = max(0.16 - ((x[1]+0.6)^2 + x[2]^2 + x[3]^2), 0.16 - ((x[1]-0.6)^2 + x[2]^2 + x[3]^2)); }",
        {});
    const double h = v.frame.voxelSize;
    const auto fromLeft = marchToSurface(v, {-3.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
    const auto fromRight = marchToSurface(v, {3.0, 0.0, 0.0}, {-1.0, 0.0, 0.0});
    ASSERT_TRUE(fromLeft && fromRight);
    EXPECT_NEAR(-3.0 + *fromLeft, -1.0, 0.1 * h);
    EXPECT_NEAR(3.0 - *fromRight, 1.0, 0.1 * h);
    // Starting between them, each way: the near side of the ball ahead.
    const auto ahead = marchToSurface(v, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
    const auto behind = marchToSurface(v, {0.0, 0.0, 0.0}, {-1.0, 0.0, 0.0});
    ASSERT_TRUE(ahead && behind);
    EXPECT_NEAR(*ahead, 0.2, 0.1 * h);
    EXPECT_NEAR(*behind, 0.2, 0.1 * h);
    // Between the balls, across them: nothing.
    EXPECT_FALSE(marchToSurface(v, {0.0, -3.0, 0.0}, {0.0, 1.0, 0.0}));
}

TEST(SurfaceRay, GrazingRaysHitInsideTheSilhouetteAndMissOutsideIt) {
    const voxel::Volume v = ball();
    const double h = v.frame.voxelSize;
    std::mt19937 rng(5);
    for (int n = 0; n < 60; ++n) {
        // A line at distance `miss` from the centre, perpendicular to `side`.
        const ModelPoint d = randomDirection(rng);
        ModelPoint side = randomDirection(rng);
        const double along = side[0] * d[0] + side[1] * d[1] + side[2] * d[2];
        for (int a = 0; a < 3; ++a) side[static_cast<std::size_t>(a)] -= along * d[static_cast<std::size_t>(a)];
        const double l = length(side);
        for (auto& s : side) s /= l;
        for (double offset : {-0.5, 0.75, 2.0, 6.0}) {  // voxels outside the ball's radius
            const double miss = kRadius + offset * h;
            const ModelPoint o = at(at(kCentre, side, miss), d, -3.0);
            const auto t = marchToSurface(v, o, d);
            if (offset < 0.0) {
                ASSERT_TRUE(t) << "ray " << n << " half a voxel inside the silhouette";
                EXPECT_NEAR(length(minus(at(o, d, *t), kCentre)), kRadius, 0.1 * h);
                EXPECT_NEAR(*t, *exactEntry(o, d, kCentre, kRadius), 0.5 * h) << "along a grazing ray";
            } else {
                EXPECT_FALSE(t) << "ray " << n << ", " << offset << " voxels outside: t " << t.value_or(-1);
            }
        }
    }
}

TEST(SurfaceRay, RaysThatCannotMeetTheSolidMiss) {
    const voxel::Volume v = ball();
    // Pointing away, from outside the box and from inside it.
    EXPECT_FALSE(marchToSurface(v, {3.0, 0.1, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {1.1, 0.1, 0.0}, {1.0, 0.2, 0.0}));
    // The ball lies behind the origin on the line.
    EXPECT_FALSE(marchToSurface(v, {-1.1, 0.1, 0.0}, {-1.0, 0.0, 0.0}));
    // Parallel to an axis outside the model box's slab; through the box
    // beside the ball, and along its edge.
    EXPECT_FALSE(marchToSurface(v, {0.15, 1.5, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {-3.0, 1.1, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {-1.19, -1.19, -3.0}, {0.0, 0.0, 1.0}));
    // Missing the box altogether.
    EXPECT_FALSE(marchToSurface(v, {5.0, 5.0, 5.0}, {1.0, -0.1, 0.0}));
    // No direction.
    EXPECT_FALSE(marchToSurface(v, {3.0, 0.0, 0.0}, {0.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, kCentre, {0.0, 0.0, 0.0}));
    // A NaN or infinite pose meets nothing (and returns: a NaN origin once
    // passed the box test and marched for ever).
    const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(marchToSurface(v, {nan, nan, nan}, {1.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {-3.0, nan, 0.0}, {1.0, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {-3.0, 0.0, 0.0}, {nan, 0.0, 0.0}));
    EXPECT_FALSE(marchToSurface(v, {-inf, 0.0, 0.0}, {1.0, 0.0, 0.0}));
}

TEST(SurfaceRay, TIsInUnitsOfTheDirectionsLength) {
    const voxel::Volume v = ball();
    std::mt19937 rng(21);
    for (int n = 0; n < 40; ++n) {
        const ModelPoint o = at(kCentre, randomDirection(rng), 2.5);
        const ModelPoint target = at(kCentre, randomDirection(rng), 0.5);
        const ModelPoint d = minus(target, o);
        const auto t = marchToSurface(v, o, d);
        ASSERT_TRUE(t);
        for (double s : {2.0, 0.25, 1024.0}) {
            const auto ts = marchToSurface(v, o, {d[0] * s, d[1] * s, d[2] * s});
            ASSERT_TRUE(ts);
            EXPECT_EQ(*ts, *t / s) << "the same samples, t scaled exactly";
        }
        const auto t3 = marchToSurface(v, o, {d[0] * 3.0, d[1] * 3.0, d[2] * 3.0});
        ASSERT_TRUE(t3);
        EXPECT_NEAR(*t3 * 3.0, *t, 1e-9);
    }
}

TEST(SurfaceRay, StartingInsideTheSolidOrTheBox) {
    const voxel::Volume v = ball();
    const double h = v.frame.voxelSize;
    // In the solid: it is met at once.
    EXPECT_EQ(marchToSurface(v, kCentre, {0.0, 1.0, 0.0}), 0.0);
    EXPECT_EQ(marchToSurface(v, at(kCentre, {1.0, 0.0, 0.0}, kRadius - 3.0 * h), {1.0, 0.0, 0.0}), 0.0);
    // In the box, outside the solid: where the ray from outside the box hits.
    const ModelPoint d{-0.6, -0.64, 0.48};  // unit
    const ModelPoint far = at(kCentre, d, -3.0), near = at(kCentre, d, -1.0);
    const auto tFar = marchToSurface(v, far, d), tNear = marchToSurface(v, near, d);
    ASSERT_TRUE(tFar && tNear);
    EXPECT_NEAR(*tNear + 2.0, *tFar, 0.05 * h);
    EXPECT_NEAR(*tNear, 1.0 - kRadius, 0.1 * h);
}

}  // namespace
}  // namespace hg::garden
