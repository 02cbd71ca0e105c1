// Interval evaluator: bounds of the program's value over an axis-aligned box.
// Sound: for every point of the box, the value the batch evaluator returns
// (including kOutsideValue for failing points and the +-kValueLimit clamp)
// lies inside the returned bounds. Used to skip space that is certainly
// inside or outside the solid.
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
    const Tape& tape_;
    std::vector<Interval> regs_;
};

}  // namespace hg::frep
