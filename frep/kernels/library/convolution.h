// Convolution surfaces with the Cauchy kernel 1 / (1 + S^2 r^2)^2 around
// skeletons: points, line segments, arcs, triangles, polylines and triangle
// meshes (Sherstyuk's closed forms, as coded in the reference library).
// The number of skeleton elements is the size of the kernel-width array S,
// except for hfConvLineR (see there).
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/primitives.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

namespace detail {

// Field of one line segment from b to e at the point p, kernel width s
// (hfConvLine and hfConvCurve). The reference aborts on a zero-length
// segment; here that gives a non-finite value.
template <class V>
V convSegment(const V& px, const V& py, const V& pz, const V& bx, const V& by, const V& bz,
              const V& ex, const V& ey, const V& ez, const V& s) {
    V l = sqrt((ex - bx) * (ex - bx) + (ey - by) * (ey - by) + (ez - bz) * (ez - bz));
    V ax = (ex - bx) / l;
    V ay = (ey - by) / l;
    V az = (ez - bz) / l;
    V dx = px - bx;
    V dy = py - by;
    V dz = pz - bz;
    V xx = dx * ax + dy * ay + dz * az;
    V p = sqrt(1.0 + s * s * (dx * dx + dy * dy + dz * dz - xx * xx));
    V q = sqrt(1.0 + s * s * (dx * dx + dy * dy + dz * dz + l * l - 2.0 * l * xx));
    return xx / (2.0 * p * p * (p * p + s * s * xx * xx)) + (l - xx) / (2.0 * p * p * q * q) +
           (atan(s * xx / p) + atan(s * (l - xx) / p)) / (2.0 * s * p * p * p);
}

// One triangle's field (hfConvTriangle, hfConvMesh): vertices a1, a2, a3
// (each 3 values), kernel width s. The vertices are first cycled so that
// the edge a1-a2 is the longest, as the reference does.
template <class V>
V convTriangle(const std::vector<V>& x, V a1x, V a1y, V a1z, V a2x, V a2y, V a2z, V a3x,
               V a3y, V a3z, const V& s) {
    V len0 = sqrt((a2x - a1x) * (a2x - a1x) + (a2y - a1y) * (a2y - a1y) +
                  (a2z - a1z) * (a2z - a1z));
    V len1 = sqrt((a3x - a2x) * (a3x - a2x) + (a3y - a2y) * (a3y - a2y) +
                  (a3z - a2z) * (a3z - a2z));
    V len2 = sqrt((a1x - a3x) * (a1x - a3x) + (a1y - a3y) * (a1y - a3y) +
                  (a1z - a3z) * (a1z - a3z));
    // Case 1 (edge 2-3 longest): (a1, a2, a3) <- (a2, a3, a1);
    // else case 2 (edge 3-1 longest): (a1, a2, a3) <- (a3, a1, a2).
    V c1 = land(ge(len1, len2), gt(len1, len0));
    V c2 = land(ge(len2, len1), gt(len2, len0));
    V b1x = select(c1, a2x, select(c2, a3x, a1x));
    V b1y = select(c1, a2y, select(c2, a3y, a1y));
    V b1z = select(c1, a2z, select(c2, a3z, a1z));
    V b2x = select(c1, a3x, select(c2, a1x, a2x));
    V b2y = select(c1, a3y, select(c2, a1y, a2y));
    V b2z = select(c1, a3z, select(c2, a1z, a2z));
    V b3x = select(c1, a1x, select(c2, a2x, a3x));
    V b3y = select(c1, a1y, select(c2, a2y, a3y));
    V b3z = select(c1, a1z, select(c2, a2z, a3z));
    a1x = b1x; a1y = b1y; a1z = b1z;
    a2x = b2x; a2y = b2y; a2z = b2z;
    a3x = b3x; a3y = b3y; a3z = b3z;
    // Only the new len[0] is used below.
    len0 = sqrt((a2x - a1x) * (a2x - a1x) + (a2y - a1y) * (a2y - a1y) +
                (a2z - a1z) * (a2z - a1z));

    V a21x = a2x - a1x;
    V a21y = a2y - a1y;
    V a21z = a2z - a1z;
    V a13x = a1x - a3x;
    V a13y = a1y - a3y;
    V a13z = a1z - a3z;

    // b: foot of the perpendicular from a3 onto the line a1-a2.
    V t = -(a21x * a13x + a21y * a13y + a21z * a13z) / (len0 * len0);
    V bx = a1x + t * a21x;
    V by = a1y + t * a21y;
    V bz = a1z + t * a21z;

    V dx = x[0] - bx;
    V dy = x[1] - by;
    V dz = x[2] - bz;

    V ux = a2x - bx;
    V uy = a2y - by;
    V uz = a2z - bz;
    V ul = sqrt(ux * ux + uy * uy + uz * uz);
    ux = ux / ul;
    uy = uy / ul;
    uz = uz / ul;

    V vx = a3x - bx;
    V vy = a3y - by;
    V vz = a3z - bz;
    V vl = sqrt(vx * vx + vy * vy + vz * vz);
    vx = vx / vl;
    vy = vy / vl;
    vz = vz / vl;

    V d2 = dx * dx + dy * dy + dz * dz;
    V u = dx * ux + dy * uy + dz * uz;
    V v = dx * vx + dy * vy + dz * vz;
    V h = sqrt((a3x - bx) * (a3x - bx) + (a3y - by) * (a3y - by) + (a3z - bz) * (a3z - bz));
    V a1 = sqrt((a1x - bx) * (a1x - bx) + (a1y - by) * (a1y - by) + (a1z - bz) * (a1z - bz));
    V a2 = sqrt((a2x - bx) * (a2x - bx) + (a2y - by) * (a2y - by) + (a2z - bz) * (a2z - bz));

    V g = v - h;
    V m = a2 * g + u * h;
    V k = u * h - a1 * g;
    V c2sq = 1.0 / (s * s) + d2 - u * u;
    V cc = sqrt(c2sq);
    V q = c2sq - v * v;
    V w = c2sq - 2.0 * v * h + h * h;
    V aa2 = a1 * a1 * w + h * h * (q + u * u) - 2.0 * a1 * h * u * g;
    V aa = sqrt(aa2);
    V bb2 = a2 * a2 * w + h * h * (q + u * u) + 2.0 * a2 * h * u * g;
    V bb = sqrt(bb2);

    V n1 = a1 + u;
    V n2 = a2 - u;
    V n3 = a1 * n1 + v * h;
    V n4 = -a1 * u - g * h;
    V n5 = -a2 * n2 - v * h;
    V n6 = -a2 * u + g * h;

    V arc1 = k * (atan(n3 / aa) + atan(n4 / aa)) / aa;
    V arc2 = m * (atan(n5 / bb) + atan(n6 / bb)) / bb;
    V arc3 = v * (atan(n1 / cc) + atan(n2 / cc)) / cc;
    return (arc1 + arc2 + arc3) / (2.0 * q * s);
}

// atanh as the reference library defines it (archyp.h).
template <class V>
V refAtanh(const V& z) {
    return log((1.0 + z) * sqrt(1.0 / (1.0 - z * z)));
}

// Field of an arc of `th` radians (0 < th <= pi) of radius r in the plane
// z = 0, starting on the x axis, at the local point (nx, ny, nz).
template <class V>
V convArcField(const V& nx, const V& ny, const V& nz, const V& r, const V& s, const V& th) {
    V a = 2.0 * r * s * s;
    V d2 = nx * nx + ny * ny + nz * nz;
    V b = 1.0 + r * r * (s * s) + s * s * d2;
    V p2 = -((r * r) * (r * r)) * ((s * s) * (s * s)) +
           2.0 * (r * r) * (s * s) * (s * s * (d2 - 2.0 * (nz * nz)) - 1.0) -
           (1.0 + s * s * d2) * (1.0 + s * s * d2);
    // The reference takes sqrt(-p2) for p2 < 0 and sqrt(p2) otherwise, which
    // is sqrt(|p2|); written so that no branch takes the root of a negative.
    V p1 = sqrt(fabs(p2));
    V p3 = p1 * p2;

    V f1 = (b * ny) / (nx * p2 * (a * nx - b)) +
           (a * (nx * nx + ny * ny) * sin(th) - b * ny) /
               (nx * p2 * (a * (nx * cos(th) + ny * sin(th)) - b));

    V f2neg = 2.0 * b * (atan(-a * ny / p1) + atan((a * ny - (a * nx + b) * tan(th / 2.0)) / p1)) /
              p3;
    V f2pos = 2.0 * b *
              (refAtanh(a * ny / p1) + refAtanh(((a * nx + b) * tan(th / 2.0) - a * ny) / p1)) /
              p3;
    V f2 = select(lt(p2, V(0.0)), f2neg, f2pos);
    return f1 + f2;
}

// Degrees to radians with the reference's pi = 3.141592.
constexpr double kArcDegree = 3.141592 / 180.0;

// An arc's frame: centre (3), then the rotation into the arc's plane (3x3,
// row major).
constexpr size_t kArcFrame = 12;

// (ox, oy, oz) = m (x, y, z) in the reference's order of operations.
template <class V, class M>
void arcRotate(const M* m, const V& x, const V& y, const V& z, V& ox, V& oy, V& oz) {
    ox = m[0] * x + m[1] * y + m[2] * z;
    oy = m[3] * x + m[4] * y + m[5] * z;
    oz = m[6] * x + m[7] * y + m[8] * z;
}

// The reference's turn by -180 degrees about the z axis, which carries the
// part of an arc beyond 180 degrees; rounded as the reference rounds it
// (cos and sin of 3.141592 / 180 * -180 are not exactly -1 and 0).
inline void arcOverTurn(double m[9]) {
    const double i = 0.0, j = 0.0, k = 1.0;
    const double c = std::cos(kArcDegree * (-180.0));
    const double s = std::sin(kArcDegree * (-180.0));
    const double oneC = 1.0 - c;
    const double ii = i * i, jj = j * j, kk = k * k;
    const double ij = i * j, jk = j * k, ki = k * i;
    const double is = i * s, js = j * s, ks = k * s;
    const double t[9] = {c + ii * oneC, -ks + ij * oneC, js + ki * oneC,
                         ks + ij * oneC, c + jj * oneC, -is + jk * oneC,
                         -js + ki * oneC, is + jk * oneC, c + kk * oneC};
    for (int n = 0; n < 9; ++n) m[n] = t[n];
}

// Field at the point (x0, x1, x2) of one piece of an hfConvArc arc: the
// point is moved into the arc's frame (kArcFrame values), for the part
// beyond 180 degrees also turned by `turn` (arcOverTurn; null for the first
// 180 degrees), then the arc of `th` radians is evaluated there. The
// compiler replaces this by a fused kernel when everything but the point is
// constant.
template <class V>
V convArcPiece(const V& x0, const V& x1, const V& x2, const V* frame, const double* turn, const V& r,
               const V& s, const V& th) {
    V px = x0 - frame[0];
    V py = x1 - frame[1];
    V pz = x2 - frame[2];
    V nx, ny, nz;
    arcRotate(frame + 3, px, py, pz, nx, ny, nz);
    if (turn) {
        V ox, oy, oz;
        arcRotate(turn, nx, ny, nz, ox, oy, oz);
        nx = ox;
        ny = oy;
        nz = oz;
    }
    return convArcField(nx, ny, nz, r, s, th);
}

}  // namespace detail

