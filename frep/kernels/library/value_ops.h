// The operations library routines may use on a value type V, written here
// for V = double with exactly the C semantics of the reference interpreter.
// frep/compiler/sym.h provides the same set for the symbolic type Sym (found by
// argument-dependent lookup), so routine templates compile for both.
#pragma once

#include <cmath>

namespace hg::frep::lib {

inline double sqrt(double v) { return std::sqrt(v); }
inline double exp(double v) { return std::exp(v); }
inline double log(double v) { return std::log(v); }
inline double sin(double v) { return std::sin(v); }
inline double cos(double v) { return std::cos(v); }
inline double tan(double v) { return std::tan(v); }
inline double atan(double v) { return std::atan(v); }
inline double asin(double v) { return std::asin(v); }
inline double acos(double v) { return std::acos(v); }
inline double atan2(double y, double x) { return std::atan2(y, x); }
inline double fabs(double v) { return std::fabs(v); }
inline double pow(double b, double e) { return std::pow(b, e); }
inline double floor(double v) { return std::floor(v); }

// Comparisons give 1.0 or 0.0.
inline double lt(double a, double b) { return a < b ? 1.0 : 0.0; }
inline double le(double a, double b) { return a <= b ? 1.0 : 0.0; }
inline double gt(double a, double b) { return a > b ? 1.0 : 0.0; }
inline double ge(double a, double b) { return a >= b ? 1.0 : 0.0; }
// Logical combinations of 0/1 values.
inline double land(double a, double b) { return (a != 0.0 && b != 0.0) ? 1.0 : 0.0; }
inline double lor(double a, double b) { return (a != 0.0 || b != 0.0) ? 1.0 : 0.0; }
// cond != 0 ? a : b. Both sides are computed: keep them free of effects.
inline double select(double cond, double a, double b) { return cond != 0.0 ? a : b; }

inline bool isConstant(double) { return true; }
inline double constantValue(double v) { return v; }

}  // namespace hg::frep::lib
