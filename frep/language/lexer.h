// The HyperFun scanner, token for token as the reference interpreter's
// (pmur002/hyperfun, src/interpreter_lib/int_scanner.c):
//
//  * white space is ' ', '\t' and '\n' only; a carriage return is an illegal
//    character, so CRLF files do not parse;
//  * "--" starts a comment anywhere (so "3--2" is "3" then a comment); a
//    comment longer than 256 characters is an illegal token;
//  * numbers are Integer[.Integer][(E|e)[+|-]Integer] or .Integer; a number
//    may not start with 0 followed by a digit, and exponent digits may not
//    start with 0; the value is accumulated digit by digit (fraction digits
//    as d/10, d/100, ...) and scaled by exp(n * log(10));
//  * names start with a letter, continue with letters, digits and '_', are
//    case-insensitive and at most 256 characters long;
//  * x, a, s, the keywords and every routine name the reference knows are
//    reserved;
//  * a NUL byte ends the program.
//
// Columns count bytes from 1; a tab counts as one.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "frep/language/ast.h"

namespace hg::frep::syntax {

enum class TokenKind {
    Illegal,
    Array, If, Then, Else, EndIf, While, Loop, EndLoop,
    Assign,                                   // =
    LParen, RParen, LBracket, RBracket, LBrace, RBrace,
    And, Not, Or, Xor,
    NotEqual, Less, LessEqual, Greater, GreaterEqual,  // /= < <= > >=
    Power, Plus, Minus, Tilde, Slash, Star,   // ^ + - ~ / *
    Ampersand, Union, Backslash, At,          // & | \ @
    Comma, Semicolon,
    Number, String,
    XId, AId, SId,                            // x a s
    Function,                                 // a built-in or library routine name
    Identifier,
    End,
    Comment,  // internal: never returned by Lexer::next()
};

// Why a token is Illegal (used for notes under diagnostics).
enum class LexProblem {
    None,
    LeadingZero,        // 05
    BadExponent,        // 1e, 1e05, 1e-0
    LoneDot,            // .
    CarriageReturn,
    UnknownCharacter,
    LongComment,        // more than 256 characters after "--"
    LongIdentifier,     // more than 256 characters
    UnterminatedString,
};

struct Token {
    TokenKind kind = TokenKind::End;
    SourceLoc loc;
    size_t offset = 0;   // byte offset of the first character
    size_t length = 0;   // bytes consumed
    std::string name;    // lower case; Identifier, Function, keywords, x/a/s
    double number = 0.0; // Number
    int function = -1;   // Function: index into referenceFunctions()
    LexProblem problem = LexProblem::None;
};

// A routine the reference interpreter registers: its lower-case name and its
// parameter kinds, one character each ('A' array, 'R' scalar).
struct ReferenceFunction {
    std::string_view name;
    std::string_view params;
};

// The reference's routine table in its order: the 23 built-in functions
// first (sqrt ... frac, in Builtin enum order), then the library routines,
// including those Hypergarden does not implement.
const std::vector<ReferenceFunction>& referenceFunctions();
constexpr int kBuiltinCount = 23;

// Longest name and comment the reference accepts.
constexpr size_t kMaxLexemLength = 256;

class Lexer {
public:
    explicit Lexer(std::string_view source);

    // The next token, comments skipped. After End, returns End again.
    Token next();

    std::string_view source() const { return src_; }

private:
    Token scan();
    char at(size_t i) const { return i < src_.size() ? src_[i] : '\0'; }
    void advance(size_t n = 1);

    std::string_view src_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

// Text of a problem, for a note under the diagnostic ("" for None).
std::string describe(const Token& token, std::string_view source);

}  // namespace hg::frep::syntax
