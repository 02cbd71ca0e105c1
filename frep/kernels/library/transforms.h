// Space transformations. Each routine rewrites the point array it is given
// (the inverse mapping of the deformation, so that a primitive sampled at the
// rewritten point appears deformed) and returns 1, as the reference does.
//
// The reference reads and writes the first three items without checking the
// array's size; when the array has fewer than three items (where the
// reference would run past it) these routines leave it alone and return the
// sentinel.
#pragma once

#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/primitives.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

// hfScale3D(xt, sx, sy, sz): xt <- (x/sx, y/sy, z/sz). No check for zero
// factors (the reference's check is not applied).
template <class V>
V hfScale3D(std::vector<V>& xt, const V& sx, const V& sy, const V& sz) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    xt[0] = xt[0] / sx;
    xt[1] = xt[1] / sy;
    xt[2] = xt[2] / sz;
    return V(1.0);
}

// hfShift3D(xt, dx, dy, dz): xt <- xt - (dx, dy, dz), i.e. the shape moves by d.
template <class V>
V hfShift3D(std::vector<V>& xt, const V& dx, const V& dy, const V& dz) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    xt[0] = xt[0] - dx;
    xt[1] = xt[1] - dy;
    xt[2] = xt[2] - dz;
    return V(1.0);
}

// hfRotate3DZ(xt, theta): rotate the shape by theta radians about the z axis
// (x' = x cos + y sin, y' = -x sin + y cos).
template <class V>
V hfRotate3DZ(std::vector<V>& xt, const V& theta) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V ct = cos(theta);
    V st = sin(theta);
    V xr = xt[0] * ct + xt[1] * st;
    V yr = -xt[0] * st + xt[1] * ct;
    xt[0] = xr;
    xt[1] = yr;
    return V(1.0);
}

// hfRotate3DY(xt, theta): about the y axis (z' = z cos + x sin,
// x' = -z sin + x cos).
template <class V>
V hfRotate3DY(std::vector<V>& xt, const V& theta) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V ct = cos(theta);
    V st = sin(theta);
    V zr = xt[2] * ct + xt[0] * st;
    V xr = -xt[2] * st + xt[0] * ct;
    xt[0] = xr;
    xt[2] = zr;
    return V(1.0);
}

// hfRotate3DX(xt, theta): about the x axis (y' = y cos + z sin,
// z' = -y sin + z cos).
template <class V>
V hfRotate3DX(std::vector<V>& xt, const V& theta) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V ct = cos(theta);
    V st = sin(theta);
    V yr = xt[1] * ct + xt[2] * st;
    V zr = -xt[1] * st + xt[2] * ct;
    xt[1] = yr;
    xt[2] = zr;
    return V(1.0);
}

// hfTwistZ(xt, z1, z2, theta1, theta2): rotation about the z axis by an
// angle interpolated linearly in z, theta1 at z1 and theta2 at z2 (and
// extrapolated beyond); angles in radians.
template <class V>
V hfTwistZ(std::vector<V>& xt, const V& z1, const V& z2, const V& theta1, const V& theta2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V t = (xt[2] - z1) / (z2 - z1);
    V theta = (1.0 - t) * theta1 + t * theta2;
    V ct = cos(theta);
    V st = sin(theta);
    V xr = xt[0] * ct + xt[1] * st;
    V yr = -xt[0] * st + xt[1] * ct;
    xt[0] = xr;
    xt[1] = yr;
    return V(1.0);
}

// hfTwistY(xt, y1, y2, theta1, theta2): as hfTwistZ about the y axis.
template <class V>
V hfTwistY(std::vector<V>& xt, const V& y1, const V& y2, const V& theta1, const V& theta2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V t = (xt[1] - y1) / (y2 - y1);
    V theta = (1.0 - t) * theta1 + t * theta2;
    V ct = cos(theta);
    V st = sin(theta);
    V zr = xt[2] * ct + xt[0] * st;
    V xr = -xt[2] * st + xt[0] * ct;
    xt[0] = xr;
    xt[2] = zr;
    return V(1.0);
}

// hfTwistX(xt, x1, x2, theta1, theta2): as hfTwistZ about the x axis.
template <class V>
V hfTwistX(std::vector<V>& xt, const V& x1, const V& x2, const V& theta1, const V& theta2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V t = (xt[0] - x1) / (x2 - x1);
    V theta = (1.0 - t) * theta1 + t * theta2;
    V ct = cos(theta);
    V st = sin(theta);
    V yr = xt[1] * ct + xt[2] * st;
    V zr = -xt[1] * st + xt[2] * ct;
    xt[1] = yr;
    xt[2] = zr;
    return V(1.0);
}

namespace detail {

// Scale factor of the tapers: s1 below c1, s2 above c2, linear in between;
// a factor whose magnitude is below EPS is replaced by 1.
template <class V>
V taperScale(const V& coord, const V& c1, const V& c2, const V& s1, const V& s2) {
    V t = (coord - c1) / (c2 - c1);
    V inner = (1.0 - t) * s1 + t * s2;
    V scale = select(lt(coord, c1), s1, select(gt(coord, c2), s2, inner));
    return select(lt(fabs(scale), V(kEps)), V(1.0), scale);
}

}  // namespace detail

