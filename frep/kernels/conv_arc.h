// Fused tape kernel Op::ConvArc: one piece of an hfConvArc arc (its first
// 180 degrees, or the part beyond them), parameters as in frep/compiler/tape.h. The
// field is the integral of the Cauchy kernel K(d) = 1 / (1 + s^2 d^2)^2 over
// the arc's angle, F(p) = int_0^th K(|n - r (cos t, sin t, 0)|) dt, n the
// point in the arc's frame.
//
// The library's closed form divides by the frame coordinate n_x: it is NaN
// or meaningless on and next to the plane n_x = 0, where its two terms
// cancel. The double path keeps it (bit for bit with the reference), the
// float path uses a cancellation-free rewrite, and the bounds account for
// the double path's rounding.
#pragma once

#include <cstddef>

#include "frep/kernels/interval.h"

namespace hg::frep {

// The library's value, bit for bit.
double arcPieceField(double px, double py, double pz, const double* params);
// Evaluates n points; float version vectorized, double version exact.
void arcPieceBatch(const float* px, const float* py, const float* pz, float* out, size_t n, const double* params);
void arcPieceBatch(const double* px, const double* py, const double* pz, double* out, size_t n, const double* params);
// Sound bounds over a box (see conv_arc.cpp for the derivation).
Interval arcPieceBounds(const Interval& px, const Interval& py, const Interval& pz, const double* params);
// Value (as arcPieceField) and its partial derivatives along px, py, pz.
double arcPieceGradient(double px, double py, double pz, const double* params, double grad[3]);

}  // namespace hg::frep
