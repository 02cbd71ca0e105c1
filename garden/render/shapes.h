// Procedural meshes and outlines the renderer draws itself (the detail
// sphere) and the tests render with known geometry.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "polygonizer/mesh.h"

namespace hg::garden {

// A UV sphere at the origin: `slices` around y, `stacks` pole to pole,
// unit normals, counter-clockwise from outside, no degenerate triangles
// (2 * slices * (stacks - 1) of them). Vertices on the seam and poles are
// repeated, so it is closed in shape but not welded.
poly::Mesh uvSphereMesh(float radius, int slices, int stacks);

// `segments` points on a circle of `radius` about `center` in the plane
// spanned by unit vectors u and v, for a line loop.
std::vector<glm::vec3> circlePoints(const glm::vec3& center, float radius, const glm::vec3& u, const glm::vec3& v,
                                    int segments);

}  // namespace hg::garden
