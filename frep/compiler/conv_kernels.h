// The fused kernels of the tape (Op::ConvSegment in conv_segment.h,
// Op::ConvArc in conv_arc.h, Op::SoftStep in soft_step.h), dispatched by
// opcode so that the builder and the evaluators treat every fused kernel
// alike. `params` points at the instruction's block in Tape::params. The
// inputs are named for the point kernels; SoftStep reads (sum, r2) from px
// and py and gives no slope along pz.
#pragma once

#include <cstddef>

#include "frep/kernels/interval.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

// The library's value at one point, bit for bit (constant folding, exact path).
double fusedField(Op op, double px, double py, double pz, const double* params);
// n points: the float version vectorized, the double version exact.
void fusedBatch(Op op, const float* px, const float* py, const float* pz, float* out, size_t n, const double* params);
void fusedBatch(Op op, const double* px, const double* py, const double* pz, double* out, size_t n,
                const double* params);
// Sound bounds over a box.
Interval fusedBounds(Op op, const Interval& px, const Interval& py, const Interval& pz, const double* params);
// Value (as fusedField) and its analytic partial derivatives along px, py, pz.
double fusedGradient(Op op, double px, double py, double pz, const double* params, double grad[3]);

}  // namespace hg::frep
