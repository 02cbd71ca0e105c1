#include "garden/gesture/stroke.h"

#include <cmath>

namespace hg::garden {

namespace {

double distance(const StrokePoint& a, const StrokePoint& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

}  // namespace

double strokeLength(const StrokePoints& points) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) length += distance(points[i - 1], points[i]);
    return length;
}

StrokePoints resampleStroke(const StrokePoints& points, int count) {
    StrokePoints out;
    const double total = strokeLength(points);
    if (count < 2 || points.size() < 2 || !(total > 0.0)) return out;
    out.reserve(static_cast<std::size_t>(count));
    out.push_back(points.front());
    const double step = total / (count - 1);
    // Walk the segments once; `along` is the distance of the next sample
    // from the start, `before` the length of the segments passed.
    double before = 0.0;
    std::size_t seg = 1;
    for (int k = 1; k < count - 1; ++k) {
        const double along = step * k;
        while (seg + 1 < points.size() && before + distance(points[seg - 1], points[seg]) < along) {
            before += distance(points[seg - 1], points[seg]);
            ++seg;
        }
        const StrokePoint& a = points[seg - 1];
        const StrokePoint& b = points[seg];
        const double len = distance(a, b);
        const double t = len > 0.0 ? std::fmin(1.0, std::fmax(0.0, (along - before) / len)) : 0.0;
        out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
    out.push_back(points.back());
    return out;
}

}  // namespace hg::garden
