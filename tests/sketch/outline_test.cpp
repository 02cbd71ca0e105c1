// Sketch to outline: uniform resampling, the self-crossing cut, joined
// ends, orientation, and the refusals (issue 22, "Sketching").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "garden/sketch/outline.h"
#include "tests/sketch/sketch_shapes.h"

namespace hg::garden::sketch {
namespace {

using namespace hg::test::sketch;

struct SpacingStats {
    double mean = 0.0, minimum = 1e300, maximum = 0.0;
};

SpacingStats spacingOf(const std::vector<Vec2>& p) {
    SpacingStats s;
    for (size_t i = 0; i < p.size(); ++i) {
        const double d = distance2(p[i], p[(i + 1) % p.size()]);
        s.mean += d;
        s.minimum = std::min(s.minimum, d);
        s.maximum = std::max(s.maximum, d);
    }
    s.mean /= static_cast<double>(p.size());
    return s;
}

TEST(SketchOutline, ResamplesToUniformSpacing) {
    // Uneven drawing speed and 2 mm of tremor on a 0.3 m circle.
    const auto raw = circlePath(0.3, 500, 0.002);
    OutlineOptions o;
    o.samples = 64;
    const Outline out = makeOutline(raw, o);
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_EQ(out.points.size(), 64u);
    const SpacingStats s = spacingOf(out.points);
    // Chords of equal arcs: only corners of the drawn polyline shorten one.
    EXPECT_GT(s.minimum, 0.97 * s.mean);
    EXPECT_LT(s.maximum, 1.01 * s.mean);
    EXPECT_NEAR(out.spacing, s.mean, 0.01 * s.mean);
    // Jitter removed: the outline stays within the tremor of the circle.
    for (const Vec2& p : out.points) EXPECT_NEAR(length2(p), 0.3, 0.004);
}

TEST(SketchOutline, SpacingSetsTheSampleCount) {
    OutlineOptions o;
    o.spacing = 0.02;
    const Outline out = makeOutline(circlePath(0.3, 500), o);
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_NEAR(static_cast<double>(out.points.size()), 2 * kPi * 0.3 / 0.02, 2.0);
    EXPECT_NEAR(out.spacing, 0.02, 0.001);
}

TEST(SketchOutline, OrientationIsCounterClockwise) {
    auto raw = circlePath(0.2, 300);
    std::reverse(raw.begin(), raw.end());
    const Outline out = makeOutline(raw);
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_GT(signedArea(out.points), 0.0);
}

TEST(SketchOutline, SelfCrossingKeepsTheLoopAndCutsTheEnds) {
    const Outline out = makeOutline(lassoPath(0.25));
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_TRUE(out.cutAtCrossing);
    EXPECT_TRUE(isSimplePolygon(out.points));
    // The loop is the circle: no lead-in or overshoot left outside it.
    double worst = 0.0;
    for (const Vec2& p : out.points) worst = std::max(worst, std::fabs(length2(p) - 0.25));
    EXPECT_LT(worst, 0.01);
    EXPECT_NEAR(signedArea(out.points), kPi * 0.25 * 0.25, 0.03 * kPi * 0.25 * 0.25);
}

TEST(SketchOutline, OpenEndsAreJoined) {
    // Three quarters of a circle and a bit: the gap is closed by a chord.
    std::vector<Vec2> raw;
    for (int i = 0; i <= 300; ++i) {
        const double a = 1.7 * kPi * i / 300.0;
        raw.push_back(0.2 * Vec2(std::cos(a), std::sin(a)));
    }
    const Outline out = makeOutline(raw);
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_FALSE(out.cutAtCrossing);
    EXPECT_TRUE(isSimplePolygon(out.points));
}

TEST(SketchOutline, SmallCurlAtTheStartDoesNotEndTheSketch) {
    // A small curl at the start (crossing itself early, a loop of a few
    // percent of the path) and then a large circle crossing the lead-in:
    // the seed's rule skips the curl and the circle's loop is kept.
    std::vector<Vec2> raw;
    const Vec2 start(0.35, -0.05);
    for (int i = 0; i <= 60; ++i) {
        const double a = 2.2 * kPi * i / 60.0;
        raw.push_back(start + 0.01 * Vec2(std::cos(a) - 1.0, std::sin(a)) + Vec2(-0.0015 * i, 0.0));
    }
    for (Vec2 q : circlePath(0.25, 300, 0.0, 1.1)) raw.push_back(q);
    const Outline out = makeOutline(raw);
    ASSERT_TRUE(out.ok()) << out.error;
    EXPECT_TRUE(out.cutAtCrossing);
    EXPECT_NEAR(signedArea(out.points), kPi * 0.25 * 0.25, 0.05 * kPi * 0.25 * 0.25);
}

TEST(SketchOutline, RefusesTooFewPoints) {
    const Outline out = makeOutline({{0, 0}, {0.1, 0.0}});
    EXPECT_FALSE(out.ok());
    EXPECT_NE(out.error.find("too few points"), std::string::npos) << out.error;
    EXPECT_TRUE(out.points.empty());
    EXPECT_FALSE(makeOutline({}).ok());
    // Repeated points are one point.
    EXPECT_FALSE(makeOutline({{0, 0}, {0, 0}, {0, 0}, {0.1, 0}}).ok());
}

TEST(SketchOutline, RefusesZeroArea) {
    std::vector<Vec2> line;
    for (int i = 0; i < 100; ++i) line.push_back({0.005 * i, 0.002 * i});
    Outline out = makeOutline(line);
    EXPECT_FALSE(out.ok());
    EXPECT_NE(out.error.find("no area"), std::string::npos) << out.error;
    // Back and forth along a line.
    for (int i = 99; i >= 0; --i) line.push_back({0.005 * i, 0.002 * i + 1e-5});
    out = makeOutline(line);
    EXPECT_FALSE(out.ok());
    EXPECT_NE(out.error.find("no area"), std::string::npos) << out.error;
    EXPECT_TRUE(out.points.empty());
}

TEST(SketchOutline, RefusesFigureEight) {
    for (double start : {0.01, 0.25, 0.1}) {
        const Outline out = makeOutline(figureEightPath(0.3, start));
        EXPECT_FALSE(out.ok()) << "start " << start;
        EXPECT_NE(out.error.find("figure eight"), std::string::npos) << out.error;
        EXPECT_TRUE(out.points.empty());
    }
}

TEST(SketchOutline, RefusesALoopInsideTheOutline) {
    // A circle drawn with a small curl halfway round and the ends joined:
    // the curl is a crossing whose loop is far less than half the path, so
    // it does not end the sketch, and the joined outline crosses itself.
    std::vector<Vec2> raw;
    for (int i = 0; i <= 400; ++i) {
        const double s = i / 400.0;
        const double a = 1.9 * kPi * s;
        Vec2 p = 0.25 * Vec2(std::cos(a), std::sin(a));
        const double curl = (s - 0.5) / 0.04;  // a loop (a prolate trochoid's) around s = 0.5
        if (std::fabs(curl) < 1.0) {
            const double b = kPi * curl;
            const Vec2 along(-std::sin(a), std::cos(a)), in(-std::cos(a), -std::sin(a));
            p += 0.03 * (-std::sin(b) * along + (1.0 + std::cos(b)) * in);
        }
        raw.push_back(p);
    }
    const Outline out = makeOutline(raw);
    EXPECT_FALSE(out.ok());
    EXPECT_FALSE(out.error.empty());
    EXPECT_TRUE(out.points.empty());
}

TEST(SketchOutline, SimplePolygonCheck) {
    EXPECT_TRUE(isSimplePolygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    EXPECT_FALSE(isSimplePolygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));  // a bow tie
    EXPECT_FALSE(isSimplePolygon({{0, 0}, {1, 0}}));
}

}  // namespace
}  // namespace hg::garden::sketch
