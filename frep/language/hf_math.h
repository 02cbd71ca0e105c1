// The arithmetic of the HyperFun language, exactly as the reference
// interpreter computes it (conformance README, "Arithmetic"). One definition
// shared by the scalar interpreter and the tape evaluators, templated on the
// floating type so the float batch evaluator follows the same rules.
//
// Functions that can fail return DomainError::None on success and write the
// result to `out`.
#pragma once

#include <cmath>

#include "frep/language/domain_error.h"

namespace hg::frep::hf {

template <class T> constexpr T kEps = T(1e-6);

// The reference's HF_round: nearest integer, halves toward +infinity.
template <class T>
inline long long round(T d) {
    T c = std::ceil(d);
    return static_cast<long long>((c - d > T(0.5)) ? (c - T(1)) : c);
}

template <class T> inline bool truthy(T v) { return std::fabs(v) >= kEps<T>; }
template <class T> inline T fromBool(bool b) { return b ? T(1) : T(0); }

template <class T> inline T equal(T p, T q) { return fromBool<T>(std::fabs(p - q) < kEps<T>); }
template <class T> inline T notEqual(T p, T q) { return fromBool<T>(std::fabs(p - q) >= kEps<T>); }
template <class T> inline T logicalAnd(T p, T q) { return fromBool<T>(truthy(p) && truthy(q)); }
template <class T> inline T logicalOr(T p, T q) { return fromBool<T>(truthy(p) || truthy(q)); }
template <class T> inline T logicalNot(T p) { return fromBool<T>(!truthy(p)); }

// R-functions with alpha = 0; written as the reference evaluates them.
template <class T> inline T unite(T f, T g) { return f + g + std::sqrt(std::fabs(f * f + g * g)); }
template <class T> inline T intersect(T f, T g) { return f + g - std::sqrt(std::fabs(f * f + g * g)); }
template <class T> inline T subtract(T f, T g) {
    T ng = -g;
    return f + ng - std::sqrt(std::fabs(f * f + ng * ng));
}

template <class T>
inline DomainError divide(T p, T q, T& out) {
    if (std::fabs(q) < kEps<T>) return DomainError::DivisionByZero;
    out = p / q;
    return DomainError::None;
}

// b ^ e, reference rules: near-zero base, integer exponent by repeated
// product (negative bases allowed), otherwise exp(e * log(b)).
template <class T>
inline DomainError power(T b, T e, T& out) {
    if (std::fabs(b) < kEps<T>) {
        if (e <= kEps<T>) return DomainError::ZeroBasePower;
        out = T(0);
        return DomainError::None;
    }
    if (e - std::floor(e) < kEps<T>) {
        long long n = round<T>(std::fabs(e));
        T v = T(1);
        for (long long i = 0; i < n; ++i) v *= b;
        if (e < T(0)) v = T(1) / v;
        out = v;
        return DomainError::None;
    }
    if (b < T(0)) return DomainError::NegativeBasePower;
    out = std::exp(e * std::log(b));
    return DomainError::None;
}

template <class T>
inline DomainError checkedSqrt(T v, T& out) {
    if (v < T(0)) return DomainError::NegativeSqrt;
    out = std::sqrt(v);
    return DomainError::None;
}
template <class T>
inline DomainError checkedLog(T v, T& out) {
    if (!(v > T(0))) return DomainError::LogDomain;
    out = std::log(v);
    return DomainError::None;
}
template <class T>
inline DomainError checkedLog10(T v, T& out) {
    if (!(v > T(0))) return DomainError::LogDomain;
    out = std::log10(v);
    return DomainError::None;
}
template <class T>
inline DomainError checkedAsin(T v, T& out) {
    if (std::fabs(v) > T(1)) return DomainError::AsinAcosRange;
    out = std::asin(v);
    return DomainError::None;
}
template <class T>
inline DomainError checkedAcos(T v, T& out) {
    if (std::fabs(v) > T(1)) return DomainError::AsinAcosRange;
    out = std::acos(v);
    return DomainError::None;
}
template <class T>
inline DomainError checkedTan(T v, T& out) {
    if (std::fabs(std::cos(v)) < kEps<T>) return DomainError::TanPole;
    out = std::tan(v);
    return DomainError::None;
}

// mod rounds both arguments (halves up) and takes the C remainder.
template <class T>
inline DomainError mod(T p, T q, T& out) {
    long long qi = round<T>(q);
    if (qi == 0) return DomainError::NotANumber;
    out = static_cast<T>(std::fmod(static_cast<double>(round<T>(p)), static_cast<double>(qi)));
    return DomainError::None;
}

template <class T> inline T truncate(T v) { return std::trunc(v); }
template <class T> inline T fraction(T v) { return v - std::trunc(v); }
template <class T> inline T maximum(T p, T q) { return (p > q) ? p : q; }
template <class T> inline T minimum(T p, T q) { return (p < q) ? p : q; }

}  // namespace hg::frep::hf
