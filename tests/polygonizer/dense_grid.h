// Volumes made straight from voxel values, for tests (and the mesher's fuzz
// target) that need fields no HyperFun program gives exactly: white noise,
// values exactly zero on grid points, boxes whose faces lie on grid planes.
// Voxel (i, j, k) sits at model position (i, j, k): one model unit a voxel.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>

#include "voxel/volume.h"
#include "voxel/volume_frame.h"
#include "voxel/volume_vdb.h"

namespace hg::poly::test {

// A volume over the model box [0, cells[a]] on each axis (at least 4 along
// the longest; its index box runs band + 1 = 4 voxels further each way, as
// voxelize()'s does) whose every voxel of the index box holds
// field(i, j, k), clamped to +-band (3); voxels beyond the index box read
// the background (outside). Every voxel is a leaf's, so no surface is lost
// between tiles (export_mesher.h).
inline voxel::Volume denseVolume(const std::array<int, 3>& cells, const std::function<float(int, int, int)>& field) {
    voxel::Volume v;
    // A frame has at least kMinResolution voxels along its longest side:
    // smaller grids get a longer box on their first longest axis.
    std::size_t longest = 0;
    for (std::size_t a = 1; a < 3; ++a)
        if (cells[a] > cells[longest]) longest = a;
    const int resolution = std::max(cells[longest], voxel::kMinResolution);
    frep::Box3 box;
    for (std::size_t a = 0; a < 3; ++a) {
        box.lo[a] = 0.0;
        box.hi[a] = a == longest ? resolution : cells[a];
    }
    if (!voxel::makeFrame(box, resolution, v.frame.band, v.frame).empty()) throw std::invalid_argument("denseVolume: no frame");
    const float band = v.frame.band;
    openvdb::FloatGrid& grid = voxel::vdb(v);
    grid.setTransform(voxel::frameTransform(v.frame));
    // Not registered with the tree (nothing else changes it meanwhile).
    openvdb::tree::ValueAccessor<openvdb::FloatTree, false> acc(grid.tree());
    const voxel::IndexBox& b = v.frame.indexBox;
    for (int i = b.lo[0]; i <= b.hi[0]; ++i)
        for (int j = b.lo[1]; j <= b.hi[1]; ++j)
            for (int k = b.lo[2]; k <= b.hi[2]; ++k) {
                float f = field(i, j, k);
                f = f > band ? band : f < -band ? -band : f;
                acc.setValueOn(openvdb::Coord(i, j, k), f);
            }
    return v;
}

}  // namespace hg::poly::test
