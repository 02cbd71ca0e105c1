// Constrained Delaunay triangulation of a simple polygon (issue 22,
// "Inflation"; Teddy's first step). The outline's edges are the
// constraints and no vertex is added, so the triangles are made by ear
// clipping and then every interior edge is flipped (Lawson) until it is
// locally Delaunay. Inside a simple polygon every interior edge is a
// diagonal, so "locally Delaunay except the constraints" is exactly the
// constrained Delaunay triangulation; its interior edges are the chords
// whose midpoints make the chordal axis.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "garden/sketch/geometry2d.h"

namespace hg::garden::sketch {

struct Triangulation {
    // Counter-clockwise vertex indices into the polygon.
    std::vector<std::array<int, 3>> triangles;
    // neighbours[t][k]: the triangle across the edge opposite corner k
    // (the edge from corner k+1 to corner k+2), or -1 where that edge is an
    // outline edge.
    std::vector<std::array<int, 3>> neighbours;
    int flips = 0;      // Lawson flips made
    std::string error;  // "" on success
    bool ok() const { return error.empty(); }
};

// `polygon`: simple, counter-clockwise, at least 3 vertices (makeOutline's
// result). n vertices give n - 2 triangles.
Triangulation triangulatePolygon(const std::vector<Vec2>& polygon);

// The in-circle determinant of d against the counter-clockwise triangle
// abc, scaled by the magnitude of its terms: > 0 when d is inside the
// circumcircle, about 0 when the four points are cocircular.
double inCircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// The relative in-circle tolerance the flips use: cocircular points (a
// regular polygon) count as Delaunay either way, which also guarantees the
// flips end.
constexpr double kDelaunayTolerance = 1e-9;

}  // namespace hg::garden::sketch
