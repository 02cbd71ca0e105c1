#include "frep/language/domain_error.h"

namespace hg::frep {

const char* describe(DomainError e) {
    switch (e) {
        case DomainError::None: return "no error";
        case DomainError::DivisionByZero: return "division by zero (|divisor| < 1e-6)";
        case DomainError::NegativeSqrt: return "square root of a negative number";
        case DomainError::LogDomain: return "logarithm of a number that is not positive";
        case DomainError::AsinAcosRange: return "asin/acos argument outside [-1, 1]";
        case DomainError::TanPole: return "tan at a pole (|cos| < 1e-6)";
        case DomainError::ZeroBasePower: return "zero raised to a zero or negative power";
        case DomainError::NegativeBasePower: return "negative number raised to a non-integer power";
        case DomainError::IndexOutOfRange: return "array index out of range";
        case DomainError::UnassignedValue: return "value read before it was assigned";
        case DomainError::NotANumber: return "computation produced NaN";
    }
    return "unknown error";
}

}  // namespace hg::frep
