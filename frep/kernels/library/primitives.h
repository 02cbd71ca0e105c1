// Library primitives: sphere, ellipsoid, block, cylinders, elliptic
// cylinders, tori, cones, elliptic cones and the superellipsoid.
//
// Every routine is a template over the value type V (see library.h for the
// rules) and repeats the reference's floating-point operations in the same
// order and grouping. This header also holds the small helpers shared by the
// other routine headers (namespace detail).
#pragma once

#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

namespace detail {

// EPS of the reference interpreter (0.1e-5): the degeneracy threshold of
// the library routines.
constexpr double kEps = 1e-6;

// True when the point array has the three items the reference requires.
template <class V>
bool isPoint(const std::vector<V>& x) {
    return x.size() == 3;
}

// True when `a` has at least n items. The reference reads parameter arrays
// without checking their sizes; where it would read past the end we return
// the sentinel instead.
template <class V>
bool hasItems(const std::vector<V>& a, size_t n) {
    return a.size() >= n;
}

// select(cond, kSentinel, f): the reference returns the sentinel when a
// size parameter is degenerate.
template <class V>
V sentinelIf(const V& cond, const V& f) {
    return select(cond, V(kSentinel), f);
}

// |v| < EPS as 1/0.
template <class V>
V nearZero(const V& v) {
    return lt(fabs(v), V(kEps));
}

}  // namespace detail

// hfSphere(x, center, R): R^2 - |x - center|^2.
//   x: point (3 items); center: centre (3 items); R: radius.
template <class V>
V hfSphere(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = x[1] - center[1];
    V zt = x[2] - center[2];
    return r * r - xt * xt - yt * yt - zt * zt;
}

// hfEllipsoid(x, center, a, b, c): 1 - ((x-x0)/a)^2 - ((y-y0)/b)^2 - ((z-z0)/c)^2.
//   a, b, c: semi-axes along x, y, z; the sentinel when one is below EPS.
template <class V>
V hfEllipsoid(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b,
              const V& c) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V bad = lor(lor(detail::nearZero(a), detail::nearZero(b)), detail::nearZero(c));
    V xt = (x[0] - center[0]) / a;
    V yt = (x[1] - center[1]) / b;
    V zt = (x[2] - center[2]) / c;
    V f = 1.0 - xt * xt - yt * yt - zt * zt;
    return detail::sentinelIf(bad, f);
}

// hfTorusX/Y/Z(x, center, R, r0): torus around the axis through center:
// r0^2 - |p|^2 - R^2 + 2R*sqrt(planar^2), with p = x - center and planar the
// two components across the axis.
//   R: radius of revolution; r0: radius of the tube.
template <class V>
V hfTorusX(const std::vector<V>& x, const std::vector<V>& center, const V& bigR, const V& r0) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = x[1] - center[1];
    V zt = x[2] - center[2];
    V z2 = zt * zt;
    V y2 = yt * yt;
    return r0 * r0 - xt * xt - y2 - z2 - bigR * bigR + 2.0 * bigR * sqrt(z2 + y2);
}

template <class V>
V hfTorusY(const std::vector<V>& x, const std::vector<V>& center, const V& bigR, const V& r0) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = x[1] - center[1];
    V zt = x[2] - center[2];
    V z2 = zt * zt;
    V x2 = xt * xt;
    return r0 * r0 - x2 - yt * yt - z2 - bigR * bigR + 2.0 * bigR * sqrt(z2 + x2);
}

template <class V>
V hfTorusZ(const std::vector<V>& x, const std::vector<V>& center, const V& bigR, const V& r0) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = x[1] - center[1];
    V zt = x[2] - center[2];
    V x2 = xt * xt;
    V y2 = yt * yt;
    return r0 * r0 - x2 - y2 - zt * zt - bigR * bigR + 2.0 * bigR * sqrt(x2 + y2);
}

// hfEllCylX/Y/Z(x, center, a, b): elliptic cylinder along the axis,
// 1 - (u/a)^2 - (v/b)^2 where (u, v) are the two other components of
// x - center in the order (y, z), (x, z), (x, y).
//   a, b: semi-axes; the sentinel when one is below EPS.
template <class V>
V hfEllCylX(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V bad = lor(detail::nearZero(a), detail::nearZero(b));
    V yt = (x[1] - center[1]) / a;
    V zt = (x[2] - center[2]) / b;
    V f = 1.0 - yt * yt - zt * zt;
    return detail::sentinelIf(bad, f);
}

template <class V>
V hfEllCylY(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V bad = lor(detail::nearZero(a), detail::nearZero(b));
    V xt = (x[0] - center[0]) / a;
    V zt = (x[2] - center[2]) / b;
    V f = 1.0 - xt * xt - zt * zt;
    return detail::sentinelIf(bad, f);
}

template <class V>
V hfEllCylZ(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V bad = lor(detail::nearZero(a), detail::nearZero(b));
    V xt = (x[0] - center[0]) / a;
    V yt = (x[1] - center[1]) / b;
    V f = 1.0 - xt * xt - yt * yt;
    return detail::sentinelIf(bad, f);
}

