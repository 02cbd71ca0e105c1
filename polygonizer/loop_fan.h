// Where the cell and transition tables start the fan that triangulates one
// loop of crossings, so that no triangle edge inside a cell lies on one of
// the cell's faces.
//
// Why it matters (issue 20: 2 to 4 non-manifold edges on thin, box-aligned
// sculptures). A loop is fanned from one of its crossings; each chord of the
// fan (joining that crossing to a crossing of the loop that is not next to
// it) is an edge of two of the cell's triangles. Where the loop runs through
// an ambiguous face (four crossings: inside corners on a diagonal, the face
// rule cuts each off by its own segment), both of those segments belong to
// it, and a fan from one of the face's crossings may draw a chord to
// another of them: an edge lying in the face. The cell across that face sees
// the same four crossings and may draw the very same chord. The mesh then
// has an edge used by four triangles: two welded vertices (one per grid
// edge, shared by both cells) joined from both sides of the face. It takes a
// checkerboard face between two cells that both have one loop through both
// of its segments (e.g. a one-voxel pit in a one-voxel plate, with a
// one-voxel rod across it; or two blobs that touch at a grid point); smooth
// fields almost never make one, thin features on grid planes do.
//
// A fan none of whose chords lies on a face has no such edge: every edge
// between two crossings of a face is then one of the face's segments, used
// once by each of the two cells on it; a chord lies inside its cell, and no
// other cell has both of its grid edges. Every edge of the mesh is used
// exactly twice, once each way. Every loop of both tables has such a
// start (tests/polygonizer/manifold_property_test.cpp checks every case);
// the first one in loop order is taken, so loops whose plain fan was
// already free of face chords keep their triangles. A fan of n crossings
// makes n - 2 triangles from any start, so the tables' triangle counts (and
// the export mesher's allocation) do not change.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace hg::poly {

// The position in `loop` to fan from: the first whose chords (to every
// crossing but its two neighbours in the loop) join no two crossings that
// share a face of the cell (`shareFace(a, b)` for crossing numbers a, b).
template <class ShareFace>
std::size_t fanStartOffFaces(const std::vector<int>& loop, ShareFace shareFace) {
    const std::size_t n = loop.size();
    for (std::size_t s = 0; s < n; ++s) {
        bool clear = true;
        for (std::size_t k = 2; k + 1 < n && clear; ++k) clear = !shareFace(loop[s], loop[(s + k) % n]);
        if (clear) return s;
    }
    throw std::logic_error("cell tables: a loop with a chord on a face from every start");
}

}  // namespace hg::poly
