#include "frep/compiler/compiler.h"

#include <stdexcept>

#include "frep/language/hf_math.h"
#include "frep/kernels/library/library.h"
#include "frep/compiler/sym.h"
#include "frep/compiler/tape_builder.h"

namespace hg::frep {
namespace {

// Loops are unrolled up to this many iterations in total.
constexpr long long kMaxUnrolledIterations = 200'000;

struct CannotFlatten {
    std::string reason;
    SourceLoc loc;
};

// A value plus whether it has been assigned (a 0/1 value: it may depend on
// which branches the point took).
struct Slot {
    std::uint32_t value = kNoReg;
    std::uint32_t assigned = kNoReg;  // kNoReg: never assigned on any path
};

struct Frame {
    std::vector<std::vector<Slot>> arrays;
    std::vector<Slot> vars;
};

// The values built while an expression compiles (its own operations, or
// the whole expansion of a library call) carry its location, so that an
// evaluator can say where a NaN came from.
class LocScope {
public:
    LocScope(TapeBuilder& b, SourceLoc loc) : b_(b), saved_(b.setLoc(loc)) {}
    ~LocScope() { b_.setLoc(saved_); }
    LocScope(const LocScope&) = delete;
    LocScope& operator=(const LocScope&) = delete;

private:
    TapeBuilder& b_;
    SourceLoc saved_;
};

class Compiler {
public:
    Compiler(const Program& p, TapeBuilder& b) : program_(p), b_(b) {
        one_ = b_.constant(1.0);
        zero_ = b_.constant(0.0);
    }

    std::uint32_t compileBody(int body, Frame& f, std::uint32_t guard) {
        const Body& bd = program_.bodies[static_cast<size_t>(body)];
        block(bd.statements, bd, f, guard);
        return expr(*bd.result, bd, f, guard);
    }

    Frame newFrame(int body) {
        const Body& bd = program_.bodies[static_cast<size_t>(body)];
        Frame f;
        f.arrays.resize(bd.arrays.size());
        for (size_t i = 0; i < bd.arrays.size(); ++i) {
            f.arrays[i].assign(static_cast<size_t>(bd.arrays[i].size), Slot{zero_, zero_});
        }
        f.vars.assign(bd.variables.size(), Slot{zero_, zero_});
        return f;
    }

    std::uint32_t one_ = kNoReg, zero_ = kNoReg;

private:
    [[noreturn]] void cannot(const std::string& why, SourceLoc loc) { throw CannotFlatten{why, loc}; }

    // Reads a slot: where it may be unassigned, that is a runtime error.
    std::uint32_t read(const Slot& s, std::uint32_t guard, SourceLoc loc) {
        b_.check(s.assigned, guard, loc, DomainError::UnassignedValue);
        return s.value;
    }

    bool constIndex(const Expr& e, const Body& bd, Frame& f, std::uint32_t guard, int slot, size_t& out) {
        std::uint32_t v = expr(e, bd, f, guard);
        if (!b_.isConstant(v)) cannot("array index depends on the point", e.loc);
        long long i = hf::round(b_.constantValue(v));
        long long size = bd.arrays[static_cast<size_t>(slot)].size;
        if (i < 1 || i > size) {
            b_.check(zero_, guard, e.loc, DomainError::IndexOutOfRange);
            return false;
        }
        out = static_cast<size_t>(i - 1);
        return true;
    }

    void block(const std::vector<Stmt>& stmts, const Body& bd, Frame& f, std::uint32_t guard) {
        for (const Stmt& s : stmts) statement(s, bd, f, guard);
    }

