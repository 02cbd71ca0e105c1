// The library routines instantiated on Sym: the compiler records each
// routine's operations onto the tape (see frep/kernels/library/library.h).
//
// Two routine pieces are replaced by fused tape kernels (fast vector loops,
// tight interval bounds): a Cauchy line segment with constant end points and
// width becomes one Op::ConvSegment instead of ~40 instructions, and a piece
// of an hfConvArc arc with constant frame, radius, width and span one
// Op::ConvArc instead of ~100; and a step of hfSoft's sum with a constant
// radius one Op::SoftStep, whose bounds follow the kernel's fall with
// distance instead of bounding each power of it apart.
#include <cmath>

#include "frep/kernels/library/library_impl.h"
#include "frep/compiler/sym.h"

namespace hg::frep {
namespace {
// Same value as Sym, but a distinct type, so the generic expansion of
// convSegment stays reachable from its specialization below.
struct SymExpanded : Sym {
    SymExpanded(double c = 0.0) : Sym(c) {}  // NOLINT: implicit like Sym
    SymExpanded(const Sym& s) : Sym(s) {}    // NOLINT
};
}  // namespace
}  // namespace hg::frep

namespace hg::frep::lib::detail {

template <>
Sym convSegment<Sym>(const Sym& px, const Sym& py, const Sym& pz, const Sym& bx, const Sym& by, const Sym& bz,
                     const Sym& ex, const Sym& ey, const Sym& ez, const Sym& s) {
    const Sym* params[kConvSegmentParams] = {&bx, &by, &bz, &ex, &ey, &ez, &s};
    double q[kConvSegmentParams];
    bool constant = true;
    for (std::uint32_t i = 0; i < kConvSegmentParams; ++i) {
        constant = constant && params[i]->isConstant();
        q[i] = params[i]->isConstant() ? params[i]->constant() : 0.0;
    }
    // Zero-length segments keep the generic form (the reference aborts).
    bool degenerate = q[0] == q[3] && q[1] == q[4] && q[2] == q[5];
    TapeBuilder* b = px.builder() ? px.builder() : py.builder() ? py.builder() : pz.builder();
    if (constant && !degenerate && b)
        return Sym(b, b->fused(Op::ConvSegment, px.on(*b), py.on(*b), pz.on(*b), q));
    return convSegment<SymExpanded>(px, py, pz, bx, by, bz, ex, ey, ez, s);
}

template <>
Sym convArcPiece<Sym>(const Sym& x0, const Sym& x1, const Sym& x2, const Sym* frame, const double* turn,
                      const Sym& r, const Sym& s, const Sym& th) {
    double q[kConvArcParams];
    bool constant = r.isConstant() && s.isConstant() && th.isConstant();
    for (size_t i = 0; i < kArcFrame; ++i) {
        constant = constant && frame[i].isConstant();
        q[i] = frame[i].isConstant() ? frame[i].constant() : 0.0;
    }
    q[kArcFrame] = r.isConstant() ? r.constant() : 0.0;
    q[kArcFrame + 1] = s.isConstant() ? s.constant() : 0.0;
    q[kArcFrame + 2] = th.isConstant() ? th.constant() : 0.0;
    q[kArcFrame + 3] = turn ? 1.0 : 0.0;
    bool finite = true;
    for (double v : q) finite = finite && std::isfinite(v);
    // The fused kernel's float rewrite and bounds assume a proper arc of at
    // most 180 degrees; anything else keeps the generic form.
    const bool proper = finite && q[kArcFrame] > 0.0 && q[kArcFrame + 1] != 0.0 && q[kArcFrame + 2] > 0.0 &&
                        q[kArcFrame + 2] <= 180.0 * kArcDegree;
    TapeBuilder* b = x0.builder() ? x0.builder() : x1.builder() ? x1.builder() : x2.builder();
    if (constant && proper && b) return Sym(b, b->fused(Op::ConvArc, x0.on(*b), x1.on(*b), x2.on(*b), q));
    SymExpanded f[kArcFrame];
    for (size_t i = 0; i < kArcFrame; ++i) f[i] = frame[i];
    return convArcPiece<SymExpanded>(x0, x1, x2, f, turn, r, s, th);
}

template <>
Sym softStep<Sym>(const Sym& soft, const Sym& r2, const Sym& d) {
    TapeBuilder* b = soft.builder() ? soft.builder() : r2.builder();
    // A radius whose sixth power is a normal double: every constant the
    // kernel divides by is finite and non-zero (others keep the generic form).
    const double r = d.isConstant() ? d.constant() : 0.0;
    const double r6 = r * r * r * r * r * r;
    const bool fusable = d.isConstant() && r > 0.0 && std::isnormal(r6);
    if (fusable && b) {
        const double q[kSoftStepParams] = {d.constant()};
        const std::uint32_t reg = r2.on(*b);
        return Sym(b, b->fused(Op::SoftStep, soft.on(*b), reg, reg, q));
    }
    return softStep<SymExpanded>(soft, r2, d);
}

}  // namespace hg::frep::lib::detail

namespace hg::frep::lib {
template Sym call<Sym>(int, const Args<Sym>&);
}  // namespace hg::frep::lib
