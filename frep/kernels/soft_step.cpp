#include "frep/kernels/soft_step.h"

#include <algorithm>
#include <cmath>

#include "frep/kernels/library/skeletal.h"

namespace hg::frep {

namespace {

// The kernel alone, 1 - 22 q / 9 + 17 q^2 / 9 - 4 q^3 / 9 with q = r2 / d^2,
// and 0 beyond d. Its derivative in q is -2 (6 q^2 - 17 q + 11) / 9, whose
// roots are 1 and 11/6, so it falls all the way from 1 (q = 0) to 0 (q = 1)
// and, being 0 beyond, never rises with r2.
double kernel(double r2, double d) {
    const double q = std::max(r2, 0.0) / (d * d);
    if (q >= 1.0) return 0.0;
    return 1.0 - 22.0 * q / 9.0 + 17.0 * q * q / 9.0 - 4.0 * q * q * q / 9.0;
}

}  // namespace

double softStepField(double soft, double r2, const double* q) {
    return lib::detail::softStep<double>(soft, r2, q[0]);
}

void softStepBatch(const double* soft, const double* r2, double* out, size_t n, const double* q) {
    for (size_t i = 0; i < n; ++i) out[i] = softStepField(soft[i], r2[i], q);
}

void softStepBatch(const float* soft, const float* r2, float* out, size_t n, const double* q) {
    // The constants as the generic tape folds them (in double, then float).
    const double d = q[0], d2 = d * d, d4 = d2 * d2;
    const float df = static_cast<float>(d);
    const float c1 = static_cast<float>(9.0 * d2), c2 = static_cast<float>(9.0 * d4),
                c3 = static_cast<float>(9.0 * d4 * d2);
    for (size_t i = 0; i < n; ++i) {
        const float s = soft[i], r = r2[i];
        const float r4 = r * r;
        const float added = s + 1.0f - 22.0f * r / c1 + 17.0f * r4 / c2 - 4.0f * r4 * r / c3;
        out[i] = std::sqrt(r) <= df ? added : s;
    }
}

Interval softStepBounds(const Interval& soft, const Interval& r2, const double* q) {
    const double d = q[0];
    const bool nan = soft.maybeNaN || r2.maybeNaN;
    // The kernel never rises with r2: its largest value is at r2's low end.
    const double lo = soft.lo + kernel(r2.hi, d);
    const double hi = soft.hi + kernel(std::max(r2.lo, 0.0), d);
    // Room for rounding: the float path sums terms up to about 2.5 and
    // cancels to 0 at r2 = d^2.
    const double pad = 1e-6 * (3.0 + std::max(std::fabs(soft.lo), std::fabs(soft.hi)));
    return {lo - pad, hi + pad, nan};
}

double softStepGradient(double soft, double r2, const double* q, double grad[2]) {
    const double d = q[0];
    const double value = softStepField(soft, r2, q);
    grad[0] = 1.0;
    grad[1] = 0.0;
    if (std::sqrt(r2) <= d) {
        const double d2 = d * d;
        const double u = r2 / d2;
        grad[1] = (-22.0 + 34.0 * u - 12.0 * u * u) / (9.0 * d2);
    }
    return value;
}

}  // namespace hg::frep
