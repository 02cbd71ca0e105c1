// The library routines instantiated on Sym: the compiler records each
// routine's operations onto the tape (see frep/library/library.h).
//
// One routine piece is replaced by a fused tape kernel: a Cauchy line
// segment with constant end points and width becomes one Op::ConvSegment
// (fast vector loop, tight interval bounds) instead of ~40 instructions.
#include "frep/library/library_impl.h"
#include "frep/sym.h"

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
        return Sym(b, b->convSegment(px.on(*b), py.on(*b), pz.on(*b), q));
    return convSegment<SymExpanded>(px, py, pz, bx, by, bz, ex, ey, ez, s);
}

}  // namespace hg::frep::lib::detail

namespace hg::frep::lib {
template Sym call<Sym>(int, const Args<Sym>&);
}  // namespace hg::frep::lib
