// Every grid of a .vdb file, for the readers that pick one (vdb_io.cpp's
// our grids, scalar_volume.cpp's scanned float grids). OpenVDB's headers:
// include only in voxel/*.cpp.
#pragma once

#include <openvdb/openvdb.h>

#include <string>

namespace hg::voxel {

// "" and the file's grids, or why not (the file named).
std::string readVdbGrids(const std::string& path, openvdb::GridPtrVecPtr& grids);

}  // namespace hg::voxel
