#include "garden/export/hf_text.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "frep/language/hf_math.h"
#include "frep/language/writer.h"

namespace hg::garden::hfexport {

namespace {

bool plainDecimal(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!(c == '.' || (c >= '0' && c <= '9'))) return false;
    return true;
}

HfStatements* bodyOf(const HfText& a, const HfText& b) {
    HfStatements* w = a.body() ? a.body() : b.body();
    if (a.body() && b.body() && a.body() != b.body())
        throw std::logic_error("HfText: an operation on values of two different bodies");
    return w;
}

HfText binary(const HfText& a, const char* op, const HfText& b) {
    HfStatements& w = *bodyOf(a, b);
    return HfText::assign(w, a.operandIn(w) + " " + op + " " + b.operandIn(w));
}

HfText call(const char* f, const HfText& a, const HfText& b) {
    HfStatements& w = *bodyOf(a, b);
    return HfText::assign(w, std::string(f) + "(" + a.operandIn(w) + ", " + b.operandIn(w) + ")");
}

std::string asOperand(const std::string& s) { return plainDecimal(s) ? s : "(" + s + ")"; }

bool plainItem(const std::string& s) {
    return plainDecimal(s) || (s.size() > 1 && s[0] == '-' && plainDecimal(s.substr(1)));
}

}  // namespace

HfStatements::HfStatements(std::string prefix)
    : prefix_(std::move(prefix)), free_(std::make_shared<std::vector<std::size_t>>()) {}

HfStatements::~HfStatements() = default;

void HfStatements::statement(const std::string& text) {
    text_ += "   ";
    text_ += text;
    text_ += ";\n";
    ++statements_;
}

void HfStatements::comment(const std::string& text) {
    // One line each: a line break would end the comment.
    std::string line;
    for (char c : text) line += c == '\n' || c == '\r' ? ' ' : c;
    text_ += "   -- " + line + "\n";
}

const std::string& HfStatements::number(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    auto found = numbers_.find(bits);
    if (found == numbers_.end()) found = numbers_.emplace(bits, frep::writeNumber(v)).first;
    return found->second;
}

std::shared_ptr<const std::string> HfStatements::temporary() {
    std::size_t n;
    if (!free_->empty()) {
        n = free_->back();
        free_->pop_back();
    } else {
        n = ++next_;
    }
    std::weak_ptr<std::vector<std::size_t>> pool = free_;
    auto release = [pool, n](const std::string* s) {
        if (auto p = pool.lock()) p->push_back(n);
        delete s;
    };
    return std::shared_ptr<const std::string>(new std::string(prefix_ + std::to_string(n)), release);
}

HfText HfText::named(HfStatements& body, const std::string& name) {
    HfText t;
    t.body_ = &body;
    t.name_ = std::make_shared<const std::string>(name);
    return t;
}

HfText HfText::assign(HfStatements& body, const std::string& rhs) {
    HfText t;
    t.body_ = &body;
    t.name_ = body.temporary();
    body.statement(*t.name_ + " = " + rhs);
    return t;
}

std::string HfText::operand() const { return body_ ? *name_ : asOperand(frep::writeNumber(constant_)); }

std::string HfText::operandIn(HfStatements& body) const { return body_ ? *name_ : asOperand(body.number(constant_)); }

std::string literalItem(double v) {
    const std::string s = frep::writeNumber(v);
    return plainItem(s) ? s : std::string();
}

void fillArray(HfStatements& body, const std::string& name, const std::vector<double>& values) {
    std::string literal = name + " = [";
    std::vector<std::string> later;
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::string plain = body.number(values[i]);
        if (!plainItem(plain)) {
            later.push_back(name + "[" + std::to_string(i + 1) + "] = " + asOperand(plain));
            plain = "0";
        }
        literal += (i ? ", " : "") + plain;
    }
    body.statement(literal + "]");
    for (const std::string& l : later) body.statement(l);
}

HfText operator+(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(a.constant() + b.constant());
    return binary(a, "+", b);
}

HfText operator-(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(a.constant() - b.constant());
    return binary(a, "-", b);
}

HfText operator*(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(a.constant() * b.constant());
    return binary(a, "*", b);
}

HfText operator/(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(a.constant() / b.constant());
    const double c = b.constant();
    if (b.isConstant() && c != 0.0 && std::isfinite(c) && std::fabs(c) < frep::hf::kEps<double>) {
        // HyperFun refuses to divide by it: scale both by a power of two so
        // the divisor passes; products by 2^k are exact, so is the quotient.
        int k = 0;
        while (std::fabs(std::ldexp(c, k)) < frep::hf::kEps<double>) ++k;
        const HfText scaled = a * HfText(std::ldexp(1.0, k));
        return binary(scaled, "/", HfText(std::ldexp(c, k)));
    }
    return binary(a, "/", b);
}

HfText operator-(const HfText& a) {
    if (a.isConstant()) return HfText(-a.constant());
    return HfText::assign(*a.body(), "-" + a.operand());
}

}  // namespace hg::garden::hfexport

namespace hg::garden::editops {

using hfexport::HfText;

HfText vmin(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(frep::hf::minimum(a.constant(), b.constant()));
    return hfexport::call("min", a, b);
}

HfText vmax(const HfText& a, const HfText& b) {
    if (a.isConstant() && b.isConstant()) return HfText(frep::hf::maximum(a.constant(), b.constant()));
    return hfexport::call("max", a, b);
}

HfText vabs(const HfText& a) {
    if (a.isConstant()) return HfText(std::fabs(a.constant()));
    return HfText::assign(*a.body(), "abs(" + a.operand() + ")");
}

HfText vsqrt(const HfText& a) {
    if (a.isConstant()) return HfText(std::sqrt(a.constant()));
    return HfText::assign(*a.body(), "sqrt(" + a.operand() + ")");
}

}  // namespace hg::garden::editops

namespace hg::frep::lib::detail {

using garden::hfexport::HfStatements;
using garden::hfexport::HfText;

template <>
HfText convSegment<HfText>(const HfText& px, const HfText& py, const HfText& pz, const HfText& bx, const HfText& by,
                           const HfText& bz, const HfText& ex, const HfText& ey, const HfText& ez, const HfText& s) {
    if (px.isConstant() || py.isConstant() || pz.isConstant() || px.name() != "x[1]" || py.name() != "x[2]" ||
        pz.name() != "x[3]")
        throw std::logic_error("HfText: a segment's field is written for the body's point x only");
    for (const HfText* c : {&bx, &by, &bz, &ex, &ey, &ez, &s})
        if (!c->isConstant()) throw std::logic_error("HfText: a segment's ends and width must be constants");
    HfStatements& body = *px.body();
    body.useSegmentArrays();
    garden::hfexport::fillArray(body, garden::hfexport::kSegmentBegin, {bx.constant(), by.constant(), bz.constant()});
    garden::hfexport::fillArray(body, garden::hfexport::kSegmentEnd, {ex.constant(), ey.constant(), ez.constant()});
    garden::hfexport::fillArray(body, garden::hfexport::kSegmentWidth, {s.constant()});
    return HfText::assign(body, std::string("hfConvLine(x, ") + garden::hfexport::kSegmentBegin + ", " +
                                    garden::hfexport::kSegmentEnd + ", " + garden::hfexport::kSegmentWidth + ", 0)");
}

}  // namespace hg::frep::lib::detail
