// The three morph sources in one shared model frame: each source's f times
// its own normalization (so it rises by about one unit per voxel of the
// shared frame), sampled densely and unclamped over the frame's whole index
// box (voxel::sampleDense) and kept block by block (blocked_field.h).
// Blending clamped narrow-band values would be wrong away from the band
// (docs/design.md §4); these caches are what the blend reads, and what the
// balancing factors are measured on.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "frep/eval/model.h"
#include "garden/morph/blocked_field.h"
#include "voxel/dense_field.h"
#include "voxel/volume_frame.h"

namespace hg::garden {

struct MorphSources {
    voxel::VolumeFrame frame;                  // shared by the sources and the result
    std::array<BlockedField, 3> fields;        // each covers frame.indexBox exactly
    std::array<double, 3> normalization{1.0, 1.0, 1.0};  // field = f_i * normalization[i]
    std::array<double, 3> surfaceGradient{1.0, 1.0, 1.0};  // median |grad field_i| per voxel at its surface
};

struct MorphSourcesResult {
    std::optional<MorphSources> sources;
    std::string error;  // why there are none (bad frame, memory guard)
    double seconds = 0.0;
};

// Samples the three models over `box` at `resolution` voxels along its
// longest side. Each source's normalization is estimated in this frame
// (voxel::estimateNormalization). `memoryLimit` as for sampleDense.
MorphSourcesResult buildMorphSources(const std::array<const frep::Model*, 3>& models, const frep::Box3& box,
                                     int resolution, float band = 3.0f, std::uint64_t memoryLimit = 0);

// Sources from three dense caches of frame.indexBox: measures each one's
// surface gradient and keeps it block by block.
MorphSources morphSourcesFromDense(const voxel::VolumeFrame& frame, const std::array<voxel::DenseField, 3>& dense,
                                   const std::array<double, 3>& normalization = {1.0, 1.0, 1.0});

// "" when the three fields cover the frame's index box; else what is wrong.
std::string checkSources(const MorphSources& sources);

// Median |grad| per voxel (central differences) over the voxels where the
// field changes sign towards a face neighbour: how fast it rises across its
// surface. 0 when the field has no surface.
double surfaceGradient(const voxel::DenseField& field);

// The box that holds all three: the union of the sources' model boxes.
frep::Box3 unionBox(const std::array<frep::Box3, 3>& boxes);

}  // namespace hg::garden
