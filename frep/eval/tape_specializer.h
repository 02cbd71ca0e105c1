// A tape specialized to a box (docs/hyperfun.md, "Evaluation specialized to
// a region"), the technique that makes libfive fast on large trees: one
// interval pass over the box (eval_interval.h, with a trace) shows where a
// min or max has one operand that wins at every point of the box (a carve
// far from this box is clamped to its floor, which the field never
// reaches); the tape is rewritten with that operand in the operation's
// place, and what no longer reaches the result is dropped. Nested boxes
// specialize the specialized tape further.
//
// Exact: the shortened tape computes the same value as the full one at every
// point of the box, bit for bit, in double and in float. In double the
// interval bounds are sound, so a tie (a <= b everywhere) is enough; float
// evaluation rounds differently from the bounds, so there a winner must win
// by a margin, or both bounds must be constants that float keeps exactly
// (IntervalTrace's exact bits: a clamp's floor against a clamped field).
// Operations that may fail in the box stay, as do their operands (a failure
// anywhere fails the point); NaN is never pruned around.
//
// Gradients: min and max carry the derivative of the operand they return,
// so a tie is pruned only where both operands' derivatives are zero at the
// tied value (an edit's running field at the band's floor against a far
// piece clamped to that floor). The values are the full tape's bit for bit;
// a derivative may then be a zero of the other sign, which no later
// operation turns into anything but a zero: the magnitudes are the same bit
// for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "frep/eval/eval_interval.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

// What evaluates the specialized tape: the double or float batch
// evaluators, or the gradient evaluator (double, whose min and max carry
// the derivative of the operand they return: a tie must keep the one the
// operation itself returns).
enum class Precision { Double, Float, Gradient };

// Whether the evaluators over space specialize their tapes (default on;
// HG_NO_SPECIALIZE=1 in the environment turns it off, as the benchmarks'
// and tests' comparison runs do through setSpecialization).
bool specializationEnabled();
void setSpecialization(bool enabled);

// A specialized tape and the affine forms of its instructions (on the tape
// it came from), for an IntervalEvaluator over it.
struct SpecializedTape {
    Tape tape;
    std::vector<IntervalEvaluator::Affine> affine;
};

// Reusable scratch space; one per thread.
class TapeSpecializer {
public:
    // Specializes `tape` (whose affine forms are `affine`) to the box that
    // `trace` was evaluated over. False, leaving `out` alone, when nothing
    // would be removed.
    bool specialize(const Tape& tape, const std::vector<IntervalEvaluator::Affine>& affine, const IntervalTrace& trace,
                    Precision precision, SpecializedTape& out);

private:
    // Gradients: whether instruction k's derivative is zero wherever its
    // value is t (a clamp at its floor, a constant, a max of pieces all at
    // their floors there), from the values noted for it (NaN: none).
    bool isFlat(std::uint32_t k, double t) const;
    void noteFlat(const Instr& in, std::size_t k, const IntervalTrace& trace);

    std::vector<double> flatLo_, flatHi_;  // per instruction, gradients only
    std::vector<std::uint32_t> def_;    // per register: the instruction that last wrote it
    std::vector<std::uint32_t> alias_;  // per instruction: the instruction whose value it equals in the box
    std::vector<char> live_;
    std::vector<Instr> ssa_;
    std::vector<SourceLoc> locs_;
    std::vector<std::uint32_t> order_;
};

}  // namespace hg::frep
