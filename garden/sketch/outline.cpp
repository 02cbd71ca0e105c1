#include "garden/sketch/outline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace hg::garden::sketch {

namespace {

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

double pathLength(const std::vector<Vec2>& p) {
    double s = 0.0;
    for (size_t i = 1; i < p.size(); ++i) s += distance2(p[i - 1], p[i]);
    return s;
}

// Drops non-finite points and points within `minStep` of the last kept one
// (the last raw point is kept in place of the last kept one, so the path
// still ends where the pen stopped).
std::vector<Vec2> dropJitter(const std::vector<Vec2>& raw, double minStep) {
    std::vector<Vec2> out;
    for (const Vec2& p : raw) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        if (out.empty() || distance2(out.back(), p) >= minStep) out.push_back(p);
    }
    return out;
}

// (1 2 1)/4 passes over the open path, ends fixed: removes the hand's
// tremor below the spacing without moving the outline by more than a
// fraction of it.
void smoothOpen(std::vector<Vec2>& p, int passes) {
    if (p.size() < 3) return;
    std::vector<Vec2> q(p.size());
    for (int k = 0; k < passes; ++k) {
        q.front() = p.front();
        q.back() = p.back();
        for (size_t i = 1; i + 1 < p.size(); ++i) q[i] = 0.25 * p[i - 1] + 0.5 * p[i] + 0.25 * p[i + 1];
        p.swap(q);
    }
}

struct Crossing {
    size_t i = 0, j = 0;  // segments i (earlier) and j (later) of the path
    double s = 0.0, t = 0.0;
    Vec2 at;
};

// Crossings of segment j with the segments before it, in the order the pen
// met them (along segment j).
std::vector<Crossing> crossingsOf(const std::vector<Vec2>& p, size_t j) {
    std::vector<Crossing> out;
    const Vec2 &c = p[j], &d = p[j + 1];
    const double minx = std::min(c.x, d.x), maxx = std::max(c.x, d.x);
    const double miny = std::min(c.y, d.y), maxy = std::max(c.y, d.y);
    for (size_t i = 0; i + 1 < j; ++i) {
        const Vec2 &a = p[i], &b = p[i + 1];
        if (std::max(a.x, b.x) < minx || std::min(a.x, b.x) > maxx || std::max(a.y, b.y) < miny ||
            std::min(a.y, b.y) > maxy)
            continue;
        Crossing x;
        if (segmentsCross(a, b, c, d, x.s, x.t)) {
            x.i = i;
            x.j = j;
            x.at = a + x.s * (b - a);
            out.push_back(x);
        }
    }
    std::sort(out.begin(), out.end(), [](const Crossing& u, const Crossing& v) { return u.t < v.t; });
    return out;
}

// The points' spread across their main direction over their spread along
// it (the square root of the covariance's eigenvalue ratio): 0 for points
// on a line, 1 for a round cloud.
double flatness(const std::vector<Vec2>& p) {
    Vec2 mean(0.0);
    for (const Vec2& q : p) mean += q;
    mean /= static_cast<double>(p.size());
    double xx = 0.0, xy = 0.0, yy = 0.0;
    for (const Vec2& q : p) {
        const Vec2 d = q - mean;
        xx += d.x * d.x;
        xy += d.x * d.y;
        yy += d.y * d.y;
    }
    const double half = 0.5 * (xx + yy);
    const double root = std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy);
    const double major = half + root, minor = std::max(half - root, 0.0);
    return major > 0.0 ? std::sqrt(minor / major) : 0.0;
}

}  // namespace

bool isSimplePolygon(const std::vector<Vec2>& poly, double tolerance) {
    const size_t n = poly.size();
    if (n < 3) return false;
    for (size_t i = 0; i < n; ++i)
        if (distance2(poly[i], poly[(i + 1) % n]) <= 0.0) return false;
    for (size_t i = 0; i < n; ++i) {
        const Vec2 &a = poly[i], &b = poly[(i + 1) % n];
        for (size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
            const Vec2 &c = poly[j], &d = poly[(j + 1) % n];
            if (std::max(a.x, b.x) + tolerance < std::min(c.x, d.x) || std::min(a.x, b.x) - tolerance > std::max(c.x, d.x) ||
                std::max(a.y, b.y) + tolerance < std::min(c.y, d.y) || std::min(a.y, b.y) - tolerance > std::max(c.y, d.y))
                continue;
            double s, t;
            if (segmentsCross(a, b, c, d, s, t)) return false;
            // Touching: an end of one edge on (or within tolerance of) the other.
            if (segmentDistance(a, c, d) <= tolerance || segmentDistance(b, c, d) <= tolerance ||
                segmentDistance(c, a, b) <= tolerance || segmentDistance(d, a, b) <= tolerance)
                return false;
        }
    }
    return true;
}