    void statement(const Stmt& s, const Body& bd, Frame& f, std::uint32_t guard) {
        switch (s.kind) {
            case StmtKind::Assign:
                f.vars[static_cast<size_t>(s.slot)] = Slot{expr(*s.value, bd, f, guard), one_};
                return;
            case StmtKind::AssignElement: {
                size_t i = 0;
                bool inRange = constIndex(*s.index, bd, f, guard, s.slot, i);
                std::uint32_t v = expr(*s.value, bd, f, guard);
                if (inRange) f.arrays[static_cast<size_t>(s.slot)][i] = Slot{v, one_};
                return;
            }
            case StmtKind::AssignArray: {
                auto& arr = f.arrays[static_cast<size_t>(s.slot)];
                for (size_t i = 0; i < arr.size() && i < s.literal.size(); ++i)
                    arr[i] = Slot{b_.constant(s.literal[i]), one_};
                return;
            }
            case StmtKind::If: {
                std::uint32_t c = b_.op(Op::Truthy, expr(*s.condition, bd, f, guard));
                if (b_.isConstant(c)) {
                    block(b_.constantValue(c) != 0.0 ? s.thenBody : s.elseBody, bd, f, guard);
                    return;
                }
                Frame thenFrame = f;
                Frame elseFrame = f;
                block(s.thenBody, bd, thenFrame, b_.andGuard(guard, c));
                block(s.elseBody, bd, elseFrame, b_.andGuard(guard, b_.op(Op::Not, c)));
                merge(c, thenFrame, elseFrame, f);
                return;
            }
            case StmtKind::While: {
                for (;;) {
                    std::uint32_t c = b_.op(Op::Truthy, expr(*s.condition, bd, f, guard));
                    if (!b_.isConstant(c)) cannot("while condition depends on the point", s.condition->loc);
                    if (b_.constantValue(c) == 0.0) break;
                    if (++iterations_ > kMaxUnrolledIterations) cannot("loop too long to unroll", s.loc);
                    block(s.thenBody, bd, f, guard);
                }
                return;
            }
        }
    }

    Slot mergeSlot(std::uint32_t c, const Slot& t, const Slot& e) {
        return Slot{b_.op(Op::Select, c, t.value, e.value), b_.op(Op::Select, c, t.assigned, e.assigned)};
    }

    void merge(std::uint32_t c, const Frame& t, const Frame& e, Frame& out) {
        for (size_t i = 0; i < out.vars.size(); ++i) out.vars[i] = mergeSlot(c, t.vars[i], e.vars[i]);
        for (size_t a = 0; a < out.arrays.size(); ++a)
            for (size_t i = 0; i < out.arrays[a].size(); ++i)
                out.arrays[a][i] = mergeSlot(c, t.arrays[a][i], e.arrays[a][i]);
    }

    // Every item of an array handed to a routine or body must be assigned.
    void requireAssigned(const std::vector<Slot>& arr, std::uint32_t guard, SourceLoc loc) {
        std::uint32_t all = one_;
        for (const Slot& s : arr) all = b_.op(Op::And, all, s.assigned);
        b_.check(all, guard, loc, DomainError::UnassignedValue);
    }

    std::uint32_t fallible(Op op, std::uint32_t a, std::uint32_t b, std::uint32_t guard, SourceLoc loc) {
        return b_.fallible(op, a, b, guard, loc);
    }

    // b ^ e with a constant integer exponent: the reference's repeated
    // product, so results match bit for bit.
    std::uint32_t power(std::uint32_t base, std::uint32_t e, std::uint32_t guard, SourceLoc loc) {
        if (!b_.isConstant(e) || b_.isConstant(base)) return fallible(Op::HfPow, base, e, guard, loc);
        double ev = b_.constantValue(e);
        if (!(ev - std::floor(ev) < hf::kEps<double>)) return fallible(Op::HfPow, base, e, guard, loc);
        long long n = hf::round(std::fabs(ev));
        if (n > 64) return fallible(Op::HfPow, base, e, guard, loc);
        std::uint32_t v = one_;
        for (long long i = 0; i < n; ++i) v = b_.op(Op::Mul, v, base);
        if (ev < 0.0) v = b_.op(Op::Div, one_, v);
        std::uint32_t nearZero = b_.op(Op::Lt, b_.op(Op::Abs, base), b_.constant(hf::kEps<double>));
        if (ev <= hf::kEps<double>) {
            b_.check(b_.op(Op::Not, nearZero), guard, loc, DomainError::ZeroBasePower);
            return v;
        }
        return b_.op(Op::Select, nearZero, zero_, v);
    }

