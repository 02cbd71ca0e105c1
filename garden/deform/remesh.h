// Keeping the deformable model's triangulation uniform (the seed's
// "refinement": coarsening, refinement and smoothing; docs/sketching.md
// "Deformable model"), after Botsch and Kobbelt's isotropic remeshing: split
// edges longer than 4/3 of the target, collapse those shorter than 4/5,
// flip edges toward valence 6, and move vertices toward their neighbours'
// centroid within the tangent plane. Every operation keeps a closed
// manifold closed and manifold, and every round runs in a fixed order
// (edges sorted by length, then by their vertices), so the result is the
// same on every run.
#pragma once

#include <functional>

#include "garden/deform/deform_mesh.h"

namespace hg::garden::deform {

// Moves a point back onto the surface being remeshed (identity if empty).
using SurfaceProjection = std::function<glm::dvec3(const glm::dvec3&)>;

// One round of each: the number of edges changed. A round changes edges
// that share no triangle (collapses and flips: no vertex of a one-ring
// already touched), so each round is a set of independent local edits.
int splitLongEdges(DeformMesh& mesh, double maxLength);
int collapseShortEdges(DeformMesh& mesh, double minLength, double maxLength);
int flipTowardEvenValence(DeformMesh& mesh);
// Each vertex moves `factor` of the way toward its neighbours' centroid,
// within its tangent plane (reading the old positions only).
void smoothTangentially(DeformMesh& mesh, double factor);

// One round of split, collapse and flip toward `edgeLength`: what the snake
// runs between its steps. Returns the edges changed.
int remeshRound(DeformMesh& mesh, double edgeLength);

// `passes` of: splits and collapses until none is left (bounded),
// flips, tangential smoothing, then projection onto the surface.
DeformMesh remeshUniform(DeformMesh mesh, double edgeLength, int passes, const SurfaceProjection& project);
DeformMesh remeshUniform(DeformMesh mesh, double edgeLength, int passes);

}  // namespace hg::garden::deform
