// Inflation to FRep (issue 22, "Inflation"): a circle inflates to a sphere,
// an oval to a sausage, silhouettes fit their outlines, and the HyperFun
// text evaluates exactly as the C++ field. Every field value checked here
// comes from the emitted text parsed by our HyperFun parser, unless a test
// says it compares the two.
#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <random>

#include "frep/eval/model.h"
#include "garden/sketch/inflation.h"
#include "garden/sketch/inflation_field.h"
#include "garden/sketch/inflation_text.h"
#include "garden/sketch/outline.h"
#include "tests/sketch/sketch_shapes.h"

namespace hg::garden::sketch {
namespace {

using namespace hg::test::sketch;

// A tilted plane away from the origin, so that the world transform is
// exercised everywhere.
SketchPlane tiltedPlane() { return planeFacing(Vec3(1.0, 2.0, 0.5), Vec3(0.3, -0.5, 0.8)); }

struct Sketched {
    Outline outline;
    Inflation inflation;
    std::string text;
    std::optional<frep::Model> model;

    // The parsed text's values at world points.
    std::vector<double> eval(const std::vector<Vec3>& pts) const {
        std::vector<double> x, y, z, out(pts.size());
        for (const Vec3& p : pts) {
            x.push_back(p.x);
            y.push_back(p.y);
            z.push_back(p.z);
        }
        frep::PointSampler<double> sampler(*model);
        frep::ErrorReport errors;
        sampler.evaluate(x.data(), y.data(), z.data(), out.data(), pts.size(), errors);
        EXPECT_EQ(errors.count, 0u);
        return out;
    }
    double eval(const Vec3& p) const { return eval(std::vector<Vec3>{p})[0]; }
    Vec3 world(const Vec2& q, double w = 0.0) const {
        const SketchPlane& pl = inflation.solid.plane;
        return pl.toWorld(q) + w * pl.normal;
    }
};

Sketched sketch(const std::vector<Vec2>& raw, int samples, const SketchPlane& plane = tiltedPlane(),
                const InflationOptions& options = {}) {
    Sketched s;
    OutlineOptions o;
    o.samples = samples;
    s.outline = makeOutline(raw, o);
    EXPECT_TRUE(s.outline.ok()) << s.outline.error;
    s.inflation = inflate(s.outline.points, s.outline.spacing, plane, options);
    EXPECT_TRUE(s.inflation.ok()) << s.inflation.error;
    s.text = inflatedHyperFun(s.inflation.solid);
    std::string error;
    s.model = compileHyperFun(s.text, error);
    EXPECT_TRUE(s.model.has_value()) << error;
    return s;
}

TEST(SketchInflation, CircleInflatesToASphere) {
    const double R = 0.3;
    const Sketched s = sketch(circlePath(R, 500, 0.001), 96);
    ASSERT_TRUE(s.model);
    // Points on the sphere of radius R about the circle's centre: the field
    // there (about a distance) is within a few percent of R of zero.
    std::vector<Vec3> pts;
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for (int i = 0; i < 2000; ++i) {
        Vec3 d(g(rng), g(rng), g(rng));
        d = glm::normalize(d);
        pts.push_back(s.world(Vec2(0.0)) + R * d);
    }
    double worst = 0.0;
    for (double f : s.eval(pts)) worst = std::max(worst, std::fabs(f));
    std::printf("circle R %.2f: worst |f| on the sphere %.4f m (%.2f%% of R), %zu pieces\n", R, worst, 100 * worst / R,
                s.inflation.solid.pieces.size());
    EXPECT_LT(worst, 0.05 * R);
    // The centre is R deep; the thickness through it is 2R.
    EXPECT_NEAR(s.eval(s.world(Vec2(0.0))), R, 0.03 * R);
}

// Half-thickness across the plane at plane point q: where the field along
// the normal through q crosses zero (bisection on the parsed text).
double halfThickness(const Sketched& s, const Vec2& q, double far) {
    double in = 0.0, out = far;
    if (s.eval(s.world(q)) < 0.0) return 0.0;
    for (int i = 0; i < 50; ++i) {
        const double mid = 0.5 * (in + out);
        (s.eval(s.world(q, mid)) >= 0.0 ? in : out) = mid;
    }
    return in;
}

TEST(SketchInflation, OvalInflatesToASausage) {
    const double a = 0.5, b = 0.1;
    const Sketched s = sketch(ellipsePath(a, b, 800, 0.0005), 200);
    ASSERT_TRUE(s.model);
    // Thickness follows the half-width: at the centre and half-way out it is
    // the ellipse's half-width there (the distance to the outline).
    for (double x : {0.0, 0.25, -0.25}) {
        const double halfWidth = b * std::sqrt(1.0 - x * x / (a * a));
        const double h = halfThickness(s, Vec2(x, 0.0), 1.0);
        std::printf("oval: half-thickness at x = %.2f: %.4f (half-width %.4f)\n", x, h, halfWidth);
        EXPECT_NEAR(h, halfWidth, 0.05 * b);
    }
    // Rounded ends: thin but present near the tips.
    EXPECT_GT(halfThickness(s, Vec2(0.45, 0.0), 1.0), 0.01);
    // A sausage is round across: the cross-section at the centre is a disc.
    for (double angle : {0.3, 0.8, 1.2}) {
        const Vec3 p = s.world(Vec2(0.0, b * std::cos(angle)), b * std::sin(angle));
        EXPECT_NEAR(s.eval(p), 0.0, 0.05 * b);
    }
}

struct Fit {
    double covered = 0.0;     // fraction of the outline's area inside the silhouette
    double spill = 0.0;       // silhouette area outside the outline / outline area
    double worstOutside = 0.0;  // farthest silhouette sample outside the outline, m
};

// The solid seen along the plane's normal: a grid over the outline's box;
// a grid point is in the silhouette when the parsed text is >= 0 at any of
// the samples along the normal line through it.
Fit silhouetteFit(const Sketched& s, int grid) {
    const auto& poly = s.outline.points;
    Vec2 lo(1e9), hi(-1e9);
    for (const Vec2& p : poly) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Vec2 pad = 0.1 * (hi - lo);
    lo -= pad;
    hi += pad;
    double maxR = 0.0;
    for (const ConePiece& c : s.inflation.solid.pieces) maxR = std::max({maxR, c.ra, c.rb});
    std::vector<Vec2> cells;
    std::vector<Vec3> pts;
    const int lineSamples = 9;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            const Vec2 q = lo + (hi - lo) * Vec2((i + 0.5) / grid, (j + 0.5) / grid);
            cells.push_back(q);
            for (int k = 0; k < lineSamples; ++k)
                pts.push_back(s.world(q, maxR * (k - lineSamples / 2) / (lineSamples / 2)));
        }
    const std::vector<double> f = s.eval(pts);
    Fit fit;
    double inside = 0.0, both = 0.0, spill = 0.0;
    for (size_t c = 0; c < cells.size(); ++c) {
        bool solid = false;
        for (int k = 0; k < lineSamples; ++k) solid = solid || f[c * lineSamples + static_cast<size_t>(k)] >= 0.0;
        const bool in = insidePolygon(cells[c], poly);
        inside += in;
        both += in && solid;
        if (solid && !in) {
            spill += 1.0;
            fit.worstOutside = std::max(fit.worstOutside, boundaryDistance(cells[c], poly));
        }
    }
    fit.covered = both / inside;
    fit.spill = spill / inside;
    return fit;
}

TEST(SketchInflation, SilhouettesFitTheirOutlines) {
    struct Shape {
        const char* name;
        std::vector<Vec2> raw;
        int samples;
    };
    const std::vector<Shape> shapes = {
        {"circle", circlePath(0.3, 500, 0.001), 96},
        {"long oval", ellipsePath(0.5, 0.1, 800, 0.0005), 200},
        {"L", polygonPath(lCorners(), 500.0, 0.0005), 200},
        {"star", polygonPath(starCorners(), 500.0, 0.0005), 200},
    };
    for (const Shape& shape : shapes) {
        SCOPED_TRACE(shape.name);
        const Sketched s = sketch(shape.raw, shape.samples);
        ASSERT_TRUE(s.model);
        const Fit fit = silhouetteFit(s, 160);
        std::printf("%-9s: %3zu pieces (%2d spokes), covers %.2f%% of the outline, %.2f%% outside it, "
                    "at most %.2f mm out (spacing %.1f mm)\n",
                    shape.name, s.inflation.solid.pieces.size(), s.inflation.spokes, 100 * fit.covered,
                    100 * fit.spill, 1000 * fit.worstOutside, 1000 * s.outline.spacing);
        EXPECT_GT(fit.covered, 0.965);
        EXPECT_LT(fit.spill, 0.01);
        EXPECT_LT(fit.worstOutside, 0.25 * s.outline.spacing);
    }
}

TEST(SketchInflation, TextEvaluatesAsTheField) {
    const Sketched s = sketch(polygonPath(starCorners(), 500.0, 0.0005), 150);
    ASSERT_TRUE(s.model);
    const InflatedSolid& solid = s.inflation.solid;
    std::mt19937 rng(11);
    std::vector<Vec3> pts;
    const Vec3 lo = solid.paddedLo(0.1), hi = solid.paddedHi(0.1);
    for (int i = 0; i < 3000; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
        pts.push_back(p);
    }
    const std::vector<double> parsed = s.eval(pts);
    double worst = 0.0;
    for (size_t i = 0; i < pts.size(); ++i) worst = std::max(worst, std::fabs(parsed[i] - inflatedValue(solid, pts[i])));
    EXPECT_EQ(worst, 0.0) << "the text and the C++ field differ by up to " << worst;
    EXPECT_TRUE(s.model->compiled()) << s.model->fallbackReason();
}

TEST(SketchInflation, BoundsHoldTheSolid) {
    const Sketched s = sketch(polygonPath(lCorners(), 500.0, 0.0005), 120);
    ASSERT_TRUE(s.model);
    const InflatedSolid& solid = s.inflation.solid;
    const Vec3 lo = solid.paddedLo(0.2), hi = solid.paddedHi(0.2);
    std::mt19937 rng(3);
    std::vector<Vec3> pts;
    for (int i = 0; i < 20000; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
        pts.push_back(p);
    }
    const std::vector<double> f = s.eval(pts);
    Vec3 seenLo(1e9), seenHi(-1e9);
    for (size_t i = 0; i < pts.size(); ++i) {
        if (f[i] < 0.0) continue;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(pts[i][k], solid.lo[k]);
            EXPECT_LE(pts[i][k], solid.hi[k]);
        }
        seenLo = glm::min(seenLo, pts[i]);
        seenHi = glm::max(seenHi, pts[i]);
    }
    // Tight: the inside samples reach close to every face of the box.
    for (int k = 0; k < 3; ++k) {
        const double size = solid.hi[k] - solid.lo[k];
        EXPECT_LT(seenLo[k] - solid.lo[k], 0.1 * size);
        EXPECT_LT(solid.hi[k] - seenHi[k], 0.1 * size);
    }
}

TEST(SketchInflation, ThicknessScalesAcrossThePlane) {
    InflationOptions o;
    o.thickness = 0.5;
    const Sketched s = sketch(circlePath(0.3, 500), 96, planeFacing(Vec3(0.0), Vec3(0, 0, 1)), o);
    ASSERT_TRUE(s.model);
    EXPECT_NEAR(halfThickness(s, Vec2(0.0), 1.0), 0.15, 0.01);
    EXPECT_NEAR(s.eval(s.world(Vec2(0.3, 0.0))), 0.0, 0.01);
}

TEST(SketchInflation, RefusesABadPlane) {
    const Outline o = makeOutline(circlePath(0.3, 300));
    SketchPlane p;
    p.u = Vec3(1, 1, 0);
    EXPECT_FALSE(inflate(o.points, o.spacing, p).ok());
}

}  // namespace
}  // namespace hg::garden::sketch
