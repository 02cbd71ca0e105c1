// What each tape opcode computes at one point, for any floating type. The
// builder folds constants with it and the batch evaluators use it for the
// opcodes that have no vector loop of their own, so every path shares one
// definition (language rules in hf_math.h).
#pragma once

#include <cmath>

#include "frep/language/hf_math.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

// Computes `op` on a, b, c. Returns the domain error of a fallible op (the
// caller decides whether its guard holds); `out` is then unspecified.
template <class T>
inline DomainError applyOp(Op op, DomainError checkError, T a, T b, T c, T& out) {
    using std::fabs;
    switch (op) {
        case Op::X: case Op::Y: case Op::Z: case Op::Const: out = a; return DomainError::None;
        case Op::Add: out = a + b; break;
        case Op::Sub: out = a - b; break;
        case Op::Mul: out = a * b; break;
        case Op::Div: out = a / b; break;
        case Op::Neg: out = -a; break;
        case Op::Abs: out = fabs(a); break;
        case Op::Sqrt: out = std::sqrt(a); break;
        case Op::Exp: out = std::exp(a); break;
        case Op::Log: out = std::log(a); break;
        case Op::Sin: out = std::sin(a); break;
        case Op::Cos: out = std::cos(a); break;
        case Op::Tan: out = std::tan(a); break;
        case Op::Atan: out = std::atan(a); break;
        case Op::Asin: out = std::asin(a); break;
        case Op::Acos: out = std::acos(a); break;
        case Op::Atan2: out = std::atan2(a, b); break;
        case Op::Pow: out = std::pow(a, b); break;
        case Op::Floor: out = std::floor(a); break;
        case Op::Ceil: out = std::ceil(a); break;
        case Op::Trunc: out = std::trunc(a); break;
        case Op::Sinh: out = std::sinh(a); break;
        case Op::Cosh: out = std::cosh(a); break;
        case Op::Tanh: out = std::tanh(a); break;
        case Op::Lt: out = hf::fromBool<T>(a < b); break;
        case Op::Le: out = hf::fromBool<T>(a <= b); break;
        case Op::Gt: out = hf::fromBool<T>(a > b); break;
        case Op::Ge: out = hf::fromBool<T>(a >= b); break;
        case Op::EqEps: out = hf::equal(a, b); break;
        case Op::NeEps: out = hf::notEqual(a, b); break;
        case Op::And: out = hf::logicalAnd(a, b); break;
        case Op::Or: out = hf::logicalOr(a, b); break;
        case Op::Not: out = hf::logicalNot(a); break;
        case Op::Truthy: out = hf::fromBool<T>(hf::truthy(a)); break;
        case Op::Select: out = (a != T(0)) ? b : c; break;
        case Op::Min: out = hf::minimum(a, b); break;
        case Op::Max: out = hf::maximum(a, b); break;
        case Op::Union: out = hf::unite(a, b); break;
        case Op::Intersect: out = hf::intersect(a, b); break;
        case Op::Subtract: out = hf::subtract(a, b); break;
        case Op::HfDiv: return hf::divide(a, b, out);
        case Op::HfPow: return hf::power(a, b, out);
        case Op::HfSqrt: return hf::checkedSqrt(a, out);
        case Op::HfLog: return hf::checkedLog(a, out);
        case Op::HfLog10: return hf::checkedLog10(a, out);
        case Op::HfAsin: return hf::checkedAsin(a, out);
        case Op::HfAcos: return hf::checkedAcos(a, out);
        case Op::HfTan: return hf::checkedTan(a, out);
        case Op::HfMod: return hf::mod(a, b, out);
        case Op::Check:
            out = a;
            return a != T(0) ? DomainError::None : checkError;
        case Op::ConvSegment:  // fused kernels need their parameters: evaluated by the callers
        case Op::ConvArc:
        case Op::SoftStep:
        case Op::W:  // the base value input: read by the batch evaluator itself
            out = T(0);
            break;
    }
    return DomainError::None;
}

}  // namespace hg::frep
