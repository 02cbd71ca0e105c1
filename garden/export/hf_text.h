// The third value type of the edit list's expression templates (docs/design.md §4,
// garden/sculpt/edit_field.h): a value that writes HyperFun text. Every
// operation on a value that is not a constant appends one statement
// `tN = A op B;` to the body being written and returns the temporary tN, so
// the exported file stays linear in the edits and no expression is deeper
// than one operation, however many edits there are. The text is evaluated
// by a HyperFun interpreter with the same double operations, in the same
// order, as the template on double:
//
//  * +, -, *, / and unary minus are HyperFun's operators; min, max, abs and
//    sqrt its built-ins (hf::minimum and hf::maximum are the interpreter's
//    min and max; abs is fabs; the roots here are never of a negative).
//  * Constants are written with frep::writeNumber, which reads back to the
//    same double bit for bit. Operations on two constants are folded here
//    (the same IEEE operation the interpreter would run).
//  * HyperFun's `/` fails when |divisor| < 1e-6: a division by such a
//    constant c is written (a * 2^k) / (c * 2^k), both products exact, so
//    the quotient is the same double.
//  * convSegment (one segment of hfConvLine's field, convolution.h) is
//    written as a call hfConvLine(x, segb, sege, segs, 0) on one segment:
//    the library computes (0 + conv) - 0, which is conv exactly.
//
// Temporaries are reused: a name returns to the body's pool when the last
// value holding it is destroyed, so a body with thousands of edits uses a
// few dozen names. Include this header before anything that includes
// edit_field.h: the templates call editops::vmin and friends by qualified
// name, which finds only the overloads declared before them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "frep/kernels/library/convolution.h"

namespace hg::garden::hfexport {

// The statements of one body being written, and its pool of temporaries.
class HfStatements {
public:
    // Temporaries are named `prefix` followed by a number.
    explicit HfStatements(std::string prefix = "t");
    ~HfStatements();
    HfStatements(const HfStatements&) = delete;
    HfStatements& operator=(const HfStatements&) = delete;

    // A statement (without its `;`), or a comment line (without `--`).
    void statement(const std::string& text);
    void comment(const std::string& text);
    // Holds a free temporary's name until the last copy of it is gone.
    std::shared_ptr<const std::string> temporary();
    // frep::writeNumber(v), remembered: a stroke's segments share their
    // ends, widths and thresholds, and writeNumber checks its spelling by
    // running the lexer on it.
    const std::string& number(double v);

    // The arrays the segment calls use (declared by the body's writer).
    bool usesSegmentArrays() const { return segmentArrays_; }
    void useSegmentArrays() { segmentArrays_ = true; }

    const std::string& text() const { return text_; }
    std::size_t statementCount() const { return statements_; }
    std::size_t temporariesUsed() const { return next_; }

private:
    std::string prefix_;
    std::string text_;
    std::size_t statements_ = 0;
    std::size_t next_ = 0;
    std::shared_ptr<std::vector<std::size_t>> free_;  // shared with the names' deleters
    std::unordered_map<std::uint64_t, std::string> numbers_;  // by the double's bits
    bool segmentArrays_ = false;
};

// The names of the arrays a segment call is given.
constexpr const char* kSegmentBegin = "segb";
constexpr const char* kSegmentEnd = "sege";
constexpr const char* kSegmentWidth = "segs";

// A value while a body is written: a constant, or a name (x[1], a
// temporary) holding a value computed by the statements before.
class HfText {
public:
    HfText() = default;  // the constant 0
    explicit HfText(double c) : constant_(c) {}
    // A value the body holds under a fixed name (x[1], a[1]).
    static HfText named(HfStatements& body, const std::string& name);
    // `rhs` assigned to a new temporary.
    static HfText assign(HfStatements& body, const std::string& rhs);

    bool isConstant() const { return body_ == nullptr; }
    double constant() const { return constant_; }
    HfStatements* body() const { return body_; }
    const std::string& name() const { return *name_; }
    // The text as an operand: a name, or the constant's spelling
    // (parenthesized unless it is a plain unsigned decimal).
    std::string operand() const;
    // The same, the constant's spelling remembered by `body`.
    std::string operandIn(HfStatements& body) const;

private:
    double constant_ = 0.0;
    HfStatements* body_ = nullptr;
    std::shared_ptr<const std::string> name_;
};

HfText operator+(const HfText& a, const HfText& b);
HfText operator-(const HfText& a, const HfText& b);
HfText operator*(const HfText& a, const HfText& b);
HfText operator/(const HfText& a, const HfText& b);
HfText operator-(const HfText& a);

// A number as an item of an array literal: the plain spelling (a sign
// allowed), or "" when writeNumber needs an expression for it.
std::string literalItem(double v);

// `name = [v1, ..., vn];`, an item that needs an expression written 0 in
// the literal and assigned after it.
void fillArray(HfStatements& body, const std::string& name, const std::vector<double>& values);

}  // namespace hg::garden::hfexport

namespace hg::garden::editops {
hfexport::HfText vmin(const hfexport::HfText& a, const hfexport::HfText& b);
hfexport::HfText vmax(const hfexport::HfText& a, const hfexport::HfText& b);
hfexport::HfText vabs(const hfexport::HfText& a);
hfexport::HfText vsqrt(const hfexport::HfText& a);
}  // namespace hg::garden::editops

namespace hg::frep::lib::detail {
// One segment's field at the body's point x as hfConvLine on one segment;
// the point must be x[1], x[2], x[3] and the rest constants.
template <>
garden::hfexport::HfText convSegment<garden::hfexport::HfText>(
    const garden::hfexport::HfText& px, const garden::hfexport::HfText& py, const garden::hfexport::HfText& pz,
    const garden::hfexport::HfText& bx, const garden::hfexport::HfText& by, const garden::hfexport::HfText& bz,
    const garden::hfexport::HfText& ex, const garden::hfexport::HfText& ey, const garden::hfexport::HfText& ez,
    const garden::hfexport::HfText& s);
}  // namespace hg::frep::lib::detail
