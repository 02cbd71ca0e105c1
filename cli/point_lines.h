// The "x y z" lines `hypergarden eval` reads from standard input: read in
// blocks (never waiting for more than is there, so a terminal or a program
// at the other end of a pipe gets its answer line by line) and scanned
// without iostreams, accepting exactly what `std::cin >> x >> y >> z` did.
#pragma once

#include <string_view>
#include <vector>

namespace hg::garden::cli {

// The point at the start of `line`: three numbers separated by white space,
// as std::istream reads them in the "C" locale (sign, digits, one decimal
// point, an exponent with at least one digit; no hexadecimal, inf or nan;
// out of double range fails), with the same correctly rounded value.
// Whatever follows the third number is ignored. False when the line does not
// start with three numbers.
bool parsePointLine(std::string_view line, double& x, double& y, double& z);

// Only spaces, tabs and carriage returns (or nothing): skipped, not an error.
bool blankLine(std::string_view line);

// Whole lines of a file descriptor, without their '\n' (the last one also
// when the input does not end with one).
class LineReader {
public:
    explicit LineReader(int fd);

    // The next line already read; false when none is left (call fill()).
    bool next(std::string_view& line);
    // Reads what the descriptor has (waiting only when it has nothing);
    // false at the end of the input. A read error ends the input too, with
    // error() set.
    bool fill();
    // The errno of a failed read, else 0.
    int error() const { return error_; }

private:
    int fd_;
    std::vector<char> buf_;
    size_t begin_ = 0, end_ = 0;  // unread bytes
    bool eof_ = false;
    int error_ = 0;
};

}  // namespace hg::garden::cli
