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
    double error = 0.0;  // the largest deviation meshoptimizer reports, model units
};

// Collapses edges while the surface moves by at most `maxError` model units
// (> 0), as few triangles as that allows. Unused vertices are dropped. The
// result may in rare cases not be manifold (two sheets pulled together):
// validate it (mesh_validation.h).
Mesh simplifyMesh(const Mesh& mesh, double maxError, SimplifyStats* stats = nullptr);

}  // namespace hg::poly
