// Dual: a value with its partial derivatives along the three inputs of a
// fused tape kernel (forward-mode differentiation). It provides the
// operations of frep/kernels/library/value_ops.h, so the gradient evaluator runs a
// fused kernel's own library code on it and gets the analytic derivative of
// exactly the closed form the other paths compute; the value part uses the
// same double operations, so it matches them bit for bit.
#pragma once

#include <cmath>

namespace hg::frep {

struct Dual {
    double v = 0.0;
    double d[3] = {0.0, 0.0, 0.0};

    Dual(double c = 0.0) : v(c) {}  // NOLINT: implicit, like a double literal
    // The k-th input (k = 0, 1, 2) with value c.
    static Dual input(double c, int k) {
        Dual r(c);
        r.d[k] = 1.0;
        return r;
    }
};

namespace dual_detail {
// f(a) with f'(a) = slope.
inline Dual chain(double value, const Dual& a, double slope) {
    Dual r(value);
    for (int k = 0; k < 3; ++k) r.d[k] = slope * a.d[k];
    return r;
}
}  // namespace dual_detail

inline Dual operator+(const Dual& a, const Dual& b) {
    Dual r(a.v + b.v);
    for (int k = 0; k < 3; ++k) r.d[k] = a.d[k] + b.d[k];
    return r;
}
inline Dual operator-(const Dual& a, const Dual& b) {
    Dual r(a.v - b.v);
    for (int k = 0; k < 3; ++k) r.d[k] = a.d[k] - b.d[k];
    return r;
}
inline Dual operator*(const Dual& a, const Dual& b) {
    Dual r(a.v * b.v);
    for (int k = 0; k < 3; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
    return r;
}
inline Dual operator/(const Dual& a, const Dual& b) {
    Dual r(a.v / b.v);
    for (int k = 0; k < 3; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
    return r;
}
inline Dual operator-(const Dual& a) { return dual_detail::chain(-a.v, a, -1.0); }

inline Dual sqrt(const Dual& a) {
    const double s = std::sqrt(a.v);
    return dual_detail::chain(s, a, 0.5 / s);
}
inline Dual fabs(const Dual& a) { return dual_detail::chain(std::fabs(a.v), a, a.v < 0.0 ? -1.0 : 1.0); }
inline Dual log(const Dual& a) { return dual_detail::chain(std::log(a.v), a, 1.0 / a.v); }
inline Dual sin(const Dual& a) { return dual_detail::chain(std::sin(a.v), a, std::cos(a.v)); }
inline Dual cos(const Dual& a) { return dual_detail::chain(std::cos(a.v), a, -std::sin(a.v)); }
inline Dual tan(const Dual& a) {
    const double c = std::cos(a.v);
    return dual_detail::chain(std::tan(a.v), a, 1.0 / (c * c));
}
inline Dual atan(const Dual& a) { return dual_detail::chain(std::atan(a.v), a, 1.0 / (1.0 + a.v * a.v)); }

// Comparisons and logic: piecewise constant, derivative 0.
inline Dual lt(const Dual& a, const Dual& b) { return Dual(a.v < b.v ? 1.0 : 0.0); }
inline Dual gt(const Dual& a, const Dual& b) { return Dual(a.v > b.v ? 1.0 : 0.0); }
inline Dual select(const Dual& c, const Dual& a, const Dual& b) { return c.v != 0.0 ? a : b; }

}  // namespace hg::frep
