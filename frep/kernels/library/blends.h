// Pasko's blending set operations: the alpha-0 R-function union or
// intersection plus a displacement a0 / (1 + (f1/a1)^2 + (f2/a2)^2) that
// fades with the distance from the two surfaces.
#pragma once

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

// hfBlendUni(f1, f2, a0, a1, a2) =
//   f1 + f2 + sqrt(f1^2 + f2^2) + a0 / (1 + (f1/a1)^2 + (f2/a2)^2).
//   f1, f2: the two function values; a0: amount of added material;
//   a1, a2: how far the blend reaches along f1 and f2. No check for zero
//   a1, a2 (the reference's check is not applied).
template <class V>
V hfBlendUni(const V& f1, const V& f2, const V& a0, const V& a1, const V& a2) {
    V d = a0 / (1.0 + (f1 / a1) * (f1 / a1) + (f2 / a2) * (f2 / a2));
    return f2 + f1 + sqrt(f1 * f1 + f2 * f2) + d;
}

// hfBlendInt(f1, f2, a0, a1, a2) =
//   f1 + f2 - sqrt(f1^2 + f2^2) + a0 / (1 + (f1/a1)^2 + (f2/a2)^2).
//   Parameters as for hfBlendUni.
template <class V>
V hfBlendInt(const V& f1, const V& f2, const V& a0, const V& a1, const V& a2) {
    V d = a0 / (1.0 + (f1 / a1) * (f1 / a1) + (f2 / a2) * (f2 / a2));
    return f2 + f1 - sqrt(f1 * f1 + f2 * f2) + d;
}

}  // namespace hg::frep::lib
