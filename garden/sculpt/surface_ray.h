// Where a ray in a sculpture's model frame first meets the surface of its
// grid (its trilinear field crosses zero), marching half a voxel at a time
// through the model box and refining between the last two samples. What
// the tools aim with: the tool hand's ray, each impact's path.
#pragma once

#include <functional>
#include <optional>

#include "garden/sculpt/edit.h"
#include "voxel/volume.h"

namespace hg::garden {

// The ray parameter t (origin + t * direction) of the first surface point,
// or none when the ray misses the solid inside the model box.
std::optional<double> marchToSurface(const voxel::Volume& volume, const ModelPoint& origin, const ModelPoint& direction);

// The same through the frame's voxels taken every 2^level (a coarser level
// of detail, whose voxel (i, j, k) is `value(i, j, k)`): how the tools aim
// at a far sculpture whose grid is on disk (garden/app/grid_pager.h).
std::optional<double> marchToSurface(const voxel::VolumeFrame& frame, int level,
                                     const std::function<float(int, int, int)>& value, const ModelPoint& origin,
                                     const ModelPoint& direction);

}  // namespace hg::garden