    std::uint32_t expr(const Expr& e, const Body& bd, Frame& f, std::uint32_t guard) {
        LocScope at(b_, e.loc);
        switch (e.kind) {
            case ExprKind::Number: return b_.constant(e.number);
            case ExprKind::Variable: return read(f.vars[static_cast<size_t>(e.slot)], guard, e.loc);
            case ExprKind::ArrayElement: {
                size_t i = 0;
                if (!constIndex(*e.args[0], bd, f, guard, e.slot, i)) return zero_;
                return read(f.arrays[static_cast<size_t>(e.slot)][i], guard, e.loc);
            }
            case ExprKind::ArrayName: return zero_;
            case ExprKind::Unary: {
                std::uint32_t v = expr(*e.args[0], bd, f, guard);
                switch (e.unaryOp) {
                    case UnaryOp::Plus: return v;
                    case UnaryOp::Minus:
                    case UnaryOp::Tilde: return b_.op(Op::Neg, v);
                    case UnaryOp::Not: return b_.op(Op::Not, v);
                }
                return v;
            }
            case ExprKind::Binary: {
                std::uint32_t r = expr(*e.args[1], bd, f, guard);
                std::uint32_t l = expr(*e.args[0], bd, f, guard);
                switch (e.binaryOp) {
                    case BinaryOp::Add: return b_.op(Op::Add, l, r);
                    case BinaryOp::Sub: return b_.op(Op::Sub, l, r);
                    case BinaryOp::Mul: return b_.op(Op::Mul, l, r);
                    case BinaryOp::Div: return fallible(Op::HfDiv, l, r, guard, e.loc);
                    case BinaryOp::Pow: return power(l, r, guard, e.loc);
                    case BinaryOp::Union: return b_.op(Op::Union, l, r);
                    case BinaryOp::Intersection: return b_.op(Op::Intersect, l, r);
                    case BinaryOp::Difference: return b_.op(Op::Subtract, l, r);
                    case BinaryOp::Equal: return b_.op(Op::EqEps, l, r);
                    case BinaryOp::NotEqual: return b_.op(Op::NeEps, l, r);
                    case BinaryOp::Less: return b_.op(Op::Lt, l, r);
                    case BinaryOp::LessEqual: return b_.op(Op::Le, l, r);
                    case BinaryOp::Greater: return b_.op(Op::Gt, l, r);
                    case BinaryOp::GreaterEqual: return b_.op(Op::Ge, l, r);
                    case BinaryOp::And: return b_.op(Op::And, l, r);
                    case BinaryOp::Or: return b_.op(Op::Or, l, r);
                }
                return l;
            }
            case ExprKind::BuiltinCall: return builtin(e, bd, f, guard);
            case ExprKind::LibraryCall: return library(e, bd, f, guard);
            case ExprKind::BodyCall: return bodyCall(e, bd, f, guard);
        }
        return zero_;
    }

    std::uint32_t builtin(const Expr& e, const Body& bd, Frame& f, std::uint32_t guard) {
        std::uint32_t v[2] = {zero_, zero_};
        for (size_t i = e.args.size(); i-- > 0;) v[i < 2 ? i : 1] = expr(*e.args[i], bd, f, guard);
        switch (e.builtin) {
            case Builtin::Sqrt: return fallible(Op::HfSqrt, v[0], kNoReg, guard, e.loc);
            case Builtin::Exp: return b_.op(Op::Exp, v[0]);
            case Builtin::Log: return fallible(Op::HfLog, v[0], kNoReg, guard, e.loc);
            case Builtin::Logd: return fallible(Op::HfLog10, v[0], kNoReg, guard, e.loc);
            case Builtin::Sin: return b_.op(Op::Sin, v[0]);
            case Builtin::Cos: return b_.op(Op::Cos, v[0]);
            case Builtin::Tan: return fallible(Op::HfTan, v[0], kNoReg, guard, e.loc);
            case Builtin::Asin: return fallible(Op::HfAsin, v[0], kNoReg, guard, e.loc);
            case Builtin::Acos: return fallible(Op::HfAcos, v[0], kNoReg, guard, e.loc);
            case Builtin::Atan: return b_.op(Op::Atan, v[0]);
            case Builtin::Atan2: return b_.op(Op::Atan2, v[0], v[1]);
            case Builtin::Abs: return b_.op(Op::Abs, v[0]);
            case Builtin::Sinh: return b_.op(Op::Sinh, v[0]);
            case Builtin::Cosh: return b_.op(Op::Cosh, v[0]);
            case Builtin::Tanh: return b_.op(Op::Tanh, v[0]);
            case Builtin::Sign: return one_;
            case Builtin::Mod: return fallible(Op::HfMod, v[0], v[1], guard, e.loc);
            case Builtin::Max: return b_.op(Op::Max, v[0], v[1]);
            case Builtin::Min: return b_.op(Op::Min, v[0], v[1]);
            case Builtin::Ceil: return b_.op(Op::Ceil, v[0]);
            case Builtin::Floor: return b_.op(Op::Floor, v[0]);
            case Builtin::Int: return b_.op(Op::Trunc, v[0]);
            case Builtin::Frac: return b_.op(Op::Sub, v[0], b_.op(Op::Trunc, v[0]));
        }
        return zero_;
    }

