#include "frep/kernels/conv_arc.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frep/kernels/dual.h"
#include "frep/kernels/fast_math.h"
#include "frep/kernels/library/convolution.h"
#include "frep/kernels/simd.h"

namespace hg::frep {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kUlp = std::numeric_limits<double>::epsilon();

// Parameter layout (frep/compiler/tape.h): frame (centre, rotation), then these.
constexpr int kRadius = 12, kWidth = 13, kSpan = 14, kOver = 15;

// Bound on the integral of |K'(|n - c|)| over the arc length of a whole
// circle, for any point n, radius and width s: the length of circle within
// distance rho of n is at most 2 pi rho, so the integral is at most
// 2 pi int_0^inf max_{t >= rho} |K'(t)| drho = 2 pi (r* |K'(r*)| + K(r*))
// with r* = 1 / (s sqrt 5) where |K'| peaks: 2 pi (0.46297 + 0.69445).
// Per radian of the arc's angle it is this over the radius.
constexpr double kCircleLipschitz = 7.273;

// The bounds split the arc into this many equal parts.
constexpr int kSubArcs = 8;

// The rotation from the world into the piece's frame, with the turn by -180
// degrees composed in for the part beyond 180 degrees. Approximate (the
// evaluators rotate twice); callers allow for the difference.
void frameRotation(const double* q, double m[9]) {
    if (q[kOver] == 0.0) {
        std::copy(q + 3, q + 12, m);
        return;
    }
    double t[9];
    lib::detail::arcOverTurn(t);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            m[3 * i + j] = t[3 * i] * q[3 + j] + t[3 * i + 1] * q[6 + j] + t[3 * i + 2] * q[9 + j];
}

// The turn for the part beyond 180 degrees, or null.
const double* pieceTurn(const double* q, double turn[9]) {
    if (q[kOver] == 0.0) return nullptr;
    lib::detail::arcOverTurn(turn);
    return turn;
}

double kernel(double s, double d) {
    const double u = 1.0 + s * s * d * d;
    return 1.0 / (u * u);
}

// max over t >= d of |K'(t)| = 4 s^2 t / (1 + s^2 t^2)^3.
double kernelSlope(double s, double d) {
    const double t = std::max(d, 1.0 / (s * std::sqrt(5.0)));
    const double u = 1.0 + s * s * t * t;
    return 4.0 * s * s * t / (u * u * u);
}

// Distance between the interval and [lo, hi] (0 where they meet), and the
// farthest distance between their points.
double gap(const Interval& a, double lo, double hi) { return std::max({0.0, lo - a.hi, a.lo - hi}); }
double farthest(const Interval& a, double lo, double hi) { return std::max(std::fabs(a.hi - lo), std::fabs(hi - a.lo)); }

}  // namespace

double arcPieceField(double px, double py, double pz, const double* q) {
    double turn[9];
    return lib::detail::convArcPiece<double>(px, py, pz, q, pieceTurn(q, turn), q[kRadius], q[kWidth], q[kSpan]);
}

void arcPieceBatch(const double* px, const double* py, const double* pz, double* out, size_t n, const double* q) {
    double turn[9];
    const double* t = pieceTurn(q, turn);
    for (size_t i = 0; i < n; ++i)
        out[i] = lib::detail::convArcPiece<double>(px[i], py[i], pz[i], q, t, q[kRadius], q[kWidth], q[kSpan]);
}

double arcPieceGradient(double px, double py, double pz, const double* q, double grad[3]) {
    Dual frame[lib::detail::kArcFrame];
    for (size_t k = 0; k < lib::detail::kArcFrame; ++k) frame[k] = Dual(q[k]);
    double turn[9];
    const Dual f = lib::detail::convArcPiece<Dual>(Dual::input(px, 0), Dual::input(py, 1), Dual::input(pz, 2), frame,
                                                   pieceTurn(q, turn), Dual(q[kRadius]), Dual(q[kWidth]),
                                                   Dual(q[kSpan]));
    for (int k = 0; k < 3; ++k) grad[k] = f.d[k];
    return f.v;
}

