// Skeletal (implicit-blob) primitives: Blinn's blobby model, Nishimura's
// metaballs and Wyvill's soft objects. Each sums a kernel over a list of
// centres given as three coordinate arrays; the number of centres is the
// size of the first coordinate array, as in the reference.
#pragma once

#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/primitives.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

// hfBlobby(x, x0, y0, z0, a, b, T): sum_i b_i exp(-a_i r_i^2) - T, with r_i the
// distance from x to centre i.
//   x0, y0, z0: centre coordinates; a: decay factors; b: weights;
//   T: threshold.
template <class V>
V hfBlobby(const std::vector<V>& x, const std::vector<V>& x0, const std::vector<V>& y0,
           const std::vector<V>& z0, const std::vector<V>& a, const std::vector<V>& b,
           const V& t) {
    const size_t num = x0.size();
    if (num == 0 || !detail::hasItems(x, 3) || !detail::hasItems(y0, num) ||
        !detail::hasItems(z0, num) || !detail::hasItems(a, num) || !detail::hasItems(b, num))
        return V(kSentinel);
    V blobby = V(0.0);
    for (size_t i = 0; i < num; ++i) {
        V xt = x[0] - x0[i];
        V yt = x[1] - y0[i];
        V zt = x[2] - z0[i];
        blobby = blobby + b[i] * exp(-a[i] * (xt * xt + yt * yt + zt * zt));
    }
    return blobby - t;
}

// hfMetaball(x, x0, y0, z0, b, d, T): sum_i f_i(r_i) - T with the piecewise
// quadratic kernel f(r) = b (1 - 3 r^2/d^2) for r <= d/3,
// 1.5 b (1 - r/d)^2 for d/3 < r < d, and 0 beyond d.
//   x0, y0, z0: centre coordinates; b: weights; d: radii of influence
//   (a centre whose d is not positive is ignored); T: threshold.
template <class V>
V hfMetaball(const std::vector<V>& x, const std::vector<V>& x0, const std::vector<V>& y0,
             const std::vector<V>& z0, const std::vector<V>& b, const std::vector<V>& d,
             const V& t) {
    const size_t num = x0.size();
    if (num == 0 || !detail::hasItems(x, 3) || !detail::hasItems(y0, num) ||
        !detail::hasItems(z0, num) || !detail::hasItems(b, num) || !detail::hasItems(d, num))
        return V(kSentinel);
    V mb = V(0.0);
    for (size_t i = 0; i < num; ++i) {
        // A constant non-positive reach: the centre is skipped, statically.
        if (isConstant(d[i]) && !(constantValue(d[i]) > 0.0)) continue;
        V xt = x[0] - x0[i];
        V yt = x[1] - y0[i];
        V zt = x[2] - z0[i];
        V r2 = xt * xt + yt * yt + zt * zt;
        V r = sqrt(r2);
        V rd = r / d[i];
        V inner = mb + b[i] * (1.0 - 3.0 * rd * rd);
        V outer = select(lt(r, d[i]), mb + 1.5 * b[i] * (1.0 - rd) * (1.0 - rd), mb);
        V updated = select(le(r, d[i] / 3.0), inner, outer);
        mb = select(gt(d[i], V(0.0)), updated, mb);
    }
    return mb - t;
}

namespace detail {

// One step of hfSoft's sum: `soft` plus the kernel of a centre at squared
// distance r2 with radius of influence d (nothing beyond d), in the
// reference's order of operations. The tape fuses it (Op::SoftStep) when d
// is constant: its interval bounds then follow the kernel's fall with r2.
template <class V>
V softStep(const V& soft, const V& r2, const V& d) {
    V r4 = r2 * r2;
    V d2 = d * d;
    V d4 = d2 * d2;
    V added = soft + 1.0 - 22.0 * r2 / (9.0 * d2) + 17.0 * r4 / (9.0 * d4) - 4.0 * r4 * r2 / (9.0 * d4 * d2);
    return select(le(sqrt(r2), d), added, soft);
}

}  // namespace detail

// hfSoft(x, x0, y0, z0, d, T): sum_i f_i - T with Wyvill's kernel
// f = 1 - 22 r^2/(9 d^2) + 17 r^4/(9 d^4) - 4 r^6/(9 d^6) for r <= d, else 0.
//   x0, y0, z0: centre coordinates; d: radii of influence; T: threshold.
template <class V>
V hfSoft(const std::vector<V>& x, const std::vector<V>& x0, const std::vector<V>& y0,
         const std::vector<V>& z0, const std::vector<V>& d, const V& t) {
    const size_t num = x0.size();
    if (num == 0 || !detail::hasItems(x, 3) || !detail::hasItems(y0, num) ||
        !detail::hasItems(z0, num) || !detail::hasItems(d, num))
        return V(kSentinel);
    V soft = V(0.0);
    for (size_t i = 0; i < num; ++i) {
        V xt = x[0] - x0[i];
        V yt = x[1] - y0[i];
        V zt = x[2] - z0[i];
        V r2 = xt * xt + yt * yt + zt * zt;
        soft = detail::softStep(soft, r2, d[i]);
    }
    return soft - t;
}

}  // namespace hg::frep::lib