// hfConvPoint(x, vect, S, T): sum_n 1 / (1 + S_n^2 r_n^2)^2 - T, r_n the
// distance from x to point n.
//   vect: points (3 values each); S: kernel widths (one per point);
//   T: threshold.
template <class V>
V hfConvPoint(const std::vector<V>& x, const std::vector<V>& vect, const std::vector<V>& s,
              const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(vect, 3 * n)) return V(kSentinel);
    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        V r2 = (vect[3 * i] - x[0]) * (vect[3 * i] - x[0]) +
               (vect[3 * i + 1] - x[1]) * (vect[3 * i + 1] - x[1]) +
               (vect[3 * i + 2] - x[2]) * (vect[3 * i + 2] - x[2]);
        V k = 1.0 + s[i] * s[i] * r2;
        f = f + 1.0 / (k * k);
    }
    return f - t;
}

// hfConvLine(x, begin, end, S, T): sum of the line-segment fields - T.
//   begin, end: segment end points (3 values each); S: kernel widths (one
//   per segment); T: threshold.
template <class V>
V hfConvLine(const std::vector<V>& x, const std::vector<V>& begin, const std::vector<V>& end,
             const std::vector<V>& s, const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(begin, 3 * n) || !detail::hasItems(end, 3 * n))
        return V(kSentinel);
    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        f = f + detail::convSegment(x[0], x[1], x[2], begin[3 * i], begin[3 * i + 1],
                                    begin[3 * i + 2], end[3 * i], end[3 * i + 1], end[3 * i + 2],
                                    s[i]);
    }
    return f - t;
}

