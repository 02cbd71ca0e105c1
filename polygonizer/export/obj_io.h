// Wavefront OBJ for other programs (Blender, MeshLab, game engines): one
// object, a `v` line per vertex, a `vn` line per vertex normal and an
// `f a//a b//b c//c` line per triangle, counter-clockwise from outside.
// Written to a temporary name beside the target and renamed into place, so
// a failure never leaves a partial file.
#pragma once

#include <string>

#include "polygonizer/mesh.h"

namespace hg::poly {

// Writes `mesh` with every position multiplied by `scale` (metres per model
// unit, the sculpture's placement scale; finite and positive). Numbers are
// the shortest text that reads back as the same float. The mesh must have a
// normal per vertex. "" on success, otherwise what went wrong, with the path.
std::string writeObj(const Mesh& mesh, const std::string& path, double scale = 1.0,
                     const std::string& objectName = "hypergarden");

}  // namespace hg::poly
