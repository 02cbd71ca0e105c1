// The sketched model as the deformable model's starting mesh (issue 22,
// docs/sketching.md "Deformable model"): the inflated solid's field sampled
// on a grid finer than the target edge, meshed by OpenVDB's volumeToMesh,
// then remeshed to a uniform triangulation of about `edgeLength` with each
// pass's vertices put back on the solid's surface (the seed's refinement:
// smoothing, coarsening and refinement).
#pragma once

#include "garden/deform/deform_mesh.h"
#include "garden/sketch/inflation.h"

namespace hg::garden::deform {

// Empty when the solid has no pieces.
DeformMesh meshOfInflatedSketch(const sketch::InflatedSolid& solid, double edgeLength);

}  // namespace hg::garden::deform
