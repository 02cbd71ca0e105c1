// Raw sketch paths for the sketch tests and bench: shapes drawn the way a
// hand draws them (uneven point spacing, a little deterministic tremor),
// and the polygons they should give.
#pragma once

#include <cmath>
#include <vector>

#include "garden/sketch/geometry2d.h"

namespace hg::test::sketch {

using garden::sketch::Vec2;

constexpr double kPi = 3.141592653589793;

// Deterministic tremor in [-1, 1].
inline double wobble(int i) { return std::sin(i * 12.9898 + 0.3) * std::cos(i * 4.1414 + 1.7); }

// A closed curve r(theta) sampled unevenly (speeding up and slowing down),
// with tremor of `noise` metres; `turns` > 1 overshoots past the start.
template <class F>
std::vector<Vec2> drawn(F point, int count, double noise, double turns = 1.0) {
    std::vector<Vec2> p;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / count;
        const double eased = s + 0.05 * std::sin(2.0 * kPi * s * 3.0) / (2.0 * kPi * 3.0) * 6.0;
        const Vec2 q = point(eased * turns);
        p.push_back(q + noise * Vec2(wobble(i), wobble(i + 7919)));
    }
    return p;
}

inline std::vector<Vec2> circlePath(double r, int count = 400, double noise = 0.0, double turns = 1.0,
                                    Vec2 c = Vec2(0.0)) {
    return drawn([&](double s) { return c + r * Vec2(std::cos(2 * kPi * s), std::sin(2 * kPi * s)); }, count, noise,
                 turns);
}

inline std::vector<Vec2> ellipsePath(double a, double b, int count = 600, double noise = 0.0) {
    return drawn([&](double s) { return Vec2(a * std::cos(2 * kPi * s), b * std::sin(2 * kPi * s)); }, count, noise);
}

// A closed polygon walked along its edges with `perEdge` points per metre.
inline std::vector<Vec2> polygonPath(const std::vector<Vec2>& corners, double perMetre, double noise = 0.0) {
    std::vector<Vec2> p;
    int k = 0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
        const int steps = std::max(1, static_cast<int>(garden::sketch::distance2(a, b) * perMetre));
        for (int j = 0; j < steps; ++j, ++k) p.push_back(a + (b - a) * (static_cast<double>(j) / steps) + noise * Vec2(wobble(k), wobble(k + 31)));
    }
    return p;
}

// An L: a 0.6 x 0.2 bar with a 0.2 x 0.4 upright on its left end.
inline std::vector<Vec2> lCorners() {
    return {{0.0, 0.0}, {0.6, 0.0}, {0.6, 0.2}, {0.2, 0.2}, {0.2, 0.6}, {0.0, 0.6}};
}

// A five-pointed star, outer radius R, inner r.
inline std::vector<Vec2> starCorners(double R = 0.5, double r = 0.25) {
    std::vector<Vec2> c;
    for (int i = 0; i < 10; ++i) {
        const double a = kPi / 2 + i * kPi / 5;
        const double q = i % 2 == 0 ? R : r;
        c.push_back({q * std::cos(a), q * std::sin(a)});
    }
    return c;
}

// A lasso: a lead-in from outside, one turn of a circle and an overshoot
// that crosses the lead-in.
inline std::vector<Vec2> lassoPath(double r) {
    std::vector<Vec2> p;
    for (int i = 0; i < 20; ++i) p.push_back({r * (1.4 - 0.4 * i / 20.0), -0.3 * r + 0.3 * r * i / 20.0});
    for (Vec2 q : circlePath(r, 300, 0.0, 1.08)) p.push_back(q);
    return p;
}

// A figure eight (a lemniscate of Gerono), started at `start` turns.
inline std::vector<Vec2> figureEightPath(double size, double start) {
    std::vector<Vec2> p;
    for (int i = 0; i < 400; ++i) {
        const double t = 2 * kPi * (start + i / 400.0);
        p.push_back(size * Vec2(std::sin(t), std::sin(t) * std::cos(t)));
    }
    return p;
}

}  // namespace hg::test::sketch
