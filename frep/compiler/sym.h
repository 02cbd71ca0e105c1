// Sym: a value on a tape under construction. Library routines written over
// a value type (frep/kernels/library/value_ops.h) run on Sym to record their
// operations; a Sym without a builder is a plain constant.
#pragma once

#include <cstdint>

#include "frep/compiler/tape_builder.h"

namespace hg::frep {

class Sym {
public:
    Sym(double c = 0.0) : constant_(c) {}  // NOLINT: implicit, like a double literal
    Sym(TapeBuilder* b, std::uint32_t id) : builder_(b), id_(id) {}

    TapeBuilder* builder() const { return builder_; }
    bool isConstant() const { return builder_ == nullptr || builder_->isConstant(id_); }
    double constant() const { return builder_ == nullptr ? constant_ : builder_->constantValue(id_); }
    // The value's id on `b`, materializing a constant when needed.
    std::uint32_t on(TapeBuilder& b) const { return builder_ ? id_ : b.constant(constant_); }

private:
    TapeBuilder* builder_ = nullptr;
    std::uint32_t id_ = kNoReg;
    double constant_ = 0.0;
};

Sym symOp(Op op, const Sym& a);
Sym symOp(Op op, const Sym& a, const Sym& b);
Sym symOp(Op op, const Sym& a, const Sym& b, const Sym& c);

inline Sym operator+(const Sym& a, const Sym& b) { return symOp(Op::Add, a, b); }
inline Sym operator-(const Sym& a, const Sym& b) { return symOp(Op::Sub, a, b); }
inline Sym operator*(const Sym& a, const Sym& b) { return symOp(Op::Mul, a, b); }
inline Sym operator/(const Sym& a, const Sym& b) { return symOp(Op::Div, a, b); }
inline Sym operator-(const Sym& a) { return symOp(Op::Neg, a); }
inline Sym& operator+=(Sym& a, const Sym& b) { return a = a + b; }
inline Sym& operator-=(Sym& a, const Sym& b) { return a = a - b; }
inline Sym& operator*=(Sym& a, const Sym& b) { return a = a * b; }
inline Sym& operator/=(Sym& a, const Sym& b) { return a = a / b; }

inline Sym sqrt(const Sym& a) { return symOp(Op::Sqrt, a); }
inline Sym exp(const Sym& a) { return symOp(Op::Exp, a); }
inline Sym log(const Sym& a) { return symOp(Op::Log, a); }
inline Sym sin(const Sym& a) { return symOp(Op::Sin, a); }
inline Sym cos(const Sym& a) { return symOp(Op::Cos, a); }
inline Sym tan(const Sym& a) { return symOp(Op::Tan, a); }
inline Sym atan(const Sym& a) { return symOp(Op::Atan, a); }
inline Sym asin(const Sym& a) { return symOp(Op::Asin, a); }
inline Sym acos(const Sym& a) { return symOp(Op::Acos, a); }
inline Sym atan2(const Sym& y, const Sym& x) { return symOp(Op::Atan2, y, x); }
inline Sym fabs(const Sym& a) { return symOp(Op::Abs, a); }
inline Sym pow(const Sym& b, const Sym& e) { return symOp(Op::Pow, b, e); }
inline Sym floor(const Sym& a) { return symOp(Op::Floor, a); }
inline Sym lt(const Sym& a, const Sym& b) { return symOp(Op::Lt, a, b); }
inline Sym le(const Sym& a, const Sym& b) { return symOp(Op::Le, a, b); }
inline Sym gt(const Sym& a, const Sym& b) { return symOp(Op::Gt, a, b); }
inline Sym ge(const Sym& a, const Sym& b) { return symOp(Op::Ge, a, b); }
inline Sym land(const Sym& a, const Sym& b) { return symOp(Op::And, a, b); }
inline Sym lor(const Sym& a, const Sym& b) { return symOp(Op::Or, a, b); }
inline Sym select(const Sym& c, const Sym& a, const Sym& b) { return symOp(Op::Select, c, a, b); }
inline bool isConstant(const Sym& a) { return a.isConstant(); }
inline double constantValue(const Sym& a) { return a.constant(); }

}  // namespace hg::frep
