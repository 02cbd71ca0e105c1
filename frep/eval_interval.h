// Interval evaluator: bounds of the program's value over an axis-aligned box.
// Sound for the double batch evaluator: for every point of the box, the value
// it returns (including kOutsideValue for failing points and the
// +-kValueLimit clamp) lies inside the returned bounds. The float batch
// evaluator rounds differently: the fused kernels leave room for their float
// loops' error, generic operations do not (a constant 0.3 reads 0.30000001 in
// float), which is why the sampler culls only boxes a whole band past the
// surface. Used to skip space that is certainly inside or outside the solid.
#pragma once

#include <vector>

#include "frep/interval.h"
#include "frep/tape.h"

namespace hg::frep {

class IntervalEvaluator {
public:
    explicit IntervalEvaluator(const Tape& tape);

    Interval evaluate(const Interval& x, const Interval& y, const Interval& z);

private:
    // An instruction whose value is an affine function of the point,
    // c[0] + c[1] x + c[2] y + c[3] z (shifts, rotations and scales of the
    // coordinates, and compositions of them): its exact range over a box,
    // where interval arithmetic would widen every composition (a rotated
    // coordinate fed to a second rotation counts x twice).
    struct Affine {
        bool valid = false;
        double c[4] = {0.0, 0.0, 0.0, 0.0};
    };

    const Tape& tape_;
    std::vector<Interval> regs_;
    std::vector<Affine> affine_;  // per instruction
};

}  // namespace hg::frep
