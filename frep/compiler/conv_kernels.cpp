#include "frep/compiler/conv_kernels.h"

#include "frep/kernels/conv_arc.h"
#include "frep/kernels/conv_segment.h"
#include "frep/kernels/soft_step.h"

namespace hg::frep {

// Op::SoftStep's inputs are (sum, r2, r2), not a point: it reads a and b.

double fusedField(Op op, double px, double py, double pz, const double* q) {
    switch (op) {
        case Op::ConvArc: return arcPieceField(px, py, pz, q);
        case Op::SoftStep: return softStepField(px, py, q);
        default: return convSegmentField(px, py, pz, q);
    }
}

void fusedBatch(Op op, const float* px, const float* py, const float* pz, float* out, size_t n, const double* q) {
    switch (op) {
        case Op::ConvArc: arcPieceBatch(px, py, pz, out, n, q); break;
        case Op::SoftStep: softStepBatch(px, py, out, n, q); break;
        default: convSegmentBatch(px, py, pz, out, n, q); break;
    }
}

void fusedBatch(Op op, const double* px, const double* py, const double* pz, double* out, size_t n,
                const double* q) {
    switch (op) {
        case Op::ConvArc: arcPieceBatch(px, py, pz, out, n, q); break;
        case Op::SoftStep: softStepBatch(px, py, out, n, q); break;
        default: convSegmentBatch(px, py, pz, out, n, q); break;
    }
}

Interval fusedBounds(Op op, const Interval& px, const Interval& py, const Interval& pz, const double* q) {
    switch (op) {
        case Op::ConvArc: return arcPieceBounds(px, py, pz, q);
        case Op::SoftStep: return softStepBounds(px, py, q);
        default: return convSegmentBounds(px, py, pz, q);
    }
}

double fusedGradient(Op op, double px, double py, double pz, const double* q, double grad[3]) {
    switch (op) {
        case Op::ConvArc: return arcPieceGradient(px, py, pz, q, grad);
        case Op::SoftStep: {
            const double v = softStepGradient(px, py, q, grad);
            grad[2] = 0.0;
            return v;
        }
        default: return convSegmentGradient(px, py, pz, q, grad);
    }
}

}  // namespace hg::frep
