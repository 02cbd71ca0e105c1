// Builds a Tape in SSA form: folds constants with the same double arithmetic
// the evaluators use (so folding never changes a value), shares repeated
// subexpressions, and at the end drops dead code and allocates registers.
#pragma once

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "frep/compiler/tape.h"

namespace hg::frep {

class TapeBuilder {
public:
    // Hard cap on SSA values, so that unrolling cannot exhaust memory.
    static constexpr size_t kMaxValues = 4'000'000;

    // `loc` is recorded with the inputs (x, y, z) and with every value built
    // until setLoc() says otherwise.
    explicit TapeBuilder(SourceLoc loc = {});

    // The source location recorded with the values built from now on (the
    // expression being compiled); returns the previous one.
    SourceLoc setLoc(SourceLoc loc) {
        SourceLoc previous = loc_;
        loc_ = loc;
        return previous;
    }

    std::uint32_t x() const { return x_; }
    std::uint32_t y() const { return y_; }
    std::uint32_t z() const { return z_; }
    std::uint32_t constant(double v);
    // The base value input (Op::W), for edit expressions.
    std::uint32_t w();

    // A pure operation: folded when its inputs are constant, shared when the
    // same operation was built before.
    std::uint32_t op(Op op, std::uint32_t a, std::uint32_t b = kNoReg, std::uint32_t c = kNoReg);

    // A language operation that may fail where `guard` (0/1 value, or kNoReg
    // for "always") is non-zero; `loc` is reported on failure.
    std::uint32_t fallible(Op op, std::uint32_t a, std::uint32_t b, std::uint32_t guard, SourceLoc loc,
                           DomainError checkError = DomainError::None);

    // Fails with `error` where `ok` is 0 and `guard` holds.
    void check(std::uint32_t ok, std::uint32_t guard, SourceLoc loc, DomainError error);

    // A fused kernel (`op` with fusedParamCount(op) > 0) at (px, py, pz);
    // `params` holds its fusedParamCount(op) constant parameters.
    std::uint32_t fused(Op op, std::uint32_t px, std::uint32_t py, std::uint32_t pz, const double* params);

    // guard && cond, treating kNoReg as "true".
    std::uint32_t andGuard(std::uint32_t guard, std::uint32_t cond);

    bool isConstant(std::uint32_t v) const { return code_[v].op == Op::Const; }
    double constantValue(std::uint32_t v) const { return code_[v].imm; }
    size_t size() const { return code_.size(); }

    // Dead-code elimination and register allocation. Registers 0..2 hold
    // x, y, z and every constant gets a register of its own that no
    // instruction overwrites, so evaluators fill them once.
    Tape finish(std::uint32_t result) const;

private:
    std::uint32_t push(const Instr& in);
    bool fold(Op op, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t& out);
    bool rFunction(Op op, std::uint32_t a, std::uint32_t b, std::uint32_t& out);

    struct Key {
        Op op; DomainError error; std::uint32_t a, b, c, guard, site, param; std::uint64_t imm;
        bool operator==(const Key& o) const {
            return op == o.op && error == o.error && a == o.a && b == o.b && c == o.c &&
                   guard == o.guard && site == o.site && param == o.param && imm == o.imm;
        }
    };
    struct KeyHash { size_t operator()(const Key& k) const; };

    std::vector<Instr> code_;
    std::vector<SourceLoc> locs_;  // one per value in code_
    SourceLoc loc_;
    std::vector<SourceLoc> sites_;
    std::vector<double> params_;
    // Parameter blocks by opcode and bits, so identical kernels share one.
    std::map<std::vector<std::uint64_t>, std::uint32_t> paramBlocks_;
    std::unordered_map<Key, std::uint32_t, KeyHash> cse_;
    std::uint32_t x_, y_, z_;
};

// Register allocation of SSA code whose operands are value indices: the
// values marked `live` (x, y and z always), x, y, z and the constants first
// in fixed registers, the rest in order with registers recycled after their
// last use. `order`, if given, receives each tape instruction's SSA index.
// TapeBuilder::finish and the tape specializer (tape_specializer.h) share it.
Tape assembleTape(const std::vector<Instr>& code, const std::vector<SourceLoc>& locs, const std::vector<char>& live,
                  std::uint32_t result, std::vector<SourceLoc> sites, std::vector<double> params,
                  std::vector<std::uint32_t>* order = nullptr);

}  // namespace hg::frep