// hfTaperZ(xt, z1, z2, s1, s2): x and y divided by a scale factor that
// goes linearly from s1 at z1 to s2 at z2 (s1 below z1, s2 above z2).
// Negative factors are accepted; a factor below EPS in magnitude counts as 1.
template <class V>
V hfTaperZ(std::vector<V>& xt, const V& z1, const V& z2, const V& s1, const V& s2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V scale = detail::taperScale(xt[2], z1, z2, s1, s2);
    xt[0] = xt[0] / scale;
    xt[1] = xt[1] / scale;
    return V(1.0);
}

// hfTaperY(xt, y1, y2, s1, s2): as hfTaperZ along y (z and x are scaled).
template <class V>
V hfTaperY(std::vector<V>& xt, const V& y1, const V& y2, const V& s1, const V& s2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V scale = detail::taperScale(xt[1], y1, y2, s1, s2);
    xt[2] = xt[2] / scale;
    xt[0] = xt[0] / scale;
    return V(1.0);
}

// hfTaperX(xt, x1, x2, s1, s2): as hfTaperZ along x (y and z are scaled).
template <class V>
V hfTaperX(std::vector<V>& xt, const V& x1, const V& x2, const V& s1, const V& s2) {
    if (!detail::hasItems(xt, 3)) return V(kSentinel);
    V scale = detail::taperScale(xt[0], x1, x2, s1, s2);
    xt[1] = xt[1] / scale;
    xt[2] = xt[2] / scale;
    return V(1.0);
}

// hfStretch3D(xt, x0, sx, sy, sz): stretching about the anchor x0,
// xt <- x0 + (xt - x0) / s per axis. No check for zero factors.
template <class V>
V hfStretch3D(std::vector<V>& xt, const std::vector<V>& x0, const V& sx, const V& sy,
              const V& sz) {
    if (!detail::hasItems(xt, 3) || !detail::hasItems(x0, 3)) return V(kSentinel);
    // Item by item, as the reference: xt and x0 may be the same array.
    xt[0] = x0[0] + (xt[0] - x0[0]) / sx;
    xt[1] = x0[1] + (xt[1] - x0[1]) / sy;
    xt[2] = x0[2] + (xt[2] - x0[2]) / sz;
    return V(1.0);
}

namespace detail {

// Common loop of the space maps. For each triple of source/target points
// (3 values each) and influence ratios (3 values each, per axis), with
// d = target - source and u = (xt - target) / (ratio (1 + |d|)) per axis:
// cubic: r = |u|, xt <- xt - d (1 - r)^3 / (1 + r) where r <= 1;
// otherwise: xt <- xt - d exp(-|u|^2). The triples apply in turn.
template <class V>
V spaceMap(std::vector<V>& xt, const std::vector<V>& from, const std::vector<V>& to,
           const std::vector<V>& ratio, bool cubic) {
    const size_t n = from.size();
    if (!hasItems(xt, 3) || n % 3 != 0 || !hasItems(to, n) || !hasItems(ratio, n))
        return V(kSentinel);
    for (size_t i = 0; i < n; i += 3) {
        V dt0 = to[i + 0] - from[i + 0];
        V dt1 = to[i + 1] - from[i + 1];
        V dt2 = to[i + 2] - from[i + 2];
        V x = (xt[0] - to[i + 0]) / (ratio[i + 0] * (1.0 + sqrt(dt0 * dt0)));
        V y = (xt[1] - to[i + 1]) / (ratio[i + 1] * (1.0 + sqrt(dt1 * dt1)));
        V z = (xt[2] - to[i + 2]) / (ratio[i + 2] * (1.0 + sqrt(dt2 * dt2)));
        x = x * x;
        y = y * y;
        z = z * z;
        if (cubic) {
            V tmp = sqrt(x + y + z);
            V on = le(tmp, V(1.0));
            V w = (1.0 - tmp) * (1.0 - tmp) * (1.0 - tmp) / (1.0 + tmp);
            xt[0] = select(on, xt[0] - w * dt0, xt[0]);
            xt[1] = select(on, xt[1] - w * dt1, xt[1]);
            xt[2] = select(on, xt[2] - w * dt2, xt[2]);
        } else {
            V tmp = x + y + z;
            tmp = exp(-tmp);
            xt[0] = xt[0] - tmp * dt0;
            xt[1] = xt[1] - tmp * dt1;
            xt[2] = xt[2] - tmp * dt2;
        }
    }
    return V(1.0);
}

}  // namespace detail

// hfSpaceMapCubic(xt, source, target, b): point-to-point space mapping with
// a cubic falloff (see detail::spaceMap): points near the target are pulled
// from the source, so the shape near the source moves to the target.
//   source, target: points (3 values each); b: influence ratio per axis
//   (3 values per point). The number of points is size(source) / 3.
template <class V>
V hfSpaceMapCubic(std::vector<V>& xt, const std::vector<V>& source, const std::vector<V>& target,
                  const std::vector<V>& ratio) {
    return detail::spaceMap(xt, source, target, ratio, true);
}

// hfSpaceMapExp(xt, source, target, b): as hfSpaceMapCubic with the
// falloff exp(-|u|^2), which has no cut-off.
template <class V>
V hfSpaceMapExp(std::vector<V>& xt, const std::vector<V>& source, const std::vector<V>& target,
                const std::vector<V>& ratio) {
    return detail::spaceMap(xt, source, target, ratio, false);
}

}  // namespace hg::frep::lib
