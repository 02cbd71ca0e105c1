// Inflation (issue 22): a closed outline on a plane in space becomes an FRep
// solid whose half-thickness across the plane at each chordal-axis point is
// that point's distance to the outline (times `thickness`): a circle gives
// a sphere, a long oval a rounded sausage.
//
// The representation, and why: a union (max) of "cone pieces" along the
// chordal axis. A piece is a segment a-b of the axis with radii ra, rb; its
// field is r(t) - |p - q(t)|, q(t) the point of the segment nearest p (t
// clamped to [0, 1]) and r(t) = ra + t (rb - ra). At an axis node the
// piece is a ball of radius r, the node's distance to the outline, so the
// union is the union of the outline's inscribed balls along the axis: the
// silhouette seen along the normal is the outline (up to the gaps between
// balls, a fraction of the sample spacing) and never leaves it by more
// than the radius tolerance, and a circle's single centre node is exactly
// a sphere. Where the pruned axis does not reach into a corner or a spike
// (the ball at the axis end is tangent short of it) a "spoke" piece runs
// from the nearest axis node to the outline vertex with radius falling to
// 0, so corners and tips are in the silhouette too, thin as in Teddy.
//
// The alternative, a Cauchy convolution surface along the axis
// (hfConvLine), sums the segments' fields: its thickness at a point
// depends on the neighbouring segments' lengths and widths and on one iso
// level for all, so fitting a varying half-width needs a solve, and its
// fields reach everywhere, so nothing can be dropped per box. The max of
// pieces has a closed form per piece, is about a distance (1-Lipschitz),
// and the tape specializer (frep/eval/tape_specializer.h) drops every piece that
// cannot win in a box, so voxelizing costs a few pieces per box, not all.
// Its one visual cost: shallow creases where branches meet at a junction.
//
// The solid is written as a HyperFun body the reference interpreter reads
// (inflation_text.h); inflation_field.h evaluates the same operations in
// the same order in C++.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

#include "garden/sketch/chordal_axis.h"
#include "garden/sketch/geometry2d.h"
#include "garden/sketch/triangulation.h"

namespace hg::garden::sketch {

using Vec3 = glm::dvec3;

// The sketch plane: plane coordinates (s, t) are the point
// origin + s u + t v; `normal` is the thickness direction. u, v, normal
// must be unit length and orthogonal.
struct SketchPlane {
    Vec3 origin{0.0, 0.0, 0.0};
    Vec3 u{1.0, 0.0, 0.0};
    Vec3 v{0.0, 1.0, 0.0};
    Vec3 normal{0.0, 0.0, 1.0};

    Vec3 toWorld(const Vec2& p) const { return origin + p.x * u + p.y * v; }
    // "" when the axes are unit and orthogonal (within 1e-6); else why not.
    std::string check() const;
};

// A plane through `origin` facing `normal` (any length), with u and v
// chosen orthonormal to it.
SketchPlane planeFacing(const Vec3& origin, const Vec3& normal);

// One piece of the solid, in plane coordinates: the segment a-b (a point
// when a == b) with radii ra at a and rb at b.
struct ConePiece {
    Vec2 a, b;
    double ra = 0.0, rb = 0.0;
    bool spoke = false;  // runs out to an outline corner (radius rb = 0)
};

struct InflatedSolid {
    SketchPlane plane;
    double thickness = 1.0;  // half-thickness across the plane / radius in it
    std::vector<ConePiece> pieces;
    // Axis-aligned bounds in world coordinates, tight: the union of the
    // pieces' end balls' boxes (a piece's box lies inside its ends' boxes).
    Vec3 lo{0.0}, hi{0.0};

    // The bounds grown by `margin` metres on every side.
    Vec3 paddedLo(double margin) const { return lo - Vec3(margin); }
    Vec3 paddedHi(double margin) const { return hi + Vec3(margin); }
};

struct InflationOptions {
    double thickness = 1.0;
    AxisOptions axis;
    // Axis chains are simplified while position and radius stay within
    // this many outline spacings of the full axis.
    double simplifyTolerance = 0.1;
    // A piece's radius may exceed the true distance to the outline between
    // its ends by this many spacings before the piece is split.
    double overshootTolerance = 0.05;
    // An outline vertex farther than this many spacings outside the pieces
    // gets a spoke (smaller: more spokes, a closer silhouette at corners).
    double coverTolerance = 0.5;
};

struct Inflation {
    Triangulation triangulation;
    ChordalAxis axis;
    InflatedSolid solid;
    int spokes = 0;
    std::string error;  // "" on success
    bool ok() const { return error.empty(); }
};

// `polygon`: a simple counter-clockwise outline (makeOutline's points),
// `spacing` its sample spacing (metres).
Inflation inflate(const std::vector<Vec2>& polygon, double spacing, const SketchPlane& plane,
                  const InflationOptions& options = {});

// How far a plane point is inside the pieces' silhouette, by the union of
// the pieces' in-plane discs (> 0 inside): the solid's cross-section in
// the plane, which is also its shadow along the normal.
double silhouetteValue(const std::vector<ConePiece>& pieces, const Vec2& p);

}  // namespace hg::garden::sketch