namespace {

// The float path rewrites the closed form without its cancellations. With
// rho^2 = nx^2 + ny^2, b = 1 + s^2 (r^2 + |n|^2), a = 2 r s^2 and the arc's
// end points e0 = (r, 0, 0), e1 = r (cos th, sin th, 0):
//   -p2 = b^2 - a^2 rho^2 = e1 e2, e1,2 = 1 + s^2 ((rho -+ r)^2 + nz^2);
//   a nx - b = -(1 + s^2 |n - e0|^2), a (n . e1) / r - b = -(1 + s^2 |n - e1|^2);
//   the first term's two fractions over nx share one numerator, which is nx
//   times a (b (ny (cos th - 1) - nx sin th) + a rho^2 sin th);
//   the two arctangents are one: atan(u) + atan(v) = atan2(u + v, 1 - u v)
//   when u + v < 0 (here -(a nx + b) tan(th / 2) / p1), scaled by p1^2.
// Constants in double, then the per-point formula in float.
struct ArcLoop {
    float m[9], cx, cy, cz, r, r2, s2, a, cosM1, sinTh, ex, ey, tanHalf, far;

    explicit ArcLoop(const double* q) {
        double md[9];
        frameRotation(q, md);
        for (int k = 0; k < 9; ++k) m[k] = static_cast<float>(md[k]);
        const double rd = q[kRadius], s = q[kWidth], th = q[kSpan];
        cx = static_cast<float>(q[0]); cy = static_cast<float>(q[1]); cz = static_cast<float>(q[2]);
        r = static_cast<float>(rd);
        r2 = static_cast<float>(rd * rd);
        s2 = static_cast<float>(s * s);
        a = static_cast<float>(2.0 * rd * s * s);
        cosM1 = static_cast<float>(std::cos(th) - 1.0);
        sinTh = static_cast<float>(std::sin(th));
        ex = static_cast<float>(rd * std::cos(th));
        ey = static_cast<float>(rd * std::sin(th));
        tanHalf = static_cast<float>(std::tan(th / 2.0));
        // Coordinates beyond r + 1e4 / s are clamped there: the field is
        // below 1e-15 on and beyond that, and the products below cannot
        // overflow.
        far = static_cast<float>(rd + 1e4 / std::fabs(s));
    }

    HG_ALWAYS_INLINE void run(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
                              float* __restrict out, size_t n) const {
        const float m0 = m[0], m1 = m[1], m2 = m[2], m3 = m[3], m4 = m[4], m5 = m[5], m6 = m[6], m7 = m[7],
                    m8 = m[8];
        const float cx_ = cx, cy_ = cy, cz_ = cz, r_ = r, r2_ = r2, s2_ = s2, a_ = a, cosM1_ = cosM1,
                    sinTh_ = sinTh, ex_ = ex, ey_ = ey, tanHalf_ = tanHalf, far_ = far;
        for (size_t i = 0; i < n; ++i) {
            const float dx = px[i] - cx_, dy = py[i] - cy_, dz = pz[i] - cz_;
            const float nx = std::min(std::max(m0 * dx + m1 * dy + m2 * dz, -far_), far_);
            const float ny = std::min(std::max(m3 * dx + m4 * dy + m5 * dz, -far_), far_);
            const float nz = std::min(std::max(m6 * dx + m7 * dy + m8 * dz, -far_), far_);
            const float rho2 = nx * nx + ny * ny, nz2 = nz * nz;
            const float rho = std::sqrt(rho2);
            const float e1 = 1.0f + s2_ * ((rho - r_) * (rho - r_) + nz2);
            const float e2 = 1.0f + s2_ * ((rho + r_) * (rho + r_) + nz2);
            const float e12 = e1 * e2;
            const float p1 = std::sqrt(e12);
            const float b = 1.0f + s2_ * (r2_ + rho2 + nz2);
            const float d0 = 1.0f + s2_ * ((nx - r_) * (nx - r_) + ny * ny + nz2);
            const float d1 = 1.0f + s2_ * ((nx - ex_) * (nx - ex_) + (ny - ey_) * (ny - ey_) + nz2);
            // Reciprocals apart, so that the divisions overlap.
            const float g0 = 1.0f / (e1 * d0), g1 = 1.0f / (e2 * d1), g2 = 1.0f / (p1 * e12);
            const float f1 = -(a_ * (b * (ny * cosM1_ - nx * sinTh_) + a_ * rho2 * sinTh_)) * g0 * g1;
            const float u = (a_ * nx + b) * tanHalf_;
            const float den = e12 + a_ * ny * (a_ * ny - u);
            const float angle = -fast::angleAbove(u * p1, den);
            out[i] = f1 - 2.0f * b * angle * g2;
        }
    }
};

}  // namespace

