// Batch evaluator: runs a tape over up to kBatch points at once, structure
// of arrays, one tight loop per instruction (the compiler vectorizes the
// arithmetic ones). Templated on float (sampling) and double (conformance,
// export checks). Failing points and NaN come out as kOutsideValue and are
// counted (a NaN at the location of the operation that produced it);
// values beyond +-kValueLimit, infinities included, are clamped to it unless
// the caller asks for them as computed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "frep/language/domain_error.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

template <class T>
class BatchEvaluator {
public:
    static constexpr size_t kBatch = 256;

    // `tape` must outlive the evaluator. One evaluator per thread.
    explicit BatchEvaluator(const Tape& tape);

    // Any n; processed in chunks of kBatch. `failed`, if given, receives 1 for
    // each point where the program failed (or produced NaN), else 0.
    void evaluate(const T* x, const T* y, const T* z, T* out, size_t n, ErrorReport& errors,
                  std::uint8_t* failed = nullptr);
    // The same for a tape that reads the base value input (Op::W): w[i] is
    // point i's base value.
    void evaluate(const T* x, const T* y, const T* z, const T* w, T* out, size_t n, ErrorReport& errors,
                  std::uint8_t* failed = nullptr);

    // Clamp to +-kValueLimit (the default: what sampling, bounds and
    // gradients expect), or keep every non-NaN value as computed, as the
    // interpreter and the reference do (`hypergarden eval` prints those).
    void setClamped(bool clamped) { clamped_ = clamped; }

    const Tape& tape() const { return *tape_; }

    // Runs `tape` from now on (it must outlive the evaluator), keeping the
    // registers' memory: a tape specialized to each box costs no allocation
    // once the largest has been seen.
    void rebind(const Tape& tape);

private:
    // `w`: the base value input (Op::W), or null. `trace` (one point):
    // also follow where a NaN comes from, in nanFrom_.
    void chunk(const T* x, const T* y, const T* z, const T* w, T* out, size_t n, ErrorReport& errors,
               std::uint8_t* failed, bool trace = false);
    void traceNan(size_t k);
    T* reg(std::uint32_t r) { return regs_.data() + static_cast<size_t>(r) * kBatch; }

    const Tape* tape_;
    size_t firstInstr_ = 0;  // instructions before this are x, y, z and constants
    std::vector<T> regs_;
    std::vector<std::uint8_t> fail_;
    std::vector<std::uint8_t> bad_;
    bool clamped_ = true;
    // While tracing: per register, the instruction that made the NaN it
    // holds (the earliest one, where several meet), else kNoReg.
    std::vector<std::uint32_t> nanFrom_;
};

extern template class BatchEvaluator<float>;
extern template class BatchEvaluator<double>;

}  // namespace hg::frep
