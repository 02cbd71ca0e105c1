#include "cli/point_lines.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace hg::garden::cli {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// One number at `pos`, after white space, as libstdc++'s num_get takes it:
// the longest prefix of [+-] digits [. digits] [(e|E) [+-] digits], where
// the exponent needs a mantissa digit before it; then the whole prefix must
// be a number (so "1e", "." and "-" fail) and finite. `pos` ends after the
// prefix either way.
bool scanNumber(std::string_view s, size_t& pos, double& v) {
    while (pos < s.size() && isSpace(s[pos])) ++pos;
    const size_t start = pos;
    if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) ++pos;
    bool mantissa = false;
    while (pos < s.size() && isDigit(s[pos])) { ++pos; mantissa = true; }
    if (pos < s.size() && s[pos] == '.') {
        ++pos;
        while (pos < s.size() && isDigit(s[pos])) { ++pos; mantissa = true; }
    }
    bool exponentOk = true;
    if (mantissa && pos < s.size() && (s[pos] == 'e' || s[pos] == 'E')) {
        ++pos;
        if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) ++pos;
        exponentOk = false;
        while (pos < s.size() && isDigit(s[pos])) { ++pos; exponentOk = true; }
    }
    if (!mantissa || !exponentOk) return false;
    // from_chars takes no '+'; it is correctly rounded, like the strtod
    // that istream calls, and several times faster.
    const char* first = s.data() + start;
    const char* last = s.data() + pos;
    if (*first == '+') ++first;
    auto [end, ec] = std::from_chars(first, last, v);
    if (ec == std::errc() && end == last) return true;
    // Out of range: istream refuses overflow but keeps what underflows (to a
    // subnormal or zero), which from_chars refuses too; strtod says which.
    const std::string text(s.substr(start, pos - start));
    v = std::strtod(text.c_str(), nullptr);
    return !std::isinf(v);
}

}  // namespace

bool parsePointLine(std::string_view line, double& x, double& y, double& z) {
    size_t pos = 0;
    return scanNumber(line, pos, x) && scanNumber(line, pos, y) && scanNumber(line, pos, z);
}

bool blankLine(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

LineReader::LineReader(int fd) : fd_(fd), buf_(1 << 16) {}

bool LineReader::next(std::string_view& line) {
    if (begin_ == end_) return false;
    const char* data = buf_.data() + begin_;
    const size_t n = end_ - begin_;
    const void* nl = std::memchr(data, '\n', n);
    if (nl) {
        const size_t len = static_cast<size_t>(static_cast<const char*>(nl) - data);
        line = std::string_view(data, len);
        begin_ += len + 1;
        return true;
    }
    if (!eof_) return false;  // the rest of this line is still to come
    line = std::string_view(data, n);
    begin_ = end_;
    return true;
}

bool LineReader::fill() {
    if (eof_) return false;
    // Keep the unfinished line at the front; make room for a long one.
    std::memmove(buf_.data(), buf_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
    if (end_ == buf_.size()) buf_.resize(buf_.size() * 2);
    for (;;) {
        const ssize_t got = ::read(fd_, buf_.data() + end_, buf_.size() - end_);
        if (got > 0) {
            end_ += static_cast<size_t>(got);
            return true;
        }
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) error_ = errno;
        eof_ = true;
        return end_ > begin_;  // a last line without '\n'
    }
}

}  // namespace hg::garden::cli