void arcPieceBatch(const float* px, const float* py, const float* pz, float* out, size_t n, const double* q) {
    simd::run(ArcLoop(q), px, py, pz, out, n);
}

// Bounds over a box, in the piece's frame:
//  * The frame coordinates range over the image of the box under the
//    rotation (exact for a linear map, widened for the evaluators'
//    rounding). If n_x can be 0 the double path can return anything there
//    (NaN, or huge values next to it where its two terms over n_x cancel):
//    no bound.
//  * Each of kSubArcs equal parts of the arc lies between dmin and dmax from
//    the box (distance to the circle and to the part's bounding box), so
//    its share of F lies between (th / kSubArcs) K(dmax) and ... K(dmin).
//  * |grad F| <= int |K'| dt, at most the sum over the parts of
//    (th / kSubArcs) max_{d >= dmin} |K'(d)| and at most kCircleLipschitz / r;
//    in world units times the rotation's norm. So F lies within that slope
//    times the box's half-diagonal of its value at the box centre.
//  * The double path's rounding error, from the closed form's
//    cancellations: |p2| >= b, |a nx - b| >= 1, |a (n . e1) / r - b| >= 1
//    bound its two fractions over nx by (rho + 2 |ny|) / |nx| and their
//    relative error by ~40 eps b; the arctangent term's arguments carry an
//    absolute error ~ eps (1 + 2 tan(th / 2)) sqrt(b) that the prefactor
//    2 b / |p3| <= 2 / sqrt(b) scales back. Allowed for with a margin.
Interval arcPieceBounds(const Interval& px, const Interval& py, const Interval& pz, const double* q) {
    const Interval p[3] = {px, py, pz};
    for (const Interval& v : p)
        if (!std::isfinite(v.lo) || !std::isfinite(v.hi)) return Interval::entire();
    const bool nan = px.maybeNaN || py.maybeNaN || pz.maybeNaN;
    const double r = q[kRadius], s = std::fabs(q[kWidth]), th = q[kSpan];
    double m[9];
    frameRotation(q, m);

    // Frame coordinates: centre and half-width of the image of the box.
    double mid[3], half[3], reach = 0.0, mMax = 0.0;
    for (int j = 0; j < 3; ++j) {
        mid[j] = 0.5 * (p[j].lo + p[j].hi) - q[j];
        half[j] = 0.5 * (p[j].hi - p[j].lo);
        reach += std::fabs(mid[j]) + half[j];
    }
    for (int k = 0; k < 9; ++k) mMax = std::max({mMax, std::fabs(m[k]), std::fabs(q[3 + k])});
    const double slack = 64.0 * kUlp * reach * std::max(1.0, mMax) * std::max(1.0, mMax) + 1e-300;
    Interval f[3];
    for (int i = 0; i < 3; ++i) {
        double c = 0.0, w = 0.0;
        for (int j = 0; j < 3; ++j) {
            c += m[3 * i + j] * mid[j];
            w += std::fabs(m[3 * i + j]) * half[j];
        }
        f[i] = Interval(c - w - slack, c + w + slack);
    }
    if (f[0].lo <= 0.0 && f[0].hi >= 0.0) return Interval::entire();

    // Distances from the box to each of kSubArcs equal parts of the arc: at
    // least the distance to the circle and to the part's bounding box, at
    // most the distance to the circle's and to the part's far side.
    const double gx = gap(f[0], 0.0, 0.0), gy = gap(f[1], 0.0, 0.0), gz = gap(f[2], 0.0, 0.0);
    const double fx = farthest(f[0], 0.0, 0.0), fy = farthest(f[1], 0.0, 0.0), fz = farthest(f[2], 0.0, 0.0);
    const double rhoLo = std::sqrt(gx * gx + gy * gy), rhoHi = std::sqrt(fx * fx + fy * fy);
    const double ringGap = std::max({0.0, rhoLo - r, r - rhoHi});
    const double toCircle2 = ringGap * ringGap + gz * gz;
    const double farCircle2 = (rhoHi + r) * (rhoHi + r) + fz * fz;
    const double tiny = 1e-12 * (r + reach);  // rounding of the distances
    const double part = th / kSubArcs;
    double lo = 0.0, hi = 0.0, partSlopes = 0.0;
    for (int k = 0; k < kSubArcs; ++k) {
        // The part spans [t0, t1] within [0, pi]: cos falls, sin >= 0.
        const double t0 = part * k, t1 = part * (k + 1);
        const double s0 = std::sin(t0), s1 = std::sin(t1);
        const double boxLo[2] = {r * std::cos(t1), r * std::min(s0, s1)};
        const double boxHi[2] = {r * std::cos(t0), t0 <= 0.5 * kPi && t1 >= 0.5 * kPi ? r : r * std::max(s0, s1)};
        double toBox2 = gz * gz, farBox2 = fz * fz;
        for (int i = 0; i < 2; ++i) {
            const double g = gap(f[i], boxLo[i], boxHi[i]), d = farthest(f[i], boxLo[i], boxHi[i]);
            toBox2 += g * g;
            farBox2 += d * d;
        }
        const double dmin = std::max(0.0, std::sqrt(std::max(toCircle2, toBox2)) - tiny);
        const double dmax = std::sqrt(std::min(farCircle2, farBox2)) + tiny;
        lo += part * kernel(s, dmax);
        hi += part * kernel(s, dmin);
        partSlopes += part * kernelSlope(s, dmin);
    }

    // Rounding error of the double path anywhere in the box.
    const double b = 1.0 + r * r * s * s + s * s * (fx * fx + fy * fy + fz * fz);
    if (!(b < 1e12)) return Interval::entire();  // p2's sign no longer certain
    const double nxMin = std::min(std::fabs(f[0].lo), std::fabs(f[0].hi));
    const double err = kUlp * (400.0 * b * rhoHi / nxMin + 2000.0 * b + 16.0 * (1.0 + 2.0 * std::tan(0.5 * th)));

    lo -= err;
    hi += err;
    // Lipschitz band around the centre value; the rotation's norm from the
    // Gershgorin bound on m^T m.
    double norm2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        double row = 0.0;
        for (int j = 0; j < 3; ++j)
            row += std::fabs(m[i] * m[j] + m[3 + i] * m[3 + j] + m[6 + i] * m[6 + j]);
        norm2 = std::max(norm2, row);
    }
    // How far the frame coordinates of a point of the box can be from those
    // of its centre.
    const double radius = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]) * std::sqrt(norm2) *
                              (1.0 + 1e-9) + 2.0 * slack;
    const double slope = std::min(partSlopes, kCircleLipschitz / r);
    const double centre = arcPieceField(0.5 * (px.lo + px.hi), 0.5 * (py.lo + py.hi), 0.5 * (pz.lo + pz.hi), q);
    lo = std::max(lo, centre - slope * radius - 2.0 * err);
    hi = std::min(hi, centre + slope * radius + 2.0 * err);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) return Interval::entire();
    // Room for the float path's rounding.
    const double pad = 1e-9 + 1e-6 * std::max(std::fabs(lo), std::fabs(hi));
    return {lo - pad, hi + pad, nan};
}

}  // namespace hg::frep
