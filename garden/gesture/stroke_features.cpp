#include "garden/gesture/stroke_features.h"

#include <algorithm>
#include <cmath>

namespace hg::garden {

namespace {

constexpr double kPi = 3.141592653589793;

// Root mean square distance of the points from their centroid: a size that
// does not change when the stroke turns.
double rmsRadius(const StrokePoints& points) {
    double mx = 0.0, my = 0.0;
    for (const StrokePoint& p : points) { mx += p[0]; my += p[1]; }
    mx /= static_cast<double>(points.size());
    my /= static_cast<double>(points.size());
    double sum = 0.0;
    for (const StrokePoint& p : points) sum += (p[0] - mx) * (p[0] - mx) + (p[1] - my) * (p[1] - my);
    return std::sqrt(sum / static_cast<double>(points.size()));
}

// Drops points within a small fraction of the stroke's size of the last
// point kept. Jitter between closely spaced samples (a slow hand, a fast
// mouse) would otherwise lengthen the path where the hand was slow and
// bend the arc-length resampling; the last point is always kept.
StrokePoints thinned(const StrokePoints& points) {
    StrokePoints out;
    if (points.empty()) return out;
    const double spacing = rmsRadius(points) * kFeatureThinning;
    out.push_back(points.front());
    for (std::size_t i = 1; i < points.size(); ++i)
        if (std::hypot(points[i][0] - out.back()[0], points[i][1] - out.back()[1]) >= spacing) out.push_back(points[i]);
    if (out.size() > 1 && out.back() != points.back()) out.back() = points.back();
    else if (out.size() == 1 && points.back() != out.back()) out.push_back(points.back());
    return out;
}

// The path the turns are measured on: thinned, evenly resampled, smoothed
// with the ends held (so a stroke keeps its extent), resampled again so
// that the segments are equal after smoothing shortened the corners.
StrokePoints normalizedPath(const StrokePoints& points) {
    StrokePoints dense = resampleStroke(thinned(points), kFeatureResample);
    if (dense.empty()) return dense;
    for (int pass = 0; pass < kFeatureSmoothing; ++pass) {
        StrokePoints next = dense;
        for (std::size_t i = 1; i + 1 < dense.size(); ++i)
            for (int c = 0; c < 2; ++c) next[i][c] = 0.25 * dense[i - 1][c] + 0.5 * dense[i][c] + 0.25 * dense[i + 1][c];
        dense.swap(next);
    }
    return resampleStroke(dense, kFeatureSegments + 1);
}

// sqrt(smaller / larger eigenvalue) of the points' covariance.
double roundness(const StrokePoints& path) {
    double mx = 0.0, my = 0.0;
    for (const StrokePoint& p : path) { mx += p[0]; my += p[1]; }
    const double n = static_cast<double>(path.size());
    mx /= n;
    my /= n;
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (const StrokePoint& p : path) {
        sxx += (p[0] - mx) * (p[0] - mx);
        syy += (p[1] - my) * (p[1] - my);
        sxy += (p[0] - mx) * (p[1] - my);
    }
    const double half = 0.5 * (sxx + syy);
    const double root = std::sqrt(std::max(0.0, 0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy));
    const double large = half + root, small = std::max(0.0, half - root);
    return large > 0.0 ? std::sqrt(small / large) : 0.0;
}

}  // namespace

std::vector<double> strokeTurns(const StrokePoints& points) {
    std::vector<double> turns;
    const StrokePoints path = normalizedPath(points);
    if (path.size() != static_cast<std::size_t>(kFeatureSegments + 1)) return turns;
    turns.reserve(kFeatureTurns);
    for (int i = 1; i < kFeatureSegments; ++i) {
        const double ax = path[i][0] - path[i - 1][0], ay = path[i][1] - path[i - 1][1];
        const double bx = path[i + 1][0] - path[i][0], by = path[i + 1][1] - path[i][1];
        // y down: a positive cross product is clockwise as seen on screen.
        turns.push_back(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
    }
    return turns;
}

std::vector<double> strokeFeatures(const StrokePoints& points) {
    std::vector<double> features;
    const std::vector<double> turns = strokeTurns(points);
    if (turns.empty()) return features;
    features.reserve(kFeatureCount);
    double signedTurn = 0.0, absoluteTurn = 0.0, largest = 0.0;
    for (double t : turns) {
        features.push_back(std::sin(t));
        features.push_back(std::cos(t));
        signedTurn += t;
        absoluteTurn += std::fabs(t);
        largest = std::max(largest, std::fabs(t));
    }
    const StrokePoints path = resampleStroke(thinned(points), kFeatureResample);
    const double length = strokeLength(path);
    const double gap = std::hypot(path.back()[0] - path.front()[0], path.back()[1] - path.front()[1]);
    features.push_back(std::clamp(signedTurn / (4.0 * kPi), -2.0, 2.0));
    features.push_back(std::min(absoluteTurn / (4.0 * kPi), 2.0));
    features.push_back(absoluteTurn > 0.0 ? signedTurn / absoluteTurn : 0.0);
    features.push_back(length > 0.0 ? gap / length : 0.0);
    features.push_back(largest / kPi);
    features.push_back(roundness(path));
    return features;
}

}  // namespace hg::garden
