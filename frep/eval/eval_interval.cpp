#include "frep/eval/eval_interval.h"

#include <cmath>

#include "frep/compiler/conv_kernels.h"
#include "frep/language/domain_error.h"
#include "frep/language/hf_math.h"

namespace hg::frep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 1e-6;

// Outward rounding by 2^-50 relative (four to eight ulps, more than libm's
// sub-ulp errors plus the operation's own rounding) and the smallest normal
// absolute: a few flops, where two nextafter calls per bound cost a third of
// a voxel sampler's time. inf - inf (an infinite bound moved inward) becomes
// the largest finite double, as nextafter would give.
double down(double v) {
    double r = v - (std::fabs(v) * 0x1p-50 + 0x1p-1022);
    return r == r ? r : std::numeric_limits<double>::max();
}
double up(double v) {
    double r = v + (std::fabs(v) * 0x1p-50 + 0x1p-1022);
    return r == r ? r : -std::numeric_limits<double>::max();
}

Interval make(double lo, double hi, bool nan) {
    if (std::isnan(lo) || std::isnan(hi)) return Interval::entire();
    return {down(lo), up(hi), nan};
}

// Like make(), for results that cancel large terms: the rounding error is
// relative to `magnitude` (the terms), not to the result.
Interval makeCancelling(double lo, double hi, double magnitude, bool nan) {
    const double pad = 8.0 * std::numeric_limits<double>::epsilon() * magnitude;
    return make(lo - pad, hi + pad, nan);
}

// Bounds of f over [lo, hi] for monotone non-decreasing f.
template <class F>
Interval increasing(const Interval& a, F f) {
    return make(f(a.lo), f(a.hi), a.maybeNaN);
}

Interval add(const Interval& a, const Interval& b) { return make(a.lo + b.lo, a.hi + b.hi, a.maybeNaN || b.maybeNaN); }
Interval sub(const Interval& a, const Interval& b) { return make(a.lo - b.hi, a.hi - b.lo, a.maybeNaN || b.maybeNaN); }
Interval neg(const Interval& a) { return {-a.hi, -a.lo, a.maybeNaN}; }

Interval mul(const Interval& a, const Interval& b, bool same) {
    bool nan = a.maybeNaN || b.maybeNaN;
    if (same) {  // a square is never negative
        double l = a.lo * a.lo, h = a.hi * a.hi;
        if (a.lo <= 0.0 && a.hi >= 0.0) return make(0.0, std::max(l, h), nan);
        return make(std::min(l, h), std::max(l, h), nan);
    }
    double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    for (double& v : p)
        if (std::isnan(v)) v = 0.0;  // 0 * inf: the bound is attained elsewhere or is 0
    bool infProduct = (std::isinf(a.lo) || std::isinf(a.hi) || std::isinf(b.lo) || std::isinf(b.hi)) &&
                      (a.contains(0.0) || b.contains(0.0));
    return make(*std::min_element(p, p + 4), *std::max_element(p, p + 4), nan || infProduct);
}

Interval recip(const Interval& b) {
    if (b.lo > 0.0 || b.hi < 0.0) return make(1.0 / b.hi, 1.0 / b.lo, b.maybeNaN);
    return Interval::entire();
}

Interval div(const Interval& a, const Interval& b) {
    if (b.lo > 0.0 || b.hi < 0.0) return mul(a, recip(b), false);
    return Interval::entire();
}

// a / b restricted to |b| >= eps (the other points fail and are counted).
Interval guardedDiv(const Interval& a, const Interval& b) {
    if (b.lo >= kEps || b.hi <= -kEps) return div(a, b);
    Interval r;
    bool any = false;
    if (b.hi >= kEps) { r = div(a, Interval(kEps, b.hi, b.maybeNaN)); any = true; }
    if (b.lo <= -kEps) {
        Interval n = div(a, Interval(b.lo, -kEps, b.maybeNaN));
        r = any ? hull(r, n) : n;
        any = true;
    }
    return any ? r : Interval(0.0);
}

Interval absI(const Interval& a) {
    if (a.lo >= 0.0) return a;
    if (a.hi <= 0.0) return neg(a);
    return {0.0, std::max(-a.lo, a.hi), a.maybeNaN};
}

