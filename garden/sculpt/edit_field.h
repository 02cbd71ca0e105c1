// The one expression builder of the edit list (docs/design.md §4): each edit as an
// FRep operation on the field before it, written once as a template over
// the value type. On frep::Sym it records the grid update's tape (the base
// field is the tape's W input); on double it is the reference the tests
// compare against (the same operations the HyperFun interpreter runs for
// the exported text: min and max are HyperFun's built-ins, hfConvLine's
// segment field the library's own template).
//
// Why each edit leaves the field exactly unchanged outside its reach: the
// field is kept in [-band, band]; a tool's field G is clamped to a floor
// that it reaches beyond the reach box, where the operation returns its
// input: min(f, -floor) = f for carve, max(f, floor) = f for add, the
// rounded minimum's blend term is exactly zero for melt (its floor is
// band + softness below), max(Q, 0) = 0 for a perturbation, and the
// falloff weight is exactly 0 beyond a smooth or inflate stroke's radius.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "frep/language/hf_math.h"
#include "frep/kernels/library/convolution.h"
#include "frep/compiler/sym.h"
#include "garden/sculpt/edit.h"

namespace hg::garden {

namespace editops {

inline double vmin(double a, double b) { return frep::hf::minimum(a, b); }
inline double vmax(double a, double b) { return frep::hf::maximum(a, b); }
inline frep::Sym vmin(const frep::Sym& a, const frep::Sym& b) { return frep::symOp(frep::Op::Min, a, b); }
inline frep::Sym vmax(const frep::Sym& a, const frep::Sym& b) { return frep::symOp(frep::Op::Max, a, b); }
inline double vabs(double a) { return std::fabs(a); }
inline frep::Sym vabs(const frep::Sym& a) { return frep::fabs(a); }
inline double vsqrt(double a) { return std::sqrt(a); }
inline frep::Sym vsqrt(const frep::Sym& a) { return frep::sqrt(a); }

template <class V>
V clamp(const V& v, double lo, double hi) { return vmax(vmin(v, V(hi)), V(lo)); }

}  // namespace editops

// A selection limits a tool to its inside (garden/sculpt/edit.h,
// SelectionMask): the tool's field G becomes min(G, M), M the mask's field
// in voxels clamped like G to [floor, band], the intersection of tool and
// selection. Where M is at its floor, min(G, M) is too and the edit leaves
// f exactly as it was, as beyond any tool's reach; and since each piece's
// G is limited alone, a stroke extended piece by piece still equals its
// rebuild (min and max chains, in the same order).
template <class V>
std::optional<V> limitOf(const V* mask, double floor, double band) {
    if (!mask) return std::nullopt;
    return editops::clamp<V>(*mask, floor, band);
}
template <class V>
V limited(const V& g, const std::optional<V>& m) {
    return m ? editops::vmin(g, *m) : g;
}

// The floor a stroke's tool field is clamped to, voxels.
inline double strokeFloor(const Stroke& s, const FieldUnits& u) {
    return s.tool == StrokeTool::Melt ? -(u.band + s.softness) : -u.band;
}

// One segment's tool field G at (x, y, z), voxels.
template <class V>
V segmentField(const V& x, const V& y, const V& z, const StrokeSegment& g, double floor, double band) {
    using frep::lib::detail::convSegment;
    const V conv = convSegment<V>(x, y, z, V(g.begin[0]), V(g.begin[1]), V(g.begin[2]), V(g.end[0]),
                                  V(g.end[1]), V(g.end[2]), V(g.s));
    return editops::clamp<V>(V(g.scale) * (conv - V(g.t)), floor, band);
}

// A smooth or inflate segment's weight at (x, y, z): w = max(1 - d^2 / r^2,
// 0), d the distance to the segment, shaped by the falloff curve; every
// curve is exactly 0 where w is (beyond the radius), so the stroke leaves
// the field exactly as it was outside its segments' capsules.
template <class V>
V segmentWeight(const V& x, const V& y, const V& z, const StrokeSegment& g, double radius, Falloff falloff,
                const FieldUnits& u) {
    using namespace editops;
    const double ax = g.end[0] - g.begin[0], ay = g.end[1] - g.begin[1], az = g.end[2] - g.begin[2];
    const double l2 = ax * ax + ay * ay + az * az;
    const V px = x - V(g.begin[0]), py = y - V(g.begin[1]), pz = z - V(g.begin[2]);
    const V t = l2 > 0.0 ? clamp<V>((px * V(ax) + py * V(ay) + pz * V(az)) * V(1.0 / l2), 0.0, 1.0) : V(0.0);
    const V ex = px - t * V(ax), ey = py - t * V(ay), ez = pz - t * V(az);
    const V w = vmax(V(1.0) - (ex * ex + ey * ey + ez * ez) * V(1.0 / (radius * radius)), V(0.0));
    switch (falloff) {
        case Falloff::Smooth: return w * w * (V(3.0) - V(2.0) * w);
        case Falloff::Linear: return w;
        case Falloff::Sharp: return w * w * w;
        case Falloff::Constant:
            // Near the edge w is about 2 (r - d) / r: full weight from one
            // voxel inside the radius.
            return vmin(w * V(radius / (2.0 * u.voxelSize)), V(1.0));
    }
    return w;
}

// Q of a smooth segment's fitted quadric at (x, y, z), voxels.
template <class V>
V fitValue(const V& x, const V& y, const V& z, const SegmentFit& q) {
    const double inv = 1.0 / q.scale;
    const V a = (x - V(q.centre[0])) * V(inv), b = (y - V(q.centre[1])) * V(inv), c = (z - V(q.centre[2])) * V(inv);
    const auto& k = q.c;
    return V(k[0]) + a * V(k[1]) + b * V(k[2]) + c * V(k[3]) + a * a * V(k[4]) + b * b * V(k[5]) + c * c * V(k[6]) +
           a * b * V(k[7]) + b * c * V(k[8]) + a * c * V(k[9]);
}

// Inflate: f + strength * W, W the largest weight over the listed segments,
// clamped to the band. A segment left out (not reaching where the caller
// evaluates) has weight exactly 0 there and would not change the maximum.
template <class V>
V applyInflate(const V& f, const V& x, const V& y, const V& z, const Stroke& s,
               const std::vector<std::uint32_t>& segments, const FieldUnits& u, const V* mask) {
    using namespace editops;
    if (segments.empty()) return f;
    std::optional<V> w;
    for (std::uint32_t i : segments) {
        const V wi = segmentWeight(x, y, z, s.segments[i], s.radius, s.falloff, u);
        w = w ? vmax(*w, wi) : wi;
    }
    if (mask) w = *w * clamp<V>(*mask + V(0.5), 0.0, 1.0);
    return clamp<V>(f + V(s.strength) * *w, -u.band, u.band);
}

// Smooth: segment by segment, f <- f + strength * w_i * g(f) * (clamp(Q_i)
// - f), a convex blend of two values in [-band, band] (so it stays there),
// g(f) = clamp(band - |f|, 0, 1) a gate that keeps clamped field (far air,
// deep inside) exactly as it is: the quadric's extrapolation cannot make a
// surface in the air. A segment without a fit, or out of its capsule
// (w_i == 0), leaves f exactly as it was.
template <class V>
V applySmooth(const V& f, const V& x, const V& y, const V& z, const Stroke& s,
              const std::vector<std::uint32_t>& segments, const FieldUnits& u, const V* mask) {
    using namespace editops;
    std::optional<V> m;
    if (mask) m = clamp<V>(*mask + V(0.5), 0.0, 1.0);
    V out = f;
    bool changed = false;
    for (std::uint32_t i : segments) {
        if (i >= s.fits.size() || !s.fits[i]) continue;
        V w = segmentWeight(x, y, z, s.segments[i], s.radius, s.falloff, u) * V(s.strength);
        if (m) w = w * *m;
        const V gate = clamp<V>(V(u.band) - vabs(out), 0.0, 1.0);
        const V target = clamp<V>(fitValue(x, y, z, *s.fits[i]), -u.band, u.band);
        out = out + w * gate * (target - out);
        changed = true;
    }
    return changed ? clamp<V>(out, -u.band, u.band) : out;
}

// The field after a stroke, given the field f before it; only the segments
// whose indices are listed take part (the others leave f unchanged where
// the caller evaluates: outside their reach).
template <class V>
V applyStroke(const V& f, const V& x, const V& y, const V& z, const Stroke& s, const std::vector<std::uint32_t>& segments,
              const FieldUnits& u, const V* mask = nullptr) {
    using namespace editops;
    const double floor = strokeFloor(s, u);
    const std::optional<V> m = limitOf(mask, floor, u.band);
    V out = f;
    switch (s.tool) {
        case StrokeTool::Carve:
            for (std::uint32_t i : segments) out = vmin(out, -limited(segmentField(x, y, z, s.segments[i], floor, u.band), m));
            return out;
        case StrokeTool::Add:
            for (std::uint32_t i : segments) out = vmax(out, limited(segmentField(x, y, z, s.segments[i], floor, u.band), m));
            return out;
        case StrokeTool::Melt: {
            // min(f, -G) - k/6 h^3, h = max(k - |f + G|, 0) / k: the polynomial
            // smooth minimum, exactly min(f, -G) where |f + G| >= k.
            V g = V(floor);
            for (std::uint32_t i : segments) g = vmax(g, limited(segmentField(x, y, z, s.segments[i], floor, u.band), m));
            const double k = s.softness;
            const V h = vmax(V(k) - vabs(f + g), V(0.0)) / V(k);
            return vmax(vmin(f, -g) - V(k / 6.0) * (h * h * h), V(-u.band));
        }
        case StrokeTool::Inflate: return applyInflate(f, x, y, z, s, segments, u, mask);
        case StrokeTool::Smooth: return applySmooth(f, x, y, z, s, segments, u, mask);
    }
    return out;
}

// An impact tool's field at (x, y, z), voxels, clamped to [-band, band]:
// about the distance into the tool's solid (a ball; a V-shaped chisel, its
// edge at the tip across `across`, opening back along the ray at 45
// degrees; a square punch of side `size`, as deep as it is wide).
template <class V>
V impactField(const V& x, const V& y, const V& z, const Impact& m, const FieldUnits& u) {
    using namespace editops;
    const V dx = x - V(m.tip[0]), dy = y - V(m.tip[1]), dz = z - V(m.tip[2]);
    const double inv = 1.0 / u.voxelSize;
    if (m.shape == ImpactShape::Sphere) {
        // The ball's centre is one radius back from the tip.
        const double r = m.size;
        const V cx = dx + V(r * m.direction[0]), cy = dy + V(r * m.direction[1]), cz = dz + V(r * m.direction[2]);
        return clamp<V>((V(r) - vsqrt(cx * cx + cy * cy + cz * cz)) * V(inv), -u.band, u.band);
    }
    const ModelPoint& d = m.direction;
    const ModelPoint& a = m.across;
    const ModelPoint b{d[1] * a[2] - d[2] * a[1], d[2] * a[0] - d[0] * a[2], d[0] * a[1] - d[1] * a[0]};
    const V back = -(dx * V(d[0]) + dy * V(d[1]) + dz * V(d[2]));  // >= 0 behind the tip
    const V w = dx * V(a[0]) + dy * V(a[1]) + dz * V(a[2]);
    const V l = dx * V(b[0]) + dy * V(b[1]) + dz * V(b[2]);
    const double half = 0.5 * m.size;
    V g;
    if (m.shape == ImpactShape::Chisel) {
        // Inside: back >= |l| (the V's faces at 45 degrees), |w| <= half
        // (its edge's length), back <= size (its height).
        const double s = 0.7071067811865476;
        g = vmin(vmin((back - vabs(l)) * V(s), V(half) - vabs(w)), V(m.size) - back);
    } else {
        g = vmin(vmin(V(half) - vabs(w), V(half) - vabs(l)), vmin(back, V(m.size) - back));
    }
    return clamp<V>(g * V(inv), -u.band, u.band);
}

// The listed impacts of a series subtracted, in order.
template <class V>
V applyImpacts(const V& f, const V& x, const V& y, const V& z, const ImpactSeries& s,
               const std::vector<std::uint32_t>& pieces, const FieldUnits& u, const V* mask = nullptr) {
    const std::optional<V> m = limitOf(mask, -u.band, u.band);
    V out = f;
    for (std::uint32_t i : pieces) out = editops::vmin(out, -limited(impactField(x, y, z, s.impacts[i], u), m));
    return out;
}

// Q of a perturbation's quadric at (x, y, z): >= 0 inside.
template <class V>
V quadric(const V& x, const V& y, const V& z, const Perturbation& p) {
    const V dx = x - V(p.center[0]), dy = y - V(p.center[1]), dz = z - V(p.center[2]);
    const auto& a = p.axes;
    const V u = dx * V(a[0][0]) + dy * V(a[0][1]) + dz * V(a[0][2]);
    const V v = dx * V(a[1][0]) + dy * V(a[1][1]) + dz * V(a[1][2]);
    const V w = dx * V(a[2][0]) + dy * V(a[2][1]) + dz * V(a[2][2]);
    if (p.shape == QuadricShape::Ellipsoid) {
        const V su = u / V(p.radii[0]), sv = v / V(p.radii[1]), sw = w / V(p.radii[2]);
        return V(1.0) - su * su - sv * sv - sw * sw;
    }
    const V ring = editops::vsqrt(u * u + v * v) - V(p.radii[0]);
    return V(1.0) - (ring * ring + w * w) / V(p.radii[1] * p.radii[1]);
}

// The listed pieces of a perturbation (0: its quadric, 1: the mirrored
// one), their terms added in order, then the field clamped.
// Under a selection the quadric's term fades with the mask's weight w (1
// half a voxel inside, 0 half a voxel outside): q w, cubed.
template <class V>
V applyPerturbation(const V& f, const V& x, const V& y, const V& z, const Perturbation& p,
                    const std::vector<std::uint32_t>& pieces, const FieldUnits& u, const V* mask = nullptr) {
    std::optional<V> w;
    if (mask) w = editops::clamp<V>(*mask + V(0.5), 0.0, 1.0);
    V out = f;
    for (std::uint32_t piece : pieces) {
        V q = editops::vmax(quadric(x, y, z, piece == 0 ? p : mirrored(p)), V(0.0));
        if (w) q = q * *w;
        out = out + V(p.strength) * (q * q * q);
    }
    return editops::clamp<V>(out, -u.band, u.band);
}

// One cone piece of a sketch's solid at plane coordinates (u, v) and the
// squared, thickness-scaled normal coordinate ww: r(t) - |p - q(t)|, model
// units (garden/sketch/inflation.h).
template <class V>
V sketchPieceField(const V& u, const V& v, const V& ww, const sketch::ConePiece& c) {
    using namespace editops;
    const double dx = c.b.x - c.a.x, dy = c.b.y - c.a.y, l2 = dx * dx + dy * dy;
    const V eu = u - V(c.a.x), ev = v - V(c.a.y);
    if (!(l2 > 0.0)) return V(c.ra) - vsqrt(eu * eu + ev * ev + ww);
    const V t = clamp<V>((eu * V(dx) + ev * V(dy)) * V(1.0 / l2), 0.0, 1.0);
    const V ex = eu - t * V(dx), ey = ev - t * V(dy);
    return V(c.ra) + t * V(c.rb - c.ra) - vsqrt(ex * ex + ey * ey + ww);
}

// The field after a sketch's listed pieces (0..n-1 on its plane, n..2n-1 on
// the mirrored one) joined (add) or cut: the tool field G is the max of
// the pieces' fields in voxels, each clamped to [-band, band], so a piece
// is exactly -band (and leaves f unchanged) outside its reach.
template <class V>
V applySketch(const V& f, const V& x, const V& y, const V& z, const SketchSolid& s,
              const std::vector<std::uint32_t>& pieces, const FieldUnits& u, const V* mask = nullptr) {
    using namespace editops;
    if (pieces.empty()) return f;
    const std::optional<V> m = limitOf(mask, -u.band, u.band);
    const std::size_t n = s.solid.pieces.size();
    const double inv = 1.0 / u.voxelSize, across = 1.0 / s.solid.thickness;
    // Plane coordinates, computed once per plane that a listed piece is on.
    struct Coordinates {
        V u, v, ww;
    };
    const auto onPlane = [&](const sketch::SketchPlane& p) {
        const V px = x - V(p.origin.x), py = y - V(p.origin.y), pz = z - V(p.origin.z);
        const V w = (px * V(p.normal.x) + py * V(p.normal.y) + pz * V(p.normal.z)) * V(across);
        return Coordinates{px * V(p.u.x) + py * V(p.u.y) + pz * V(p.u.z), px * V(p.v.x) + py * V(p.v.y) + pz * V(p.v.z),
                           w * w};
    };
    std::optional<Coordinates> own, reflected;
    std::optional<V> g;
    for (std::uint32_t i : pieces) {
        const bool mirrored = i >= n;
        std::optional<Coordinates>& c = mirrored ? reflected : own;
        if (!c) c = onPlane(mirrored ? *s.mirroredPlane : s.solid.plane);
        const V piece = clamp<V>(sketchPieceField(c->u, c->v, c->ww, s.solid.pieces[mirrored ? i - n : i]) * V(inv),
                                 -u.band, u.band);
        g = g ? vmax(*g, piece) : piece;
    }
    const V tool = limited(*g, m);
    return s.mode == SketchMode::Add ? vmax(f, tool) : vmin(f, -tool);
}

// The weight of an edit under a selection mask at (x, y, z): 1 at least
// half a voxel inside the balls, 0 at least half a voxel outside, linear
// between (M, the largest r - |p - c| in voxels, plus one half, clamped).
// The mask's balls' field: the largest r - |p - c| over the balls, in
// list order, voxels (unclamped); -band with no balls.
template <class V>
V maskVoxels(const V& x, const V& y, const V& z, const SelectionMask& mask, const FieldUnits& u) {
    using namespace editops;
    std::optional<V> m;
    for (const MaskBall& b : mask.balls) {
        const V dx = x - V(b.centre[0]), dy = y - V(b.centre[1]), dz = z - V(b.centre[2]);
        const V ball = V(b.radius) - vsqrt(dx * dx + dy * dy + dz * dz);
        m = m ? vmax(*m, ball) : ball;
    }
    return m ? *m * V(1.0 / u.voxelSize) : V(-u.band);
}
// Whether an edit under the mask acts at (x, y, z) at all: its tools'
// fields are limited to M (carve, add, melt, impacts, sketches), a
// perturbation's term fades to 0 half a voxel outside.
template <class V>
V maskWeight(const V& x, const V& y, const V& z, const SelectionMask& mask, const FieldUnits& u) {
    return editops::clamp<V>(maskVoxels(x, y, z, mask, u) + V(0.5), 0.0, 1.0);
}
// The part of a field inside the mask (an extracted part, in voxels):
// min(f, M) with M clamped to the band like every stored field.
template <class V>
V insideMask(const V& f, const V& x, const V& y, const V& z, const SelectionMask& mask, const FieldUnits& u) {
    return editops::vmin(f, editops::clamp<V>(maskVoxels(x, y, z, mask, u), -u.band, u.band));
}
// Any edit's listed pieces applied to the field before it: the one
// dispatch of the grid's tape, the double reference and the export.
template <class V>
V applyEdit(const V& f, const V& x, const V& y, const V& z, const Edit& e, const std::vector<std::uint32_t>& pieces,
            const FieldUnits& u) {
    std::optional<V> m;
    if (e.mask && !pieces.empty()) m = maskVoxels(x, y, z, *e.mask, u);
    const V* mask = m ? &*m : nullptr;
    if (const auto* s = std::get_if<Stroke>(&e.op)) return applyStroke(f, x, y, z, *s, pieces, u, mask);
    if (const auto* i = std::get_if<ImpactSeries>(&e.op)) return applyImpacts(f, x, y, z, *i, pieces, u, mask);
    if (const auto* k = std::get_if<SketchSolid>(&e.op)) return applySketch(f, x, y, z, *k, pieces, u, mask);
    return applyPerturbation(f, x, y, z, std::get<Perturbation>(e.op), pieces, u, mask);
}

}  // namespace hg::garden
