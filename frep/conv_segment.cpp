#include "frep/conv_segment.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frep/dual.h"
#include "frep/fast_math.h"
#include "frep/library/convolution.h"
#include "frep/simd.h"

namespace hg::frep {
namespace {

// Bound on |grad F| for the Cauchy line field of any segment and any width:
// the integral of |K'| along an infinite line, at most 2.178 (at distance
// 0.3 / s); rounded up.
constexpr double kLineLipschitz = 2.25;

}  // namespace

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

Interval convSegmentBounds(const Interval& px, const Interval& py, const Interval& pz, const double* q) {
    const double l = std::sqrt((q[3] - q[0]) * (q[3] - q[0]) + (q[4] - q[1]) * (q[4] - q[1]) + (q[5] - q[2]) * (q[5] - q[2]));
    const double s = q[6];
    const Interval p[3] = {px, py, pz};
    // Distances between the box and the segment's bounding box.
    double dmin2 = 0.0, dmax2 = 0.0, rb2 = 0.0;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
        const double slo = std::min(q[k], q[k + 3]), shi = std::max(q[k], q[k + 3]);
        const double gap = std::max({0.0, slo - p[k].hi, p[k].lo - shi});
        const double far = std::max(std::fabs(p[k].hi - slo), std::fabs(shi - p[k].lo));
        dmin2 += gap * gap;
        dmax2 += far * far;
        rb2 += 0.25 * p[k].width() * p[k].width();
        finite = finite && std::isfinite(p[k].lo) && std::isfinite(p[k].hi);
    }
    auto kernel = [s](double d2) { double u = 1.0 + s * s * d2; return 1.0 / (u * u); };
    double lo = l * kernel(dmax2);
    double hi = l * kernel(dmin2);
    if (finite) {
        const double c = convSegmentField(0.5 * (px.lo + px.hi), 0.5 * (py.lo + py.hi), 0.5 * (pz.lo + pz.hi), q);
        // Lipschitz band; far from the segment |K'| itself bounds the slope.
        const double dmin = std::sqrt(dmin2);
        const double rStar = 1.0 / (s * std::sqrt(5.0));
        const double r = std::max(dmin, rStar);
        const double u = 1.0 + s * s * r * r;
        const double slope = std::min(kLineLipschitz, l * 4.0 * s * s * r / (u * u * u));
        const double rb = std::sqrt(rb2);
        lo = std::max(lo, c - slope * rb);
        hi = std::min(hi, c + slope * rb);
    }
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) return {0.0, l, px.maybeNaN || py.maybeNaN || pz.maybeNaN};
    // Room for rounding in the closed form and in the float path.
    const double pad = 1e-9 + 1e-6 * std::max(std::fabs(lo), std::fabs(hi));
    return {std::max(0.0, lo - pad), hi + pad, px.maybeNaN || py.maybeNaN || pz.maybeNaN};
}

}  // namespace hg::frep
