#include "frep/conv_kernels.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "frep/fast_math.h"
#include "frep/library/convolution.h"

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

void convSegmentBatch(const double* px, const double* py, const double* pz, double* out, size_t n,
                      const double* q) {
    for (size_t i = 0; i < n; ++i) out[i] = convSegmentField(px[i], py[i], pz[i], q);
}

void convSegmentBatch(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
                      float* __restrict out, size_t n, const double* q) {
    // Segment constants in double, then the per-point formula in float.
    const double ld = std::sqrt((q[3] - q[0]) * (q[3] - q[0]) + (q[4] - q[1]) * (q[4] - q[1]) + (q[5] - q[2]) * (q[5] - q[2]));
    const float bx = static_cast<float>(q[0]), by = static_cast<float>(q[1]), bz = static_cast<float>(q[2]);
    const float ax = static_cast<float>((q[3] - q[0]) / ld), ay = static_cast<float>((q[4] - q[1]) / ld),
                az = static_cast<float>((q[5] - q[2]) / ld);
    const float l = static_cast<float>(ld), s = static_cast<float>(q[6]), s2 = s * s;
    const float inv2s = static_cast<float>(1.0 / (2.0 * q[6]));
    for (size_t i = 0; i < n; ++i) {
        const float dx = px[i] - bx, dy = py[i] - by, dz = pz[i] - bz;
        const float xx = dx * ax + dy * ay + dz * az;
        const float d2 = dx * dx + dy * dy + dz * dz;
        const float p2 = 1.0f + s2 * std::max(d2 - xx * xx, 0.0f);
        const float q2 = 1.0f + s2 * (d2 + l * l - 2.0f * l * xx);
        const float p = std::sqrt(p2);
        const float lx = l - xx;
        out[i] = xx / (2.0f * p2 * (p2 + s2 * xx * xx)) + lx / (2.0f * p2 * q2) +
                 (fast::atan(s * xx / p) + fast::atan(s * lx / p)) * inv2s / (p2 * p);
    }
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
