#include "frep/compiler/tape_builder.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "frep/compiler/conv_kernels.h"
#include "frep/compiler/op_semantics.h"

namespace hg::frep {
namespace {
std::uint64_t bitsOf(double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
}
}  // namespace

size_t TapeBuilder::KeyHash::operator()(const Key& k) const {
    std::uint64_t h = static_cast<std::uint64_t>(k.op) * 0x9E3779B97F4A7C15ull;
    for (std::uint64_t v : {std::uint64_t(k.a), std::uint64_t(k.b), std::uint64_t(k.c),
                            std::uint64_t(k.guard), std::uint64_t(k.site), std::uint64_t(k.param), k.imm,
                            std::uint64_t(k.error)})
        h = (h ^ v) * 0x100000001B3ull + (h >> 29);
    return static_cast<size_t>(h);
}

TapeBuilder::TapeBuilder(SourceLoc loc) : loc_(loc) {
    Instr in;
    in.op = Op::X; x_ = push(in);
    in.op = Op::Y; y_ = push(in);
    in.op = Op::Z; z_ = push(in);
}

std::uint32_t TapeBuilder::push(const Instr& in) {
    Key key{in.op, in.error, in.a, in.b, in.c, in.guard, in.site, in.param, bitsOf(in.imm)};
    auto it = cse_.find(key);
    if (it != cse_.end()) return it->second;
    if (code_.size() >= kMaxValues)
        throw std::length_error("program too large to flatten into a tape");
    code_.push_back(in);
    locs_.push_back(loc_);
    auto id = static_cast<std::uint32_t>(code_.size() - 1);
    cse_.emplace(key, id);
    return id;
}

std::uint32_t TapeBuilder::w() {
    Instr in;
    in.op = Op::W;
    return push(in);
}

std::uint32_t TapeBuilder::constant(double v) {
    Instr in;
    in.op = Op::Const;
    in.imm = v;
    return push(in);
}

bool TapeBuilder::fold(Op op, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t& out) {
    auto isC = [&](std::uint32_t r) { return r == kNoReg || isConstant(r); };
    auto val = [&](std::uint32_t r) { return r == kNoReg ? 0.0 : constantValue(r); };
    if (isC(a) && isC(b) && isC(c)) {
        double v = 0.0;
        if (applyOp<double>(op, DomainError::None, val(a), val(b), val(c), v) == DomainError::None) {
            out = constant(v);
            return true;
        }
        return false;
    }
    // Identities that hold bit for bit (up to the sign of zero).
    auto is = [&](std::uint32_t r, double v) { return r != kNoReg && isConstant(r) && constantValue(r) == v; };
    switch (op) {
        case Op::Add:
            if (is(b, 0.0)) { out = a; return true; }
            if (is(a, 0.0)) { out = b; return true; }
            break;
        case Op::Sub:
            if (is(b, 0.0)) { out = a; return true; }
            break;
        case Op::Mul:
            if (is(b, 1.0)) { out = a; return true; }
            if (is(a, 1.0)) { out = b; return true; }
            break;
        case Op::Div:
            if (is(b, 1.0)) { out = a; return true; }
            break;
        case Op::Neg:
            if (code_[a].op == Op::Neg) { out = code_[a].a; return true; }
            break;
        case Op::Select:
            if (isConstant(a)) { out = constantValue(a) != 0.0 ? b : c; return true; }
            if (b == c) { out = b; return true; }
            break;
        default: break;
    }
    return false;
}

bool TapeBuilder::rFunction(Op o, std::uint32_t a, std::uint32_t b, std::uint32_t& out) {
    // (p + q) +- sqrt(p*p + q*q), in either order, is the alpha-0 R-function
    // union/intersection: the fused op computes the same bits (IEEE addition
    // commutes; fabs of a sum of squares changes nothing) and has monotone,
    // tight interval bounds where the expanded form suffers from dependency.
    if ((o != Op::Add && o != Op::Sub) || code_[a].op != Op::Add || code_[b].op != Op::Sqrt) return false;
    const Instr& sum = code_[code_[b].a];
    if (sum.op != Op::Add) return false;
    auto squareOf = [&](std::uint32_t v) {
        const Instr& m = code_[v];
        return m.op == Op::Mul && m.a == m.b ? m.a : kNoReg;
    };
    const std::uint32_t p = code_[a].a, q = code_[a].b;
    const std::uint32_t s1 = squareOf(sum.a), s2 = squareOf(sum.b);
    if (!((s1 == p && s2 == q) || (s1 == q && s2 == p))) return false;
    out = op(o == Op::Add ? Op::Union : Op::Intersect, p, q);
    return true;
}

std::uint32_t TapeBuilder::op(Op o, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t folded;
    if (fold(o, a, b, c, folded)) return folded;
    if (rFunction(o, a, b, folded)) return folded;
    Instr in;
    in.op = o;
    in.a = a; in.b = b; in.c = c;
    return push(in);
}

std::uint32_t TapeBuilder::fused(Op o, std::uint32_t px, std::uint32_t py, std::uint32_t pz, const double* params) {
    if (isConstant(px) && isConstant(py) && isConstant(pz))
        return constant(fusedField(o, constantValue(px), constantValue(py), constantValue(pz), params));
    // Identical kernels share one parameter block (and so one instruction).
    const std::uint32_t count = fusedParamCount(o);
    std::vector<std::uint64_t> key{static_cast<std::uint64_t>(o)};
    for (std::uint32_t i = 0; i < count; ++i) key.push_back(bitsOf(params[i]));
    auto [it, added] = paramBlocks_.emplace(std::move(key), static_cast<std::uint32_t>(params_.size()));
    if (added) params_.insert(params_.end(), params, params + count);
    Instr in;
    in.op = o;
    in.a = px; in.b = py; in.c = pz;
    in.param = it->second;
    return push(in);
}

std::uint32_t TapeBuilder::andGuard(std::uint32_t guard, std::uint32_t cond) {
    if (guard == kNoReg) return cond;
    return op(Op::And, guard, cond);
}

std::uint32_t TapeBuilder::fallible(Op o, std::uint32_t a, std::uint32_t b, std::uint32_t guard,
                                    SourceLoc loc, DomainError checkError) {
    bool guardOff = guard != kNoReg && isConstant(guard) && constantValue(guard) == 0.0;
    bool allConst = isConstant(a) && (b == kNoReg || isConstant(b));
    if (allConst) {
        double v = 0.0;
        DomainError e = applyOp<double>(o, checkError, constantValue(a),
                                        b == kNoReg ? 0.0 : constantValue(b), 0.0, v);
        if (e == DomainError::None) return constant(v);
        if (guardOff) return constant(0.0);  // never reached
    } else if (guardOff) {
        // Unreachable: the value is never selected, any finite stand-in will do.
        return constant(0.0);
    }
    if (guard != kNoReg && isConstant(guard)) guard = kNoReg;  // constant non-zero: always
    sites_.push_back(loc);
    Instr in;
    in.op = o;
    in.error = checkError;
    in.a = a; in.b = b;
    in.guard = guard;
    in.site = static_cast<std::uint32_t>(sites_.size() - 1);
    return push(in);
}

void TapeBuilder::check(std::uint32_t ok, std::uint32_t guard, SourceLoc loc, DomainError error) {
    if (isConstant(ok) && constantValue(ok) != 0.0) return;
    fallible(Op::Check, ok, kNoReg, guard, loc, error);
}

Tape TapeBuilder::finish(std::uint32_t result) const {
    const size_t n = code_.size();
    // Liveness: the result, and every fallible operation (it reports errors).
    std::vector<char> live(n, 0);
    live[result] = 1;
    for (size_t i = 0; i < n; ++i)
        if (opCanFail(code_[i].op)) live[i] = 1;
    for (size_t i = n; i-- > 0;) {
        if (!live[i]) continue;
        const Instr& in = code_[i];
        for (std::uint32_t r : {in.a, in.b, in.c, in.guard})
            if (r != kNoReg) live[r] = 1;
    }
    return assembleTape(code_, locs_, live, result, sites_, params_);
}

Tape assembleTape(const std::vector<Instr>& code, const std::vector<SourceLoc>& locs, const std::vector<char>& live,
                  std::uint32_t result, std::vector<SourceLoc> sites, std::vector<double> params,
                  std::vector<std::uint32_t>* order) {
    const size_t n = code.size();
    if (order) order->clear();
    // Last use of each value, to recycle its register.
    std::vector<size_t> lastUse(n, 0);
    for (size_t i = 0; i < n; ++i) {
        if (!live[i]) continue;
        const Instr& in = code[i];
        for (std::uint32_t r : {in.a, in.b, in.c, in.guard})
            if (r != kNoReg) lastUse[r] = std::max(lastUse[r], i);
    }
    lastUse[result] = n;

    Tape t;
    const std::size_t kept = static_cast<std::size_t>(std::count(live.begin(), live.end(), char(1))) + 3;
    t.code.reserve(kept);
    t.out.reserve(kept);
    t.locs.reserve(kept);
    if (order) order->reserve(kept);
    std::vector<std::uint32_t> reg(n, kNoReg);
    std::uint32_t next = 0;
    // x, y, z, then constants: fixed registers.
    for (size_t i = 0; i < n; ++i) {
        const Op o = code[i].op;
        if (o == Op::X || o == Op::Y || o == Op::Z || (o == Op::Const && live[i])) {
            reg[i] = next++;
            Instr in = code[i];
            t.code.push_back(in);
            t.out.push_back(reg[i]);
            t.locs.push_back(locs[i]);
            if (order) order->push_back(static_cast<std::uint32_t>(i));
        }
    }
    std::vector<std::uint32_t> freeRegs;
    for (size_t i = 0; i < n; ++i) {
        const Instr& src = code[i];
        if (!live[i] || src.op == Op::X || src.op == Op::Y || src.op == Op::Z || src.op == Op::Const) continue;
        Instr in = src;
        for (std::uint32_t* r : {&in.a, &in.b, &in.c, &in.guard})
            if (*r != kNoReg) *r = reg[*r];
        std::uint32_t r;
        if (!freeRegs.empty()) { r = freeRegs.back(); freeRegs.pop_back(); }
        else r = next++;
        reg[i] = r;
        t.code.push_back(in);
        t.out.push_back(r);
        t.locs.push_back(locs[i]);
        if (order) order->push_back(static_cast<std::uint32_t>(i));
        // Operands whose last use is here free their registers only now, so
        // an instruction never writes a register it reads.
        for (std::uint32_t s : {src.a, src.b, src.c, src.guard}) {
            if (s == kNoReg || lastUse[s] != i) continue;
            const Op so = code[s].op;
            if (so == Op::X || so == Op::Y || so == Op::Z || so == Op::Const) continue;
            if (std::find(freeRegs.begin(), freeRegs.end(), reg[s]) == freeRegs.end()) freeRegs.push_back(reg[s]);
        }
        if (lastUse[i] == 0 && i != result) freeRegs.push_back(r);  // value never read (fallible op)
    }
    t.registers = next;
    t.result = reg[result];
    t.sites = std::move(sites);
    t.params = std::move(params);
    return t;
}

}  // namespace hg::frep
