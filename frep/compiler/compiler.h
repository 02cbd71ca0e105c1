// Compiles one body of a program into a flat Tape by executing it
// symbolically: a[] values are constants, x[1..3] are the tape's inputs.
// Operands are visited right to left as the reference evaluates them, so
// in-place rewrites of arrays by library routines land in the same order.
//
//  * constants are folded and repeated subexpressions shared (TapeBuilder);
//  * library routines are expanded into tape operations (library_impl.h);
//  * an `if` whose condition depends on the point becomes a select over both
//    branches; runtime errors inside a branch only count where it is taken;
//  * `while` loops whose condition is known at compile time are unrolled.
// Anything else (a loop or an array index that depends on the point) cannot
// be flattened: compile() then returns no tape and says why, and the
// program runs on the scalar interpreter.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "frep/language/ast.h"
#include "frep/compiler/tape.h"

namespace hg::frep {

struct CompileResult {
    std::optional<Tape> tape;
    std::string reason;  // why there is no tape
    SourceLoc reasonLoc;
};

CompileResult compile(const Program& program, int body, const std::vector<double>& a = {});

}  // namespace hg::frep
