// Unclamped normalized values of every voxel of a box: the source cache the
// morph blends from (docs/design.md §4: blending clamped narrow-band values is wrong
// away from the band), and the dense peer the culled sampler is measured
// against.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frep/language/domain_error.h"
#include "frep/eval/model.h"
#include "voxel/volume_frame.h"

namespace hg::voxel {

struct DenseField {
    IndexBox box;
    std::vector<float> values;  // x fastest, then y, then z

    std::size_t at(int i, int j, int k) const {
        return (static_cast<std::size_t>(k - box.lo[2]) * static_cast<std::size_t>(box.extent(1)) +
                static_cast<std::size_t>(j - box.lo[1])) * static_cast<std::size_t>(box.extent(0)) +
               static_cast<std::size_t>(i - box.lo[0]);
    }
    float value(int i, int j, int k) const { return values[at(i, j, k)]; }
};

struct DenseResult {
    DenseField field;
    std::string error;  // non-empty: refused by the memory guard, no field
    std::uint64_t bytes = 0;
    double seconds = 0.0;
    frep::ErrorReport errors;
};

// Samples f * scale at every voxel of `box` (clipped to nothing: the box may
// reach past the frame's index box) on TBB workers, one z-slice per task.
// `memoryLimit` 0: 80% of the memory available now.
DenseResult sampleDense(const frep::Model& model, const VolumeFrame& frame, double scale, const IndexBox& box,
                        std::uint64_t memoryLimit = 0);

}  // namespace hg::voxel

namespace hg::voxel {

class Volume;
struct VolumeSource;

// The field as a volume of kind DenseSource (every voxel active, no clamp),
// for writing to .vdb. `field` is consumed.
Volume volumeFromDense(DenseField&& field, const VolumeFrame& frame, double scale, const VolumeSource& source);

}  // namespace hg::voxel
