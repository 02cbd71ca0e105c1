// Measurements of a stored volume, for `voxelize --stats` and the tests:
// how close the normalized field is to one unit per voxel at the surface,
// and how the grid is laid out.
#pragma once

#include <cstddef>

#include "voxel/volume.h"

namespace hg::voxel {

struct GridStats {
    std::size_t surfaceVoxels = 0;   // voxels within half a voxel of the surface
    double medianGradient = 0.0;     // |grad| of the stored field, per voxel
    double p90Gradient = 0.0;
    std::size_t activeVoxels = 0;
    std::size_t leaves = 0;
    std::size_t tilesInside = 0;     // tiles holding +band (any level)
    std::size_t tilesOutside = 0;
    std::size_t memoryBytes = 0;
};

// |grad| by central differences at active voxels with |value| < 0.5 whose six
// neighbours are all inside the band (so the clamp does not bend it).
GridStats measureGrid(const Volume& volume);

}  // namespace hg::voxel
