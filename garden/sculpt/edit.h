// What a user did to a sculpture, as data (docs/design.md §4): the ordered edit list
// is the sculpture's source of truth next to its HyperFun source, and the
// grid is a cache rebuilt from both. Each edit is one FRep operation on the
// field before it, built by the one expression template in edit_field.h
// (tape for the grid, double for checks, HyperFun text for export).
//
// Units: positions and lengths in the sculpture's model frame; field values
// in voxels of its grid (the stored field: about one unit per voxel at the
// surface, clamped to +-band). Every edit keeps the field in [-band, band],
// so it stays bounded at any number of edits, and leaves it exactly
// unchanged outside its reach box, so a box update needs only the edits
// that reach the box (edit_index.h).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "frep/kernels/box.h"
#include "garden/sketch/inflation.h"

namespace hg::garden {

using ModelPoint = std::array<double, 3>;

// Melt is shown as "soft carve" (a carve with a rounded edge); the journal
// keeps the word "melt" so old sessions play bit for bit.
enum class StrokeTool { Carve, Add, Melt, Smooth, Inflate };

// How a smooth or inflate stroke's weight falls from its path to its radius
// (docs/sculpting.md "Smooth and inflate"): each curve maps the capsule
// weight w = max(1 - d^2 / r^2, 0) to [0, 1] and is exactly 0 where w is,
// so the stroke is exactly local.
enum class Falloff { Smooth, Linear, Sharp, Constant };
const char* falloffName(Falloff f);

// A sculpture's mirror plane (model frame): a stroke or perturbation made
// while it is set acts on both sides, as one edit.
struct MirrorPlane {
    ModelPoint point{};
    ModelPoint normal{1.0, 0.0, 0.0};  // unit length
};
ModelPoint reflect(const MirrorPlane& m, const ModelPoint& p);
ModelPoint reflectDirection(const MirrorPlane& m, const ModelPoint& d);
const char* strokeToolName(StrokeTool t);

// One Cauchy line segment of a stroke with the constants that give its
// surface the tool's radius (stroke_segments.h computes them):
//   G = clamp(scale * (conv(p; begin, end, s) - t), floor, band)
// where conv is hfConvLine's field of the segment. G is about the distance
// to the segment's surface in voxels, positive inside the tool, and exactly
// `floor` beyond `reach`.
struct StrokeSegment {
    ModelPoint begin{}, end{};
    double s = 1.0;      // kernel width (hfConvLine's S)
    double t = 0.0;      // threshold (hfConvLine's T)
    double scale = 1.0;  // voxels per unit of field at the surface
    frep::Box3 reach;    // outside it G == floor exactly
};

// A smooth stroke's low-pass of the field about one segment: the quadric
// Q(u) = c0 + c1 u + c2 v + c3 w + c4 u^2 + c5 v^2 + c6 w^2 + c7 u v
// + c8 v w + c9 u w, (u, v, w) = (p - centre) / scale, voxels; fitted to
// the field where the segment was drawn (garden/sculpt/smooth_fit.h) and
// kept in the edit and its journal entry, so rebuilds, replays and the
// export never fit again.
struct SegmentFit {
    ModelPoint centre{};
    double scale = 1.0;
    std::array<double, 10> c{};
};

// Carve (f \ tool), add (f | tool) or melt (a rounded subtraction, "soft
// carve") along a path: the union of its segments' convolution surfaces.
// Inflate adds strength * W to the field (W the falloff weight, the
// largest over the segments: at most 1 on the path, exactly 0 beyond the
// radius); smooth blends the field towards each segment's fitted quadric,
// segment by segment, with weight strength * w_i (edit_field.h).
struct Stroke {
    StrokeTool tool = StrokeTool::Carve;
    double radius = 0.1;     // model units
    double softness = 2.0;   // melt: width of the rounded edge, voxels
    // Inflate: voxels, |strength| < band (negative deflates); smooth: the
    // blend's weight in (0, 1]. Already scaled by the pen's pressure.
    double strength = 1.0;
    Falloff falloff = Falloff::Smooth;  // inflate and smooth
    // Smooth: one fit per segment once it is fitted (none: too few samples
    // there, the segment leaves the field as it is).
    std::vector<std::optional<SegmentFit>> fits;
    std::vector<ModelPoint> path;        // as the hand drew it (model frame)
    std::optional<MirrorPlane> mirror;   // the path also drawn reflected
    // The path resampled for the radius; with a mirror, each segment is
    // followed by its reflection.
    std::vector<StrokeSegment> segments;
};

enum class QuadricShape { Ellipsoid, Torus };

// f + k * max(Q, 0)^3 (seed 000's perturbation, seed 001's field tools),
// Q >= 0 inside the quadric: for an ellipsoid 1 - sum (u_i / r_i)^2, for a
// torus 1 - ((sqrt(u^2 + v^2) - R)^2 + w^2) / r^2, with (u, v, w) the point
// in the tool's frame. k > 0 pulls material out, k < 0 pushes it in.
struct Perturbation {
    QuadricShape shape = QuadricShape::Ellipsoid;
    ModelPoint center{};
    std::array<ModelPoint, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // orthonormal: u, v, w
    ModelPoint radii{0.1, 0.1, 0.1};  // ellipsoid: r_u, r_v, r_w; torus: R, r, (unused)
    double strength = 2.0;            // k, voxels
    std::optional<MirrorPlane> mirror;  // a second quadric, reflected: piece 1
};
// The reflected quadric of a mirrored perturbation.
Perturbation mirrored(const Perturbation& p);

enum class ImpactShape { Sphere, Chisel, Square };
const char* impactShapeName(ImpactShape s);

// One impact (seed 002): a small tool pushed into the surface along a ray,
// as deep as removes the compaction volume; its field is the tool's solid,
// subtracted like a carve (min(f, -G)). Resolved against the grid when it
// was made, so a journal replays it exactly.
struct Impact {
    ImpactShape shape = ImpactShape::Sphere;
    ModelPoint tip{};             // the tool's deepest point
    ModelPoint direction{0, 0, -1};  // unit, into the material
    ModelPoint across{1, 0, 0};   // unit, normal to direction: the chisel's width, the square's side
    double size = 0.02;           // sphere radius, chisel edge length, square side (model units)
    double depth = 0.0;           // how far below the surface the tip went (model units)
    frep::Box3 reach;             // outside it G == -band exactly
};

// The impacts of one trigger pull: one edit, undone as one.
struct ImpactSeries {
    std::vector<Impact> impacts;
    // The series as fired, to fire again at another sculpture: each ray's
    // origin as fractions of the model box, its direction, and the tool's
    // compaction volume (cubic model units).
    std::vector<ModelPoint> rayOrigins, rayDirections;
    double volume = 0.0;
};

enum class SketchMode { Add, Cut };
const char* sketchModeName(SketchMode m);

// A sketched outline inflated to a solid (seed 003; garden/sketch,
// docs/sketching.md) and joined to the sculpture (max(f, G)) or cut from
// it (min(f, -G)), G the solid's field in voxels clamped to [-band, band]:
// the union of its cone pieces along the outline's chordal axis, each
// about the distance into it. What the user drew is kept (the outline and
// its plane's normal, model frame); the rest is derived from it
// (resolveSketch, garden/sculpt/sketch_edit.h), so a journal replays it.
struct SketchSolid {
    SketchMode mode = SketchMode::Add;
    std::vector<ModelPoint> outline;   // as drawn: points on or near the plane
    ModelPoint normal{0.0, 0.0, 1.0};  // the plane's normal
    double thickness = 1.0;            // half-thickness across the plane over the half-width in it
    std::optional<MirrorPlane> mirror;  // the solid also on the reflected plane: pieces n..2n-1
    // Derived: the inflated solid (pieces in plane coordinates, model
    // units), the reflected plane, each piece's reach.
    sketch::InflatedSolid solid;
    std::optional<sketch::SketchPlane> mirroredPlane;
    std::vector<frep::Box3> reach;
};

using EditOp = std::variant<Stroke, Perturbation, ImpactSeries, SketchSolid>;

// A selection made with the deformable model (issue 22, docs/sketching.md
// "Selections"): a union of balls, model frame. An edit made while it is
// on acts only inside it: its tool's field G is limited to min(G, M), M
// the largest r - |p - c| over the balls in voxels, so the tool acts on
// the intersection of tool and selection (garden/sculpt/edit_field.h).
// Written into the edit, so undo, rebuilds and the export see the mask
// the edit was made with.
struct MaskBall {
    ModelPoint centre{0.0, 0.0, 0.0};
    double radius = 0.0;
};
struct SelectionMask {
    std::vector<MaskBall> balls;
    frep::Box3 box;  // the balls' hull grown by the edit's floor: beyond it the edit does nothing
};
// The hull of `balls` grown by `margin`.
frep::Box3 maskBox(const std::vector<MaskBall>& balls, double margin);

struct Edit {
    std::uint64_t id = 0;  // unique in the sculpture, in creation order
    EditOp op;
    frep::Box3 reach;      // the field changes only inside this box
    std::optional<SelectionMask> mask;  // acts only inside the selection
};

// The constants every edit expression of one sculpture shares: they come
// from its grid (edits are made in voxel units).
struct FieldUnits {
    double voxelSize = 0.01;  // model units
    double band = 3.0;        // the stored field's clamp, voxels
};

std::string describe(const Edit& e);

}  // namespace hg::garden
