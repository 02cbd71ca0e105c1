// Gardner's solid noise: a product of three sine series, one per axis.
#pragma once

#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/primitives.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

// hfNoiseG(x, amp, freq, phase) = Sx * Sy * Sz with
//   Sx = amp sin(freq x) + (amp/1.17) sin(freq x / 1.35 + phase sin(freq z)),
//   Sy, Sz the same with (y, x) and (z, y) in place of (x, z).
//   x: point (3 items); amp: amplitude; freq: frequency; phase: phase
//   coupling of the second terms.
template <class V>
V hfNoiseG(const std::vector<V>& x, const V& amp, const V& freq, const V& phase) {
    if (!detail::isPoint(x)) return V(kSentinel);
    V a2x = freq * x[0];
    V a2y = freq * x[1];
    V a2z = freq * x[2];
    V sx = sin(a2x);
    V sy = sin(a2y);
    V sz = sin(a2z);
    V a1d = amp / 1.17;
    V sx2 = a1d * sin(a2x / 1.35 + phase * sz);
    V sy2 = a1d * sin(a2y / 1.35 + phase * sx);
    V sz2 = a1d * sin(a2z / 1.35 + phase * sy);
    V serX = amp * sx + sx2;
    V serY = amp * sy + sy2;
    V serZ = amp * sz + sz2;
    return serX * serY * serZ;
}

}  // namespace hg::frep::lib
