#include "garden/sculpt/stroke_segments.h"

#include <algorithm>
#include <cmath>

#include "garden/sculpt/edit_field.h"

namespace hg::garden {

namespace {

constexpr double kPi = 3.14159265358979323846;

double distance(const ModelPoint& a, const ModelPoint& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The segment's field at distance d from its axis, in the plane through its
// middle.
double fieldBeside(const ModelPoint& a, const ModelPoint& b, double s, double d) {
    const ModelPoint dir{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    // A unit vector normal to the segment.
    ModelPoint n = std::fabs(dir[0]) < std::fabs(dir[1]) ? ModelPoint{0.0, dir[2], -dir[1]} : ModelPoint{dir[2], 0.0, -dir[0]};
    if (std::fabs(dir[0]) < 1e-300 && std::fabs(dir[1]) < 1e-300) n = {1.0, 0.0, 0.0};
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double px = 0.5 * (a[0] + b[0]) + d * n[0] / nl, py = 0.5 * (a[1] + b[1]) + d * n[1] / nl,
                 pz = 0.5 * (a[2] + b[2]) + d * n[2] / nl;
    return frep::lib::detail::convSegment<double>(px, py, pz, a[0], a[1], a[2], b[0], b[1], b[2], s);
}

// Distance from the segment beyond which its field is at most `level`:
// the field at distance d from a segment of length L is below both
// L / (1 + s^2 d^2)^2 (every point of it at least d away) and the infinite
// line's pi / (2 s (1 + s^2 d^2)^1.5).
double reachDistance(double length, double s, double level) {
    const double viaLength = std::sqrt(std::max(std::sqrt(length / level) - 1.0, 0.0)) / s;
    const double viaLine = std::sqrt(std::max(std::pow(kPi / (2.0 * s * level), 2.0 / 3.0) - 1.0, 0.0)) / s;
    return std::min(viaLength, viaLine);
}

}  // namespace

StrokeSegment makeStrokeSegment(const ModelPoint& a, const ModelPoint& b, double radius, double floor,
                                const FieldUnits& units) {
    StrokeSegment g;
    g.begin = a;
    g.end = b;
    const double length = distance(a, b);
    // The kernel's width sets how far the field reaches: s * radius = 1
    // unless the field would not fall below the floor soon enough (small
    // radii in voxels), then wider kernels, whose field falls more slowly
    // in voxel terms, until the far value is twice the floor.
    double s = 1.0 / radius;
    for (int attempt = 0; attempt < 40; ++attempt) {
        const double t = fieldBeside(a, b, s, radius);
        const double h = 1e-4 * radius;
        const double slope = (fieldBeside(a, b, s, radius - h) - fieldBeside(a, b, s, radius + h)) / (2.0 * h);
        const double scale = 1.0 / (units.voxelSize * slope);
        g.s = s;
        g.t = t;
        g.scale = scale;
        if (scale * t >= 2.0 * -floor) break;
        s *= 0.8;
    }
    // G > floor needs conv > t + floor / scale (>= t / 2 by the choice above).
    const double level = g.t + floor / g.scale;
    const double d = reachDistance(length, g.s, level) * 1.02 + 2.0 * units.voxelSize;
    for (int i = 0; i < 3; ++i) {
        g.reach.lo[i] = std::min(a[i], b[i]) - d;
        g.reach.hi[i] = std::max(a[i], b[i]) + d;
    }
    return g;
}

double strokeStep(double radius, double voxelSize) {
    return std::clamp(std::sqrt(2.0 * radius * voxelSize), 0.25 * radius, 0.5 * radius);
}

std::size_t extendStrokeSegments(Stroke& stroke, std::size_t firstPoint, const FieldUnits& units) {
    const std::size_t first = stroke.segments.size();
    if (stroke.path.empty()) return first;
    const double step = strokeStep(stroke.radius, units.voxelSize);
    const double floor = strokeFloor(stroke, units);
    // Segment 0 is a short one through the first point (the stroke's round
    // start, and all of a click); then the path, each point taken once it
    // is half a step from the last one taken. The segments are a function
    // of the path alone, however it arrived: frame by frame while the hand
    // draws, or whole from a journal.
    // A segment, then its reflection when the stroke is mirrored.
    const std::size_t perSegment = stroke.mirror ? 2 : 1;
    // Smooth and inflate weigh by the distance to the segment, exactly 0
    // beyond the radius: their reach is the capsule's box (and a voxel).
    const bool capsule = stroke.tool == StrokeTool::Smooth || stroke.tool == StrokeTool::Inflate;
    const auto segment = [&](const ModelPoint& a, const ModelPoint& b) {
        StrokeSegment g = makeStrokeSegment(a, b, stroke.radius, floor, units);
        if (capsule)
            for (int i = 0; i < 3; ++i) {
                g.reach.lo[i] = std::min(a[i], b[i]) - stroke.radius - units.voxelSize;
                g.reach.hi[i] = std::max(a[i], b[i]) + stroke.radius + units.voxelSize;
            }
        return g;
    };
    const auto add = [&](const ModelPoint& a, const ModelPoint& b) {
        stroke.segments.push_back(segment(a, b));
        if (stroke.mirror) stroke.segments.push_back(segment(reflect(*stroke.mirror, a), reflect(*stroke.mirror, b)));
    };
    if (stroke.segments.empty()) {
        const ModelPoint& p = stroke.path[0];
        add({p[0] - 0.5 * step, p[1], p[2]}, {p[0] + 0.5 * step, p[1], p[2]});
    }
    ModelPoint from = stroke.segments.size() == perSegment ? stroke.path[0]
                                                           : stroke.segments[stroke.segments.size() - perSegment].end;
    for (std::size_t i = std::max<std::size_t>(firstPoint, 1); i < stroke.path.size(); ++i) {
        const ModelPoint& to = stroke.path[i];
        const double d = distance(from, to);
        if (d < 0.5 * step) continue;
        const int pieces = std::max(1, static_cast<int>(std::ceil(d / step)));
        ModelPoint a = from;
        for (int k = 1; k <= pieces; ++k) {
            const double f = static_cast<double>(k) / pieces;
            const ModelPoint b = k == pieces ? to
                                             : ModelPoint{from[0] + f * (to[0] - from[0]), from[1] + f * (to[1] - from[1]),
                                                          from[2] + f * (to[2] - from[2])};
            add(a, b);
            a = b;
        }
        from = to;
    }
    return first;
}

std::string checkStroke(const Stroke& stroke, const FieldUnits& units) {
    if (!(std::isfinite(stroke.radius) && stroke.radius > 0.0))
        return "the tool radius must be a positive number";
    if (stroke.radius < 0.5 * units.voxelSize)
        return "the tool radius is under half a voxel (" + std::to_string(units.voxelSize) + " model units)";
    if (stroke.radius > 4096.0 * units.voxelSize) return "the tool radius is over 4096 voxels";
    if (stroke.tool == StrokeTool::Melt && !(std::isfinite(stroke.softness) && stroke.softness > 0.0 &&
                                             stroke.softness <= 64.0))
        return "the soft carve's softness must be in (0, 64] voxels";
    // Inflate: one stroke adds under the band at most, so a point in the air
    // (the field at -band) stays below the surface: no stroke makes a
    // surface where there was none within the band.
    if (stroke.tool == StrokeTool::Inflate &&
        !(std::isfinite(stroke.strength) && std::fabs(stroke.strength) < units.band))
        return "the inflate strength must be under the band (" + std::to_string(units.band) + " voxels) either way";
    if (stroke.tool == StrokeTool::Smooth && !(std::isfinite(stroke.strength) && stroke.strength > 0.0 &&
                                               stroke.strength <= 1.0))
        return "the smooth strength must be in (0, 1]";
    if (stroke.tool == StrokeTool::Smooth) {
        for (const auto& fit : stroke.fits)
            if (fit) {
                bool finite = std::isfinite(fit->scale) && fit->scale > 0.0;
                for (double c : fit->c) finite = finite && std::isfinite(c);
                for (double c : fit->centre) finite = finite && std::isfinite(c);
                if (!finite) return "a smooth stroke's fit is not made of finite numbers";
            }
    }
    if (stroke.path.empty()) return "the stroke has no path";
    for (const ModelPoint& p : stroke.path)
        for (double c : p)
            if (!std::isfinite(c)) return "the stroke's path has a point that is not a finite number";
    return "";
}

}  // namespace hg::garden
