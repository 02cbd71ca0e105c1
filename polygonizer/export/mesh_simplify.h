// Fewer triangles where the surface is flat, through meshoptimizer's
// edge-collapse simplifier (meshopt_simplify): our meshes carry about twice
// a dual-contouring peer's triangles on flat faces, which printing services
// and other tools pay for. Kept vertices keep their positions and normals.
#pragma once

#include "polygonizer/mesh.h"

namespace hg::poly {

struct SimplifyStats {
    std::size_t trianglesBefore = 0;
    std::size_t trianglesAfter = 0;
    double error = 0.0;       // the sum of the passes' deviations (meshoptimizer's), model units
    int passes = 0;           // passes kept
    // A further collapse would have left the mesh not closed or not
    // manifold, so simplification stopped before the error allowed.
    bool stoppedByTopology = false;
};

// Collapses edges while the surface moves by at most `maxError` model units
// (> 0), as few triangles as that allows. meshoptimizer does not check that
// a collapse keeps the surface manifold: where it flattens a fin it leaves
// two triangles on the same three vertices in opposite orders (on a sphere
// of 1.6 million triangles, one such fold at an error of a third of a
// voxel). Those folds enclose nothing and are removed; then the pass is
// validated (mesh_validation.h), and one that still breaks the surface is
// retried with half the step, down to 1% of the triangles, before
// simplification stops there. After a pass that holds, another tries what
// is left of the error. The result is therefore closed, manifold and
// outward when `mesh` is. Unused vertices are dropped.
Mesh simplifyMesh(const Mesh& mesh, double maxError, SimplifyStats* stats = nullptr);

}  // namespace hg::poly
