// A sculpture's unedited grid from its source, whichever kind it is: the
// HyperFun body sampled (voxel::voxelize), a scanned volume's iso-surface
// rebuilt as a level set (voxel::levelSetFromScalar, docs/volumes.md,
// "Scanned volumes") or a mesh's (voxel::levelSetFromMesh, "Imported meshes"). The session's start, the background loader and a
// source read again after it changed on disk all come here.
#pragma once

#include <string>
#include <vector>

#include "garden/app/sculpture.h"
#include "garden/morph/garden_morph.h"
#include "garden/scene/garden_file.h"
#include "io/progress.h"
#include "voxel/sampler.h"

namespace hg::garden {

// `request` is the spec's box, resolution and band (GardenSession::volumeRequest).
// A scan's errors name the garden file's entry. `progress` (may be null) is
// told and asked by a HyperFun body's sampling (voxel::SampleOptions); a
// scan's or a mesh's level set is made whole.
voxel::VoxelizeResult sampleSculptureSource(const SculptureSpec& spec, const SculptureLoad& load,
                                            const voxel::VolumeRequest& request, io::Progress* progress = nullptr);

// What a HyperFun sculpture's unedited grid is sampled from, as text: its
// file, body, a[], box, resolution and band. Sampling is deterministic, so
// equal keys give equal grids (the loader samples copies once; copies
// share an impostor). "" for a scan or a mesh: never shared.
std::string sampledSourceKey(const SculptureSpec& spec);

// The model boxes the sculptures' grids were sampled in, by index (none
// for a morph result, one without a grid yet, or a missing one): what a
// morph's shared box is made of without estimating the boxes again.
ResolvedBoxes sampledModelBoxes(const std::vector<Sculpture>& sculptures);

}  // namespace hg::garden