    std::uint32_t library(const Expr& e, const Body& bd, Frame& f, std::uint32_t guard) {
        const auto& info = lib::functions()[static_cast<size_t>(e.function)];
        lib::Args<Sym> args;
        args.arrays.assign(e.args.size(), nullptr);
        args.scalars.assign(e.args.size(), Sym());
        // Last argument first; arrays are checked where they stand in that
        // order but read when the routine runs (they are passed by reference).
        for (size_t i = e.args.size(); i-- > 0;) {
            const Expr& arg = *e.args[i];
            if (info.params[i] == lib::ParamKind::Array)
                requireAssigned(f.arrays[static_cast<size_t>(arg.slot)], guard, arg.loc);
            else
                args.scalars[i] = Sym(&b_, expr(arg, bd, f, guard));
        }
        // One working copy per distinct array, so aliasing behaves as in C.
        std::vector<std::pair<int, std::vector<Sym>>> work;
        work.reserve(e.args.size());
        for (size_t i = 0; i < e.args.size(); ++i) {
            if (info.params[i] != lib::ParamKind::Array) continue;
            int slot = e.args[i]->slot;
            std::vector<Sym>* w = nullptr;
            for (auto& [s, v] : work)
                if (s == slot) w = &v;
            if (!w) {
                std::vector<Sym> v;
                for (const Slot& s : f.arrays[static_cast<size_t>(slot)]) v.emplace_back(&b_, s.value);
                work.emplace_back(slot, std::move(v));
                w = &work.back().second;
            }
            args.arrays[i] = w;
        }
        Sym r;
        try {
            r = lib::call<Sym>(e.function, args);
        } catch (const lib::NotCompilable& nc) {
            cannot(std::string(info.spelling) + ": " + nc.what(), e.loc);
        }
        for (auto& [slot, v] : work) {
            auto& arr = f.arrays[static_cast<size_t>(slot)];
            for (size_t i = 0; i < arr.size(); ++i) arr[i].value = v[i].on(b_);
        }
        return r.on(b_);
    }

    std::uint32_t bodyCall(const Expr& e, const Body&, Frame& f, std::uint32_t guard) {
        Frame cf = newFrame(e.function);
        int sSource = kArrayS;
        for (size_t i = e.args.size(); i-- > 0;) {
            const Expr& arg = *e.args[i];
            const auto& arr = f.arrays[static_cast<size_t>(arg.slot)];
            requireAssigned(arr, guard, arg.loc);
            for (size_t k = 0; k < cf.arrays[i].size() && k < arr.size(); ++k)
                cf.arrays[i][k] = Slot{arr[k].value, one_};
            if (i == static_cast<size_t>(kArrayS)) sSource = arg.slot;
        }
        if (e.args.size() <= static_cast<size_t>(kArrayS)) {
            const auto& arr = f.arrays[kArrayS];
            for (size_t k = 0; k < cf.arrays[kArrayS].size() && k < arr.size(); ++k)
                cf.arrays[kArrayS][k] = Slot{arr[k].value, one_};
        }
        std::uint32_t r = compileBody(e.function, cf, guard);
        auto& dst = f.arrays[static_cast<size_t>(sSource)];
        for (size_t k = 0; k < dst.size() && k < cf.arrays[kArrayS].size(); ++k) dst[k] = cf.arrays[kArrayS][k];
        return r;
    }

    const Program& program_;
    TapeBuilder& b_;
    long long iterations_ = 0;
};

}  // namespace

CompileResult compile(const Program& program, int body, const std::vector<double>& a) {
    CompileResult result;
    if (body < 0 || static_cast<size_t>(body) >= program.bodies.size()) {
        result.reason = "no such body";
        return result;
    }
    try {
        // Inputs (x, a[]) carry the body's location, as the interpreter
        // reports a NaN that no operation produced.
        TapeBuilder b(program.bodies[static_cast<size_t>(body)].resultLoc);
        Compiler c(program, b);
        Frame f = c.newFrame(body);
        const std::uint32_t xyz[3] = {b.x(), b.y(), b.z()};
        for (size_t i = 0; i < f.arrays[kArrayX].size(); ++i)
            f.arrays[kArrayX][i] = Slot{i < 3 ? xyz[i] : c.zero_, c.one_};
        for (size_t i = 0; i < f.arrays[kArrayA].size(); ++i)
            f.arrays[kArrayA][i] = Slot{b.constant(i < a.size() ? a[i] : 0.0), c.one_};
        for (auto& s : f.arrays[kArrayS]) s = Slot{c.zero_, c.one_};
        std::uint32_t r = c.compileBody(body, f, kNoReg);
        result.tape = b.finish(r);
    } catch (const CannotFlatten& cf) {
        result.reason = cf.reason;
        result.reasonLoc = cf.loc;
    } catch (const std::length_error& le) {
        result.reason = le.what();
    }
    return result;
}

}  // namespace hg::frep
