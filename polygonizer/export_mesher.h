// The export mesher: the whole grid at one level as one welded mesh, closed
// and manifold wherever the grid's surface is (each crossing of a grid edge
// is one vertex shared by every triangle that uses it; cells triangulate by
// cell_table.h's consistent rule), outward-facing, with normals from the
// field's gradient. What `hypergarden mesh` writes to STL.
#pragma once

#include "polygonizer/mesh.h"
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

}  // namespace hg::poly