// hfCylinderX/Y/Z(x, center, R): circular cylinder along the axis,
// R^2 - u^2 - v^2 with (u, v) as for the elliptic cylinders.
template <class V>
V hfCylinderX(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V yt = x[1] - center[1];
    V zt = x[2] - center[2];
    return r * r - yt * yt - zt * zt;
}

template <class V>
V hfCylinderY(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V zt = x[2] - center[2];
    return r * r - xt * xt - zt * zt;
}

template <class V>
V hfCylinderZ(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = x[1] - center[1];
    return r * r - xt * xt - yt * yt;
}

// hfBlock(x, vertex, dx, dy, dz): axis-aligned box [vertex, vertex + d].
// Each axis gives a slab (x - v)(v + d - x); the three slabs are combined
// with the alpha-0 R-intersection f & g = f + g - sqrt(f^2 + g^2) (the
// reference's 2*ALPHA*f*g term is 0 and is left out).
//   dx, dy, dz: edge lengths; the sentinel when one is negative.
template <class V>
V hfBlock(const std::vector<V>& x, const std::vector<V>& vertex, const V& dx, const V& dy,
          const V& dz) {
    if (!detail::isPoint(x) || !detail::hasItems(vertex, 3)) return V(kSentinel);
    V bad = lor(lor(lt(dx, V(0.0)), lt(dy, V(0.0))), lt(dz, V(0.0)));
    V xt = (x[0] - vertex[0]) * (vertex[0] + dx - x[0]);
    V yt = (x[1] - vertex[1]) * (vertex[1] + dy - x[1]);
    V zt = (x[2] - vertex[2]) * (vertex[2] + dz - x[2]);
    V f = xt + yt - sqrt(xt * xt + yt * yt);
    f = f + zt - sqrt(f * f + zt * zt);
    return detail::sentinelIf(bad, f);
}

// hfConeX/Y/Z(x, center, R): double cone with apex at center along the
// axis: axial^2 - (u/R)^2 - (v/R)^2.
//   R: radius at distance 1 from the apex (no check for R = 0).
template <class V>
V hfConeX(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = (x[1] - center[1]) / r;
    V zt = (x[2] - center[2]) / r;
    return xt * xt - yt * yt - zt * zt;
}

template <class V>
V hfConeY(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = (x[0] - center[0]) / r;
    V yt = x[1] - center[1];
    V zt = (x[2] - center[2]) / r;
    return yt * yt - xt * xt - zt * zt;
}

template <class V>
V hfConeZ(const std::vector<V>& x, const std::vector<V>& center, const V& r) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = (x[0] - center[0]) / r;
    V yt = (x[1] - center[1]) / r;
    V zt = x[2] - center[2];
    return zt * zt - xt * xt - yt * yt;
}

// hfEllConeX/Y/Z(x, center, a, b): elliptic double cone along the axis:
// axial^2 - (u/a)^2 - (v/b)^2.
//   a, b: semi-axes at distance 1 from the apex (no check for 0).
template <class V>
V hfEllConeX(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = x[0] - center[0];
    V yt = (x[1] - center[1]) / a;
    V zt = (x[2] - center[2]) / b;
    return xt * xt - yt * yt - zt * zt;
}

template <class V>
V hfEllConeY(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = (x[0] - center[0]) / a;
    V yt = x[1] - center[1];
    V zt = (x[2] - center[2]) / b;
    return yt * yt - xt * xt - zt * zt;
}

template <class V>
V hfEllConeZ(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V xt = (x[0] - center[0]) / a;
    V yt = (x[1] - center[1]) / b;
    V zt = x[2] - center[2];
    return zt * zt - xt * xt - yt * yt;
}

// hfSuperell(x, center, a, b, c, s1, s2): superellipsoid
// 1 - (|u|^(2/s2) + |v|^(2/s2))^(s2/s1) - |w|^(2/s1), with u, v, w the
// components of x - center divided by a, b, c.
//   a, b, c: semi-axes; s1: shape exponent along z; s2: in the xy plane.
//   The sentinel when any of a, b, c, s1, s2 is below EPS in magnitude.
template <class V>
V hfSuperell(const std::vector<V>& x, const std::vector<V>& center, const V& a, const V& b,
             const V& c, const V& s1, const V& s2) {
    if (!detail::isPoint(x) || !detail::hasItems(center, 3)) return V(kSentinel);
    V bad = lor(lor(lor(lor(detail::nearZero(a), detail::nearZero(b)), detail::nearZero(c)),
                    detail::nearZero(s1)),
                detail::nearZero(s2));
    V xt = (x[0] - center[0]) / a;
    V yt = (x[1] - center[1]) / b;
    V zt = (x[2] - center[2]) / c;
    V p = 2.0 / s2;
    V xp = pow(fabs(xt), p);
    V yp = pow(fabs(yt), p);
    V zp = pow(fabs(zt), 2.0 / s1);
    V xyp = pow(xp + yp, s2 / s1);
    V f = 1.0 - xyp - zp;
    return detail::sentinelIf(bad, f);
}

}  // namespace hg::frep::lib
