// The morph selector's maths (docs/design.md §4, seed 004): a point in the morph
// triangle gives each source the area of the sub-triangle opposite its
// corner over the whole area (barycentric coordinates), times a balancing
// factor that makes the sources' fields rise equally fast across their
// surfaces; the products are normalized to sum to 1. A point outside the
// triangle is first moved to the nearest point of the triangle.
#pragma once

#include <array>

namespace hg::garden {

using Point2 = std::array<double, 2>;

struct MorphTriangle {
    std::array<Point2, 3> corners;  // corner i holds source i

    double signedArea() const;
    Point2 centroid() const;
};

// The point of the triangle (inside or on its edges) nearest to `p`.
Point2 clampToTriangle(const MorphTriangle& t, const Point2& p);

// Sub-triangle areas over the whole area for a point of the triangle: each
// in [0, 1], summing to 1. Exactly (1, 0, 0) at corner 0, and so on.
std::array<double, 3> barycentric(const MorphTriangle& t, const Point2& p);

struct MorphWeights {
    Point2 point{};                    // the selector after clamping
    bool clamped = false;              // the selector lay outside the triangle
    std::array<double, 3> barycentric{};
    std::array<double, 3> balance{1.0, 1.0, 1.0};
    std::array<double, 3> w{};         // barycentric * balance, normalized: what the blend uses; sums to 1
};

// The weights for selector `p`. `balance` must be positive. A degenerate
// triangle (no area) gives the corners equal barycentric weights.
MorphWeights morphWeights(const MorphTriangle& t, const Point2& p, const std::array<double, 3>& balance = {1, 1, 1});

// Weights from barycentric coordinates given directly (tests, journal replay).
MorphWeights weightsFromBarycentric(const std::array<double, 3>& barycentric,
                                    const std::array<double, 3>& balance = {1, 1, 1});

// Balancing factors for sources whose fields rise by `surfaceGradient[i]`
// per voxel across their surfaces (median |grad|, see morph_sources.h):
// 1 / gradient, so that every balanced source rises by one unit per voxel.
// Sources already normalized to the shared frame measure about 1 and get
// factors about 1; the factors correct what the normalization left over.
std::array<double, 3> balancingFactors(const std::array<double, 3>& surfaceGradient);

}  // namespace hg::garden