Interval sqrtI(const Interval& a) {
    if (a.hi < 0.0) return {0.0, 0.0, true};  // NaN everywhere
    return make(std::sqrt(std::max(a.lo, 0.0)), std::sqrt(a.hi), a.maybeNaN || a.lo < 0.0);
}

Interval logI(const Interval& a, double (*f)(double)) {
    if (a.hi <= 0.0) return {-kInf, -kInf, true};
    double l = a.lo > 0.0 ? f(a.lo) : -kInf;
    return make(l, f(a.hi), a.maybeNaN || a.lo < 0.0);
}

// sin over [lo, hi]: extremes at the ends or at pi/2 + k*pi inside.
Interval sinI(const Interval& a) {
    if (!(a.hi - a.lo < 2 * kPi) || std::isinf(a.lo) || std::isinf(a.hi)) return {-1.0, 1.0, a.maybeNaN};
    double l = std::min(std::sin(a.lo), std::sin(a.hi));
    double h = std::max(std::sin(a.lo), std::sin(a.hi));
    double k = std::ceil((a.lo - kPi / 2) / kPi);
    for (double t = kPi / 2 + k * kPi; t <= a.hi + 1e-12; t += kPi, k += 1) {
        if (std::fmod(std::fabs(k), 2.0) == 0.0) h = 1.0; else l = -1.0;
    }
    Interval r = make(l, h, a.maybeNaN);
    r.lo = std::max(r.lo, -1.0);
    r.hi = std::min(r.hi, 1.0);
    return r;
}
Interval cosI(const Interval& a) { return sinI(add(a, Interval(kPi / 2))); }

Interval tanI(const Interval& a) {
    // Monotone between poles at pi/2 + k*pi.
    if (!(a.hi - a.lo < kPi)) return Interval::entire();
    double k1 = std::floor((a.lo - kPi / 2) / kPi), k2 = std::floor((a.hi - kPi / 2) / kPi);
    if (k1 != k2) return Interval::entire();
    return make(std::tan(a.lo), std::tan(a.hi), a.maybeNaN);
}

Interval asinI(const Interval& a, bool acosine) {
    bool nan = a.maybeNaN || a.lo < -1.0 || a.hi > 1.0;
    double l = std::max(a.lo, -1.0), h = std::min(a.hi, 1.0);
    if (l > h) return {0.0, 0.0, true};
    if (acosine) return make(std::acos(h), std::acos(l), nan);
    return make(std::asin(l), std::asin(h), nan);
}

Interval atan2I(const Interval& y, const Interval& x) {
    bool nan = y.maybeNaN || x.maybeNaN;
    // Off the branch cut (x < 0, y crossing 0) atan2 is monotone in each
    // argument over the box, so its extremes are at the corners.
    if (x.lo > 0.0 || y.lo > 0.0 || y.hi < 0.0) {
        double c[4] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo), std::atan2(y.hi, x.hi)};
        return make(*std::min_element(c, c + 4), *std::max_element(c, c + 4), nan);
    }
    return make(-kPi, kPi, nan);
}

Interval intPow(const Interval& b, long long n) {
    if (n == 0) return Interval(1.0, 1.0, b.maybeNaN);
    // Even powers: repeated products of |b|, so an interval around 0 starts
    // at 0. Odd powers are monotone; the product bounds contain them.
    const Interval base = n % 2 == 0 ? absI(b) : b;
    Interval p = base;
    for (long long i = 1; i < n; ++i) p = mul(p, base, false);
    return p;
}

// exp(e * log(b)) for b > 0 over boxes: monotone in b and e on each sign of log b.
Interval realPow(const Interval& b, const Interval& e) {
    Interval lb = logI(Interval(std::max(b.lo, 0.0), b.hi), [](double v) { return std::log(v); });
    Interval arg = mul(e, lb, false);
    // exp turns the argument's absolute rounding error into a relative one.
    const double rel = 8.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::max(std::fabs(arg.lo), std::fabs(arg.hi)));
    Interval r = increasing(arg, [](double v) { return std::exp(v); });
    return make(r.lo * (1.0 - rel), r.hi * (1.0 + rel), r.maybeNaN);
}

