#include "garden/sculpt/sketch_edit.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "garden/sketch/outline.h"

namespace hg::garden {

namespace {

sketch::Vec3 vec3(const ModelPoint& p) { return {p[0], p[1], p[2]}; }

// The box outside which a piece's field is below -band voxels: the piece is
// inside the hull of its end balls (radius linear along it), stretched by
// `thickness` across the plane; grown by the band.
frep::Box3 pieceReach(const sketch::ConePiece& c, const sketch::SketchPlane& plane, double thickness, double margin) {
    frep::Box3 b;
    const double stretch = std::max(1.0, thickness);
    for (int end = 0; end < 2; ++end) {
        const sketch::Vec3 centre = plane.toWorld(end == 0 ? c.a : c.b);
        const double half = ((end == 0 ? c.ra : c.rb) + margin) * stretch * 1.001 + 1e-9;
        for (int i = 0; i < 3; ++i) {
            const double lo = centre[i] - half, hi = centre[i] + half;
            b.lo[i] = end == 0 ? lo : std::min(b.lo[i], lo);
            b.hi[i] = end == 0 ? hi : std::max(b.hi[i], hi);
        }
    }
    return b;
}

}  // namespace

std::string resolveSketch(SketchSolid& s, const FieldUnits& u) {
    if (s.outline.size() < 3) return "a sketch needs at least 3 points";
    for (const ModelPoint& p : s.outline)
        if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
            return "a sketch's point is not a finite position";
    const sketch::Vec3 n = vec3(s.normal);
    const double normalLength = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(normalLength > 0.0) || !std::isfinite(normalLength)) return "the sketch's plane has no normal";
    if (!(s.thickness >= 0.05 && s.thickness <= 20.0)) return "the sketch's thickness must be in [0.05, 20]";
    // The plane through the outline's centroid: every point is taken onto it.
    sketch::Vec3 centroid(0.0);
    for (const ModelPoint& p : s.outline) centroid += vec3(p);
    centroid /= static_cast<double>(s.outline.size());
    const sketch::SketchPlane plane = sketch::planeFacing(centroid, n);
    std::vector<sketch::Vec2> drawn;
    for (const ModelPoint& p : s.outline) {
        const sketch::Vec3 d = vec3(p) - plane.origin;
        drawn.emplace_back(d.x * plane.u.x + d.y * plane.u.y + d.z * plane.u.z,
                           d.x * plane.v.x + d.y * plane.v.y + d.z * plane.v.z);
    }
    // kSketchSamples along the drawn loop, but no closer than half a voxel:
    // finer detail would not show in the grid, and would only cost pieces.
    double length = 0.0;
    for (std::size_t i = 0; i < drawn.size(); ++i) length += glm::length(drawn[(i + 1) % drawn.size()] - drawn[i]);
    sketch::OutlineOptions options;
    options.spacing = std::max(length / kSketchSamples, 0.5 * u.voxelSize);
    const sketch::Outline outline = sketch::makeOutline(drawn, options);
    if (!outline.ok()) return outline.error;
    sketch::InflationOptions inflation;
    inflation.thickness = s.thickness;
    const sketch::Inflation made = sketch::inflate(outline.points, outline.spacing, plane, inflation);
    if (!made.ok()) return made.error;
    s.solid = made.solid;
    s.mirroredPlane.reset();
    if (s.mirror) {
        sketch::SketchPlane m;
        m.origin = vec3(reflect(*s.mirror, {plane.origin.x, plane.origin.y, plane.origin.z}));
        m.u = vec3(reflectDirection(*s.mirror, {plane.u.x, plane.u.y, plane.u.z}));
        m.v = vec3(reflectDirection(*s.mirror, {plane.v.x, plane.v.y, plane.v.z}));
        m.normal = vec3(reflectDirection(*s.mirror, {plane.normal.x, plane.normal.y, plane.normal.z}));
        s.mirroredPlane = m;
    }
    const double margin = u.band * u.voxelSize;
    s.reach.clear();
    for (const sketch::ConePiece& c : s.solid.pieces) s.reach.push_back(pieceReach(c, plane, s.thickness, margin));
    if (s.mirroredPlane)
        for (const sketch::ConePiece& c : s.solid.pieces)
            s.reach.push_back(pieceReach(c, *s.mirroredPlane, s.thickness, margin));
    return "";
}

}  // namespace hg::garden
