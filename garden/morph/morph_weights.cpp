#include "garden/morph/morph_weights.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

namespace {

double cross(const Point2& a, const Point2& b, const Point2& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}

Point2 nearestOnSegment(const Point2& a, const Point2& b, const Point2& p) {
    double dx = b[0] - a[0], dz = b[1] - a[1];
    double len2 = dx * dx + dz * dz;
    double t = len2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return {a[0] + t * dx, a[1] + t * dz};
}

double distance2(const Point2& a, const Point2& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

}  // namespace

double MorphTriangle::signedArea() const { return 0.5 * cross(corners[0], corners[1], corners[2]); }

Point2 MorphTriangle::centroid() const {
    return {(corners[0][0] + corners[1][0] + corners[2][0]) / 3.0, (corners[0][1] + corners[1][1] + corners[2][1]) / 3.0};
}

Point2 clampToTriangle(const MorphTriangle& t, const Point2& p) {
    const auto& c = t.corners;
    double whole = cross(c[0], c[1], c[2]);
    if (whole == 0.0) return t.centroid();
    // Inside when p is on the inner side of every edge (either winding).
    bool inside = true;
    for (std::size_t i = 0; i < 3; ++i)
        if (cross(c[(i + 1) % 3], c[(i + 2) % 3], p) * whole < 0.0) inside = false;
    if (inside) return p;
    // Outside, the nearest point lies on the boundary.
    Point2 best = p;
    double bestD = INFINITY;
    for (std::size_t i = 0; i < 3; ++i) {
        Point2 q = nearestOnSegment(c[i], c[(i + 1) % 3], p);
        double d = distance2(p, q);
        if (d < bestD) { bestD = d; best = q; }
    }
    return best;
}

std::array<double, 3> barycentric(const MorphTriangle& t, const Point2& p) {
    const auto& c = t.corners;
    double whole = cross(c[0], c[1], c[2]);
    if (whole == 0.0) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
    // Corner i's weight: the area of the sub-triangle (p, next, after next),
    // with the whole triangle's orientation, over the whole area. At corner
    // i that is the whole triangle itself (exactly 1); the other two
    // sub-triangles have two equal points (exactly 0).
    std::array<double, 3> l{};
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        l[i] = std::max(0.0, cross(p, c[(i + 1) % 3], c[(i + 2) % 3]) / whole);  // rounding on an edge
        sum += l[i];
    }
    for (double& v : l) v /= sum;
    return l;
}

MorphWeights weightsFromBarycentric(const std::array<double, 3>& b, const std::array<double, 3>& balance) {
    MorphWeights m;
    m.barycentric = b;
    m.balance = balance;
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i) sum += m.w[i] = b[i] * balance[i];
    for (double& v : m.w) v = sum > 0.0 ? v / sum : 1.0 / 3.0;
    return m;
}

MorphWeights morphWeights(const MorphTriangle& t, const Point2& p, const std::array<double, 3>& balance) {
    Point2 q = clampToTriangle(t, p);
    MorphWeights m = weightsFromBarycentric(barycentric(t, q), balance);
    m.point = q;
    m.clamped = q != p;
    return m;
}

std::array<double, 3> balancingFactors(const std::array<double, 3>& g) {
    std::array<double, 3> b{};
    for (std::size_t i = 0; i < 3; ++i) b[i] = g[i] > 0.0 ? 1.0 / g[i] : 1.0;
    return b;
}

}  // namespace hg::garden
