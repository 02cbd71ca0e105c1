// A body of a parsed program, ready to evaluate: compiled to a tape when the
// program flattens, otherwise run on the scalar interpreter. Both paths give
// the reference's values; the tape adds batch speed, intervals and gradients.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frep/language/ast.h"
#include "frep/language/domain_error.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

class Model {
public:
    // `a` fills the body's a[] (missing items are 0).
    Model(std::shared_ptr<const Program> program, int body, std::vector<double> a = {});

    const Program& program() const { return *program_; }
    const Body& body() const { return program_->bodies[static_cast<size_t>(body_)]; }
    int bodyIndex() const { return body_; }
    const std::vector<double>& parameters() const { return a_; }

    bool compiled() const { return tape_.has_value(); }
    const Tape* tape() const { return tape_ ? &*tape_ : nullptr; }
    // Why the program runs on the interpreter, and where ("" when compiled).
    const std::string& fallbackReason() const { return reason_; }
    SourceLoc fallbackLoc() const { return reasonLoc_; }
    // "tape (N instructions, R registers)" or "scalar interpreter: reason".
    std::string pathDescription() const;

private:
    std::shared_ptr<const Program> program_;
    int body_;
    std::vector<double> a_;
    std::optional<Tape> tape_;
    std::string reason_;
    SourceLoc reasonLoc_;
};

// Evaluates a Model at batches of points on either path. One per thread.
template <class T>
class PointSampler {
public:
    explicit PointSampler(const Model& model);
    ~PointSampler();
    PointSampler(const PointSampler&) = delete;
    PointSampler& operator=(const PointSampler&) = delete;

    void evaluate(const T* x, const T* y, const T* z, T* out, size_t n, ErrorReport& errors,
                  std::uint8_t* failed = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

extern template class PointSampler<float>;
extern template class PointSampler<double>;

}  // namespace hg::frep
