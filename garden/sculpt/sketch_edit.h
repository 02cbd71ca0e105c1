// A sketch made an edit (garden/sculpt/edit.h, SketchSolid): the outline as
// drawn becomes the inflated solid on its plane (garden/sketch), with its
// mirror and the reach of each piece, or a refusal that says why.
#pragma once

#include <string>

#include "garden/sculpt/edit.h"

namespace hg::garden {

// Samples of the outline the inflation starts from, at most: its detail
// and cost (about 2 ms for 96 on one core, docs/sketching.md); fewer when
// they would be closer than half a voxel.
constexpr int kSketchSamples = 96;

// Fills `s`'s derived parts from its outline, normal, thickness and
// mirror; "" on success, else why the sketch is refused (too few points,
// no area, a figure eight, a bad normal).
std::string resolveSketch(SketchSolid& s, const FieldUnits& u);

}  // namespace hg::garden
