// The triangulation of a cube cell for each of its 256 sign cases,
// generated (not typed in) from one rule, which is what makes meshes of
// neighbouring cells meet without cracks or holes:
//
//   On each face, the crossing points on the face's edges are joined so that
//   every run of consecutive inside corners is cut off by its own segment.
//   An ambiguous face (inside corners on a diagonal) therefore always
//   separates its inside corners, and the two cells sharing it decide alike.
//
// The segments of the six faces chain into closed loops (the boundary of the
// inside part of the cube's surface); each loop is fanned into triangles,
// counter-clockwise seen from outside the solid, from a crossing whose
// chords lie on no face of the cube. That second rule is what makes meshes
// manifold as well as closed: a chord on a face could be the neighbour's
// chord too, an edge of four triangles (loop_fan.h).
#pragma once

#include <array>
#include <cstdint>

namespace hg::poly {

// Corner c of a cell sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1).
// Edge e joins corners kEdgeCorners[e][0] and [1], along axis kEdgeAxis[e],
// starting at corner kEdgeCorners[e][0] (the one with the smaller offset).
extern const std::array<std::array<int, 2>, 12> kEdgeCorners;
extern const std::array<int, 12> kEdgeAxis;

struct CellCase {
    std::uint8_t triangleCount = 0;
    std::array<std::uint8_t, 36> edges{};  // three edge numbers per triangle (at most 12 triangles)
};

// Case index: bit c set when corner c is inside (value > 0).
const std::array<CellCase, 256>& cellTable();

}  // namespace hg::poly
