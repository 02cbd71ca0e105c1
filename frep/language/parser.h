// The HyperFun parser: source text to the resolved AST of frep/language/ast.h,
// accepting and rejecting exactly what the reference interpreter
// (pmur002/hyperfun, int_parse_N.c) accepts and rejects, with its error
// messages and positions for the first error. A few things the reference
// accepts but cannot run are rejected with messages of our own: library
// routines Hypergarden does not implement, body-call arguments that are not
// array names, and inputs beyond the resource limits below.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frep/language/ast.h"
#include "frep/language/diagnostics.h"

namespace hg::frep {

struct ParseResult {
    std::optional<Program> program;  // set only when there is no error
    std::vector<Diagnostic> errors;  // in the order found; the first is the reference's
    bool ok() const { return program.has_value() && errors.empty(); }
};

// Resource limits: inputs beyond them are rejected with a clear message.
struct ParseLimits {
    static constexpr size_t kMaxSourceBytes = size_t{64} << 20;  // 64 MiB
    static constexpr int kMaxErrors = 50;           // then one "too many errors"
    static constexpr int kMaxNesting = 256;         // (, unary, not, calls, if/while
    static constexpr int kMaxTreeDepth = 2000;      // height of one expression tree
    static constexpr int kMaxArraySize = 1 << 20;   // items of one array
    static constexpr long long kMaxBodyArrayItems = 1 << 22;  // all arrays of a body
    static constexpr size_t kMaxNodes = size_t{1} << 23;      // AST nodes of a program (an export of ~60,000 edits)
};

ParseResult parseProgram(std::string_view source, const std::string& fileName);

// Reads and parses a file. A missing or unreadable file gives one diagnostic
// at line 0 that says why.
ParseResult parseFile(const std::string& path);

}  // namespace hg::frep