// Reference power (hf_math.h) with failures excluded.
Interval hfPow(const Interval& b, const Interval& e, bool& mayFail) {
    if (!e.isPoint()) {  // the exponent may be integer at some points: no tight bound
        mayFail = true;
        return Interval::entire();
    }
    Interval r;
    bool any = false;
    auto join = [&](const Interval& v) { r = any ? hull(r, v) : v; any = true; };
    if (b.lo < kEps && b.hi > -kEps) {  // near-zero base possible
        if (e.lo <= kEps) mayFail = true;
        else join(Interval(0.0));
    }
    if (e.lo - std::floor(e.lo) < kEps) {
        long long n = hf::round(std::fabs(e.lo));
        Interval p = intPow(b, n);
        join(e.lo < 0.0 ? recip(p) : p);
    } else {
        if (b.lo < 0.0) mayFail = true;
        if (b.hi > 0.0) join(realPow(b, e));
    }
    return any ? r : Interval(0.0);
}

bool exactInFloat(double v) { return std::isfinite(v) && static_cast<double>(static_cast<float>(v)) == v; }

bool mayBeTrue(const Interval& c) { return c.maybeNaN || c.hi != 0.0 || c.lo != 0.0; }
bool surelyTrue(const Interval& c) { return !c.maybeNaN && (c.lo > 0.0 || c.hi < 0.0); }

// truthy(v) = |v| >= eps.
Interval truthyI(const Interval& a) {
    if (!a.maybeNaN && (a.lo >= kEps || a.hi <= -kEps)) return Interval(1.0);
    if (!a.maybeNaN && a.lo > -kEps && a.hi < kEps) return Interval(0.0);
    return {0.0, 1.0};
}
Interval boolI(bool surelyT, bool surelyF) {
    if (surelyT) return Interval(1.0);
    if (surelyF) return Interval(0.0);
    return {0.0, 1.0};
}

}  // namespace

IntervalEvaluator::IntervalEvaluator(const Tape& tape, std::vector<Affine> affine)
    : tape_(&tape), regs_(tape.registers), exact_(tape.registers), affine_(std::move(affine)) {}

void IntervalEvaluator::rebind(const Tape& tape, const std::vector<Affine>& affine) {
    tape_ = &tape;
    if (regs_.size() < tape.registers) {
        regs_.resize(tape.registers);
        exact_.resize(tape.registers);
    }
    affine_.assign(affine.begin(), affine.end());
}

IntervalEvaluator::IntervalEvaluator(const Tape& tape)
    : tape_(&tape), regs_(tape.registers), exact_(tape.registers), affine_(tape.code.size()) {
    // Which registers hold affine functions of the point, in tape order
    // (registers are reused, so this follows the code).
    std::vector<Affine> reg(tape.registers);
    auto constant = [](const Affine& f) { return f.valid && f.c[1] == 0.0 && f.c[2] == 0.0 && f.c[3] == 0.0; };
    for (size_t k = 0; k < tape.code.size(); ++k) {
        const Instr& in = tape.code[k];
        const Affine none;
        const Affine& a = in.a != kNoReg ? reg[in.a] : none;
        const Affine& b = in.b != kNoReg ? reg[in.b] : none;
        Affine f;
        auto combine = [&](double ka, const Affine& p, double kb, const Affine& q) {
            f.valid = true;
            for (int i = 0; i < 4; ++i) f.c[i] = ka * p.c[i] + kb * q.c[i];
        };
        switch (in.op) {
            case Op::X: f.valid = true; f.c[1] = 1.0; break;
            case Op::Y: f.valid = true; f.c[2] = 1.0; break;
            case Op::Z: f.valid = true; f.c[3] = 1.0; break;
            case Op::Const: f.valid = std::isfinite(in.imm); f.c[0] = in.imm; break;
            case Op::Add: if (a.valid && b.valid) combine(1.0, a, 1.0, b); break;
            case Op::Sub: if (a.valid && b.valid) combine(1.0, a, -1.0, b); break;
            case Op::Neg: if (a.valid) combine(-1.0, a, 0.0, a); break;
            case Op::Mul:
                if (constant(a) && b.valid) combine(a.c[0], b, 0.0, b);
                else if (constant(b) && a.valid) combine(b.c[0], a, 0.0, a);
                break;
            case Op::Div:
            case Op::HfDiv:  // by a constant at least eps away from 0: never fails
                if (a.valid && constant(b) && std::fabs(b.c[0]) >= kEps) combine(1.0 / b.c[0], a, 0.0, a);
                break;
            default: break;
        }
        for (double c : f.c) f.valid = f.valid && std::isfinite(c);
        affine_[k] = f;
        reg[tape.out[k]] = f;
    }
}

