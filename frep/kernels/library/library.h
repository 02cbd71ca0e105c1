// The HyperFun library (hf* routines) as one table of signatures plus one
// generic implementation per routine.
//
// Each routine is written once, as a template over a value type V, and is
// instantiated twice: with V = double for the scalar interpreter (bit-exact
// with the reference interpreter), and with V = frep::Sym by the compiler,
// which records the same operations, in the same order, onto a tape. Because
// the tape's interval and gradient evaluators work on every opcode, each
// routine gets its interval and gradient versions from the same source.
//
// Rules for routine code (see value_ops.h):
//  * only the operations of value_ops.h on V; a condition that depends on a
//    value becomes select(cond, then, else), never an `if`;
//  * `if` and loops only on static facts: array sizes, or values for which
//    isConstant(v) holds (use constantValue(v)); when a value must be
//    constant but is not, throw NotCompilable;
//  * arrays arrive by reference, as the reference's routines rewrite them.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hg::frep::lib {

enum class ParamKind : unsigned char { Array, Scalar };

struct FunctionInfo {
    const char* name;  // lower case, as matched by the parser
    const char* spelling;  // canonical spelling (hfSphere), used by the writer
    std::vector<ParamKind> params;
};

// All library routines; a routine's id is its index here.
const std::vector<FunctionInfo>& functions();

// Id of the routine with that lower-case name, or -1.
int findFunction(std::string_view lowerName);

// Value the reference returns for degenerate input (wrong array size,
// degenerate size parameter).
constexpr double kSentinel = -1111111111111.0;

// Thrown by the symbolic instantiation when a routine needs a constant
// (an index, a count) that depends on the point.
struct NotCompilable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Arguments of one call, by position. Array parameters point at the
// caller's array (the routine may rewrite it); scalar parameters are values.
template <class V>
struct Args {
    std::vector<std::vector<V>*> arrays;  // non-null exactly at Array positions
    std::vector<V> scalars;               // meaningful at Scalar positions

    std::vector<V>& array(size_t i) const { return *arrays[i]; }
    const V& scalar(size_t i) const { return scalars[i]; }
};

// Calls routine `id`. Defined in library_impl.h; instantiated for double in
// library.cpp and for Sym by the compiler.
template <class V>
V call(int id, const Args<V>& args);

}  // namespace hg::frep::lib
