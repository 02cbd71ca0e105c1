// One metamorphosis while the garden runs (docs/design.md §4): its three
// source caches in the shared model frame, the balancing factors, the
// weights the selector gives and the budgeted blender that writes the
// result's grid. The result's Sculpture holds it, so a garden may hold
// several morphs, each blended and weighed on its own.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "garden/morph/morph_blend.h"
#include "garden/morph/morph_sources.h"
#include "garden/morph/morph_weights.h"

namespace hg::garden {

// Which morph of the garden file it is, is its Sculpture's `source.spec`.
struct MorphState {
    std::unique_ptr<MorphSources> sources;
    std::array<double, 3> balance{1.0, 1.0, 1.0};
    std::optional<MorphWeights> weights;
    // Reads `sources` and writes the result's grid (or its edits' base):
    // declared last, so that it goes first.
    std::unique_ptr<MorphBlender> blender;
};

}  // namespace hg::garden
