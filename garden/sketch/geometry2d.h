// Small 2D predicates and measures the sketch pipeline shares (outline,
// triangulation, chordal axis, inflation). Plain doubles: the sketches are
// a few hundred to a few thousand points of hand-drawn size, so the
// tolerances that matter are relative to the sketch's size, and each caller
// states its own; nothing here needs exact predicates.
#pragma once

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hg::garden::sketch {

using Vec2 = glm::dvec2;

inline double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
inline double dot2(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
inline double length2(const Vec2& a) { return std::sqrt(dot2(a, a)); }
inline double distance2(const Vec2& a, const Vec2& b) { return length2(b - a); }

// Twice the signed area of triangle abc: > 0 when a, b, c turn left.
inline double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross(b - a, c - a); }

// Signed area of a closed polygon (> 0 counter-clockwise).
inline double signedArea(const std::vector<Vec2>& p) {
    double s = 0.0;
    for (size_t i = 0, n = p.size(); i < n; ++i) s += cross(p[i], p[(i + 1) % n]);
    return 0.5 * s;
}

inline double perimeter(const std::vector<Vec2>& p) {
    double s = 0.0;
    for (size_t i = 0, n = p.size(); i < n; ++i) s += distance2(p[i], p[(i + 1) % n]);
    return s;
}

// Distance from p to the segment ab (a point when a == b).
inline double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double l2 = dot2(d, d);
    const double t = l2 > 0.0 ? std::clamp(dot2(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return distance2(p, a + t * d);
}

// Distance from p to the boundary of the closed polygon.
inline double boundaryDistance(const Vec2& p, const std::vector<Vec2>& poly) {
    double best = 1e300;
    for (size_t i = 0, n = poly.size(); i < n; ++i) best = std::min(best, segmentDistance(p, poly[i], poly[(i + 1) % n]));
    return best;
}

// Whether the segments ab and cd cross at a point interior to both (proper
// crossing); when they do, `s` and `t` are the parameters of that point on
// ab and cd. Touching at ends or collinear overlaps are not crossings here:
// callers that need those treat them with their own tolerance.
inline bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double& s, double& t) {
    const Vec2 r = b - a, q = d - c;
    const double den = cross(r, q);
    if (den == 0.0) return false;
    s = cross(c - a, q) / den;
    t = cross(c - a, r) / den;
    return s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0;
}

// Even-odd point-in-polygon test.
inline bool insidePolygon(const Vec2& p, const std::vector<Vec2>& poly) {
    bool in = false;
    for (size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

}  // namespace hg::garden::sketch
