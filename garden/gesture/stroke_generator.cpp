#include "garden/gesture/stroke_generator.h"

#include <algorithm>
#include <cmath>

#include "garden/gesture/gesture_random.h"

namespace hg::garden {

namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kDeg = kPi / 180.0;

// A pen in a y-down plane: heading 0 points right, and a positive turn is
// clockwise on screen (to the pen's right), as in stroke_features.h.
class Pen {
public:
    Pen() { points_.push_back({0.0, 0.0}); }
    void forward(double length) {
        const int steps = std::max(1, static_cast<int>(std::ceil(length / kStep)));
        for (int i = 0; i < steps; ++i) advance(length / steps);
    }
    // Turn by `angle` (radians, + right) along an arc of `radius`; a zero
    // radius is a sharp corner.
    void arc(double radius, double angle) {
        if (radius <= 0.0) {
            heading_ += angle;
            return;
        }
        const double length = radius * std::fabs(angle);
        const int steps = std::max(1, static_cast<int>(std::ceil(length / kStep)));
        for (int i = 0; i < steps; ++i) {
            heading_ += 0.5 * angle / steps;
            advance(length / steps);
            heading_ += 0.5 * angle / steps;
        }
    }
    void turn(double angle) { heading_ += angle; }
    StrokePoints take() { return std::move(points_); }

private:
    static constexpr double kStep = 0.01;
    void advance(double d) {
        x_ += d * std::cos(heading_);
        y_ += d * std::sin(heading_);
        points_.push_back({x_, y_});
    }
    double x_ = 0.0, y_ = 0.0, heading_ = 0.0;
    StrokePoints points_;
};

double sign(GestureRandom& r) { return r.chance(0.5) ? 1.0 : -1.0; }

// A corner that a hand draws: sharp or slightly rounded.
void corner(Pen& pen, GestureRandom& r, double angle) {
    pen.arc(r.chance(0.3) ? 0.0 : r.uniform(0.01, 0.08), angle);
}

StrokePoints sketchV(GestureRandom& r) {
    Pen pen;
    // Arms of any proportion, down to a check mark's short first arm.
    const double arm = r.uniform(0.5, 1.2);
    pen.forward(arm);
    corner(pen, r, sign(r) * r.uniform(100.0, 165.0) * kDeg);
    pen.forward(arm * std::exp(r.uniform(std::log(0.35), std::log(2.8))));
    return pen.take();
}

// A half turn of `side` (-1 left: a U; +1 right: an arch), round, squared
// or uneven, with arms of any length.
StrokePoints halfTurn(GestureRandom& r, double side) {
    Pen pen;
    const double total = r.uniform(150.0, 205.0) * kDeg;
    const double radius = r.uniform(0.25, 0.6);
    pen.forward(r.uniform(0.0, 1.2) * radius * 2.0);
    const double style = r.uniform();
    if (style < 0.45) {
        pen.arc(radius, side * total);
    } else if (style < 0.7) {
        // Squared: two rounded corners with a flat bottom.
        const double first = total * r.uniform(0.4, 0.6);
        const double round = radius * r.uniform(0.1, 0.5);
        pen.arc(round, side * first);
        pen.forward(radius * r.uniform(1.0, 2.0));
        pen.arc(round, side * (total - first));
    } else {
        // Uneven: the turn in three arcs of different radii (a parabola, a
        // lopsided U).
        double left = total;
        for (int i = 0; i < 3; ++i) {
            const double part = i == 2 ? left : total * r.uniform(0.2, 0.45);
            pen.arc(radius * r.uniform(0.4, 1.6), side * part);
            left -= part;
        }
    }
    pen.forward(r.uniform(0.0, 1.2) * radius * 2.0);
    return pen.take();
}

StrokePoints zigzagZ(GestureRandom& r) {
    Pen pen;
    const double s = sign(r);
    pen.forward(r.uniform(0.5, 1.2));
    corner(pen, r, s * r.uniform(100.0, 165.0) * kDeg);
    pen.forward(r.uniform(0.8, 1.6));
    corner(pen, r, -s * r.uniform(100.0, 165.0) * kDeg);
    pen.forward(r.uniform(0.5, 1.2));
    return pen.take();
}

// One or more turns of a loop, as an ellipse whose centre drifts and whose
// size changes as the hand circles; `direction` +1 clockwise on screen.
StrokePoints loop(GestureRandom& r, double direction) {
    StrokePoints points;
    const double turns = r.uniform(0.92, 3.5);
    const double a = 0.5, b = 0.5 * r.uniform(0.55, 1.0);
    const double growth = r.uniform(0.75, 1.3);  // size factor per turn
    const double driftAngle = r.uniform(0.0, 2.0 * kPi), drift = r.uniform(0.0, 0.3);
    const double start = r.uniform(0.0, 2.0 * kPi);
    const int steps = static_cast<int>(turns * 200.0);
    for (int i = 0; i <= steps; ++i) {
        const double u = turns * i / steps;  // turns done
        const double t = start + direction * 2.0 * kPi * u;
        const double size = std::pow(growth, u);
        // y down: increasing t moves clockwise on screen.
        points.push_back({size * a * std::cos(t) + drift * u * std::cos(driftAngle),
                          size * b * std::sin(t) + drift * u * std::sin(driftAngle)});
    }
    return points;
}

StrokePoints noGesture(GestureRandom& r) {
    Pen pen;
    const double kind = r.uniform();
    if (kind < 0.2) {
        // A straight line, wobbling a little.
        for (int i = 0; i < 10; ++i) {
            pen.turn(r.normal(0.0, 3.0 * kDeg));
            pen.forward(0.1);
        }
    } else if (kind < 0.3) {
        // A bent line: one shallow corner.
        pen.forward(r.uniform(0.4, 1.0));
        corner(pen, r, sign(r) * r.uniform(10.0, 60.0) * kDeg);
        pen.forward(r.uniform(0.4, 1.0));
    } else if (kind < 0.45) {
        // A gentle arc.
        pen.arc(r.uniform(0.6, 3.0), sign(r) * r.uniform(10.0, 80.0) * kDeg);
    } else if (kind < 0.55) {
        // A soft S: two opposite bends, each under a right angle.
        const double s = sign(r);
        pen.arc(r.uniform(0.4, 1.2), s * r.uniform(30.0, 90.0) * kDeg);
        pen.forward(r.uniform(0.0, 0.4));
        pen.arc(r.uniform(0.4, 1.2), -s * r.uniform(30.0, 90.0) * kDeg);
    } else if (kind < 0.75) {
        // A zigzag of three to seven sharp turns.
        const int corners = 3 + static_cast<int>(r.below(5));
        double s = sign(r);
        pen.forward(r.uniform(0.5, 1.0));
        for (int i = 0; i < corners; ++i) {
            corner(pen, r, s * r.uniform(90.0, 170.0) * kDeg);
            pen.forward(r.uniform(0.5, 1.0));
            if (!r.chance(0.15)) s = -s;  // mostly alternating, sometimes not
        }
    } else {
        // A scribble: a random walk of the heading, sometimes jerked round.
        const int steps = 40 + static_cast<int>(r.below(80));
        double bend = 0.0;
        for (int i = 0; i < steps; ++i) {
            bend = 0.7 * bend + r.normal(0.0, 25.0 * kDeg);
            if (r.chance(0.05)) bend += sign(r) * r.uniform(60.0, 150.0) * kDeg;
            pen.turn(bend);
            pen.forward(r.uniform(0.02, 0.06));
        }
    }
    return pen.take();
}

StrokePoints gestureTemplate(GestureLabel label, GestureRandom& r) {
    switch (label) {
        case GestureLabel::Sketch: return sketchV(r);
        case GestureLabel::Union: return halfTurn(r, -1.0);
        case GestureLabel::Intersect: return halfTurn(r, 1.0);
        case GestureLabel::Deform: return zigzagZ(r);
        case GestureLabel::Shrink: return loop(r, 1.0);
        case GestureLabel::Grow: return loop(r, -1.0);
        case GestureLabel::None: break;
    }
    return noGesture(r);
}

// A short tail at one end: a hook (pen landing or lifting) or overshoot.
void addTail(StrokePoints& p, GestureRandom& r, bool atStart) {
    if (p.size() < 3) return;
    const double length = strokeLength(p) * r.uniform(0.015, 0.05);
    const StrokePoint& end = atStart ? p.front() : p.back();
    const std::size_t back = std::min<std::size_t>(5, p.size() - 1);  // the tail leaves along the last few points
    const StrokePoint& inner = atStart ? p[back] : p[p.size() - 1 - back];
    const double outward = std::atan2(end[1] - inner[1], end[0] - inner[0]) + r.normal(0.0, 35.0 * kDeg);
    StrokePoints tail;
    for (int i = 1; i <= 5; ++i)
        tail.push_back({end[0] + length * i / 5.0 * std::cos(outward), end[1] + length * i / 5.0 * std::sin(outward)});
    if (atStart) p.insert(p.begin(), tail.rbegin(), tail.rend());
    else p.insert(p.end(), tail.begin(), tail.end());
}

// A smooth sideways wobble along the path, in path-length units.
void wobble(StrokePoints& p, GestureRandom& r) {
    // Templates are about one unit across, so this is a fraction of their size.
    const double amplitude = r.uniform(0.0, 0.025);
    const double f1 = r.uniform(1.0, 4.0), f2 = r.uniform(4.0, 9.0), ph1 = r.uniform(0.0, 6.3), ph2 = r.uniform(0.0, 6.3);
    StrokePoints out = p;
    const double total = std::max(1e-9, strokeLength(p));
    double along = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (i > 0) along += std::hypot(p[i][0] - p[i - 1][0], p[i][1] - p[i - 1][1]);
        const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(p.size() - 1, i + 1);
        double nx = -(p[b][1] - p[a][1]), ny = p[b][0] - p[a][0];
        const double len = std::hypot(nx, ny);
        if (len <= 0.0) continue;
        const double u = along / total;
        const double d = amplitude * (std::sin(2.0 * kPi * f1 * u + ph1) + 0.5 * std::sin(2.0 * kPi * f2 * u + ph2));
        out[i][0] += d * nx / len;
        out[i][1] += d * ny / len;
    }
    p.swap(out);
}

