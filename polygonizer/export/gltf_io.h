// glTF 2.0 binary (.glb) for other programs and the web, through tinygltf:
// one scene, one node, one mesh with one indexed triangle primitive
// (POSITION and NORMAL as float vec3, indices as uint32), in metres as glTF
// asks. Written to a temporary name beside the target and renamed into
// place, so a failure never leaves a partial file.
#pragma once

#include <string>

#include "polygonizer/mesh.h"

namespace hg::poly {

// Writes `mesh` with every position multiplied by `scale` (metres per model
// unit, the sculpture's placement scale; finite and positive). The mesh must
// have a normal per vertex. "" on success, otherwise what went wrong, with
// the path.
std::string writeGlb(const Mesh& mesh, const std::string& path, double scale = 1.0,
                     const std::string& meshName = "hypergarden");

}  // namespace hg::poly
