// The HyperFun writer: a parsed program (frep/language/ast.h) back to readable
// HyperFun text that our parser, and the reference interpreter, read back to
// a program with bit-identical values at every point, runtime errors
// included.
//
// What the writer guarantees and how:
//
//  * Structure is kept: bodies in order (a blank line between them), the
//    s[] parameter only when Body::declaresS, one `array` declaration with
//    the local arrays in slot order, statements in order, if/else/endif,
//    while/loop/endloop, array literals, element assignments, the final
//    `name = expr;`. Names use their declared spellings (Body::spelling,
//    VariableInfo::spelling, ArrayInfo::spelling), library routines their
//    canonical spelling (hfSphere), built-ins and keywords lower case.
//    Comments and redundant parentheses of the source are not kept.
//  * Parentheses only where the parse needs them to give back the same
//    tree: levels, loosest first, `+ - | & \` (`@` is written `&`), `* /`,
//    `^`, prefix `- + ~`; all binary levels group left to right, so a right
//    operand of the same level is parenthesised (`a - (b + c)`,
//    `u ^ (2 ^ 3)`), and `-u ^ 2` stays `(-u)^2`. A `-` never directly
//    follows a `-` (`--` starts a comment): `- -u`.
//  * Conditions (if/while): `and`/`or` share the loosest level, then the
//    comparisons, then operands (`not` operand, parenthesised condition or
//    arithmetic expression), all grouping left to right. An operand that
//    starts with `(` is read as a parenthesised condition, so an arithmetic
//    operand whose text would start with `(` is written with a leading
//    unary plus: `+(x[1] + 1) * 2 > 1`. The reparsed tree then holds an
//    extra UnaryOp::Plus node, which returns its operand unchanged and adds
//    no evaluation step that could fail or reorder anything; writing that
//    tree again gives the same text.
//  * Numbers: see writeNumber.
//
// Trees that no HyperFun text can express (a comparison, and/or or `not`
// outside a condition, an array name where a value is needed, a slot or
// routine id out of range, NaN or infinity) make the writer throw
// std::invalid_argument.
#pragma once

#include <string>

#include "frep/language/ast.h"

namespace hg::frep {

struct WriteOptions {
    int indent = 3;  // spaces per nesting level
};

// A whole program: every body, in order, a blank line between them.
std::string writeProgram(const Program& program, const WriteOptions& options = {});

// One body (names of called bodies come from `program`).
std::string writeBody(const Body& body, const Program& program, const WriteOptions& options = {});

// One expression of `body`: an arithmetic expression, or a condition when
// the top node is a comparison, `and`/`or` or `not`.
std::string writeExpression(const Expr& e, const Body& body, const Program& program);

// A number as HyperFun text that our parser and interpreter read back to
// exactly `v` (bit for bit, -0.0 included), and that the writer spells the
// same way again after a parse (so writing is idempotent):
//
//  * 0, and 1e-30 <= |v| < 1e21: the shortest plain decimal without
//    exponent (`0.1`, `0.0000001`, `123456789012`, `1000.0000000000007`)
//    that the lexer reads back to v. The lexer is not correctly rounded
//    (it accumulates digit by digit: value * 10 + d, then value + d / 10^k),
//    so the candidates (the correctly rounded 1..17 digit decimals of v and
//    their neighbours +-1, +-2 in the last digit, then a digit-by-digit
//    construction that mirrors the lexer) are checked by running the
//    project's lexer on them. Exponent spellings (`1e3`) are never written:
//    the lexer scales them by exp(n * ln 10), which is neither exact
//    (`1e3` reads as 1000.0000000000007) nor the same on every C library.
//  * Otherwise (huge or tiny, or, rarely, no plain decimal reaches v) an
//    exact arithmetic expression, checked by evaluating it with the
//    interpreter: a short plain decimal D times or divided by factors
//    `10 ^ k` with k <= 22 (each power exact, so one rounding per factor):
//    `1.5 * 10 ^ 21`, `10 ^ 22`, `10 ^ 22 * 10 ^ 8`, `1 / 10 ^ 22 / 10 ^ 13`;
//    else the exact binary form `M * 2 ^ E`, `M / 2 ^ E` or
//    `M / 2 ^ 1023 / 2 ^ E` with an odd integer M below 2^53, where every
//    step is exact (5e-324 is `1 / 2 ^ 1023 / 2 ^ 51`). These have the
//    precedence of `*` (`^` for a bare `10 ^ 22`); the expression writer
//    parenthesises them where needed. Array literal items cannot be
//    expressions: such an item is written as 0 in the literal, followed by
//    an element assignment `v[i] = <expression>;` (same values, one more
//    statement).
//  * Negative values (the language has no negative literals): a unary
//    minus on the positive spelling, `-2.5`, `-1 / 2 ^ 1023 / 2 ^ 51`; a
//    spelling that starts with a power gets a factor: `-1 * 10 ^ 22`
//    (`-10 ^ 22` would be (-10)^22). -0.0 is `-0` (minus zero is -0.0).
//  * NaN and infinities cannot be written: std::invalid_argument. (A
//    literal such as 1e400 parses to infinity; such a program cannot be
//    written.)
std::string writeNumber(double v);

}  // namespace hg::frep
