#include "frep/eval/eval_batch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "frep/compiler/conv_kernels.h"
#include "frep/kernels/fast_math.h"
#include "frep/compiler/op_semantics.h"

namespace hg::frep {

template <class T>
BatchEvaluator<T>::BatchEvaluator(const Tape& tape) : tape_(&tape), fail_(kBatch), bad_(kBatch) {
    rebind(tape);
}

template <class T>
void BatchEvaluator<T>::rebind(const Tape& tape) {
    tape_ = &tape;
    if (regs_.size() < static_cast<size_t>(tape.registers) * kBatch) regs_.resize(static_cast<size_t>(tape.registers) * kBatch);
    firstInstr_ = 0;
    for (size_t i = 0; i < tape.code.size(); ++i) {
        const Instr& in = tape.code[i];
        if (in.op == Op::X || in.op == Op::Y || in.op == Op::Z) { firstInstr_ = i + 1; continue; }
        if (in.op != Op::Const) break;
        std::fill_n(reg(tape.out[i]), kBatch, static_cast<T>(in.imm));
        firstInstr_ = i + 1;
    }
}

template <class T>
void BatchEvaluator<T>::evaluate(const T* x, const T* y, const T* z, T* out, size_t n, ErrorReport& errors,
                                 std::uint8_t* failed) {
    evaluate(x, y, z, nullptr, out, n, errors, failed);
}

template <class T>
void BatchEvaluator<T>::evaluate(const T* x, const T* y, const T* z, const T* w, T* out, size_t n,
                                 ErrorReport& errors, std::uint8_t* failed) {
    for (size_t i = 0; i < n; i += kBatch) {
        size_t m = std::min(kBatch, n - i);
        chunk(x + i, y + i, z + i, w ? w + i : nullptr, out + i, m, errors, failed ? failed + i : nullptr);
    }
}

namespace {

// Element-wise loops. `restrict` is sound: an instruction never writes a
// register it reads (TapeBuilder::finish).
template <class T, class F>
inline void unary(T* __restrict o, const T* __restrict a, size_t n, F f) {
    for (size_t i = 0; i < n; ++i) o[i] = f(a[i]);
}
template <class T, class F>
inline void binary(T* __restrict o, const T* __restrict a, const T* __restrict b, size_t n, F f) {
    for (size_t i = 0; i < n; ++i) o[i] = f(a[i], b[i]);
}

// exp, log, sin, cos: libm in double (exact path); in float a vectorized
// approximation, then libm for the lanes outside its range.
template <class T>
void transcendental(T* __restrict o, const T* __restrict a, size_t n, Op op) {
    if constexpr (std::is_same_v<T, float>) {
        unsigned fixup = 0;  // an integer reduction vectorizes; a bool one does not
        switch (op) {
            case Op::Exp:
                for (size_t i = 0; i < n; ++i) o[i] = fast::exp(a[i]);
                for (size_t i = 0; i < n; ++i) fixup |= static_cast<unsigned>(fast::needsLibmExp(a[i]));
                break;
            case Op::Log:
                for (size_t i = 0; i < n; ++i) o[i] = fast::log(a[i]);
                for (size_t i = 0; i < n; ++i) fixup |= static_cast<unsigned>(fast::needsLibmLog(a[i]));
                break;
            case Op::Sin:
                for (size_t i = 0; i < n; ++i) o[i] = fast::sin(a[i]);
                for (size_t i = 0; i < n; ++i) fixup |= static_cast<unsigned>(fast::needsLibmTrig(a[i]));
                break;
            default:
                for (size_t i = 0; i < n; ++i) o[i] = fast::cos(a[i]);
                for (size_t i = 0; i < n; ++i) fixup |= static_cast<unsigned>(fast::needsLibmTrig(a[i]));
                break;
        }
        if (!fixup) return;
        for (size_t i = 0; i < n; ++i) {
            const float v = a[i];
            switch (op) {
                case Op::Exp: if (fast::needsLibmExp(v)) o[i] = std::exp(v); break;
                case Op::Log: if (fast::needsLibmLog(v)) o[i] = std::log(v); break;
                case Op::Sin: if (fast::needsLibmTrig(v)) o[i] = std::sin(v); break;
                default: if (fast::needsLibmTrig(v)) o[i] = std::cos(v); break;
            }
        }
    } else {
        switch (op) {
            case Op::Exp: unary(o, a, n, [](T p) { return std::exp(p); }); break;
            case Op::Log: unary(o, a, n, [](T p) { return std::log(p); }); break;
            case Op::Sin: unary(o, a, n, [](T p) { return std::sin(p); }); break;
            default: unary(o, a, n, [](T p) { return std::cos(p); }); break;
        }
    }
}

}  // namespace

template <class T>
void BatchEvaluator<T>::traceNan(size_t k) {
    const Instr& in = tape_->code[k];
    const std::uint32_t o = tape_->out[k];
    if (!std::isnan(reg(o)[0])) {
        nanFrom_[o] = kNoReg;
        return;
    }
    // A NaN operand passes its origin on (a select only its chosen one);
    // with none, this instruction made the NaN. The earliest built wins:
    // instructions are in the order the compiler met them in the source.
    auto from = static_cast<std::uint32_t>(k);
    const std::uint32_t picked = in.op == Op::Select ? (reg(in.a)[0] != T(0) ? in.b : in.c) : kNoReg;
    for (std::uint32_t r : {in.a, in.b, in.c}) {
        if (r == kNoReg || (picked != kNoReg && r != picked) || !std::isnan(reg(r)[0])) continue;
        from = std::min(from, nanFrom_[r]);
    }
    nanFrom_[o] = from;
}

template <class T>
void BatchEvaluator<T>::chunk(const T* x, const T* y, const T* z, const T* w, T* out, size_t n,
                              ErrorReport& errors, std::uint8_t* failed, bool trace) {
    // Registers 0..2 are x, y, z (TapeBuilder::finish).
    for (size_t i = 0; i < tape_->code.size() && i < 3; ++i) {
        const Op op = tape_->code[i].op;
        const T* src = op == Op::X ? x : op == Op::Y ? y : z;
        std::copy_n(src, n, reg(tape_->out[i]));
    }
    if (trace) {
        nanFrom_.assign(tape_->registers, kNoReg);
        for (size_t k = 0; k < firstInstr_; ++k) traceNan(k);
    }
    std::fill_n(fail_.data(), n, std::uint8_t(0));
    bool anyFail = false;
    SourceLoc firstLoc;
    DomainError firstError = DomainError::None;

    const T eps = hf::kEps<T>;
    for (size_t k = firstInstr_; k < tape_->code.size(); ++k) {
        const Instr& in = tape_->code[k];
        T* o = reg(tape_->out[k]);
        const T* a = in.a != kNoReg ? reg(in.a) : nullptr;
        const T* b = in.b != kNoReg ? reg(in.b) : nullptr;
        const T* c = in.c != kNoReg ? reg(in.c) : nullptr;
        switch (in.op) {
            case Op::W:
                if (w) std::copy_n(w, n, o);
                else std::fill_n(o, n, T(0));  // a tape with a base input evaluated without one
                break;
            case Op::Add: binary(o, a, b, n, [](T p, T q) { return p + q; }); break;
            case Op::Sub: binary(o, a, b, n, [](T p, T q) { return p - q; }); break;
            case Op::Mul: binary(o, a, b, n, [](T p, T q) { return p * q; }); break;
            case Op::Div: binary(o, a, b, n, [](T p, T q) { return p / q; }); break;
            case Op::Neg: unary(o, a, n, [](T p) { return -p; }); break;
            case Op::Abs: unary(o, a, n, [](T p) { return std::fabs(p); }); break;
            case Op::Sqrt: unary(o, a, n, [](T p) { return std::sqrt(p); }); break;
            case Op::Exp: transcendental(o, a, n, Op::Exp); break;
            case Op::Log: transcendental(o, a, n, Op::Log); break;
            case Op::Sin: transcendental(o, a, n, Op::Sin); break;
            case Op::Cos: transcendental(o, a, n, Op::Cos); break;
            case Op::Tan: unary(o, a, n, [](T p) { return std::tan(p); }); break;
            case Op::Atan:
                if constexpr (std::is_same_v<T, float>) unary(o, a, n, [](T p) { return fast::atan(p); });
                else unary(o, a, n, [](T p) { return std::atan(p); });
                break;
            case Op::Floor: unary(o, a, n, [](T p) { return std::floor(p); }); break;
            case Op::Atan2: binary(o, a, b, n, [](T p, T q) { return std::atan2(p, q); }); break;
            case Op::EqEps: binary(o, a, b, n, [](T p, T q) { return hf::equal(p, q); }); break;
            case Op::NeEps: binary(o, a, b, n, [](T p, T q) { return hf::notEqual(p, q); }); break;
            case Op::Truthy: unary(o, a, n, [](T p) { return std::fabs(p) >= hf::kEps<T> ? T(1) : T(0); }); break;
            case Op::Not: unary(o, a, n, [](T p) { return std::fabs(p) >= hf::kEps<T> ? T(0) : T(1); }); break;
            case Op::And:
                binary(o, a, b, n, [](T p, T q) { return ((std::fabs(p) >= hf::kEps<T>) & (std::fabs(q) >= hf::kEps<T>)) ? T(1) : T(0); });
                break;
            case Op::Or:
                binary(o, a, b, n, [](T p, T q) { return ((std::fabs(p) >= hf::kEps<T>) | (std::fabs(q) >= hf::kEps<T>)) ? T(1) : T(0); });
                break;
            case Op::Min: binary(o, a, b, n, [](T p, T q) { return p < q ? p : q; }); break;
            case Op::Max: binary(o, a, b, n, [](T p, T q) { return p > q ? p : q; }); break;
            case Op::Lt: binary(o, a, b, n, [](T p, T q) { return p < q ? T(1) : T(0); }); break;
            case Op::Le: binary(o, a, b, n, [](T p, T q) { return p <= q ? T(1) : T(0); }); break;
            case Op::Gt: binary(o, a, b, n, [](T p, T q) { return p > q ? T(1) : T(0); }); break;
            case Op::Ge: binary(o, a, b, n, [](T p, T q) { return p >= q ? T(1) : T(0); }); break;
            case Op::Union:
                binary(o, a, b, n, [](T f, T g) { return f + g + std::sqrt(std::fabs(f * f + g * g)); });
                break;
            case Op::Intersect:
                binary(o, a, b, n, [](T f, T g) { return f + g - std::sqrt(std::fabs(f * f + g * g)); });
                break;
            case Op::Subtract:
                binary(o, a, b, n, [](T f, T g) { return f + -g - std::sqrt(std::fabs(f * f + g * g)); });
                break;
            case Op::Select:
                for (size_t i = 0; i < n; ++i) o[i] = a[i] != T(0) ? b[i] : c[i];
                break;
            case Op::HfDiv: {
                // Value and failure mask in separate loops: both vectorize.
                binary(o, a, b, n, [](T p, T q) { return p / q; });
                for (size_t i = 0; i < n; ++i) bad_[i] = std::fabs(b[i]) < eps;
                goto guarded;
            }
            case Op::HfSqrt: {
                unary(o, a, n, [](T p) { return std::sqrt(p); });
                for (size_t i = 0; i < n; ++i) bad_[i] = a[i] < T(0);
                goto guarded;
            }
            case Op::ConvSegment:
            case Op::ConvArc:
            case Op::SoftStep:
                fusedBatch(in.op, a, b, c, o, n, tape_->params.data() + in.param);
                break;
            case Op::Check: {
                for (size_t i = 0; i < n; ++i) { o[i] = a[i]; bad_[i] = a[i] == T(0); }
                goto guarded;
            }
            default: {
                const bool fallible = opCanFail(in.op);
                for (size_t i = 0; i < n; ++i) {
                    T v = T(0);
                    DomainError e = applyOp<T>(in.op, in.error, a ? a[i] : T(0), b ? b[i] : T(0),
                                               c ? c[i] : T(0), v);
                    o[i] = v;
                    bad_[i] = e != DomainError::None;
                }
                if (!fallible) break;
                goto guarded;
            }
            guarded: {
                const T* g = in.guard != kNoReg ? reg(in.guard) : nullptr;
                std::uint8_t hit = 0;
                for (size_t i = 0; i < n; ++i) {
                    const std::uint8_t f = static_cast<std::uint8_t>(bad_[i] & (g ? (g[i] != T(0)) : 1));
                    hit = static_cast<std::uint8_t>(hit | (f & !fail_[i]));
                    fail_[i] = static_cast<std::uint8_t>(fail_[i] | f);
                }
                if (hit && !anyFail) {
                    anyFail = true;
                    firstLoc = tape_->sites[in.site];
                    firstError = in.op == Op::Check ? in.error : [&] {
                        for (size_t i = 0; i < n; ++i) {
                            if (!bad_[i]) continue;
                            T v;
                            return applyOp<T>(in.op, in.error, a ? a[i] : T(0), b ? b[i] : T(0), T(0), v);
                        }
                        return DomainError::NotANumber;
                    }();
                }
                break;
            }
        }
        if (trace) traceNan(k);
    }

    const T* r = reg(tape_->result);
    const T limit = clamped_ ? static_cast<T>(kValueLimit) : std::numeric_limits<T>::infinity();
    std::uint64_t failures = 0;
    size_t nanPoint = n;  // the first point that failed only by being NaN, when that is the first error
    for (size_t i = 0; i < n; ++i) {
        T v = r[i];
        bool f = fail_[i] || std::isnan(v);
        if (f && !fail_[i] && firstError == DomainError::None) {
            firstError = DomainError::NotANumber;
            nanPoint = i;
        }
        failures += f;
        v = f ? static_cast<T>(kOutsideValue) : std::min(std::max(v, -limit), limit);
        out[i] = v;
        if (failed) failed[i] = f;
    }
    if (!failures) return;
    if (nanPoint < n) {
        // Where the NaN came from: that point again, following it through
        // the tape (the registers are free now). Rare, so not worth a
        // register of origins on every point.
        if (trace) {
            const std::uint32_t from = nanFrom_[tape_->result];
            if (from < tape_->locs.size()) firstLoc = tape_->locs[from];
        } else {
            ErrorReport one;
            T v;
            chunk(x + nanPoint, y + nanPoint, z + nanPoint, w ? w + nanPoint : nullptr, &v, 1, one, nullptr, true);
            firstLoc = one.firstLoc;
        }
    }
    errors.add(firstError, firstLoc, failures);
}

template class BatchEvaluator<float>;
template class BatchEvaluator<double>;

}  // namespace hg::frep