// Samples as a mouse reports them: a point every frame, so the spacing
// follows the drawing speed, which changes along the stroke.
StrokePoints sampleBySpeed(const StrokePoints& dense, GestureRandom& r) {
    // Templates are about a unit across: a long loop takes longer to draw,
    // so it gets more samples.
    const double scale = std::clamp(strokeLength(dense) / 3.0, 1.0, 3.0);
    const int count = static_cast<int>((12.0 + static_cast<double>(r.below(140))) * scale);
    const double f = r.uniform(0.5, 3.0), ph = r.uniform(0.0, 6.3), depth = r.uniform(0.0, 0.8);
    std::vector<double> cumulative{0.0};
    for (int i = 0; i < count - 1; ++i) {
        const double speed = 1.0 + depth * std::sin(2.0 * kPi * f * i / count + ph) + r.uniform(0.0, 0.3);
        cumulative.push_back(cumulative.back() + speed);
    }
    const double total = strokeLength(dense);
    auto segment = [&](std::size_t i) { return std::hypot(dense[i][0] - dense[i - 1][0], dense[i][1] - dense[i - 1][1]); };
    StrokePoints out;
    double before = 0.0;
    std::size_t seg = 1;
    for (double c : cumulative) {
        const double along = c / cumulative.back() * total;
        while (seg + 1 < dense.size() && before + segment(seg) < along) {
            before += segment(seg);
            ++seg;
        }
        const double len = segment(seg);
        const double t = len > 0.0 ? std::clamp((along - before) / len, 0.0, 1.0) : 0.0;
        out.push_back({dense[seg - 1][0] + t * (dense[seg][0] - dense[seg - 1][0]),
                       dense[seg - 1][1] + t * (dense[seg][1] - dense[seg - 1][1])});
    }
    return out;
}

