// Meshes as sculptures (docs/garden-format.md, "mesh"; docs/volumes.md,
// "Imported meshes"): a triangle mesh in its model frame turned into the
// sculpture's narrow-band level set by OpenVDB's mesh-to-volume, at the
// sculpture's own resolution. A closed mesh gives its inside; an open one
// (a hole, a single sheet) has no inside to speak of, so its surface is
// thickened into a shell kMeshShellVoxels each side, which can be sculpted
// and printed like any solid.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "frep/kernels/box.h"
#include "voxel/sampler.h"

namespace hg::voxel {

// Half the thickness of the shell an open mesh becomes, in voxels.
constexpr double kMeshShellVoxels = 1.0;
// The model box of a mesh: its bounds grown by this share of its longest
// side on each side, room for sculpting beyond the surface.
constexpr double kMeshBoxMargin = 0.05;

struct MeshLevelSetRequest {
    std::optional<frep::Box3> box;   // none: meshModelBox
    int resolution = 128;            // voxels along the model box's longest side
    float band = 3.0f;
    VolumeSource source;             // recorded in the volume's metadata
    std::uint64_t memoryLimit = 0;   // bytes; 0: 80% of the memory available now
};

// The mesh's bounds grown by kMeshBoxMargin; an empty box (lo > hi) for no
// positions.
frep::Box3 meshModelBox(const std::vector<float>& positions);
// The box of a mesh's points (x, y, z after each other), no margin.
frep::Box3 meshBounds(const std::vector<float>& positions);
// Whether every edge (vertices equal by position) is shared by exactly two
// triangles: the mesh bounds an inside.
bool meshIsClosed(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices);

// The sculpture's grid from `positions` (xyz per vertex, model units) and
// `indices` (three per triangle): a signed distance positive inside, in
// voxels, clamped to +-band, the same bits every time. Refused with a
// reason when there are no triangles, an index is out of range, a
// coordinate is not finite, the box is empty, or the grid would not fit the
// memory limit (with the resolution that would).
VoxelizeResult levelSetFromMesh(const std::vector<float>& positions, const std::vector<std::uint32_t>& indices,
                                const MeshLevelSetRequest& request);

}  // namespace hg::voxel
