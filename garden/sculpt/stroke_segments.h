// A stroke's path resampled into Cauchy line segments whose surfaces have
// the tool's radius (docs/sculpting.md: S and T chosen so that the surface radius is
// the tool radius; the path sampled finely enough for the radius).
#pragma once

#include <string>
#include <vector>

#include "garden/sculpt/edit.h"

namespace hg::garden {

// How long a stroke's segments are. Each segment's surface is rounded at
// its ends, so the union of neighbours a step s apart dips between them by
// about s^2 / (8 r): steps of sqrt(2 r v) keep that to a quarter voxel v
// (invisible), within a quarter and a half of the radius (under 1% and 3%
// of it). Small tools get far fewer segments than a fixed fraction would
// give them, and every box update and rebuild evaluates fewer.
double strokeStep(double radius, double voxelSize);

// The segment from a to b (a != b) with its constants and reach.
StrokeSegment makeStrokeSegment(const ModelPoint& a, const ModelPoint& b, double radius, double floor,
                                const FieldUnits& units);

// Appends to `stroke.segments` the segments for path points from
// `firstPoint` on (the points before were segmented already): points
// closer than half a step to the last one taken are skipped, longer steps
// split. Returns the index of the first new segment.
std::size_t extendStrokeSegments(Stroke& stroke, std::size_t firstPoint, const FieldUnits& units);

// "" when the stroke's parameters are usable, else why not.
std::string checkStroke(const Stroke& stroke, const FieldUnits& units);

}  // namespace hg::garden
