// Interval evaluator: bounds of the program's value over an axis-aligned box.
// Sound for the double batch evaluator: for every point of the box, the value
// it returns (including kOutsideValue for failing points and the
// +-kValueLimit clamp) lies inside the returned bounds. The float batch
// evaluator rounds differently: the fused kernels leave room for their float
// loops' error, generic operations do not (a constant 0.3 reads 0.30000001 in
// float), which is why the sampler culls only boxes a whole band past the
// surface. Used to skip space that is certainly inside or outside the solid.
#pragma once

#include <cstdint>
#include <vector>

#include "frep/kernels/interval.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

// What one evaluation found at each instruction of the tape, for
// specializing the tape to the box (tape_specializer.h).
struct IntervalTrace {
    enum : std::uint8_t {
        kMayFail = 1,  // a fallible operation that may fail somewhere in the box
        kLoExact = 2,  // the lower bound is a constant every precision keeps (min, max and negation of constants)
        kHiExact = 4,  // the same for the upper bound
    };
    std::vector<Interval> value;       // per instruction
    std::vector<std::uint8_t> flags;   // per instruction
};

class IntervalEvaluator {
public:
    // An instruction whose value is an affine function of the point,
    // c[0] + c[1] x + c[2] y + c[3] z (shifts, rotations and scales of the
    // coordinates, and compositions of them): its exact range over a box,
    // where interval arithmetic would widen every composition (a rotated
    // coordinate fed to a second rotation counts x twice).
    struct Affine {
        bool valid = false;
        double c[4] = {0.0, 0.0, 0.0, 0.0};
    };

    explicit IntervalEvaluator(const Tape& tape);
    // A tape specialized from another (tape_specializer.h) with the affine
    // forms of the instructions it kept, found on the tape it came from: so
    // that every box gets exactly the bounds that tape would give it (a
    // pruned min can make its user affine here, which would bound it tighter).
    IntervalEvaluator(const Tape& tape, std::vector<Affine> affine);
    // Evaluates `tape` (with its affine forms, as above) from now on,
    // keeping the memory; the tape must outlive the evaluator.
    void rebind(const Tape& tape, const std::vector<Affine>& affine);

    // `trace`: also what each instruction's value and flags were.
    Interval evaluate(const Interval& x, const Interval& y, const Interval& z, IntervalTrace* trace = nullptr);

    // Bounds of the base value input (Op::W) where the caller knows them
    // (a grid's values lie in [-band, band]); `exact`: the bounds are
    // constants every precision keeps. Default: any value, not exact.
    void setBaseBounds(const Interval& w, bool exact) {
        base_ = w;
        baseExact_ = exact;
    }

    const Tape& tape() const { return *tape_; }
    const std::vector<Affine>& affine() const { return affine_; }

private:
    const Tape* tape_;
    std::vector<Interval> regs_;
    std::vector<std::uint8_t> exact_;  // per register: IntervalTrace's exact bits
    std::vector<Affine> affine_;  // per instruction
    Interval base_{-kValueLimit, kValueLimit};
    bool baseExact_ = false;
};

}  // namespace hg::frep
