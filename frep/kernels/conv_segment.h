// Fused tape kernel Op::ConvSegment: the Cauchy line-segment field, in
// double exactly as the library routine computes it (same code, so results
// match the reference bit for bit), in float as a branch-free loop body the
// compiler vectorizes, as sound bounds over a box for the interval
// evaluator, and with its analytic gradient.
#pragma once

#include "frep/kernels/interval.h"

namespace hg::frep {

// params: begin (3), end (3), kernel width s.
double convSegmentField(double px, double py, double pz, const double* params);
// Evaluates n points; float version vectorized, double version exact.
void convSegmentBatch(const float* px, const float* py, const float* pz, float* out, size_t n, const double* params);
void convSegmentBatch(const double* px, const double* py, const double* pz, double* out, size_t n,
                      const double* params);
// Bounds of the field over a box: the field is the integral of the kernel
// K(r) = 1/(1 + s^2 r^2)^2 along the segment, so it lies between
// l K(dmax) and l K(dmin); and it falls with the distance from the
// segment's line and away from the segment's middle, so it is bounded by
// its values at the corners of the box's range of (axial position,
// distance to the line). Sound for the float path too.
Interval convSegmentBounds(const Interval& px, const Interval& py, const Interval& pz, const double* params);
// Value (as convSegmentField) and its partial derivatives along px, py, pz.
double convSegmentGradient(double px, double py, double pz, const double* params, double grad[3]);

}  // namespace hg::frep
