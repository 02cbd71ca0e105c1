// Teddy's chordal axis (Igarashi et al. 1999; the seed's "chordal axis
// calculation"): the spine of the outline's constrained Delaunay
// triangulation, with the distance to the outline at each of its points.
//
// Triangles are terminal (two outline edges), sleeve (one) or junction
// (none). The raw axis joins the midpoints of the interior edges through
// each sleeve and to the centroid of each junction. Small branches are
// pruned as Teddy does: from each terminal triangle a region grows across
// its interior edge while every outline vertex of the region lies inside
// the circle whose diameter is that edge (the semicircle test); it stops
// at the first edge that fails, or at a junction, and the region becomes a
// fan around the edge's midpoint (or the junction's centroid), the end of
// the pruned axis. So a round end (an oval's) folds into one axis end near
// its centre, a sharp spike keeps its axis nearly to the tip, and a circle
// folds into one node at its centre: the sphere's centre.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "garden/sketch/geometry2d.h"
#include "garden/sketch/triangulation.h"

namespace hg::garden::sketch {

enum class TriangleKind { Junction, Sleeve, Terminal, Whole };

struct AxisNode {
    Vec2 p;
    double radius = 0.0;  // distance from p to the outline: the half-width there
};

struct ChordalAxis {
    std::vector<TriangleKind> kinds;  // per triangle
    std::vector<char> pruned;         // per triangle: folded into a terminal fan
    std::vector<AxisNode> nodes;
    std::vector<std::array<int, 2>> edges;  // node indices
    // Per triangle, the axis nodes it is fanned from or spans (a pruned
    // triangle: its fan's apex; a junction: its centroid; a sleeve: the
    // midpoints of its two interior edges); -1 where there is none.
    std::vector<std::array<int, 2>> triangleNodes;
    int prunedRegions = 0;
    std::string error;
    bool ok() const { return error.empty(); }
};

struct AxisOptions {
    // A region vertex passes the semicircle test within radius * (1 + slack).
    double pruneSlack = 1e-9;
};

ChordalAxis chordalAxis(const std::vector<Vec2>& polygon, const Triangulation& t, const AxisOptions& options = {});

}  // namespace hg::garden::sketch
