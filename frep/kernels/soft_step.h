// Fused tape kernel Op::SoftStep: one step of hfSoft's sum (Wyvill's soft
// objects), `soft + kernel(r2)` with a constant radius of influence d. Its
// inputs are the running sum (a) and the squared distance to the centre (b;
// c repeats b), not a point. In double exactly as the library computes it;
// in float as a loop the compiler vectorizes; as bounds over a box that use
// the kernel's fall from 1 at r2 = 0 to 0 at r2 = d^2 (the generic
// expansion bounds each power of r2 on its own and can only widen); and with
// its analytic gradient.
#pragma once

#include <cstddef>

#include "frep/kernels/interval.h"

namespace hg::frep {

// params: d, the radius of influence (> 0).
double softStepField(double soft, double r2, const double* params);
void softStepBatch(const float* soft, const float* r2, float* out, size_t n, const double* params);
void softStepBatch(const double* soft, const double* r2, double* out, size_t n, const double* params);
Interval softStepBounds(const Interval& soft, const Interval& r2, const double* params);
// Value (as softStepField) and its partial derivatives along soft and r2.
double softStepGradient(double soft, double r2, const double* params, double grad[2]);

}  // namespace hg::frep