std::vector<Vec2> resampleClosed(const std::vector<Vec2>& closed, int n) {
    std::vector<Vec2> out;
    const double total = perimeter(closed);
    if (n <= 0 || total <= 0.0) return out;
    const double step = total / n;
    out.reserve(static_cast<size_t>(n));
    size_t seg = 0;
    double segStart = 0.0;  // arc length where segment `seg` starts
    const size_t m = closed.size();
    for (int k = 0; k < n; ++k) {
        const double at = k * step;
        double len = distance2(closed[seg], closed[(seg + 1) % m]);
        while (segStart + len < at && seg + 1 < m) {
            segStart += len;
            ++seg;
            len = distance2(closed[seg], closed[(seg + 1) % m]);
        }
        const double u = len > 0.0 ? std::clamp((at - segStart) / len, 0.0, 1.0) : 0.0;
        out.push_back(closed[seg] + u * (closed[(seg + 1) % m] - closed[seg]));
    }
    return out;
}

Outline makeOutline(const std::vector<Vec2>& raw, const OutlineOptions& o) {
    Outline out;
    std::vector<Vec2> finite;
    for (const Vec2& p : raw)
        if (std::isfinite(p.x) && std::isfinite(p.y) && (finite.empty() || finite.back() != p)) finite.push_back(p);
    if (finite.size() < 3) {
        out.error = "too few points (" + std::to_string(finite.size()) + "): draw a closed outline";
        return out;
    }
    const double rawLength = pathLength(finite);
    const double spacingGuess = o.spacing > 0.0 ? o.spacing : rawLength / std::max(o.samples, 1);
    std::vector<Vec2> path = dropJitter(finite, o.jitterFraction * spacingGuess);
    if (path.size() < 3) {
        out.error = "too few points (" + std::to_string(path.size()) + " after removing jitter): the sketch is too small";
        return out;
    }
    smoothOpen(path, o.smoothingPasses);

    // The loop: between the first crossing that ends the sketch, or the
    // whole path with its ends joined.
    std::vector<Vec2> loop;
    for (size_t j = 2; j + 1 < path.size() && loop.empty(); ++j) {
        for (const Crossing& x : crossingsOf(path, j)) {
            const double head = pathLength(std::vector<Vec2>(path.begin(), path.begin() + static_cast<long>(x.i) + 1)) +
                                distance2(path[x.i], x.at);
            std::vector<Vec2> candidate{x.at};
            candidate.insert(candidate.end(), path.begin() + static_cast<long>(x.i) + 1,
                             path.begin() + static_cast<long>(x.j) + 1);
            const double loopLength = pathLength(candidate) + distance2(path[x.j], x.at);
            if (loopLength < o.minLoopFraction * (head + loopLength)) continue;  // a curl, not the end
            const double tail = distance2(x.at, path[x.j + 1]) +
                                pathLength(std::vector<Vec2>(path.begin() + static_cast<long>(x.j) + 1, path.end()));
            if (tail > o.maxTailFraction * loopLength) {
                out.error = "the path goes on for " + fmt(tail / loopLength * 100.0) +
                            "% of its loop after crossing itself (a figure eight?): draw one simple closed outline";
                return out;
            }
            loop = std::move(candidate);
            out.cutAtCrossing = true;
            break;
        }
    }
    if (loop.empty()) loop = path;
    // A loop that ends on its start would repeat the point.
    while (loop.size() > 1 && distance2(loop.front(), loop.back()) <= 1e-12 * rawLength) loop.pop_back();

    const double length = perimeter(loop);
    int n = o.spacing > 0.0 ? static_cast<int>(std::lround(length / o.spacing)) : o.samples;
    if (n < o.minSamples) {
        out.error = "the outline is too short for " + std::to_string(o.minSamples) + " samples (" + fmt(length) +
                    " m at " + fmt(o.spacing) + " m spacing)";
        return out;
    }
    // A line drawn back and forth crosses itself too, but what is wrong
    // with it is that it encloses nothing: it is told apart from a figure
    // eight (whose lobes' signed areas cancel) by being flat.
    const double loopArea = std::fabs(signedArea(loop));
    const double roundness = 4.0 * 3.141592653589793 * loopArea / (length * length);
    const bool simple = isSimplePolygon(loop);
    if (!(roundness >= o.minRoundness) && (simple || flatness(loop) < 0.05)) {
        out.error = "the outline has (almost) no area (" + fmt(loopArea) + " m^2 inside " + fmt(length) +
                    " m): it is a line, not a closed shape";
        return out;
    }
    if (!simple) {
        out.error = "the sketch crosses itself (a figure eight or a loop inside the outline): draw one simple closed outline";
        return out;
    }
    std::vector<Vec2> pts = resampleClosed(loop, n);
    const double area = signedArea(pts);
    if (area < 0.0) std::reverse(pts.begin(), pts.end());
    if (!isSimplePolygon(pts, 1e-9 * length)) {
        out.error = "the outline touches itself at " + std::to_string(n) +
                    " samples (a neck narrower than the spacing): draw it wider or use more samples";
        return out;
    }
    out.points = std::move(pts);
    out.spacing = length / n;
    return out;
}

}  // namespace hg::garden::sketch
