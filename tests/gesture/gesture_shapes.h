// Gestures drawn by hand in code for the tests: clean shapes in screen
// pixels (y down), made without the training generator, and the
// transformations a user's drawing goes through.
#pragma once

#include <cmath>
#include <string>

#include "garden/gesture/gesture_weights.h"
#include "garden/gesture/stroke.h"

namespace hg::garden::test {

constexpr double kPi = 3.141592653589793;

// The committed recognizer (content/gestures/weights.json).
inline GestureRecognizer committedRecognizer() {
    return loadGestureWeights(std::string(HG_SOURCE_DIR) + "/content/gestures/weights.json");
}

// A polyline through `corners`, `perSide` points on each side.
inline StrokePoints polyline(const StrokePoints& corners, int perSide = 20) {
    StrokePoints p{corners.front()};
    for (std::size_t i = 1; i < corners.size(); ++i)
        for (int k = 1; k <= perSide; ++k) {
            const double t = static_cast<double>(k) / perSide;
            p.push_back({corners[i - 1][0] + t * (corners[i][0] - corners[i - 1][0]),
                         corners[i - 1][1] + t * (corners[i][1] - corners[i - 1][1])});
        }
    return p;
}

// Around (cx, cy) from angle `from` by `sweep` radians; a positive sweep
// runs clockwise on screen (y down).
inline void appendArc(StrokePoints& p, double cx, double cy, double radius, double from, double sweep, int steps = 40) {
    for (int k = 0; k <= steps; ++k) {
        const double t = from + sweep * k / steps;
        p.push_back({cx + radius * std::cos(t), cy + radius * std::sin(t)});
    }
}

// A V drawn from its left tip: down, then up (a sharp left turn).
inline StrokePoints vShape() { return polyline({{100, 100}, {150, 250}, {200, 100}}); }

// A U from its left tip: down the left arm, round the bottom, up the right.
inline StrokePoints uShape() {
    StrokePoints p = polyline({{100, 100}, {100, 200}});
    appendArc(p, 150, 200, 50, kPi, -kPi);  // through the bottom (y down)
    StrokePoints right = polyline({{200, 200}, {200, 100}});
    p.insert(p.end(), right.begin() + 1, right.end());
    return p;
}

// An arch from its left foot: up, round the top, down.
inline StrokePoints archShape() {
    StrokePoints p = polyline({{100, 250}, {100, 150}});
    appendArc(p, 150, 150, 50, kPi, kPi);  // through the top
    StrokePoints right = polyline({{200, 150}, {200, 250}});
    p.insert(p.end(), right.begin() + 1, right.end());
    return p;
}

// A Z: right along the top, back down the diagonal, right along the bottom.
inline StrokePoints zShape() { return polyline({{100, 100}, {250, 100}, {100, 250}, {250, 250}}); }

// One and a half turns round a circle, clockwise on screen when `clockwise`.
inline StrokePoints loopShape(bool clockwise) {
    StrokePoints p;
    appendArc(p, 300, 300, 80, 0.0, (clockwise ? 1.0 : -1.0) * 3.0 * kPi, 120);
    return p;
}

inline StrokePoints lineShape() { return polyline({{50, 400}, {450, 340}}, 60); }

// Crossing out: back and forth seven times.
inline StrokePoints crossingOut() {
    StrokePoints c;
    for (int i = 0; i < 8; ++i) c.push_back({i % 2 ? 300.0 : 100.0, 100.0 + 12.0 * i});
    return polyline(c, 10);
}

// Rotated by `angle` about the origin, scaled by `scale`, moved by (dx, dy).
inline StrokePoints transformed(const StrokePoints& p, double angle, double scale, double dx, double dy) {
    StrokePoints out;
    for (const StrokePoint& q : p)
        out.push_back({dx + scale * (q[0] * std::cos(angle) - q[1] * std::sin(angle)),
                       dy + scale * (q[0] * std::sin(angle) + q[1] * std::cos(angle))});
    return out;
}

}  // namespace hg::garden::test
