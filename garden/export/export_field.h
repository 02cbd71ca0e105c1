// The unedited fields an exported sculpture starts from, written once as
// templates over the value type like edit_field.h: on double they are the
// reference the export tests compare against, on hfexport::HfText they are
// the exported text.
//
//  * A HyperFun sculpture's grid holds its source's f times the grid's
//    normalization (voxels per unit of f, voxel/normalization.h), clamped
//    to +-band: the sampler's stored value, in double.
//  * The morph result holds w0 F0 + w1 F1 + w2 F2 clamped to +-band, where
//    F_i = f_i * normalization_i are the sources' unclamped normalized
//    fields, all three evaluated at the same point of the shared model
//    frame (morph_sources.h), and w the morph weights (barycentric times
//    balancing factors, normalized: morph_weights.h). The grid blends the
//    float caches of F_i (blend_block.cpp) in this order; the export is the
//    same blend in double.
#pragma once

#include <array>

#include "garden/sculpt/edit_field.h"

namespace hg::garden {

template <class V>
V normalizedSourceField(const V& f, double normalization, double band) {
    return editops::clamp<V>(f * V(normalization), -band, band);
}

struct MorphBlendConstants {
    std::array<double, 3> normalization{1.0, 1.0, 1.0};
    std::array<double, 3> w{};  // the weights the blend uses (sum 1)
    double band = 3.0;
};

template <class V>
V morphBlendField(const V& f0, const V& f1, const V& f2, const MorphBlendConstants& m) {
    const V a = f0 * V(m.normalization[0]);
    const V b = f1 * V(m.normalization[1]);
    const V c = f2 * V(m.normalization[2]);
    return editops::clamp<V>(V(m.w[0]) * a + V(m.w[1]) * b + V(m.w[2]) * c, -m.band, m.band);
}

}  // namespace hg::garden
