// Where a sculpture's voxels sit in its model frame. Index (0,0,0) is the
// model box's low corner, voxels are cubes of `voxelSize`, and the sampled
// index box covers the model box plus a margin of band + 1 voxels, so a
// surface on the model box's faces still closes inside the grid.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "frep/kernels/box.h"
#include "voxel/index_box.h"

namespace hg::voxel {

struct VolumeFrame {
    frep::Box3 modelBox;
    int resolution = 0;       // voxels along the model box's longest side
    double voxelSize = 0.0;   // model units
    float band = 3.0f;        // half-width of the stored narrow band, voxels
    IndexBox indexBox;        // every voxel that is sampled

    // Model position of voxel (i, j, k). Computed in double, then rounded the
    // same way by every sampler so that intervals and points agree.
    std::array<double, 3> position(int i, int j, int k) const {
        return {modelBox.lo[0] + static_cast<double>(i) * voxelSize,
                modelBox.lo[1] + static_cast<double>(j) * voxelSize,
                modelBox.lo[2] + static_cast<double>(k) * voxelSize};
    }
    double coordinate(int axis, int index) const {
        return modelBox.lo[axis] + static_cast<double>(index) * voxelSize;
    }
    // Voxel index nearest to a model position along one axis.
    int indexOf(int axis, double model) const;
};

// Limits on what a frame may ask for.
constexpr int kMinResolution = 4;
constexpr int kMaxResolution = 16384;
constexpr float kMinBand = 1.0f;
constexpr float kMaxBand = 64.0f;

// "" when a frame may have `resolution` and `band`, else what is wrong:
// checked before a model box is searched for.
std::string checkResolutionAndBand(int resolution, float band);

// Builds the frame for `box` at `resolution` voxels along its longest side.
// Returns "" on success, else what is wrong (empty or inverted box, bad
// resolution or band).
std::string makeFrame(const frep::Box3& box, int resolution, float band, VolumeFrame& frame);

}  // namespace hg::voxel
