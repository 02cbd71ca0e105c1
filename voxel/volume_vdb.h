// The OpenVDB side of voxel::Volume. Include only where the grid itself is
// read or written: OpenVDB's headers are heavy.
#pragma once

#include <openvdb/openvdb.h>

#include "voxel/index_box.h"
#include "voxel/volume.h"

namespace hg::voxel {

struct VolumeGrid {
    openvdb::FloatGrid::Ptr grid;
};

using FloatLeaf = openvdb::FloatTree::LeafNodeType;

inline openvdb::FloatGrid& vdb(Volume& v) { return *v.grid().grid; }
inline const openvdb::FloatGrid& vdb(const Volume& v) { return *v.grid().grid; }

inline openvdb::CoordBBox toCoordBBox(const IndexBox& b) {
    return openvdb::CoordBBox(openvdb::Coord(b.lo[0], b.lo[1], b.lo[2]), openvdb::Coord(b.hi[0], b.hi[1], b.hi[2]));
}
inline IndexBox toIndexBox(const openvdb::CoordBBox& b) {
    return IndexBox::fromCorners(b.min().x(), b.min().y(), b.min().z(), b.max().x(), b.max().y(), b.max().z());
}

// The frame as an OpenVDB transform: voxel size, index (0,0,0) at the model
// box's low corner.
openvdb::math::Transform::Ptr frameTransform(const VolumeFrame& frame);

// A level set in OpenVDB's convention (distance in model units, negative
// inside) as a sculpture's grid: voxels, positive inside, clamped to the
// frame's band, active exactly inside the band, nothing outside the index
// box (volume.h). Scanned volumes and imported meshes end here.
openvdb::FloatGrid::Ptr levelSetToOurGrid(const openvdb::FloatGrid& distance, const VolumeFrame& frame);

struct VoxelizeResult;
// `distance` (as above) made the result's volume in `frame`, at the box
// origin `result.modelBox` already holds, with its statistics; `seconds`
// is how long the caller took to build it.
void adoptLevelSet(const openvdb::FloatGrid& distance, const VolumeFrame& frame, const VolumeSource& source,
                   double seconds, VoxelizeResult& result);

// Makes sure openvdb::initialize() has run (idempotent, thread-safe).
void ensureOpenVdbInitialized();

}  // namespace hg::voxel