// hfConvArc(x, center, radius, theta, axis, angle, S, T): sum of the arc
// fields - T. Arc n lies on the circle of radius[n] around center[n] in the
// plane through it normal to axis[n], is rotated by angle[n] degrees about
// the axis and spans theta[n] degrees (at most 360).
//   center, axis: 3 values per arc; radius, theta, angle, S: one per arc;
//   T: threshold.
// Like the reference, the routine writes into its inputs: angle[n] grows by
// EPS on every call, theta[n] above 360 becomes 360, and above 180 becomes
// 180 after the part beyond 180 degrees has been added. Degrees use
// pi = 3.141592, and EPS is added to every axis component.
template <class V>
V hfConvArc(const std::vector<V>& x, const std::vector<V>& center, const std::vector<V>& radius,
            std::vector<V>& theta, const std::vector<V>& axis, std::vector<V>& angle,
            const std::vector<V>& s, const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(center, 3 * n) || !detail::hasItems(radius, n) ||
        !detail::hasItems(theta, n) || !detail::hasItems(axis, 3 * n) ||
        !detail::hasItems(angle, n))
        return V(kSentinel);
    constexpr double rd = detail::kArcDegree;
    double overTurn[9];
    detail::arcOverTurn(overTurn);

    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        V r = radius[i];
        angle[i] = angle[i] + detail::kEps;

        V ai = axis[3 * i] + detail::kEps;
        V aj = axis[3 * i + 1] + detail::kEps;
        V ak = axis[3 * i + 2] + detail::kEps;
        V length = sqrt(ai * ai + aj * aj + ak * ak);
        length = select(lt(length, V(detail::kEps)), V(detail::kEps), length);
        ai = ai / length;
        aj = aj / length;
        ak = ak / length;

        V c = cos(rd * (-angle[i]));
        V sn = sin(rd * (-angle[i]));
        V oneC = 1.0 - c;
        V ii = ai * ai, jj = aj * aj, kk = ak * ak;
        V ij = ai * aj, jk = aj * ak, ki = ak * ai;
        V is = ai * sn, js = aj * sn, ks = ak * sn;

        theta[i] = select(gt(theta[i], V(360.0)), V(360.0), theta[i]);

        // Centre, then the rotation by -angle about the axis into the arc's
        // frame (row major).
        const V frame[detail::kArcFrame] = {
            center[3 * i], center[3 * i + 1], center[3 * i + 2],
            c + ii * oneC, -ks + ij * oneC, js + ki * oneC,
            ks + ij * oneC, c + jj * oneC, -is + jk * oneC,
            -js + ki * oneC, is + jk * oneC, c + kk * oneC};

        // Beyond 180 degrees: the rest of the arc, turned by -180 degrees.
        V over = gt(theta[i], V(180.0));
        V overTh = (theta[i] - 180.0) * rd;
        theta[i] = select(over, V(180.0), theta[i]);
        // Skipped statically when the span is a constant of at most 180.
        if (!isConstant(over) || constantValue(over) != 0.0) {
            V overField = detail::convArcPiece(x[0], x[1], x[2], frame, overTurn, r, s[i], overTh);
            f = select(over, f + overField, f);
        }

        V th = theta[i] * rd;
        f = f + detail::convArcPiece(x[0], x[1], x[2], frame, nullptr, r, s[i], th);
    }
    return f - t;
}

