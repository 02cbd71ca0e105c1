// Bounds of the Cauchy line-segment field over boxes (convSegmentBounds),
// on boxes placed where culling decides: around the skeleton and across the
// surface of random segments and widths. They must hold every value either
// sampling path returns, and, away from the segment's line, stay close to
// the field's real spread over the box: that is what lets the sampler skip
// leaves near thin limbs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "frep/kernels/conv_segment.h"
#include "kernel_checks.h"

namespace hg::frep {
namespace {

struct Segment {
    double q[7];  // begin, end, s
    double length() const {
        return std::sqrt((q[3] - q[0]) * (q[3] - q[0]) + (q[4] - q[1]) * (q[4] - q[1]) + (q[5] - q[2]) * (q[5] - q[2]));
    }
};

Segment randomSegment(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Segment g;
    for (int k = 0; k < 6; ++k) g.q[k] = u(rng);
    const double s = std::pow(10.0, std::uniform_real_distribution<double>(0.0, 1.5)(rng));  // 1 .. 32
    g.q[6] = u(rng) < -0.8 ? -s : s;  // the width's sign does not matter
    return g;
}

// A point at t along the segment (0: its begin, 1: its end) moved off it by
// a normal offset of deviation 1.5 / s on each axis, where the surface runs.
void nearSegment(const Segment& g, double t, std::mt19937& rng, double p[3]) {
    std::normal_distribution<double> off(0.0, 1.5 / std::fabs(g.q[6]));
    for (int k = 0; k < 3; ++k) p[k] = g.q[k] + t * (g.q[k + 3] - g.q[k]) + off(rng);
}

// The distance from p to the segment's line.
double lineDistance(const Segment& g, const double p[3]) {
    const double l = g.length();
    double d2 = 0.0, x = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double u = p[k] - g.q[k];
        d2 += u * u;
        x += u * (g.q[k + 3] - g.q[k]) / l;
    }
    return std::sqrt(std::max(d2 - x * x, 0.0));
}

struct Sampled {
    double lo = INFINITY, hi = -INFINITY;
};

// 8^3 points of the box, corners and faces included, through the double
// and the float paths; every value must lie in `bounds`.
Sampled sampleBox(const Segment& g, const double lo[3], double size, const Interval& bounds) {
    const test::BoxSamples p = test::floatPointsInBox(lo, size);
    const std::vector<double>& x = p.x;
    const std::vector<double>& y = p.y;
    const std::vector<double>& z = p.z;
    std::vector<double> out(x.size());
    std::vector<float> outf(x.size());
    convSegmentBatch(x.data(), y.data(), z.data(), out.data(), x.size(), g.q);
    convSegmentBatch(p.xf.data(), p.yf.data(), p.zf.data(), outf.data(), x.size(), g.q);
    Sampled s;
    for (std::size_t i = 0; i < out.size(); ++i) {
        EXPECT_TRUE(bounds.contains(out[i])) << "double path: F(" << x[i] << ", " << y[i] << ", " << z[i]
                                             << ") = " << out[i] << " outside [" << bounds.lo << ", " << bounds.hi << "]";
        EXPECT_TRUE(bounds.contains(outf[i])) << "float path: F(" << x[i] << ", " << y[i] << ", " << z[i]
                                              << ") = " << outf[i] << " (double path " << out[i] << ") outside [" << bounds.lo << ", " << bounds.hi << "]";
        s.lo = std::min(s.lo, out[i]);
        s.hi = std::max(s.hi, out[i]);
    }
    return s;
}

TEST(SegmentBounds, HoldEveryValueOnBoxesAroundTheSkeleton) {
    std::mt19937 rng(11);
    for (int seg = 0; seg < 60; ++seg) {
        const Segment g = randomSegment(rng);
        const double s = std::fabs(g.q[6]);
        for (int b = 0; b < 40; ++b) {
            // Along the segment or a little past its ends.
            const double t = std::uniform_real_distribution<double>(-0.3, 1.3)(rng);
            const double size = std::pow(10.0, std::uniform_real_distribution<double>(-4.0, 0.0)(rng)) / s;
            double lo[3];
            nearSegment(g, t, rng, lo);
            for (double& v : lo) v -= 0.5 * size;
            const Interval bounds = convSegmentBounds(Interval(lo[0], lo[0] + size), Interval(lo[1], lo[1] + size),
                                                      Interval(lo[2], lo[2] + size), g.q);
            ASSERT_LE(bounds.lo, bounds.hi);
            sampleBox(g, lo, size, bounds);
            if (HasFailure()) return;
        }
    }
}

TEST(SegmentBounds, StayCloseToTheSpreadAwayFromTheLine) {
    // Boxes of a fifth of a kernel width or less whose centre is at least
    // two half-diagonals off the line: the bounds are exact on the box's
    // range of (axial position, distance to the line), so they may exceed
    // the sampled spread only by how much that rectangle exceeds the box.
    std::mt19937 rng(12);
    int boxes = 0;
    for (int seg = 0; seg < 60; ++seg) {
        const Segment g = randomSegment(rng);
        const double s = std::fabs(g.q[6]);
        for (int b = 0; b < 40; ++b) {
            const double t = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
            const double size = std::uniform_real_distribution<double>(0.02, 0.2)(rng) / s;
            double lo[3], centre[3];
            nearSegment(g, t, rng, centre);
            for (int k = 0; k < 3; ++k) lo[k] = centre[k] - 0.5 * size;
            if (lineDistance(g, centre) < 2.0 * std::sqrt(3.0) * size) continue;
            const Interval bounds = convSegmentBounds(Interval(lo[0], lo[0] + size), Interval(lo[1], lo[1] + size),
                                                      Interval(lo[2], lo[2] + size), g.q);
            const Sampled seen = sampleBox(g, lo, size, bounds);
            const double spread = seen.hi - seen.lo;
            EXPECT_LE(bounds.hi - bounds.lo, 4.0 * spread + 1e-6 * seen.hi)
                << "segment " << seg << ", box " << b << ": [" << bounds.lo << ", " << bounds.hi << "] against ["
                << seen.lo << ", " << seen.hi << "]";
            ++boxes;
        }
    }
    EXPECT_GT(boxes, 1000);
}

TEST(SegmentBounds, FloatPathStaysWellInsideTheirRoundingRoom) {
    // The bounds leave room for the float path's rounding (convSegmentBounds):
    //   (|F| + pi / (2 |s| p^3)) (2e-5 + 1e-6 s^2 d^2) + 1e-9,
    // p^2 = 1 + s^2 rho^2, rho the distance to the segment's line and d the
    // distance to its begin. The float loop takes rho^2 as d^2 - x^2, which
    // cancels on the skeleton (hence s^2 d^2), and beyond the ends its terms
    // nearly cancel each other (hence the arctangent term's scale beside
    // |F|). The float path should need half of that room at most, on and
    // around the skeleton, past the ends and far away.
    std::mt19937 rng(13);
    double worst = 0.0;
    for (int seg = 0; seg < 2000; ++seg) {
        const Segment g = randomSegment(rng);
        const double s = std::fabs(g.q[6]);
        const double t = std::uniform_real_distribution<double>(-0.5, 1.5)(rng);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const std::size_t n = 256;
        std::vector<float> xf(n), yf(n), zf(n), outf(n);
        std::vector<double> x(n), y(n), z(n), out(n);
        for (std::size_t i = 0; i < n; ++i) {
            const double reach = std::pow(10.0, std::uniform_real_distribution<double>(-3.0, 1.0)(rng)) / s;
            xf[i] = static_cast<float>(g.q[0] + t * (g.q[3] - g.q[0]) + reach * u(rng));
            yf[i] = static_cast<float>(g.q[1] + t * (g.q[4] - g.q[1]) + reach * u(rng));
            zf[i] = static_cast<float>(g.q[2] + t * (g.q[5] - g.q[2]) + reach * u(rng));
            x[i] = xf[i]; y[i] = yf[i]; z[i] = zf[i];
        }
        convSegmentBatch(xf.data(), yf.data(), zf.data(), outf.data(), n, g.q);
        convSegmentBatch(x.data(), y.data(), z.data(), out.data(), n, g.q);
        for (std::size_t i = 0; i < n; ++i) {
            const double pt[3] = {x[i], y[i], z[i]};
            const double rho = lineDistance(g, pt);
            const double d2 = (x[i] - g.q[0]) * (x[i] - g.q[0]) + (y[i] - g.q[1]) * (y[i] - g.q[1]) +
                              (z[i] - g.q[2]) * (z[i] - g.q[2]);
            const double terms = std::fabs(out[i]) + 3.14159265358979 / (2.0 * s * std::pow(1.0 + s * s * rho * rho, 1.5));
            const double room = 1e-9 + terms * (2e-5 + 1e-6 * s * s * d2);
            const double error = std::fabs(static_cast<double>(outf[i]) - out[i]);
            ASSERT_LE(error, 0.5 * room) << "F(" << x[i] << ", " << y[i] << ", " << z[i] << ") = " << out[i]
                                         << " with s = " << s;
            worst = std::max(worst, error / room);
        }
    }
    std::printf("float path error: at most %.2f of the room the bounds leave\n", worst);
}

}  // namespace
}  // namespace hg::frep
