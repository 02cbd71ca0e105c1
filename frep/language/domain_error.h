// Runtime failures of a HyperFun program at one point (the reference
// interpreter's RUNTIME ERROR cases). Evaluators count them, remember the
// first location, and treat the point as outside; they never let NaN or
// infinity out.
#pragma once

#include <cstdint>

#include "frep/language/ast.h"

namespace hg::frep {

enum class DomainError : std::uint8_t {
    None = 0,
    DivisionByZero,       // |divisor| < 1e-6
    NegativeSqrt,         // sqrt of a negative number
    LogDomain,            // log/logd of a number that is not positive
    AsinAcosRange,        // asin/acos outside [-1, 1]
    TanPole,              // tan where |cos| < 1e-6
    ZeroBasePower,        // 0 ^ e with e <= 1e-6
    NegativeBasePower,    // negative base to a non-integer power
    IndexOutOfRange,      // array index outside 1..size
    UnassignedValue,      // variable or array item read before it was assigned
    NotANumber,           // a library routine or mod produced NaN
};

const char* describe(DomainError e);

// The first failure seen by an evaluation call and how many points failed.
struct ErrorReport {
    std::uint64_t count = 0;
    DomainError first = DomainError::None;
    SourceLoc firstLoc;

    void add(DomainError e, SourceLoc loc, std::uint64_t n = 1) {
        if (n == 0) return;
        if (count == 0) { first = e; firstLoc = loc; }
        count += n;
    }
    void merge(const ErrorReport& other) {
        if (other.count == 0) return;
        if (count == 0) { first = other.first; firstLoc = other.firstLoc; }
        count += other.count;
    }
};

// Value an evaluator returns at a point where the program failed: outside
// (negative), and small enough not to distort gradients or normalization.
constexpr double kOutsideValue = -1.0;
// Largest magnitude an evaluator returns; infinities are clamped to it.
constexpr double kValueLimit = 1e30;

}  // namespace hg::frep
