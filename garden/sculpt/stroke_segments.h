// A stroke's path resampled into Cauchy line segments whose surfaces have
// the tool's radius (DESIGN §4: S and T chosen so that the surface radius is
// the tool radius; the path sampled finely enough for the radius).
#pragma once

#include <string>
#include <vector>

#include "garden/sculpt/edit.h"

namespace hg::garden {

// Segments are at most this fraction of the radius long: each segment's
// surface is rounded at its ends, and at a quarter radius the union of
// neighbours dips by under 1% of the radius between them.
constexpr double kSegmentLengthPerRadius = 0.25;

// The segment from a to b (a != b) with its constants and reach.
StrokeSegment makeStrokeSegment(const ModelPoint& a, const ModelPoint& b, double radius, double floor,
                                const FieldUnits& units);

// Appends to `stroke.segments` the segments for path points from
// `firstPoint` on (the points before were segmented already): points
// closer than half a segment to the last one taken are skipped, longer
// steps split. Returns the index of the first new segment.
std::size_t extendStrokeSegments(Stroke& stroke, std::size_t firstPoint, const FieldUnits& units);

// "" when the stroke's parameters are usable, else why not.
std::string checkStroke(const Stroke& stroke, const FieldUnits& units);

}  // namespace hg::garden