// hfConvTriangle(x, vect, S, T): sum of the triangle fields - T.
//   vect: triangles (9 values each: three vertices); S: kernel widths (one
//   per triangle); T: threshold.
template <class V>
V hfConvTriangle(const std::vector<V>& x, const std::vector<V>& vect, const std::vector<V>& s,
                 const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(vect, 9 * n)) return V(kSentinel);
    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        const V* a = &vect[9 * i];
        f = f + detail::convTriangle(x, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], s[i]);
    }
    return f - t;
}

// hfConvLineR(x, begin, end, R): line segments whose kernel width is 1/R
// for R < 1 (else 1). The segment fields are added while the running sum
// is below 1 and the sum is clamped at 1. The result subtracts a threshold
// T computed from R and the length of the LAST segment only (as the
// reference does).
//   begin, end: segment end points (3 values each); the number of segments
//   is size(end) / 3; R: thickness.
template <class V>
V hfConvLineR(const std::vector<V>& x, const std::vector<V>& begin, const std::vector<V>& end,
              const V& bigR) {
    const size_t n = end.size() / 3;
    // With no segment the reference's threshold is uninitialised.
    if (!detail::isPoint(x) || n == 0 || !detail::hasItems(begin, 3 * n)) return V(kSentinel);
    V s = select(lt(bigR, V(1.0)), 1.0 / bigR, V(1.0));
    V f = V(0.0);
    V t = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        V ex = end[3 * i], ey = end[3 * i + 1], ez = end[3 * i + 2];
        V bx = begin[3 * i], by = begin[3 * i + 1], bz = begin[3 * i + 2];
        V l = sqrt((ex - bx) * (ex - bx) + (ey - by) * (ey - by) + (ez - bz) * (ez - bz));
        V ax = (ex - bx) / l;
        V ay = (ey - by) / l;
        V az = (ez - bz) / l;
        V dx = x[0] - bx;
        V dy = x[1] - by;
        V dz = x[2] - bz;

        V pT = sqrt(1.0 + (s * s) * (bigR * bigR));
        V qT2 = 1.0 + (s * s) * (bigR * bigR + l * l);
        t = l / (2.0 * (pT * pT) * qT2) + (atan(s * l / pT)) / (2.0 * s * (pT * pT) * pT);

        V xx = dx * ax + dy * ay + dz * az;
        V p = sqrt(1.0 + (s * s) * (dx * dx + dy * dy + dz * dz - xx * xx));
        V q2 = 1.0 + (s * s) * (dx * dx + dy * dy + dz * dz + l * l - 2.0 * l * xx);
        V fTmp = xx / (2.0 * p * p * (p * p + s * s * xx * xx)) + (l - xx) / (2.0 * p * p * q2) +
                 (atan(s * xx / p) + atan(s * (l - xx) / p)) / (2.0 * s * p * p * p);

        V sum = f + fTmp;
        sum = select(gt(sum, V(1.0)), V(1.0), sum);
        f = select(lt(f, V(1.0)), sum, f);
    }
    return f - t;
}

