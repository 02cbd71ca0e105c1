// The stroke description: resampling, the sign of a turn as seen on screen,
// and invariance to position, size, rotation and drawing speed.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "garden/gesture/stroke_features.h"
#include "gesture_shapes.h"

namespace hg::garden {
namespace {

using namespace test;

double totalTurn(const StrokePoints& p) {
    const std::vector<double> t = strokeTurns(p);
    return std::accumulate(t.begin(), t.end(), 0.0);
}

TEST(StrokeFeatures, ResamplingSpacesPointsEvenlyAndKeepsTheEnds) {
    const StrokePoints p = resampleStroke({{0, 0}, {10, 0}, {10, 30}}, 9);
    ASSERT_EQ(p.size(), 9u);
    EXPECT_EQ(p.front(), (StrokePoint{0, 0}));
    EXPECT_EQ(p.back(), (StrokePoint{10, 30}));
    for (std::size_t i = 1; i < p.size(); ++i)
        EXPECT_NEAR(std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]), 5.0, 1e-9) << i;
    EXPECT_TRUE(resampleStroke({{3, 3}, {3, 3}}, 9).empty());
}

TEST(StrokeFeatures, ClockwiseOnScreenTurnsPositive) {
    // y down: a loop through east, south, west is clockwise on screen.
    // 31 turns between 32 segments: the half segments at the ends are not turned.
    EXPECT_NEAR(totalTurn(loopShape(true)), 3.0 * kPi * 31.0 / 32.0, 0.2);
    EXPECT_NEAR(totalTurn(loopShape(false)), -3.0 * kPi * 31.0 / 32.0, 0.2);
    // A U drawn from its left tip turns left (counter-clockwise), an arch right.
    EXPECT_NEAR(totalTurn(uShape()), -kPi, 0.2);
    EXPECT_NEAR(totalTurn(archShape()), kPi, 0.2);
    EXPECT_LT(totalTurn(vShape()), -2.0);
}

TEST(StrokeFeatures, TheSameWhateverThePositionSizeAndRotation) {
    for (const StrokePoints& shape : {vShape(), uShape(), zShape(), loopShape(true), crossingOut()}) {
        const std::vector<double> base = strokeFeatures(shape);
        ASSERT_EQ(base.size(), static_cast<std::size_t>(kFeatureCount));
        for (double angle : {0.3, 1.7, 3.0, -2.2})
            for (double scale : {0.25, 1.0, 4.0}) {
                const std::vector<double> f = strokeFeatures(transformed(shape, angle, scale, 900.0, -300.0));
                ASSERT_EQ(f.size(), base.size());
                for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], base[i], 1e-6) << "feature " << i;
            }
    }
}

TEST(StrokeFeatures, DrawingSpeedDoesNotMatter) {
    // The same U with its points crowded where the hand was slow.
    const StrokePoints even = uShape();
    StrokePoints uneven;
    for (std::size_t i = 0; i < even.size(); ++i) {
        uneven.push_back(even[i]);
        if (i + 1 < even.size() && i % 3 == 0)
            for (int k = 1; k < 4; ++k)
                uneven.push_back({even[i][0] + k * 0.25 * (even[i + 1][0] - even[i][0]),
                                  even[i][1] + k * 0.25 * (even[i + 1][1] - even[i][1])});
    }
    const std::vector<double> a = strokeFeatures(even), b = strokeFeatures(uneven);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 0.05) << "feature " << i;
}

TEST(StrokeFeatures, MirroringFlipsTheSines) {
    StrokePoints mirrored;
    for (const StrokePoint& p : uShape()) mirrored.push_back({-p[0], p[1]});
    const std::vector<double> a = strokeFeatures(uShape()), b = strokeFeatures(mirrored);
    for (int i = 0; i < kFeatureTurns; ++i) {
        EXPECT_NEAR(a[2 * i], -b[2 * i], 1e-9);
        EXPECT_NEAR(a[2 * i + 1], b[2 * i + 1], 1e-9);
    }
}

TEST(StrokeFeatures, ADegenerateStrokeHasNone) {
    EXPECT_TRUE(strokeFeatures({}).empty());
    EXPECT_TRUE(strokeFeatures({{5, 5}}).empty());
    EXPECT_TRUE(strokeFeatures({{5, 5}, {5, 5}, {5, 5}}).empty());
    EXPECT_EQ(strokeFeatures({{5, 5}, {6, 5}}).size(), static_cast<std::size_t>(kFeatureCount));
}

}  // namespace
}  // namespace hg::garden
