#include "frep/language/diagnostics.h"

#include <algorithm>

namespace hg::frep {

namespace {
constexpr size_t kMaxShownLine = 240;  // longer lines are shown as a window
constexpr size_t kWindowBefore = 120;
}  // namespace

std::string formatDiagnostic(const Diagnostic& d) {
    std::string out = d.file;
    if (d.loc.line <= 0) {
        out += ": error: " + d.message + "\n";
        if (!d.note.empty()) out += "    note: " + d.note + "\n";
        return out;
    }
    out += ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
           ": error: " + d.message + "\n";
    out += "    " + d.sourceLine + "\n";
    out += "    ";
    int caret = d.caretColumn > 0 ? d.caretColumn : d.loc.column;
    for (int i = 1; i < caret; ++i) {
        size_t k = static_cast<size_t>(i - 1);
        out += (k < d.sourceLine.size() && d.sourceLine[k] == '\t') ? '\t' : ' ';
    }
    out += "^\n";
    if (!d.note.empty()) out += "    note: " + d.note + "\n";
    return out;
}

Diagnostic makeDiagnostic(const std::string& file, std::string_view source, size_t offset,
                          SourceLoc loc, std::string message, std::string note) {
    Diagnostic d;
    d.file = file;
    d.loc = loc;
    d.message = std::move(message);
    d.note = std::move(note);
    if (loc.line <= 0) return d;

    size_t col = loc.column > 0 ? static_cast<size_t>(loc.column - 1) : 0;
    size_t lineStart = std::min(col <= offset ? offset - col : 0, source.size());
    offset = std::min(offset, source.size());
    size_t lineEnd = source.find('\n', lineStart);
    if (lineEnd == std::string_view::npos) lineEnd = source.size();
    size_t nul = source.substr(0, lineEnd).find('\0', lineStart);
    if (nul != std::string_view::npos) lineEnd = nul;
    // A CR that ends the line is not shown.
    size_t shownEnd = lineEnd;
    if (shownEnd > lineStart && source[shownEnd - 1] == '\r') --shownEnd;

    size_t from = lineStart;
    size_t to = shownEnd;
    std::string prefix, suffix;
    if (to - from > kMaxShownLine) {
        if (offset > from + kWindowBefore) {
            from = offset - kWindowBefore;
            prefix = "...";
        }
        if (to - from > kMaxShownLine) {
            to = from + kMaxShownLine;
            suffix = "...";
        }
    }
    std::string line = prefix;
    line.reserve(prefix.size() + (to - from) + suffix.size());
    for (size_t i = from; i < to; ++i) {
        char c = source[i];
        unsigned char u = static_cast<unsigned char>(c);
        line += (u < 0x20 && c != '\t') || u == 0x7f ? '?' : c;
    }
    line += suffix;
    d.sourceLine = std::move(line);
    if (from != lineStart) d.caretColumn = static_cast<int>(offset - from + 1 + prefix.size());
    return d;
}

Diagnostic makeDiagnostic(const std::string& file, std::string_view source, SourceLoc loc,
                          std::string message, std::string note) {
    size_t offset = 0;
    if (loc.line > 0) {
        int line = 1;
        size_t i = 0;
        while (line < loc.line && i < source.size()) {
            size_t nl = source.find('\n', i);
            if (nl == std::string_view::npos) {
                i = source.size();
                break;
            }
            i = nl + 1;
            ++line;
        }
        offset = i + static_cast<size_t>(std::max(loc.column, 1) - 1);
    }
    return makeDiagnostic(file, source, offset, loc, std::move(message), std::move(note));
}

}  // namespace hg::frep
