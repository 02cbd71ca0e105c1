#include "frep/conv_kernels.h"

#include "frep/conv_arc.h"
#include "frep/conv_segment.h"

namespace hg::frep {

double fusedField(Op op, double px, double py, double pz, const double* q) {
    return op == Op::ConvArc ? arcPieceField(px, py, pz, q) : convSegmentField(px, py, pz, q);
}

void fusedBatch(Op op, const float* px, const float* py, const float* pz, float* out, size_t n, const double* q) {
    if (op == Op::ConvArc) arcPieceBatch(px, py, pz, out, n, q);
    else convSegmentBatch(px, py, pz, out, n, q);
}

void fusedBatch(Op op, const double* px, const double* py, const double* pz, double* out, size_t n,
                const double* q) {
    if (op == Op::ConvArc) arcPieceBatch(px, py, pz, out, n, q);
    else convSegmentBatch(px, py, pz, out, n, q);
}

Interval fusedBounds(Op op, const Interval& px, const Interval& py, const Interval& pz, const double* q) {
    return op == Op::ConvArc ? arcPieceBounds(px, py, pz, q) : convSegmentBounds(px, py, pz, q);
}

double fusedGradient(Op op, double px, double py, double pz, const double* q, double grad[3]) {
    return op == Op::ConvArc ? arcPieceGradient(px, py, pz, q, grad) : convSegmentGradient(px, py, pz, q, grad);
}

}  // namespace hg::frep
