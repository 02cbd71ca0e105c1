#include "frep/kernels/conv_segment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frep/kernels/dual.h"
#include "frep/kernels/fast_math.h"
#include "frep/kernels/library/convolution.h"
#include "frep/kernels/simd.h"

namespace hg::frep {

double convSegmentField(double px, double py, double pz, const double* q) {
    return lib::detail::convSegment<double>(px, py, pz, q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
}

double convSegmentGradient(double px, double py, double pz, const double* q, double grad[3]) {
    const Dual f = lib::detail::convSegment<Dual>(Dual::input(px, 0), Dual::input(py, 1), Dual::input(pz, 2), q[0],
                                                  q[1], q[2], q[3], q[4], q[5], q[6]);
    for (int k = 0; k < 3; ++k) grad[k] = f.d[k];
    return f.v;
}

void convSegmentBatch(const double* px, const double* py, const double* pz, double* out, size_t n,
                      const double* q) {
    for (size_t i = 0; i < n; ++i) out[i] = convSegmentField(px[i], py[i], pz[i], q);
}

namespace {

// The float path regroups the closed form to save divisions: the two end
// terms over one denominator p2 w1 q2, which also gives 1 / p2, 1 / (p2 p)
// as p / p2^2, and the two arctangents as one: atan(u) + atan(v) =
// atan2(u + v, 1 - u v) when u + v > 0, here scaled by p2 / p. |s| replaces
// s in the arctangents, whose sum is odd in s like the 1 / (2 s) it is
// scaled by. Segment constants in double, then the per-point formula in
// float.
struct SegmentLoop {
    float bx, by, bz, ax, ay, az, l, s2, sl, s2l, inv2s;

    explicit SegmentLoop(const double* q) {
        const double ld = std::sqrt((q[3] - q[0]) * (q[3] - q[0]) + (q[4] - q[1]) * (q[4] - q[1]) +
                                    (q[5] - q[2]) * (q[5] - q[2]));
        bx = static_cast<float>(q[0]); by = static_cast<float>(q[1]); bz = static_cast<float>(q[2]);
        ax = static_cast<float>((q[3] - q[0]) / ld);
        ay = static_cast<float>((q[4] - q[1]) / ld);
        az = static_cast<float>((q[5] - q[2]) / ld);
        l = static_cast<float>(ld);
        s2 = static_cast<float>(q[6] * q[6]);
        sl = static_cast<float>(std::fabs(q[6]) * ld);
        s2l = static_cast<float>(q[6] * q[6] * ld);
        inv2s = static_cast<float>(1.0 / (2.0 * std::fabs(q[6])));
    }

    HG_ALWAYS_INLINE void run(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
                              float* __restrict out, size_t n) const {
        const float bx_ = bx, by_ = by, bz_ = bz, ax_ = ax, ay_ = ay, az_ = az, l_ = l, s2_ = s2, sl_ = sl,
                    s2l_ = s2l, inv2s_ = inv2s;
        for (size_t i = 0; i < n; ++i) {
            const float dx = px[i] - bx_, dy = py[i] - by_, dz = pz[i] - bz_;
            const float xx = dx * ax_ + dy * ay_ + dz * az_;
            const float d2 = dx * dx + dy * dy + dz * dz;
            const float p2 = 1.0f + s2_ * std::max(d2 - xx * xx, 0.0f);
            const float lx = l_ - xx;
            const float w1 = 1.0f + s2_ * d2;          // p2 + s^2 xx^2
            const float q2 = w1 + s2l_ * (lx - xx);  // 1 + s^2 |p - e|^2
            // Overflows to 0, as does the field, beyond |s| d ~ 2e6 (the
            // point's distance d; not finite beyond |s| d ~ 4e9, far outside
            // any model).
            const float g = 1.0f / (p2 * w1 * q2);
            const float rp2 = w1 * q2 * g;
            const float p = std::sqrt(p2);
            const float ends = 0.5f * (xx * q2 + lx * w1) * g;
            const float den = p2 - s2_ * xx * lx;
            const float angle = fast::angleAbove(sl_ * p, den);
            out[i] = ends + angle * inv2s_ * (p * rp2 * rp2);
        }
    }
};

}  // namespace

void convSegmentBatch(const float* px, const float* py, const float* pz, float* out, size_t n, const double* q) {
    simd::run(SegmentLoop(q), px, py, pz, out, n);
}

namespace {

// The field as a function of the point's axial coordinate x along the
// segment (0 at the begin, l at the end) and its squared distance rho2 from
// the segment's line: the library routine's closed form
// (lib::detail::convSegment) written in x and rho2 directly. Calling the
// routine on the segment laid along the x axis gives the same values but
// makes the model box estimate a fifth slower (it normalizes the axis and
// rebuilds rho2 from 3D distances on every call).
double fieldAt(double x, double rho2, double l, double s) {
    const double s2 = s * s;
    const double p2 = 1.0 + s2 * rho2;
    const double p = std::sqrt(p2);
    const double w1 = p2 + s2 * x * x;
    const double q2 = 1.0 + s2 * (rho2 + (l - x) * (l - x));
    const double as = std::fabs(s);
    return x / (2.0 * p2 * w1) + (l - x) / (2.0 * p2 * q2) +
           (std::atan(as * x / p) + std::atan(as * (l - x) / p)) / (2.0 * as * p2 * p);
}

// Bounds from the field's shape: it falls with the distance rho from the
// segment's line at any fixed x (the kernel falls with distance), and along
// x it rises up to the middle, x = l / 2, then falls (its x-derivative is
// K at the begin minus K at the end). So over a box whose points have x in
// [x0, x1] and rho in [r0, r1] the field lies between the smaller of the
// values at (x0, r1) and (x1, r1) and the value at (clamp(l/2), r0).
// Against a Lipschitz band around the centre value this needs one more
// closed form per segment but is exact on that (x, rho) rectangle: on the
// key sculptures it culls a quarter of the leaves the band could not.
bool shapeBounds(const Interval p[3], const double* q, double l, double& lo, double& hi, double& rhoMinOut) {
    double axis[3], c[3], hw[3];
    for (int k = 0; k < 3; ++k) {
        axis[k] = (q[k + 3] - q[k]) / l;
        c[k] = 0.5 * (p[k].lo + p[k].hi) - q[k];
        hw[k] = 0.5 * p[k].width();
        if (!std::isfinite(c[k]) || !std::isfinite(hw[k])) return false;
    }
    double xc = 0.0, xr = 0.0;
    for (int k = 0; k < 3; ++k) {
        xc += c[k] * axis[k];
        xr += std::fabs(axis[k]) * hw[k];
    }
    // rho is convex, so its largest value is at a corner; its smallest is
    // at least the centre's less the box's half-diagonal (rho is
    // 1-Lipschitz).
    double rhoMax2 = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        double u[3], d2 = 0.0, x = 0.0;
        for (int k = 0; k < 3; ++k) {
            u[k] = c[k] + (((corner >> k) & 1) ? hw[k] : -hw[k]);
            d2 += u[k] * u[k];
            x += u[k] * axis[k];
        }
        rhoMax2 = std::max(rhoMax2, d2 - x * x);
    }
    const double d2c = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    const double rhoC = std::sqrt(std::max(d2c - xc * xc, 0.0));
    const double rb = std::sqrt(hw[0] * hw[0] + hw[1] * hw[1] + hw[2] * hw[2]);
    const double rhoMin = std::max(rhoC - rb, 0.0);
    rhoMinOut = rhoMin;
    const double x0 = xc - xr, x1 = xc + xr;
    const double s = q[6];
    // The field is symmetric about the middle, so the end of [x0, x1]
    // farther from it holds the smaller value.
    const double far = std::fabs(x0 - 0.5 * l) > std::fabs(x1 - 0.5 * l) ? x0 : x1;
    hi = fieldAt(std::clamp(0.5 * l, x0, x1), rhoMin * rhoMin, l, s);
    lo = fieldAt(far, rhoMax2, l, s);
    return std::isfinite(lo) && std::isfinite(hi);
}

}  // namespace

Interval convSegmentBounds(const Interval& px, const Interval& py, const Interval& pz, const double* q) {
    const double l = std::sqrt((q[3] - q[0]) * (q[3] - q[0]) + (q[4] - q[1]) * (q[4] - q[1]) + (q[5] - q[2]) * (q[5] - q[2]));
    const double s = q[6];
    const Interval p[3] = {px, py, pz};
    // Distances between the box and the segment's bounding box.
    double dmin2 = 0.0, dmax2 = 0.0;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
        const double slo = std::min(q[k], q[k + 3]), shi = std::max(q[k], q[k + 3]);
        const double gap = std::max({0.0, slo - p[k].hi, p[k].lo - shi});
        const double far = std::max(std::fabs(p[k].hi - slo), std::fabs(shi - p[k].lo));
        dmin2 += gap * gap;
        dmax2 += far * far;
        finite = finite && std::isfinite(p[k].lo) && std::isfinite(p[k].hi);
    }
    auto kernel = [s](double d2) { double u = 1.0 + s * s * d2; return 1.0 / (u * u); };
    double lo = l * kernel(dmax2);
    double hi = l * kernel(dmin2);
    double rhoMin = 0.0;
    if (finite && l > 0.0) {
        double shapeLo, shapeHi;
        if (shapeBounds(p, q, l, shapeLo, shapeHi, rhoMin)) {
            lo = std::max(lo, shapeLo);
            hi = std::min(hi, shapeHi);
        }
    }
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) return {0.0, l, px.maybeNaN || py.maybeNaN || pz.maybeNaN};
    // Room for rounding in the closed form and in the float path. The float
    // loop takes rho^2 as d^2 - x^2 (d: distance to the begin), which
    // cancels near the skeleton, and beyond the ends its terms nearly cancel
    // each other, so its error follows s^2 d^2 and the arctangent term's
    // scale pi / (2 |s| p^3), not just the value; tests/frep/
    // segment_bounds_test.cpp checks it needs at most half this room.
    double begin2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double far = std::max(std::fabs(p[k].lo - q[k]), std::fabs(p[k].hi - q[k]));
        begin2 += far * far;
    }
    const double as = std::fabs(s);
    const double pMin = std::sqrt(1.0 + s * s * rhoMin * rhoMin);
    const double terms = std::max(std::fabs(lo), std::fabs(hi)) + 1.5707963267948966 / (as * pMin * pMin * pMin);
    const double pad = 1e-9 + terms * (2e-5 + 1e-6 * s * s * begin2);
    if (!std::isfinite(pad)) return {0.0, l, px.maybeNaN || py.maybeNaN || pz.maybeNaN};
    return {std::max(0.0, lo - pad), hi + pad, px.maybeNaN || py.maybeNaN || pz.maybeNaN};
}

}  // namespace hg::frep
