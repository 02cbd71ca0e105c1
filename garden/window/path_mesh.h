// A garden path (PathSpec) as the mesh the renderer draws: a flat ribbon
// just above the ground, the path's width wide, its segments joined by
// mitres so the outer edge of a bend is one straight corner and the inner
// edge meets itself (docs/rendering.md, "Sky and ground").
#pragma once

#include "garden/scene/garden.h"
#include "polygonizer/mesh.h"

namespace hg::garden {

// At most this many half-widths from a bend's point to its mitred corner:
// a sharper bend is cut short there (the ribbon a little narrower at the
// corner instead of a spike).
constexpr float kPathMitreLimit = 2.0f;

// One pair of vertices a point (repeated points dropped), one quad a
// segment; an open path ends flush with its end points. Normals up, faces
// counter-clockwise seen from above. Empty for fewer than two distinct points.
poly::Mesh pathMesh(const PathSpec& path, double groundHeight);

}  // namespace hg::garden
