#include "frep/compiler/sym.h"

#include "frep/compiler/op_semantics.h"

namespace hg::frep {
namespace {
TapeBuilder* builderOf(const Sym& a, const Sym& b = Sym(), const Sym& c = Sym()) {
    if (a.builder()) return a.builder();
    if (b.builder()) return b.builder();
    return c.builder();
}
Sym foldFree(Op op, double a, double b, double c) {
    double v = 0.0;
    applyOp<double>(op, DomainError::None, a, b, c, v);
    return Sym(v);
}
}  // namespace

Sym symOp(Op op, const Sym& a) {
    TapeBuilder* b = builderOf(a);
    if (!b) return foldFree(op, a.constant(), 0.0, 0.0);
    return Sym(b, b->op(op, a.on(*b)));
}

Sym symOp(Op op, const Sym& a, const Sym& c2) {
    TapeBuilder* b = builderOf(a, c2);
    if (!b) return foldFree(op, a.constant(), c2.constant(), 0.0);
    return Sym(b, b->op(op, a.on(*b), c2.on(*b)));
}

Sym symOp(Op op, const Sym& a, const Sym& c2, const Sym& c3) {
    TapeBuilder* b = builderOf(a, c2, c3);
    if (!b) return foldFree(op, a.constant(), c2.constant(), c3.constant());
    return Sym(b, b->op(op, a.on(*b), c2.on(*b), c3.on(*b)));
}

}  // namespace hg::frep