// Stretch, rotate, size and place on a screen; jitter and round to pixels.
void placeOnScreen(StrokePoints& p, GestureRandom& r) {
    const double stretch = std::exp(r.uniform(-0.22, 0.22));
    const double angle = r.uniform(0.0, 2.0 * kPi);
    for (StrokePoint& q : p) {
        const double x = q[0] * stretch, y = q[1] / stretch;
        q = {x * std::cos(angle) - y * std::sin(angle), x * std::sin(angle) + y * std::cos(angle)};
    }
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const StrokePoint& q : p) {
        x0 = std::min(x0, q[0]); y0 = std::min(y0, q[1]);
        x1 = std::max(x1, q[0]); y1 = std::max(y1, q[1]);
    }
    const double size = std::exp(r.uniform(std::log(40.0), std::log(800.0)));
    const double k = size / std::max(1e-9, std::hypot(x1 - x0, y1 - y0));
    const double ox = r.uniform(0.0, 1920.0), oy = r.uniform(0.0, 1080.0);
    const double jitter = r.uniform(0.0, 0.8);
    const bool whole = r.chance(0.5);
    for (StrokePoint& q : p) {
        q = {ox + (q[0] - x0) * k + r.normal(0.0, jitter), oy + (q[1] - y0) * k + r.normal(0.0, jitter)};
        if (whole) q = {std::round(q[0]), std::round(q[1])};
    }
}

}  // namespace

StrokePoints generateStroke(GestureLabel label, std::uint64_t seed) {
    GestureRandom r(seed);
    StrokePoints p = gestureTemplate(label, r);
    wobble(p, r);
    if (r.chance(0.3)) addTail(p, r, true);
    if (r.chance(0.3)) addTail(p, r, false);
    p = sampleBySpeed(p, r);
    placeOnScreen(p, r);
    return p;
}

std::vector<LabelledStroke> generateStrokeSet(int perGesture, int none, std::uint64_t seed) {
    std::vector<LabelledStroke> set;
    GestureRandom seeds(seed);
    for (GestureLabel label : kGestureLabels) {
        const int count = label == GestureLabel::None ? none : perGesture;
        for (int i = 0; i < count; ++i) set.push_back({generateStroke(label, seeds.next()), label});
    }
    return set;
}

}  // namespace hg::garden
