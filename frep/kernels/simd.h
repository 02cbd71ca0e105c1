// The fused kernels' float loops are compiled twice from one source: for the
// x86-64 baseline (SSE2, 4 lanes) and for AVX2 (8 lanes), chosen once at run
// time. Both builds perform the same IEEE operations in the same order
// (-ffp-contract=off: no fused multiply-add), so they return the same bits.
// Elsewhere only the baseline exists.
#pragma once

#include <cstddef>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HG_SIMD_AVX2 1
#define HG_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define HG_SIMD_AVX2 0
#define HG_TARGET_AVX2
#endif

#if defined(__GNUC__) || defined(__clang__)
// A loop body that must be compiled into each build, not called.
#define HG_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define HG_ALWAYS_INLINE inline
#endif

namespace hg::frep::simd {

// Set by tests to run the baseline build where AVX2 exists too.
inline bool& baselineOnly() {
    static bool only = false;
    return only;
}

// Whether the AVX2 build runs.
inline bool avx2() {
#if HG_SIMD_AVX2
    static const bool have = __builtin_cpu_supports("avx2");
    return have && !baselineOnly();
#else
    return false;
#endif
}

// One instantiation per build of a fused kernel's loop: `Loop` has an
// HG_ALWAYS_INLINE run(px, py, pz, out, n), compiled into each.
template <class Loop>
void runBaseline(const Loop& k, const float* px, const float* py, const float* pz, float* out, std::size_t n) {
    k.run(px, py, pz, out, n);
}
#if HG_SIMD_AVX2
template <class Loop>
HG_TARGET_AVX2 void runAvx2(const Loop& k, const float* px, const float* py, const float* pz, float* out,
                            std::size_t n) {
    k.run(px, py, pz, out, n);
}
#endif

// Runs the loop in the AVX2 build where it runs, else in the baseline.
template <class Loop>
void run(const Loop& k, const float* px, const float* py, const float* pz, float* out, std::size_t n) {
#if HG_SIMD_AVX2
    if (avx2()) return runAvx2(k, px, py, pz, out, n);
#endif
    runBaseline(k, px, py, pz, out, n);
}

}  // namespace hg::frep::simd
