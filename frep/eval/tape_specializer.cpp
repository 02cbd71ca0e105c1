#include "frep/eval/tape_specializer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "frep/compiler/tape_builder.h"

namespace hg::frep {

namespace {

// How far a winner must win when the tape is evaluated in float: float
// rounds each operation to 24 bits where the bounds hold for double, so
// values a few float ulps of their terms apart may compare the other way.
// Generous: a pruned operation lost is a few flops, a wrong one a wrong
// voxel.
double floatMargin(double u, double v) { return 1e-4 * (1.0 + std::fabs(u) + std::fabs(v)); }

// True when p <= q at every point of the box in `precision`: the bounds
// say so with a margin, or exactly where both bounds are constants that
// every precision keeps.
bool surelyAtMost(const Interval& p, bool pHiExact, const Interval& q, bool qLoExact, Precision precision) {
    if (precision != Precision::Float) return p.hi <= q.lo;
    if (pHiExact && qLoExact) return p.hi <= q.lo;
    return p.hi + floatMargin(p.hi, q.lo) < q.lo;
}
// The same, where a tie must also give the same bits: the operation
// returns its other operand there, equal in value, which differs only for
// zeros of opposite signs. A tie is exact (or impossible, with a margin)
// unless the tied value is zero.
bool surelyAtMostNotZeroTie(const Interval& p, bool pHiExact, const Interval& q, bool qLoExact, Precision precision) {
    if (precision == Precision::Gradient) return p.hi < q.lo;  // equal values, other derivatives
    return surelyAtMost(p, pHiExact, q, qLoExact, precision) && (p.hi < q.lo || p.hi != 0.0);
}

// Whether, for the gradient evaluator, min or max (`op`, over operands
// bounded by `a` and `b`) has a zero derivative wherever it returns `t`:
// whichever operand it returns there is either flat at `t` (`flatA`,
// `flatB`) or cannot take that value. min returns a where a < b, max where
// a > b, else b, with that operand's derivative.
bool flatWhereItReturns(Op op, double t, const Interval& a, bool flatA, const Interval& b, bool flatB) {
    const bool bThere = b.lo <= t && t <= b.hi;
    const bool aThere = a.lo <= t && t <= a.hi && (op == Op::Max ? t > b.lo : t < b.hi);
    return (!bThere || flatB) && (!aThere || flatA);
}

std::atomic<int>& specializationSwitch() {
    static std::atomic<int> on{[] {
        const char* v = std::getenv("HG_NO_SPECIALIZE");
        return v && *v && *v != '0' ? 0 : 1;
    }()};
    return on;
}

}  // namespace

bool specializationEnabled() { return specializationSwitch().load(std::memory_order_relaxed) != 0; }
void setSpecialization(bool enabled) { specializationSwitch().store(enabled ? 1 : 0, std::memory_order_relaxed); }

bool TapeSpecializer::isFlat(std::uint32_t k, double t) const { return flatLo_[k] == t || flatHi_[k] == t; }

void TapeSpecializer::noteFlat(const Instr& in, std::size_t k, const IntervalTrace& trace) {
    const Interval& v = trace.value[k];
    if (v.maybeNaN) return;
    switch (in.op) {
        case Op::Const: flatLo_[k] = flatHi_[k] = in.imm; break;  // no derivative at all
        case Op::Neg: {
            const std::uint32_t a = def_[in.a];
            flatLo_[k] = -flatHi_[a];
            flatHi_[k] = -flatLo_[a];
            break;
        }
        case Op::Min: case Op::Max: {
            const std::uint32_t da = def_[in.a], db = def_[in.b];
            const Interval& a = trace.value[da];
            const Interval& b = trace.value[db];
            if (a.maybeNaN || b.maybeNaN) break;
            const bool isMax = in.op == Op::Max;
            const double lo = isMax ? std::max(a.lo, b.lo) : std::min(a.lo, b.lo);
            const double hi = isMax ? std::max(a.hi, b.hi) : std::min(a.hi, b.hi);
            if (flatWhereItReturns(in.op, lo, a, isFlat(da, lo), b, isFlat(db, lo))) flatLo_[k] = lo;
            if (flatWhereItReturns(in.op, hi, a, isFlat(da, hi), b, isFlat(db, hi))) flatHi_[k] = hi;
            break;
        }
        default: break;
    }
}

bool TapeSpecializer::specialize(const Tape& tape, const std::vector<IntervalEvaluator::Affine>& affine,
                                 const IntervalTrace& trace, Precision precision, SpecializedTape& out) {
    const std::size_t n = tape.code.size();
    if (n == 0 || trace.value.size() != n) return false;
    def_.assign(tape.registers, kNoReg);
    alias_.resize(n);
    ssa_.resize(n);
    if (precision == Precision::Gradient) {
        flatLo_.assign(n, std::numeric_limits<double>::quiet_NaN());
        flatHi_.assign(n, std::numeric_limits<double>::quiet_NaN());
    }
    std::size_t pruned = 0;
    constexpr std::uint8_t kLo = IntervalTrace::kLoExact, kHi = IntervalTrace::kHiExact;
    for (std::size_t k = 0; k < n; ++k) {
        const Instr& in = tape.code[k];
        // Operands as the instructions that made them (after aliasing).
        Instr s = in;
        for (std::uint32_t* r : {&s.a, &s.b, &s.c, &s.guard})
            if (*r != kNoReg) *r = alias_[def_[*r]];
        alias_[k] = static_cast<std::uint32_t>(k);
        if ((in.op == Op::Min || in.op == Op::Max) && !trace.value[k].maybeNaN) {
            const std::uint32_t da = def_[in.a], db = def_[in.b];
            const Interval& a = trace.value[da];
            const Interval& b = trace.value[db];
            const std::uint8_t fa = trace.flags[da], fb = trace.flags[db];
            if (!a.maybeNaN && !b.maybeNaN) {
                // hf::minimum(p, q) is p < q ? p : q, hf::maximum p > q ? p : q:
                // the second operand also wins ties.
                std::uint32_t winner = kNoReg;
                // For gradients a tie may return the other operand only
                // where both are flat at the tied value (their derivatives
                // are both zero there).
                const auto flatTie = [&](double t) {
                    return precision == Precision::Gradient && t != 0.0 && isFlat(da, t) && isFlat(db, t);
                };
                if (in.op == Op::Min) {
                    if (surelyAtMost(b, fb & kHi, a, fa & kLo, precision)) winner = s.b;
                    else if (surelyAtMostNotZeroTie(a, fa & kHi, b, fb & kLo, precision) ||
                             (a.hi == b.lo && flatTie(a.hi)))
                        winner = s.a;
                } else {
                    if (surelyAtMost(a, fa & kHi, b, fb & kLo, precision)) winner = s.b;
                    else if (surelyAtMostNotZeroTie(b, fb & kHi, a, fa & kLo, precision) ||
                             (b.hi == a.lo && flatTie(a.lo)))
                        winner = s.a;
                }
                if (winner != kNoReg) {
                    alias_[k] = winner;
                    ++pruned;
                }
            }
        }
        if (precision == Precision::Gradient) noteFlat(in, k, trace);
        // A value pinned to one constant that every precision keeps (a far
        // perturbation's cube of zero) becomes that constant. Not for
        // gradients: a constant has no derivative to carry.
        const Interval& v = trace.value[k];
        if (alias_[k] == k && precision != Precision::Gradient && in.op != Op::Const && !opCanFail(in.op) &&
            v.isPoint() && (trace.flags[k] & kLo) && (trace.flags[k] & kHi)) {
            Instr c;
            c.op = Op::Const;
            c.imm = v.lo;
            s = c;
            ++pruned;
        }
        ssa_[k] = s;
        def_[tape.out[k]] = static_cast<std::uint32_t>(k);
    }
    if (pruned == 0) return false;

    // Live: the result, and every operation that may fail in the box.
    live_.assign(n, 0);
    const std::uint32_t result = alias_[def_[tape.result]];
    live_[result] = 1;
    for (std::size_t k = 0; k < n; ++k)
        if (alias_[k] == k && (trace.flags[k] & IntervalTrace::kMayFail)) live_[k] = 1;
    for (std::size_t k = n; k-- > 0;) {
        if (!live_[k]) continue;
        const Instr& in = ssa_[k];
        for (std::uint32_t r : {in.a, in.b, in.c, in.guard})
            if (r != kNoReg) live_[r] = 1;
    }
    for (std::size_t k = 0; k < n && k < 3; ++k) live_[k] = 1;  // x, y, z keep their registers
    // A tape a few percent shorter is not worth its copy: the caller goes
    // on with this one (nested boxes still try).
    const auto kept = static_cast<std::size_t>(std::count(live_.begin(), live_.end(), char(1)));
    if (kept * 20 > n * 19) return false;
    locs_.assign(tape.locs.begin(), tape.locs.end());
    locs_.resize(n);
    // Only the kept instructions' kernel parameters and failure sites go
    // along: an edited sculpture's tape holds tens of thousands of segment
    // parameters, and copying them all for every box cost more than the
    // box's evaluation.
    std::vector<double> params;
    std::vector<SourceLoc> sites;
    for (std::size_t k = 0; k < n; ++k) {
        if (!live_[k]) continue;
        Instr& in = ssa_[k];
        if (const std::uint32_t count = fusedParamCount(in.op)) {
            const auto first = static_cast<std::uint32_t>(params.size());
            params.insert(params.end(), tape.params.begin() + in.param, tape.params.begin() + in.param + count);
            in.param = first;
        }
        if (opCanFail(in.op) && in.site < tape.sites.size()) {
            sites.push_back(tape.sites[in.site]);
            in.site = static_cast<std::uint32_t>(sites.size() - 1);
        }
    }
    out.tape = assembleTape(ssa_, locs_, live_, result, std::move(sites), std::move(params), &order_);
    out.affine.resize(order_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) out.affine[i] = affine[order_[i]];
    return true;
}

}  // namespace hg::frep
