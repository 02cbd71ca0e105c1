// The export mesher: the whole grid at one level as one welded mesh, closed
// and manifold wherever the grid's surface is (each crossing of a grid edge
// is one vertex shared by every triangle that uses it; cells triangulate by
// cell_table.h's consistent rule), outward-facing, with normals from the
// field's gradient. What `hypergarden mesh` writes to STL.
#pragma once

#include <cstdint>
#include <vector>

#include "polygonizer/mesh.h"
#include "voxel/index_box.h"
#include "voxel/volume.h"

namespace hg::poly {

struct ExportStats {
    std::size_t cells = 0;      // cells visited (a superset of the surface's)
    std::size_t surfaceCells = 0;
    double seconds = 0.0;
};

// Positions in model units. Cells outside the frame's index box see the
// background (outside), so a solid cut by the box is capped there.
Mesh meshVolume(const voxel::Volume& volume, ExportStats* stats = nullptr);

// The grid edge a vertex lies on, packed: axis (0..2) and the index of the
// edge's low end, each index offset by 2^19 into 20 bits.
inline std::uint64_t gridEdgeKey(int axis, int i, int j, int k) {
    constexpr int kOffset = 1 << 19;
    return static_cast<std::uint64_t>(axis) << 60 | static_cast<std::uint64_t>(i + kOffset) << 40 |
           static_cast<std::uint64_t>(j + kOffset) << 20 | static_cast<std::uint64_t>(k + kOffset);
}
inline int gridEdgeAxis(std::uint64_t key) { return static_cast<int>(key >> 60); }
inline int gridEdgeIndex(std::uint64_t key, int axis) {
    return static_cast<int>((key >> (20 * (2 - axis))) & 0xFFFFFu) - (1 << 19);
}

// One tile of a larger mesh (polygonizer/export/tiled_mesher.h). Only the cells
// whose low corner lies in `cells` make triangles; `cells` must be whole
// blocks (lo and hi + 1 multiples of 8, the mesher's block). The grid must hold the
// true values of voxels cells.lo - 1 .. cells.hi + 2 (the cells' corners
// and the gradients there): what lies further out may be anything, as
// nothing there is used. The mesh may hold vertices no triangle uses (of
// edges beyond the cells); `vertexEdges` gets each vertex's gridEdgeKey.
struct CellWindow {
    voxel::IndexBox cells;
    std::vector<std::uint64_t>* vertexEdges = nullptr;
};
Mesh meshVolume(const voxel::Volume& volume, const CellWindow& window, ExportStats* stats = nullptr);

}  // namespace hg::poly