// hfConvCurve(x, vect, S, T): polyline through the vertices of vect; segment
// n runs from vertex n to vertex n+1 with kernel width S[n]; minus T.
//   vect: vertices (3 values each, one more vertex than widths).
template <class V>
V hfConvCurve(const std::vector<V>& x, const std::vector<V>& vect, const std::vector<V>& s,
              const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(vect, 3 * (n + 1))) return V(kSentinel);
    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        f = f + detail::convSegment(x[0], x[1], x[2], vect[3 * i], vect[3 * i + 1],
                                    vect[3 * i + 2], vect[3 * (i + 1)], vect[3 * (i + 1) + 1],
                                    vect[3 * (i + 1) + 2], s[i]);
    }
    return f - t;
}

// hfConvMesh(x, vect, tri, S, T): triangle mesh; triangle n has the 1-based
// vertex indices tri[3n..3n+2] into the vertex list vect (3 values per
// vertex) and kernel width S[n]; minus T. Indices are truncated toward
// zero, as the reference's (int) cast does; they must be constants.
template <class V>
V hfConvMesh(const std::vector<V>& x, const std::vector<V>& vect, const std::vector<V>& tri,
             const std::vector<V>& s, const V& t) {
    const size_t n = s.size();
    if (!detail::isPoint(x) || !detail::hasItems(tri, 3 * n)) return V(kSentinel);
    // 0-based offset of the vertex that tri[k] names, or -1 when it is out of
    // range of vect.
    auto vertex = [&](size_t k) -> long {
        if (!isConstant(tri[k]))
            throw NotCompilable("hfConvMesh: vertex index " + std::to_string(k + 1) +
                                " of the triangle array depends on the point");
        double v = constantValue(tri[k]);
        if (!(v >= 1.0 && v < 1e9)) return -1;
        long idx = static_cast<long>(v) - 1;  // (int) truncation, then 1-based
        if (3 * static_cast<size_t>(idx) + 2 >= vect.size()) return -1;
        return 3 * idx;
    };
    V f = V(0.0);
    for (size_t i = 0; i < n; ++i) {
        long o1 = vertex(3 * i), o2 = vertex(3 * i + 1), o3 = vertex(3 * i + 2);
        if (o1 < 0 || o2 < 0 || o3 < 0) return V(kSentinel);
        const auto u1 = static_cast<size_t>(o1), u2 = static_cast<size_t>(o2),
                   u3 = static_cast<size_t>(o3);
        f = f + detail::convTriangle(x, vect[u1], vect[u1 + 1], vect[u1 + 2], vect[u2],
                                     vect[u2 + 1], vect[u2 + 2], vect[u3], vect[u3 + 1],
                                     vect[u3 + 2], s[i]);
    }
    return f - t;
}

}  // namespace hg::frep::lib
