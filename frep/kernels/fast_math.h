// Branch-free float versions of the transcendental functions, so the float
// batch evaluator's loops vectorize (glibc's scalar calls do not). Cephes
// reductions and polynomials: relative error about 1e-7 inside the stated
// ranges. Callers fix up the lanes outside them with the libm function
// (needsLibm*), so every input still gets a correct result.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace hg::frep::fast {

inline std::int32_t bits(float v) { return __builtin_bit_cast(std::int32_t, v); }
inline float fromBits(std::int32_t b) { return __builtin_bit_cast(float, b); }

// sin and cos for |x| <= 8192.
inline bool needsLibmTrig(float x) { return !(std::fabs(x) <= 8192.0f); }

inline void sinCosReduce(float x, float& r, std::int32_t& j) {
    const float ax = std::fabs(x);
    j = static_cast<std::int32_t>(ax * 1.27323954473516f);  // 4 / pi
    j = (j + 1) & ~1;
    const float y = static_cast<float>(j);
    r = ((ax - y * 0.78515625f) - y * 2.4187564849853515625e-4f) - y * 3.77489497744594108e-8f;
}
inline float sinPoly(float r) {
    const float z = r * r;
    return ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * r + r;
}
inline float cosPoly(float r) {
    const float z = r * r;
    return ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
}
inline float sin(float x) {
    float r;
    std::int32_t j;
    sinCosReduce(x, r, j);
    const float v = (j & 2) ? cosPoly(r) : sinPoly(r);
    const bool negate = ((j & 4) != 0) != (x < 0.0f);
    return negate ? -v : v;
}
inline float cos(float x) {
    float r;
    std::int32_t j;
    sinCosReduce(x, r, j);
    const float v = (j & 2) ? sinPoly(r) : cosPoly(r);
    const bool negate = ((j + 2) & 4) != 0;
    return negate ? -v : v;
}

// exp for -87 <= x <= 88.
inline bool needsLibmExp(float x) { return !(x >= -87.0f && x <= 88.0f); }
inline float exp(float x) {
    const float n = std::nearbyint(x * 1.44269504088896341f);
    const float r = (x - n * 0.693359375f) - n * -2.12194440e-4f;
    const float z = r * r;
    const float p = ((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r + 4.1665795894e-2f) * r +
                     1.6666665459e-1f) * r + 5.0000001201e-1f;
    const float e = p * z + r + 1.0f;
    // Out-of-range lanes are recomputed by the caller; clamp so the exponent
    // bits stay a valid float (and the shift defined).
    const float nc = std::fmin(std::fmax(n, -126.0f), 127.0f);
    return e * fromBits(static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::int32_t>(nc) + 127) << 23));
}

// log for normal positive x.
inline bool needsLibmLog(float x) { return !(x >= 1.17549435e-38f && x <= 3.4e38f); }
inline float log(float x) {
    const std::int32_t b = bits(x);
    float e = static_cast<float>(((b >> 23) & 0xff) - 126);
    float m = fromBits((b & 0x807fffff) | 0x3f000000);  // [0.5, 1)
    const bool small = m < 0.707106781186547524f;
    e = small ? e - 1.0f : e;
    m = small ? m + m - 1.0f : m - 1.0f;
    const float z = m * m;
    float y = ((((((((7.0376836292e-2f * m - 1.1514610310e-1f) * m + 1.1676998740e-1f) * m - 1.2420140846e-1f) * m +
                   1.4249322787e-1f) * m - 1.6668057665e-1f) * m + 2.0000714765e-1f) * m - 2.4999993993e-1f) * m +
               3.3333331174e-1f) * m * z;
    y += -2.12194440e-4f * e;
    y += -0.5f * z;
    return m + y + 0.693359375f * e;
}

// Cephes atanf polynomial on the reduced argument |r| <= tan(pi / 8).
inline float atanPoly(float r) {
    const float z = r * r;
    return (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * r + r;
}

// atan for every float (Cephes atanf reduction); every candidate is
// computed, then selected, so there is no branch.
inline float atan(float x) {
    const float t = std::fabs(x);
    const float rBig = -1.0f / (t + 1e-30f);
    const float rMid = (t - 1.0f) / (t + 1.0f);
    const bool big = t > 2.414213562f;
    const bool mid = t > 0.414213562f;
    const float y0 = big ? 1.570796327f : (mid ? 0.785398163f : 0.0f);
    const float r = big ? rBig : (mid ? rMid : t);
    const float v = y0 + atanPoly(r);
    return x < 0.0f ? -v : v;
}

// atan2(y, x) for y > 0 and finite x: the angle in (0, pi), by the same
// reduction applied to y / |x| without forming that quotient. The three
// candidate quotients do not wait for the selection, so their divisions
// overlap (the convolution kernels that use this are latency bound).
inline float angleAbove(float y, float x) {
    const float ax = std::fabs(x);
    const bool big = y > 2.414213562f * ax;
    const bool mid = y > 0.414213562f * ax;
    const float y0 = big ? 1.570796327f : (mid ? 0.785398163f : 0.0f);
    const float rBig = -ax / y, rMid = (y - ax) / (y + ax), rSmall = y / ax;
    const float r = big ? rBig : (mid ? rMid : rSmall);
    // atanPoly's polynomial in Estrin's form: a shorter dependency chain.
    const float z = r * r, z2 = z * z;
    const float p = ((-3.33329491539e-1f + 1.99777106478e-1f * z) + z2 * (-1.38776856032e-1f + 8.05374449538e-2f * z)) * z * r + r;
    const float first = y0 + p;  // angle of (|x|, y)
    return x < 0.0f ? 3.141592654f - first : first;
}

}  // namespace hg::frep::fast