Interval IntervalEvaluator::evaluate(const Interval& x, const Interval& y, const Interval& z, IntervalTrace* trace) {
    bool mayFail = false;
    if (trace) {
        trace->value.resize(tape_->code.size());
        trace->flags.assign(tape_->code.size(), 0);
    }
    for (size_t k = 0; k < tape_->code.size(); ++k) {
        const Instr& in = tape_->code[k];
        const Interval a = in.a != kNoReg ? regs_[in.a] : Interval();
        const Interval b = in.b != kNoReg ? regs_[in.b] : Interval();
        const Interval c = in.c != kNoReg ? regs_[in.c] : Interval();
        const bool nan = a.maybeNaN || b.maybeNaN || c.maybeNaN;
        bool fails = false;  // this fallible op may fail somewhere in the box
        Interval r;
        switch (in.op) {
            case Op::X: r = x; break;
            case Op::Y: r = y; break;
            case Op::Z: r = z; break;
            case Op::Const: r = Interval(in.imm); break;
            // The base value input (edit tapes) is not bounded here: any value.
            case Op::W: r = base_; break;
            case Op::Add: r = add(a, b); break;
            case Op::Sub: r = sub(a, b); break;
            case Op::Mul:
                // A product of constants that float holds exactly (0 * 0, a
                // far perturbation's cube) is that constant, not widened.
                if (a.isPoint() && b.isPoint() && exactInFloat(a.lo) && exactInFloat(b.lo) && exactInFloat(a.lo * b.lo))
                    r = Interval(a.lo * b.lo);
                else
                    r = mul(a, b, in.a == in.b);
                break;
            case Op::Div: r = div(a, b); break;
            case Op::Neg: r = neg(a); break;
            case Op::Abs: r = absI(a); break;
            case Op::Sqrt: r = sqrtI(a); break;
            case Op::Exp: r = increasing(a, [](double v) { return std::exp(v); }); break;
            case Op::Log: r = logI(a, [](double v) { return std::log(v); }); break;
            case Op::Sin: r = sinI(a); break;
            case Op::Cos: r = cosI(a); break;
            case Op::Tan: r = tanI(a); break;
            case Op::Atan: r = increasing(a, [](double v) { return std::atan(v); }); break;
            case Op::Asin: r = asinI(a, false); break;
            case Op::Acos: r = asinI(a, true); break;
            case Op::Atan2: r = atan2I(a, b); break;
            case Op::Pow:
                if (b.isPoint() && b.lo == std::floor(b.lo) && std::fabs(b.lo) <= 64) {
                    r = intPow(a, static_cast<long long>(std::fabs(b.lo)));
                    if (b.lo < 0) r = recip(r);
                } else if (a.lo > 0.0) {
                    r = realPow(a, b);
                } else {
                    r = Interval::entire();
                }
                break;
            case Op::Floor: r = increasing(a, [](double v) { return std::floor(v); }); break;
            case Op::Ceil: r = increasing(a, [](double v) { return std::ceil(v); }); break;
            case Op::Trunc: r = increasing(a, [](double v) { return std::trunc(v); }); break;
            case Op::Sinh: r = increasing(a, [](double v) { return std::sinh(v); }); break;
            case Op::Tanh: r = increasing(a, [](double v) { return std::tanh(v); }); break;
            case Op::Cosh: {
                Interval m = absI(a);
                r = increasing(m, [](double v) { return std::cosh(v); });
                break;
            }
            case Op::Lt: r = boolI(!nan && a.hi < b.lo, !nan && a.lo >= b.hi); break;
            case Op::Le: r = boolI(!nan && a.hi <= b.lo, !nan && a.lo > b.hi); break;
            case Op::Gt: r = boolI(!nan && a.lo > b.hi, !nan && a.hi <= b.lo); break;
            case Op::Ge: r = boolI(!nan && a.lo >= b.hi, !nan && a.hi < b.lo); break;
            case Op::EqEps:
            case Op::NeEps: {
                Interval d = absI(sub(a, b));
                r = boolI(!nan && d.hi < kEps, !nan && d.lo >= kEps);
                if (in.op == Op::NeEps && r.isPoint()) r = Interval(1.0 - r.lo);
                break;
            }
            case Op::Truthy: r = truthyI(a); break;
            case Op::Not: {
                Interval t = truthyI(a);
                r = t.isPoint() ? Interval(1.0 - t.lo) : Interval(0.0, 1.0);
                break;
            }
            case Op::And:
            case Op::Or: {
                Interval ta = truthyI(a), tb = truthyI(b);
                if (in.op == Op::And)
                    r = boolI(ta.lo == 1.0 && tb.lo == 1.0, ta.hi == 0.0 || tb.hi == 0.0);
                else
                    r = boolI(ta.lo == 1.0 || tb.lo == 1.0, ta.hi == 0.0 && tb.hi == 0.0);
                break;
            }
            case Op::Select:
                if (surelyTrue(a)) r = b;
                else if (!mayBeTrue(a)) r = c;
                else r = hull(b, c);
                break;
            // With a NaN operand the C ternary returns the other one (or NaN).
            case Op::Min: r = nan ? hull(a, b) : Interval(std::min(a.lo, b.lo), std::min(a.hi, b.hi)); break;
            case Op::Max: r = nan ? hull(a, b) : Interval(std::max(a.lo, b.lo), std::max(a.hi, b.hi)); break;
            case Op::Union:
            case Op::Intersect:
            case Op::Subtract: {
                // R-functions are monotone in both arguments (decreasing in
                // the second for the difference).
                const double m = std::max(std::fabs(a.lo), std::fabs(a.hi)) + std::max(std::fabs(b.lo), std::fabs(b.hi));
                if (in.op == Op::Union) r = makeCancelling(hf::unite(a.lo, b.lo), hf::unite(a.hi, b.hi), m, nan);
                else if (in.op == Op::Intersect) r = makeCancelling(hf::intersect(a.lo, b.lo), hf::intersect(a.hi, b.hi), m, nan);
                else r = makeCancelling(hf::subtract(a.lo, b.hi), hf::subtract(a.hi, b.lo), m, nan);
                break;
            }
            case Op::HfDiv:
                fails = b.lo < kEps && b.hi > -kEps;
                r = guardedDiv(a, b);
                break;
            case Op::HfPow: r = hfPow(a, b, fails); break;
            case Op::HfSqrt:
                fails = a.lo < 0.0;
                r = a.hi < 0.0 ? Interval(0.0) : sqrtI(Interval(std::max(a.lo, 0.0), a.hi, a.maybeNaN));
                break;
            case Op::HfLog:
            case Op::HfLog10: {
                fails = !(a.lo > 0.0);
                auto f = in.op == Op::HfLog ? +[](double v) { return std::log(v); } : +[](double v) { return std::log10(v); };
                if (a.hi <= 0.0) r = Interval(0.0);
                else r = make(a.lo > 0.0 ? f(a.lo) : -kInf, f(a.hi), a.maybeNaN);
                break;
            }
            case Op::HfAsin:
            case Op::HfAcos:
                fails = a.lo < -1.0 || a.hi > 1.0;
                r = asinI(a, in.op == Op::HfAcos);
                r.maybeNaN = a.maybeNaN;
                break;
            case Op::HfTan:
                r = tanI(a);
                fails = std::isinf(r.lo) || std::isinf(r.hi);
                break;
            case Op::HfMod: {
                double q = std::max(std::fabs(b.lo), std::fabs(b.hi)) + 1.0;
                fails = b.lo < 0.5 && b.hi >= -0.5;
                r = Interval(-q, q, nan);
                break;
            }
            case Op::Check:
                fails = a.maybeNaN || a.lo <= 0.0;
                r = a;
                break;
            case Op::ConvSegment:
            case Op::ConvArc:
            case Op::SoftStep: r = fusedBounds(in.op, a, b, c, tape_->params.data() + in.param); break;
        }
        bool failsHere = false;
        if (fails || (opCanFail(in.op) && nan)) {
            const bool guardMayHold = in.guard == kNoReg || mayBeTrue(regs_[in.guard]);
            if (guardMayHold) mayFail = failsHere = true;
        }
        const Affine& f = affine_[k];
        if (f.valid && in.op != Op::X && in.op != Op::Y && in.op != Op::Z && in.op != Op::Const) {
            // The exact range, less rounding: the program computes the same
            // function through several roundings, the form through others.
            const Interval* axis[3] = {&x, &y, &z};
            double mid = f.c[0], reach = 0.0, magnitude = std::fabs(f.c[0]);
            for (int i = 0; i < 3; ++i) {
                const double m = 0.5 * (axis[i]->lo + axis[i]->hi), h = 0.5 * (axis[i]->hi - axis[i]->lo);
                mid += f.c[i + 1] * m;
                reach += std::fabs(f.c[i + 1]) * h;
                magnitude += std::fabs(f.c[i + 1]) * std::max(std::fabs(axis[i]->lo), std::fabs(axis[i]->hi));
            }
            const double pad = 1e-12 * magnitude;
            if (std::isfinite(mid) && std::isfinite(reach) && std::isfinite(pad)) {
                r.lo = std::max(r.lo, mid - reach - pad);
                r.hi = std::min(r.hi, mid + reach + pad);
            }
        }
        regs_[tape_->out[k]] = r;
        if (trace) {
            // Which bounds are constants that float evaluation keeps too:
            // min, max and negation are exact in every precision.
            std::uint8_t e = 0;
            if (!r.maybeNaN) {
                const std::uint8_t ea = in.a != kNoReg ? exact_[in.a] : 0, eb = in.b != kNoReg ? exact_[in.b] : 0;
                constexpr std::uint8_t lo = IntervalTrace::kLoExact, hi = IntervalTrace::kHiExact;
                switch (in.op) {
                    case Op::Const: e = lo | hi; break;
                    case Op::W: e = baseExact_ ? lo | hi : 0; break;
                    case Op::Neg: e = static_cast<std::uint8_t>(((ea & lo) ? hi : 0) | ((ea & hi) ? lo : 0)); break;
                    // x + 0 is x, or +0 where x is -0: bounds that hold for
                    // x hold for it (a perturbation far from its quadric).
                    case Op::Add:
                        if (b.isPoint() && b.lo == 0.0 && (eb & lo) && (eb & hi)) e = ea;
                        else if (a.isPoint() && a.lo == 0.0 && (ea & lo) && (ea & hi)) e = eb;
                        break;
                    // A product of constants that float holds exactly (0 * 0).
                    case Op::Mul:
                        if (r.isPoint() && a.isPoint() && b.isPoint() && (ea & eb & lo) && (ea & eb & hi)) e = lo | hi;
                        break;
                    // min(a, b) <= a: its upper bound is the smaller operand's,
                    // exact when that one's is; it may be either operand's
                    // value, so its lower bound is exact only when both are.
                    case Op::Min:
                        if (ea & eb & lo) e |= lo;
                        if (a.hi < b.hi ? (ea & hi) : a.hi > b.hi ? (eb & hi) : ((ea | eb) & hi)) e |= hi;
                        break;
                    case Op::Max:
                        if (a.lo > b.lo ? (ea & lo) : a.lo < b.lo ? (eb & lo) : ((ea | eb) & lo)) e |= lo;
                        if (ea & eb & hi) e |= hi;
                        break;
                    default: break;
                }
            }
            exact_[tape_->out[k]] = e;
            trace->value[k] = r;
            trace->flags[k] = static_cast<std::uint8_t>(e | (failsHere ? IntervalTrace::kMayFail : 0));
        }
    }
    Interval result = regs_[tape_->result];
    if (result.maybeNaN || mayFail) result = hull(result, Interval(kOutsideValue));
    result.maybeNaN = false;
    result.lo = std::max(result.lo, -kValueLimit);
    result.hi = std::min(result.hi, kValueLimit);
    if (std::isnan(result.lo) || std::isnan(result.hi)) result = Interval(-kValueLimit, kValueLimit);
    return result;
}

}  // namespace hg::frep
