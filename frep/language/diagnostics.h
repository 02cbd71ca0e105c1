// Parse diagnostics: where (file, line, column), what, and the source line
// with a caret under the column.
#pragma once

#include <string>
#include <string_view>

#include "frep/language/ast.h"

namespace hg::frep {

struct Diagnostic {
    std::string file;
    SourceLoc loc;           // line 0: no position (for example an unreadable file)
    std::string message;     // the reference interpreter's text where it has one
    std::string sourceLine;  // the line at loc (possibly a window of a long line)
    std::string note;        // optional extra explanation ("" for none)
    int caretColumn = 0;     // column of the caret in sourceLine; 0: loc.column
};

// "file:line:col: error: message\n    <source line>\n    <spaces>^\n", then
// "    note: <note>\n" when there is a note. Tabs of the source line are kept
// in the caret line so that the caret lines up. Without a position:
// "file: error: message\n".
std::string formatDiagnostic(const Diagnostic& d);

// A diagnostic at byte `offset` of `source` (the first byte of the offending
// token; source.size() for the end), which lies on `loc`. The source line is
// cut to a window around the column when it is very long, and control
// characters are shown as '?'.
Diagnostic makeDiagnostic(const std::string& file, std::string_view source, size_t offset,
                          SourceLoc loc, std::string message, std::string note = {});

// The same, finding the offset from the location (for diagnostics raised
// after parsing, such as runtime errors).
Diagnostic makeDiagnostic(const std::string& file, std::string_view source, SourceLoc loc,
                          std::string message, std::string note = {});

}  // namespace hg::frep
