// Estimates the box a solid occupies by interval subdivision: boxes that the
// interval evaluator proves outside (f < 0 everywhere) are dropped, the rest
// are split, level by level, until the cells are small against the solid or
// the work budget is spent. The result contains the solid whenever the solid
// lies inside the search cube.
#pragma once

#include "frep/kernels/box.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

struct BoundsEstimate {
    Box3 box;
    bool empty = false;       // nothing can be inside the search cube
    bool unbounded = false;   // the kept boxes reach the search cube's faces
    bool budgetSpent = false; // stopped because a level kept more than maxBoxes
    int levels = 0;           // subdivision levels done
    double cellSize = 0.0;    // size of the last level's cells (precision)
};

// The estimate stops once its cells are at most this fraction of the box's
// longest side (or when a level keeps more than maxBoxes boxes).
constexpr double kBoundsPrecision = 64.0;

// `searchHalfSize`: the cube [-s, s]^3 is searched. `maxBoxes`: cap on the
// boxes kept per level (work budget).
BoundsEstimate estimateBounds(const Tape& tape, double searchHalfSize = 1024.0, size_t maxBoxes = 4096);

}  // namespace hg::frep
