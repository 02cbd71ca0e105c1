// How far beyond a selection's balls an edit made inside it still acts
// (docs/sketching.md "Selections"): a limited tool is at its floor, and
// leaves the field as it was, this far out: the band, a melt's softness
// below it, and a voxel more. What an edit's mask box is grown by, when
// the edit is made and when it is derived again in a new grid's units.
#pragma once

#include <variant>

#include "garden/sculpt/edit.h"

namespace hg::garden {

inline double maskMargin(const Edit& e, const FieldUnits& u) {
    double floor = u.band;
    if (const auto* s = std::get_if<Stroke>(&e.op))
        if (s->tool == StrokeTool::Melt) floor += s->softness;
    return (floor + 1.0) * u.voxelSize;
}

}  // namespace hg::garden
