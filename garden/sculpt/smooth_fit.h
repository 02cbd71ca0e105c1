// The smooth tool's low-pass (docs/sculpting.md "Smooth and inflate"): a
// quadric fitted by weighted least squares to the field about one stroke
// segment, as the grid holds it when the segment is drawn.
#pragma once

#include <optional>

#include "garden/sculpt/edit.h"
#include "voxel/volume.h"

namespace hg::garden {

// The quadric (edit.h, SegmentFit) fitted to the grid's values at the voxel
// centres within `radius` of the segment where |f| < band - 0.5 (the
// clamped field says nothing of the surface), weighted (1 - d^2 / r^2)^2,
// a bell that fades to 0 at the radius. Local coordinates about the
// segment's middle scaled by the radius keep the system well conditioned;
// a slight ridge on the non-constant terms settles directions the samples
// do not constrain (a thin shell about a flat surface) towards a plane.
// None with too few samples or an ill-conditioned system: the segment then
// leaves the field as it is.
std::optional<SegmentFit> fitSegment(const voxel::Volume& grid, const StrokeSegment& segment, double radius);

}  // namespace hg::garden
