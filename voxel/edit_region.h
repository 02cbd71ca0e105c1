// A box of an edited sculpture's grid recomputed from its unedited grid
// through an edit tape (garden/sculpt: the tape's W input is the unedited
// stored value, x, y, z the voxel's model position): the grid update of a
// stroke, of an undo, of a redo. Every voxel's value is a pure function of
// its base value, its position and the tape, so a box computed alone equals
// the same box of a whole-grid computation, bit for bit.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "frep/language/domain_error.h"
#include "frep/compiler/tape.h"
#include "voxel/index_box.h"
#include "voxel/volume.h"

namespace hg::voxel {

struct EditRegionStats {
    std::uint64_t voxels = 0;  // evaluated
    double seconds = 0.0;
    frep::ErrorReport errors;
};

// `target` and `base` share a frame (they may be the same grid: each voxel
// is read before it is written); `region` is clipped to it. Values are
// clamped to the band and stored active inside it, like the sampler's.
EditRegionStats applyEditTape(const Volume& base, Volume& target, const IndexBox& region, const frep::Tape& tape);

// Many regions, each with its own tape (`tapeOf(i)`, called from any
// thread), side by side on TBB: what a bulk rebuild of thousands of small
// cells needs (`base` and `target` distinct).
EditRegionStats applyEditTapes(const Volume& base, Volume& target, const std::vector<IndexBox>& regions,
                               const std::function<frep::Tape(std::size_t)>& tapeOf);

}  // namespace hg::voxel
