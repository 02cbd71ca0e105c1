// Gradient evaluator: value and d/dx, d/dy, d/dz of the program at a batch
// of points, by forward-mode differentiation along the tape (double).
// Where the function is not differentiable (a select switching branch,
// |x| at 0, an R-function at f = g = 0) one side's derivative is returned.
// Failing points give kOutsideValue and a zero gradient.
#pragma once

#include <cstddef>
#include <vector>

#include "frep/language/domain_error.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

struct Gradient {
    double value = 0.0, dx = 0.0, dy = 0.0, dz = 0.0;
};

class GradientEvaluator {
public:
    static constexpr size_t kBatch = 64;

    explicit GradientEvaluator(const Tape& tape);

    void evaluate(const double* x, const double* y, const double* z, Gradient* out, size_t n, ErrorReport& errors);
    Gradient evaluate(double x, double y, double z, ErrorReport& errors);
    // Runs `tape` from now on (it must outlive the evaluator), keeping the memory.
    void rebind(const Tape& tape);

private:
    void chunk(const double* x, const double* y, const double* z, Gradient* out, size_t n, ErrorReport& errors);

    const Tape* tape_;
    std::vector<double> v_, dx_, dy_, dz_;
    std::vector<unsigned char> fail_;
};

}  // namespace hg::frep
