#include "frep/language/interpreter.h"

#include <cmath>

#include "frep/language/hf_math.h"
#include "frep/kernels/library/library.h"

namespace hg::frep {
namespace {
// Bound on loop iterations per point, so a program that never leaves its
// loop cannot hang the caller; such a point is reported as failing.
constexpr long long kMaxSteps = 10'000'000;
}  // namespace

Interpreter::Interpreter(const Program& program, int body, std::vector<double> a)
    : program_(program), body_(body), a_(std::move(a)), frames_(program.bodies.size()) {}

void Interpreter::resetFrame(int bodyIndex, Frame& f) {
    const Body& b = program_.bodies[static_cast<size_t>(bodyIndex)];
    f.arrays.resize(b.arrays.size());
    f.arrayInit.resize(b.arrays.size());
    for (size_t i = 0; i < b.arrays.size(); ++i) {
        size_t n = static_cast<size_t>(b.arrays[i].size);
        f.arrays[i].assign(n, 0.0);
        // x, a and s come from the caller and count as assigned.
        f.arrayInit[i].assign(n, i <= static_cast<size_t>(kArrayS) ? 1 : 0);
    }
    f.vars.assign(b.variables.size(), 0.0);
    f.varInit.assign(b.variables.size(), 0);
}

PointResult Interpreter::evaluate(double x, double y, double z) {
    error_ = DomainError::None;
    nanSeen_ = false;
    steps_ = 0;
    Frame& f = frames_[static_cast<size_t>(body_)];
    resetFrame(body_, f);
    auto& xs = f.arrays[kArrayX];
    const double p[3] = {x, y, z};
    for (size_t i = 0; i < xs.size() && i < 3; ++i) xs[i] = p[i];
    auto& as = f.arrays[kArrayA];
    for (size_t i = 0; i < as.size() && i < a_.size(); ++i) as[i] = a_[i];
    PointResult r;
    if (!run(body_, f, r.value)) {
        r.value = kOutsideValue;
        r.error = error_;
        r.loc = errorLoc_;
    } else if (std::isnan(r.value)) {
        r.value = kOutsideValue;
        r.error = DomainError::NotANumber;
        r.loc = nanSeen_ ? nanLoc_ : program_.bodies[static_cast<size_t>(body_)].resultLoc;
    }
    return r;
}

double Interpreter::evaluateSafe(double x, double y, double z, ErrorReport& errors) {
    PointResult r = evaluate(x, y, z);
    if (!r.ok()) {
        errors.add(r.error, r.loc);
        return kOutsideValue;
    }
    if (r.value > kValueLimit) return kValueLimit;
    if (r.value < -kValueLimit) return -kValueLimit;
    return r.value;
}

bool Interpreter::fail(DomainError e, SourceLoc loc) {
    error_ = e;
    errorLoc_ = loc;
    return false;
}

bool Interpreter::run(int bodyIndex, Frame& frame, double& result) {
    const Body& b = program_.bodies[static_cast<size_t>(bodyIndex)];
    if (!exec(b.statements, b, frame)) return false;
    return eval(*b.result, b, frame, result);
}

bool Interpreter::index(const Expr& e, const Body& b, Frame& frame, int slot, size_t& out) {
    double v = 0.0;
    if (!eval(e, b, frame, v)) return false;
    long long i = hf::round(v);
    long long size = b.arrays[static_cast<size_t>(slot)].size;
    if (i < 1 || i > size) return fail(DomainError::IndexOutOfRange, e.loc);
    out = static_cast<size_t>(i - 1);
    return true;
}

bool Interpreter::exec(const std::vector<Stmt>& stmts, const Body& b, Frame& frame) {
    for (const Stmt& s : stmts) {
        switch (s.kind) {
            case StmtKind::Assign: {
                double v = 0.0;
                if (!eval(*s.value, b, frame, v)) return false;
                frame.vars[static_cast<size_t>(s.slot)] = v;
                frame.varInit[static_cast<size_t>(s.slot)] = 1;
                break;
            }
            case StmtKind::AssignElement: {
                size_t i = 0;
                if (!index(*s.index, b, frame, s.slot, i)) return false;
                double v = 0.0;
                if (!eval(*s.value, b, frame, v)) return false;
                frame.arrays[static_cast<size_t>(s.slot)][i] = v;
                frame.arrayInit[static_cast<size_t>(s.slot)][i] = 1;
                break;
            }
            case StmtKind::AssignArray: {
                auto& arr = frame.arrays[static_cast<size_t>(s.slot)];
                auto& init = frame.arrayInit[static_cast<size_t>(s.slot)];
                for (size_t i = 0; i < arr.size() && i < s.literal.size(); ++i) {
                    arr[i] = s.literal[i];
                    init[i] = 1;
                }
                break;
            }
            case StmtKind::If: {
                double c = 0.0;
                if (!eval(*s.condition, b, frame, c)) return false;
                if (!exec(hf::truthy(c) ? s.thenBody : s.elseBody, b, frame)) return false;
                break;
            }
            case StmtKind::While: {
                for (;;) {
                    double c = 0.0;
                    if (!eval(*s.condition, b, frame, c)) return false;
                    if (!hf::truthy(c)) break;
                    if (++steps_ > kMaxSteps) return fail(DomainError::NotANumber, s.loc);
                    if (!exec(s.thenBody, b, frame)) return false;
                }
                break;
            }
        }
    }
    return true;
}

bool Interpreter::eval(const Expr& e, const Body& b, Frame& frame, double& out) {
    switch (e.kind) {
        case ExprKind::Number:
            out = e.number;
            return true;
        case ExprKind::Variable:
            if (!frame.varInit[static_cast<size_t>(e.slot)]) return fail(DomainError::UnassignedValue, e.loc);
            out = frame.vars[static_cast<size_t>(e.slot)];
            return true;
        case ExprKind::ArrayElement: {
            size_t i = 0;
            if (!index(*e.args[0], b, frame, e.slot, i)) return false;
            if (!frame.arrayInit[static_cast<size_t>(e.slot)][i]) return fail(DomainError::UnassignedValue, e.loc);
            out = frame.arrays[static_cast<size_t>(e.slot)][i];
            return true;
        }
        case ExprKind::ArrayName:
            // Only meaningful as a routine or body-call argument.
            out = 0.0;
            return true;
        case ExprKind::Unary: {
            double v = 0.0;
            if (!eval(*e.args[0], b, frame, v)) return false;
            switch (e.unaryOp) {
                case UnaryOp::Plus: out = v; break;
                case UnaryOp::Minus:
                case UnaryOp::Tilde: out = -v; break;
                case UnaryOp::Not: out = hf::logicalNot(v); break;
            }
            return true;
        }
        case ExprKind::Binary: {
            // The reference computes the right operand first.
            double r = 0.0, l = 0.0;
            if (!eval(*e.args[1], b, frame, r)) return false;
            if (!eval(*e.args[0], b, frame, l)) return false;
            DomainError err = DomainError::None;
            switch (e.binaryOp) {
                case BinaryOp::Add: out = l + r; break;
                case BinaryOp::Sub: out = l - r; break;
                case BinaryOp::Mul: out = l * r; break;
                case BinaryOp::Div: err = hf::divide(l, r, out); break;
                case BinaryOp::Pow: err = hf::power(l, r, out); break;
                case BinaryOp::Union: out = hf::unite(l, r); break;
                case BinaryOp::Intersection: out = hf::intersect(l, r); break;
                case BinaryOp::Difference: out = hf::subtract(l, r); break;
                case BinaryOp::Equal: out = hf::equal(l, r); break;
                case BinaryOp::NotEqual: out = hf::notEqual(l, r); break;
                case BinaryOp::Less: out = hf::fromBool<double>(l < r); break;
                case BinaryOp::LessEqual: out = hf::fromBool<double>(l <= r); break;
                case BinaryOp::Greater: out = hf::fromBool<double>(l > r); break;
                case BinaryOp::GreaterEqual: out = hf::fromBool<double>(l >= r); break;
                case BinaryOp::And: out = hf::logicalAnd(l, r); break;
                case BinaryOp::Or: out = hf::logicalOr(l, r); break;
            }
            if (err != DomainError::None) return fail(err, e.loc);
            noteNan(out, e.loc, std::isnan(l) || std::isnan(r));
            return true;
        }
        case ExprKind::BuiltinCall: return evalBuiltin(e, b, frame, out);
        case ExprKind::LibraryCall: return evalLibrary(e, b, frame, out);
        case ExprKind::BodyCall: return evalBodyCall(e, b, frame, out);
    }
    return fail(DomainError::NotANumber, e.loc);
}

bool Interpreter::evalBuiltin(const Expr& e, const Body& b, Frame& frame, double& out) {
    double v[2] = {0.0, 0.0};
    // Last argument first.
    for (size_t i = e.args.size(); i-- > 0;)
        if (!eval(*e.args[i], b, frame, v[i < 2 ? i : 1])) return false;
    DomainError err = DomainError::None;
    switch (e.builtin) {
        case Builtin::Sqrt: err = hf::checkedSqrt(v[0], out); break;
        case Builtin::Exp: out = std::exp(v[0]); break;
        case Builtin::Log: err = hf::checkedLog(v[0], out); break;
        case Builtin::Logd: err = hf::checkedLog10(v[0], out); break;
        case Builtin::Sin: out = std::sin(v[0]); break;
        case Builtin::Cos: out = std::cos(v[0]); break;
        case Builtin::Tan: err = hf::checkedTan(v[0], out); break;
        case Builtin::Asin: err = hf::checkedAsin(v[0], out); break;
        case Builtin::Acos: err = hf::checkedAcos(v[0], out); break;
        case Builtin::Atan: out = std::atan(v[0]); break;
        case Builtin::Atan2: out = std::atan2(v[0], v[1]); break;
        case Builtin::Abs: out = std::fabs(v[0]); break;
        case Builtin::Sinh: out = std::sinh(v[0]); break;
        case Builtin::Cosh: out = std::cosh(v[0]); break;
        case Builtin::Tanh: out = std::tanh(v[0]); break;
        case Builtin::Sign: out = 1.0; break;
        case Builtin::Mod: err = hf::mod(v[0], v[1], out); break;
        case Builtin::Max: out = hf::maximum(v[0], v[1]); break;
        case Builtin::Min: out = hf::minimum(v[0], v[1]); break;
        case Builtin::Ceil: out = std::ceil(v[0]); break;
        case Builtin::Floor: out = std::floor(v[0]); break;
        case Builtin::Int: out = hf::truncate(v[0]); break;
        case Builtin::Frac: out = hf::fraction(v[0]); break;
    }
    if (err != DomainError::None) return fail(err, e.loc);
    noteNan(out, e.loc, std::isnan(v[0]) || std::isnan(v[1]));
    return true;
}

bool Interpreter::evalLibrary(const Expr& e, const Body& b, Frame& frame, double& out) {
    const auto& info = lib::functions()[static_cast<size_t>(e.function)];
    lib::Args<double> args;
    args.arrays.assign(e.args.size(), nullptr);
    args.scalars.assign(e.args.size(), 0.0);
    for (size_t i = e.args.size(); i-- > 0;) {
        const Expr& arg = *e.args[i];
        if (info.params[i] == lib::ParamKind::Array) {
            const auto& init = frame.arrayInit[static_cast<size_t>(arg.slot)];
            for (unsigned char ok : init)
                if (!ok) return fail(DomainError::UnassignedValue, arg.loc);
            args.arrays[i] = &frame.arrays[static_cast<size_t>(arg.slot)];
        } else if (!eval(arg, b, frame, args.scalars[i])) {
            return false;
        }
    }
    out = lib::call<double>(e.function, args);
    if (std::isnan(out)) {
        bool nanIn = false;
        for (size_t i = 0; i < e.args.size(); ++i)
            nanIn |= info.params[i] == lib::ParamKind::Scalar && std::isnan(args.scalars[i]);
        noteNan(out, e.loc, nanIn);
    }
    return true;
}

bool Interpreter::evalBodyCall(const Expr& e, const Body&, Frame& frame, double& out) {
    Frame& cf = frames_[static_cast<size_t>(e.function)];
    resetFrame(e.function, cf);
    // The callee works on copies of x, a and s; only s comes back.
    int sSource = kArrayS;
    for (size_t i = e.args.size(); i-- > 0;) {
        const Expr& arg = *e.args[i];
        const auto& init = frame.arrayInit[static_cast<size_t>(arg.slot)];
        for (unsigned char ok : init)
            if (!ok) return fail(DomainError::UnassignedValue, arg.loc);
        cf.arrays[i] = frame.arrays[static_cast<size_t>(arg.slot)];
        if (i == kArrayS) sSource = arg.slot;
    }
    if (e.args.size() <= kArrayS) cf.arrays[kArrayS] = frame.arrays[kArrayS];
    bool ok = run(e.function, cf, out);
    auto& dst = frame.arrays[static_cast<size_t>(sSource)];
    const auto& src = cf.arrays[kArrayS];
    for (size_t i = 0; i < dst.size() && i < src.size(); ++i) dst[i] = src[i];
    return ok;
}

}  // namespace hg::frep
