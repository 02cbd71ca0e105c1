// Per-sculpture scale of f so that the stored field rises by about one unit
// per voxel across the surface: HyperFun values are not distances (a
// convolution surface's |grad f| can be 0.01 or 100 per model unit), yet
// the narrow band, the polygonizer's interpolation and the tools' radii all
// count in voxels.
#pragma once

#include <cstddef>

#include "frep/eval/model.h"
#include "voxel/volume_frame.h"

namespace hg::voxel {

struct Normalization {
    double scale = 1.0;          // stored value = f * scale
    std::size_t surfaceSamples = 0;
    double medianGradient = 0.0; // |grad f| per model unit at the samples
    double p90Gradient = 0.0;
};

// Finds surface points on a coarse lattice over the frame (sign changes
// along lattice edges, placed by linear interpolation), measures |grad f|
// there (the gradient evaluator on the tape; central differences on the
// interpreter path) and returns scale = 1 / (voxelSize * median |grad f|).
// With no surface in the box, f is taken as a distance in model units.
// Deterministic: the lattice and the sample choice depend only on the frame.
Normalization estimateNormalization(const frep::Model& model, const VolumeFrame& frame);

// Median and 90th percentile of a set of magnitudes (the set is reordered).
void medianAndP90(double* values, std::size_t n, double& median, double& p90);

}  // namespace hg::voxel
