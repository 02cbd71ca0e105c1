// A single stroke as drawn: points in screen pixels, y pointing down, in
// the order the pen visited them (timestamps are not needed: the features
// resample by arc length, so drawing speed does not matter).
#pragma once

#include <array>
#include <vector>

namespace hg::garden {

using StrokePoint = std::array<double, 2>;
using StrokePoints = std::vector<StrokePoint>;

// Length of the polyline through `points`.
double strokeLength(const StrokePoints& points);

// `count` points spaced evenly along the polyline, first and last kept.
// Needs count >= 2 and a polyline of positive length.
StrokePoints resampleStroke(const StrokePoints& points, int count);

}  // namespace hg::garden
