// A closed interval of doubles with outward rounding, plus whether the
// value may also be NaN. Every operation returns bounds that contain the
// result of the same operation on any points of its inputs.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace hg::frep {

struct Interval {
    double lo = 0.0, hi = 0.0;
    bool maybeNaN = false;

    Interval() = default;
    Interval(double v) : lo(v), hi(v) {}  // NOLINT: a point is an interval
    Interval(double l, double h, bool nan = false) : lo(l), hi(h), maybeNaN(nan) {}

    static Interval entire() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), true};
    }
    bool contains(double v) const { return lo <= v && v <= hi; }
    bool isPoint() const { return lo == hi && !maybeNaN; }
    double width() const { return hi - lo; }
};

inline Interval hull(const Interval& a, const Interval& b) {
    return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.maybeNaN || b.maybeNaN};
}

}  // namespace hg::frep
