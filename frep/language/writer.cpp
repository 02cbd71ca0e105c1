#include "frep/language/writer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "frep/language/interpreter.h"
#include "frep/language/lexer.h"
#include "frep/kernels/library/library.h"
#include "frep/language/parser.h"

namespace hg::frep {

namespace {

// ---------------------------------------------------------------------------
// Numbers

// Precedence levels of arithmetic text, loosest first.
enum Level : int {
    kLevelAdd = 0,      // + - | & \ @
    kLevelMul = 1,      // * /
    kLevelPow = 2,      // ^
    kLevelPrefix = 3,   // - + ~ (prefix)
    kLevelPrimary = 4,  // number, name, call, parenthesised expression
};

struct Text {
    std::string s;
    int level = kLevelPrimary;
};

bool sameBits(double a, double b) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    return x == y;
}

// The value our lexer gives the text when it is exactly one number token.
std::optional<double> lexNumber(const std::string& s) {
    syntax::Lexer lexer(s);
    syntax::Token t = lexer.next();
    if (t.kind != syntax::TokenKind::Number || t.length != s.size()) return std::nullopt;
    return t.number;
}

// The value of `text` as the body's result, evaluated by the interpreter.
std::optional<double> evaluateText(const std::string& text) {
    ParseResult r = parseProgram("n(x[1], a[1]) { n = " + text + "; }", "<number>");
    if (!r.ok()) return std::nullopt;
    Interpreter interp(*r.program, 0);
    PointResult p = interp.evaluate(0.0, 0.0, 0.0);
    if (!p.ok()) return std::nullopt;
    return p.value;
}

// d1.d2d3... x 10^exp10, digits without leading zeros.
struct Decimal {
    std::string digits;
    int exp10 = 0;
};

// The correctly rounded decimal of v > 0 with p significant digits.
Decimal decimalDigits(double v, int p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", p - 1, v);
    Decimal d;
    const char* c = buf;
    for (; *c && *c != 'e'; ++c)
        if (*c >= '0' && *c <= '9') d.digits.push_back(*c);
    if (*c == 'e') d.exp10 = std::atoi(c + 1);
    return d;
}

// The decimal with `delta` added to its last digit; nullopt if not positive.
std::optional<Decimal> bump(Decimal d, int delta) {
    if (delta == 0) return d;
    std::string& s = d.digits;
    int carry = delta;
    for (size_t i = s.size(); i-- > 0 && carry != 0;) {
        int v = (s[i] - '0') + carry;
        carry = 0;
        while (v < 0) {
            v += 10;
            --carry;
        }
        while (v > 9) {
            v -= 10;
            ++carry;
        }
        s[i] = static_cast<char>('0' + v);
    }
    if (carry < 0) return std::nullopt;
    if (carry > 0) {
        s.insert(s.begin(), static_cast<char>('0' + carry));
        ++d.exp10;
    }
    while (!s.empty() && s[0] == '0') {
        s.erase(s.begin());
        --d.exp10;
    }
    if (s.empty()) return std::nullopt;
    return d;
}

// Plain decimal text without exponent: 123.45, 0.00012, 1200.
std::string toPlain(Decimal d) {
    std::string& s = d.digits;
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    const int e = d.exp10;
    if (e >= 0) {
        const size_t intDigits = static_cast<size_t>(e) + 1;
        if (s.size() <= intDigits) return s + std::string(intDigits - s.size(), '0');
        return s.substr(0, intDigits) + "." + s.substr(intDigits);
    }
    return "0." + std::string(static_cast<size_t>(-e - 1), '0') + s;
}

// Digit by digit as the lexer accumulates a fraction (value + d / scale,
// scale = 10, 100, ...): the largest digit that does not pass v each time.
std::optional<std::string> buildFraction(double v) {
    constexpr double kTwo53 = 9007199254740992.0;
    if (!(v < kTwo53)) return std::nullopt;
    const double whole = std::floor(v);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", whole);
    std::string s = buf;
    double value = whole;
    if (value == v) return s;
    s += '.';
    double scale = 10.0;
    for (int k = 0; k < 120; ++k) {
        int best = 0;
        for (int d = 9; d >= 1; --d) {
            if (value + d / scale <= v) {
                best = d;
                break;
            }
        }
        value = value + best / scale;
        scale = scale * 10.0;
        s.push_back(static_cast<char>('0' + best));
        if (value == v) {
            while (s.back() == '0') s.pop_back();
            if (s.back() == '.') s.pop_back();
            return s;
        }
    }
    return std::nullopt;
}

constexpr double kPlainMin = 1e-30;
constexpr double kPlainMax = 1e21;

// The shortest plain decimal the lexer reads back to v (v >= 0, +0 only).
std::optional<std::string> plainSpelling(double v) {
    if (v == 0.0) return std::string("0");
    if (!(v >= kPlainMin && v < kPlainMax)) return std::nullopt;
    // Integers beyond 2^53 may need all their digits.
    int maxDigits = 17;
    const int e10 = decimalDigits(v, 17).exp10;
    if (e10 + 1 > maxDigits) maxDigits = e10 + 1;
    static constexpr int kDeltas[] = {0, -1, 1, -2, 2};
    for (int p = 1; p <= maxDigits; ++p) {
        const Decimal d = decimalDigits(v, p);
        for (int delta : kDeltas) {
            std::optional<Decimal> c = bump(d, delta);
            if (!c) continue;
            std::string s = toPlain(*c);
            std::optional<double> back = lexNumber(s);
            if (back && sameBits(*back, v)) return s;
        }
    }
    std::optional<std::string> built = buildFraction(v);
    if (built) {
        std::optional<double> back = lexNumber(*built);
        if (back && sameBits(*back, v)) return built;
    }
    return std::nullopt;
}

std::string intText(long long n) { return std::to_string(n); }

// D * 10^k or D / 10^k for a short plain decimal D, with the power split
// into factors 10^k, k <= 22, each exact: `1.5 * 10 ^ 21`, `10 ^ 22`,
// `1 / 10 ^ 22 / 10 ^ 18`, `150000000 * 10 ^ 22`. Every candidate is
// computed here as the interpreter would and then checked by evaluating it.
std::optional<Text> scaledSpelling(double v) {
    auto power10 = [](int k) {
        double p = 1.0;
        for (int i = 0; i < k; ++i) p *= 10.0;  // as the interpreter's ^
        return p;
    };
    static constexpr int kDeltas[] = {0, -1, 1, -2, 2};
    for (int p = 1; p <= 17; ++p) {
        const Decimal d = decimalDigits(v, p);
        for (int delta : kDeltas) {
            const std::optional<Decimal> c = bump(d, delta);
            if (!c || c->exp10 == 0) continue;
            const bool multiply = c->exp10 > 0;
            const int total = multiply ? c->exp10 : -c->exp10;
            // Splits of the power: D in [1, 10) first, then D shifted by
            // 10^22 only.
            std::vector<std::vector<int>> forms;
            if (total <= 22) {
                forms.push_back({total});
            } else {
                if (total - 22 <= 22) forms.push_back({22, total - 22});
                forms.push_back({22});
            }
            for (const std::vector<int>& ks : forms) {
                Decimal m = *c;
                for (int k : ks) m.exp10 += multiply ? -k : k;
                if (m.exp10 < -30 || m.exp10 > 20) continue;
                const std::optional<double> dv = lexNumber(toPlain(m));
                if (!dv) continue;
                double r = *dv;
                for (int k : ks) r = multiply ? r * power10(k) : r / power10(k);
                if (!sameBits(r, v)) continue;
                // D as the writer spells that value, so that writing the
                // parsed text again gives the same text.
                const std::optional<std::string> canonical = plainSpelling(*dv);
                if (!canonical || canonical->size() > 24) continue;
                const std::string& ds = *canonical;
                Text t{multiply && ds == "1" ? std::string() : ds, kLevelMul};
                for (int k : ks) {
                    if (t.s.empty())
                        t.s = "10 ^ " + intText(k);
                    else
                        t.s += (multiply ? " * 10 ^ " : " / 10 ^ ") + intText(k);
                }
                if (ks.size() == 1 && multiply && ds == "1") t.level = kLevelPow;
                const std::optional<double> check = evaluateText(t.s);
                if (check && sameBits(*check, v)) return t;
            }
        }
    }
    return std::nullopt;
}

// v = M * 2^E with M odd below 2^53: every operation is exact.
Text binarySpelling(double v) {
    int ex = 0;
    const double m = std::frexp(v, &ex);  // v = m * 2^ex, m in [0.5, 1)
    auto mant = static_cast<long long>(std::ldexp(m, 53));
    int e = ex - 53;
    while (mant % 2 == 0) {
        mant /= 2;
        ++e;
    }
    Text t;
    if (e >= 0) {
        t = mant == 1 ? Text{"2 ^ " + intText(e), kLevelPow}
                      : Text{intText(mant) + " * 2 ^ " + intText(e), kLevelMul};
    } else if (-e <= 1023) {
        t = Text{intText(mant) + " / 2 ^ " + intText(-e), kLevelMul};
    } else {
        t = Text{intText(mant) + " / 2 ^ 1023 / 2 ^ " + intText(-e - 1023), kLevelMul};
    }
    std::optional<double> check = evaluateText(t.s);
    if (!check || !sameBits(*check, v))
        throw std::logic_error("writeNumber: exact binary spelling '" + t.s +
                               "' does not evaluate back to its value");
    return t;
}

Text numberText(double v) {
    if (std::isnan(v)) throw std::invalid_argument("HyperFun has no spelling for NaN");
    if (std::isinf(v))
        throw std::invalid_argument(std::string("HyperFun has no spelling for ") +
                                    (v > 0 ? "+" : "-") + "infinity");
    const bool negative = std::signbit(v);
    const double mag = std::fabs(v);
    Text t;
    if (std::optional<std::string> plain = plainSpelling(mag)) {
        t = Text{*plain, kLevelPrimary};
    } else if (std::optional<Text> scaled = scaledSpelling(mag)) {
        t = *scaled;
    } else {
        t = binarySpelling(mag);
    }
    if (!negative) return t;
    // A unary minus on the positive spelling (exact: negation is exact and
    // rounding is symmetric). A spelling that starts with a power (`10 ^ 22 * 10 ^ 1`) would negate
    // only the base, and (-10)^22 is positive: it gets an explicit factor.
    if (t.s.compare(0, 5, "10 ^ ") == 0 || t.s.compare(0, 4, "2 ^ ") == 0)
        return Text{"-1 * " + t.s, kLevelMul};
    if (t.level == kLevelPrimary) return Text{"-" + t.s, kLevelPrefix};
    return Text{"-" + t.s, t.level};
}

// ---------------------------------------------------------------------------
// Expressions and statements

const char* builtinName(Builtin b) {
    switch (b) {
        case Builtin::Sqrt: return "sqrt";
        case Builtin::Exp: return "exp";
        case Builtin::Log: return "log";
        case Builtin::Logd: return "logd";
        case Builtin::Sin: return "sin";
        case Builtin::Cos: return "cos";
        case Builtin::Tan: return "tan";
        case Builtin::Asin: return "asin";
        case Builtin::Acos: return "acos";
        case Builtin::Atan: return "atan";
        case Builtin::Atan2: return "atan2";
        case Builtin::Abs: return "abs";
        case Builtin::Sinh: return "sinh";
        case Builtin::Cosh: return "cosh";
        case Builtin::Tanh: return "tanh";
        case Builtin::Sign: return "sign";
        case Builtin::Mod: return "mod";
        case Builtin::Max: return "max";
        case Builtin::Min: return "min";
        case Builtin::Ceil: return "ceil";
        case Builtin::Floor: return "floor";
        case Builtin::Int: return "int";
        case Builtin::Frac: return "frac";
    }
    throw std::invalid_argument("unknown built-in function");
}

bool isLogic(BinaryOp op) { return op == BinaryOp::And || op == BinaryOp::Or; }
bool isComparison(BinaryOp op) {
    switch (op) {
        case BinaryOp::Equal:
        case BinaryOp::NotEqual:
        case BinaryOp::Less:
        case BinaryOp::LessEqual:
        case BinaryOp::Greater:
        case BinaryOp::GreaterEqual: return true;
        default: return false;
    }
}
bool isConditionNode(const Expr& e) {
    if (e.kind == ExprKind::Binary) return isLogic(e.binaryOp) || isComparison(e.binaryOp);
    return e.kind == ExprKind::Unary && e.unaryOp == UnaryOp::Not;
}

// Condition levels, loosest first.
enum CondLevel : int {
    kCondLogic = 0,    // and or
    kCondCompare = 1,  // = /= < <= > >=
    kCondOperand = 2,  // not ..., ( condition ), arithmetic expression
};

class Writer {
public:
    Writer(const Program& program, const Body& body, const WriteOptions& options)
        : program_(program), body_(body), options_(options) {}

    std::string body();
    std::string expression(const Expr& e) {
        return isConditionNode(e) ? condition(e).s : arith(e).s;
    }

private:
    Text arith(const Expr& e);
    Text condition(const Expr& e);
    std::string args(const Expr& e);
    std::string arrayName(int slot) const;
    std::string variableName(int slot) const;
    void statements(const std::vector<Stmt>& list, int depth);
    void statement(const Stmt& s, int depth);
    void line(int depth, const std::string& text) {
        out_.append(static_cast<size_t>(depth * std::max(options_.indent, 0)), ' ');
        out_ += text;
        out_ += '\n';
    }

    // head item, item, ... item tail: wrapped beyond kLineWidth columns,
    // continuation lines aligned after the head.
    void list(int depth, const std::string& head, const std::vector<std::string>& items,
              const std::string& tail);

    const Program& program_;
    const Body& body_;
    const WriteOptions& options_;
    std::string out_;
};

// Array literals wrap beyond this many columns.
constexpr size_t kLineWidth = 96;

std::string paren(const std::string& s) { return "(" + s + ")"; }

std::string Writer::arrayName(int slot) const {
    if (slot < 0 || static_cast<size_t>(slot) >= body_.arrays.size())
        throw std::invalid_argument("array slot " + std::to_string(slot) + " out of range in body '" +
                                    body_.spelling + "'");
    const ArrayInfo& a = body_.arrays[static_cast<size_t>(slot)];
    if (!a.spelling.empty()) return a.spelling;
    if (!a.name.empty()) return a.name;
    throw std::invalid_argument("array slot " + std::to_string(slot) + " of body '" + body_.spelling +
                                "' has no name");
}

std::string Writer::variableName(int slot) const {
    if (slot < 0 || static_cast<size_t>(slot) >= body_.variables.size())
        throw std::invalid_argument("variable slot " + std::to_string(slot) +
                                    " out of range in body '" + body_.spelling + "'");
    const VariableInfo& v = body_.variables[static_cast<size_t>(slot)];
    if (!v.spelling.empty()) return v.spelling;
    if (!v.name.empty()) return v.name;
    throw std::invalid_argument("variable slot " + std::to_string(slot) + " of body '" +
                                body_.spelling + "' has no name");
}

// "(arg, arg, ...)": array names for ArrayName arguments, else expressions.
std::string Writer::args(const Expr& e) {
    std::string s = "(";
    for (size_t i = 0; i < e.args.size(); ++i) {
        if (i) s += ", ";
        const Expr& a = *e.args[i];
        s += a.kind == ExprKind::ArrayName ? arrayName(a.slot) : arith(a).s;
    }
    return s + ")";
}

Text Writer::arith(const Expr& e) {
    switch (e.kind) {
        case ExprKind::Number: return numberText(e.number);
        case ExprKind::Variable: return Text{variableName(e.slot), kLevelPrimary};
        case ExprKind::ArrayElement:
            if (e.args.size() != 1) throw std::invalid_argument("array element without one index");
            return Text{arrayName(e.slot) + "[" + arith(*e.args[0]).s + "]", kLevelPrimary};
        case ExprKind::ArrayName:
            throw std::invalid_argument("array name '" + arrayName(e.slot) +
                                        "' used where a value is needed");
        case ExprKind::Unary: {
            if (e.args.size() != 1) throw std::invalid_argument("unary operator without one operand");
            if (e.unaryOp == UnaryOp::Not)
                throw std::invalid_argument("'not' outside a condition cannot be written");
            Text operand = arith(*e.args[0]);
            std::string s = operand.level < kLevelPrefix ? paren(operand.s) : operand.s;
            const char op = e.unaryOp == UnaryOp::Plus ? '+' : e.unaryOp == UnaryOp::Minus ? '-' : '~';
            // "--" would start a comment.
            std::string text(1, op);
            if (op == '-' && s[0] == '-') text += ' ';
            return Text{text + s, kLevelPrefix};
        }
        case ExprKind::Binary: {
            if (e.args.size() != 2) throw std::invalid_argument("binary operator without two operands");
            int level = kLevelAdd;
            const char* op = "+";
            switch (e.binaryOp) {
                case BinaryOp::Add: op = "+"; break;
                case BinaryOp::Sub: op = "-"; break;
                case BinaryOp::Union: op = "|"; break;
                case BinaryOp::Intersection: op = "&"; break;
                case BinaryOp::Difference: op = "\\"; break;
                case BinaryOp::Mul: op = "*"; level = kLevelMul; break;
                case BinaryOp::Div: op = "/"; level = kLevelMul; break;
                case BinaryOp::Pow: op = "^"; level = kLevelPow; break;
                default:
                    throw std::invalid_argument(
                        "a comparison or and/or outside a condition cannot be written");
            }
            Text l = arith(*e.args[0]);
            Text r = arith(*e.args[1]);
            // Left to right grouping: a right operand of the same level
            // needs parentheses, a left one does not.
            std::string ls = l.level < level ? paren(l.s) : l.s;
            std::string rs = r.level <= level ? paren(r.s) : r.s;
            return Text{ls + " " + op + " " + rs, level};
        }
        case ExprKind::BuiltinCall: return Text{builtinName(e.builtin) + args(e), kLevelPrimary};
        case ExprKind::LibraryCall: {
            const auto& table = lib::functions();
            if (e.function < 0 || static_cast<size_t>(e.function) >= table.size())
                throw std::invalid_argument("library routine id " + std::to_string(e.function) +
                                            " out of range");
            return Text{table[static_cast<size_t>(e.function)].spelling + args(e), kLevelPrimary};
        }
        case ExprKind::BodyCall: {
            if (e.function < 0 || static_cast<size_t>(e.function) >= program_.bodies.size())
                throw std::invalid_argument("called body " + std::to_string(e.function) +
                                            " out of range");
            for (const auto& a : e.args)
                if (a->kind != ExprKind::ArrayName)
                    throw std::invalid_argument("body call arguments must be array names");
            return Text{program_.bodies[static_cast<size_t>(e.function)].spelling + args(e),
                        kLevelPrimary};
        }
    }
    throw std::invalid_argument("unknown expression kind");
}

Text Writer::condition(const Expr& e) {
    if (e.kind == ExprKind::Binary && (isLogic(e.binaryOp) || isComparison(e.binaryOp))) {
        if (e.args.size() != 2) throw std::invalid_argument("binary operator without two operands");
        const bool logic = isLogic(e.binaryOp);
        const int level = logic ? kCondLogic : kCondCompare;
        const char* op = "=";
        switch (e.binaryOp) {
            case BinaryOp::And: op = "and"; break;
            case BinaryOp::Or: op = "or"; break;
            case BinaryOp::Equal: op = "="; break;
            case BinaryOp::NotEqual: op = "/="; break;
            case BinaryOp::Less: op = "<"; break;
            case BinaryOp::LessEqual: op = "<="; break;
            case BinaryOp::Greater: op = ">"; break;
            case BinaryOp::GreaterEqual: op = ">="; break;
            default: break;
        }
        Text l = condition(*e.args[0]);
        Text r = condition(*e.args[1]);
        // Left to right on both levels; a comparison's operands are
        // operands, so an and/or on its left needs parentheses.
        std::string ls = l.level < level ? paren(l.s) : l.s;
        std::string rs = r.level <= level ? paren(r.s) : r.s;
        return Text{ls + " " + op + " " + rs, level};
    }
    if (e.kind == ExprKind::Unary && e.unaryOp == UnaryOp::Not) {
        if (e.args.size() != 1) throw std::invalid_argument("'not' without one operand");
        Text operand = condition(*e.args[0]);
        std::string s = operand.level < kCondOperand ? paren(operand.s) : operand.s;
        return Text{"not " + s, kCondOperand};
    }
    // An arithmetic operand. Starting with '(' it would be read as a
    // parenthesised condition: a unary plus (the identity) avoids that.
    Text t = arith(e);
    if (!t.s.empty() && t.s.front() == '(') t.s.insert(t.s.begin(), '+');
    return Text{std::move(t.s), kCondOperand};
}

void Writer::list(int depth, const std::string& head, const std::vector<std::string>& items,
                  const std::string& tail) {
    const size_t margin = static_cast<size_t>(depth * std::max(options_.indent, 0));
    std::string text = head;
    size_t width = margin + head.size();  // of the line being filled
    for (size_t i = 0; i < items.size(); ++i) {
        const std::string piece = items[i] + (i + 1 < items.size() ? "," : tail);
        if (i > 0) {
            if (width + 1 + piece.size() > kLineWidth) {
                text += "\n" + std::string(margin + head.size(), ' ');
                width = margin + head.size();
            } else {
                text += ' ';
                ++width;
            }
        }
        text += piece;
        width += piece.size();
    }
    line(depth, text);
}

void Writer::statements(const std::vector<Stmt>& list, int depth) {
    for (const Stmt& s : list) statement(s, depth);
}

void Writer::statement(const Stmt& s, int depth) {
    switch (s.kind) {
        case StmtKind::Assign:
            if (!s.value) throw std::invalid_argument("assignment without a value");
            line(depth, variableName(s.slot) + " = " + arith(*s.value).s + ";");
            return;
        case StmtKind::AssignElement:
            if (!s.value || !s.index) throw std::invalid_argument("element assignment without index or value");
            line(depth, arrayName(s.slot) + "[" + arith(*s.index).s + "] = " + arith(*s.value).s + ";");
            return;
        case StmtKind::AssignArray: {
            const std::string name = arrayName(s.slot);
            if (s.literal.empty()) throw std::invalid_argument("empty array literal for '" + name + "'");
            // Items are numbers with at most one sign. An item without a
            // plain spelling gets 0 here and its own assignment after.
            std::vector<std::string> items;
            std::vector<std::pair<size_t, double>> patches;
            for (size_t i = 0; i < s.literal.size(); ++i) {
                const double v = s.literal[i];
                if (!std::isfinite(v))
                    throw std::invalid_argument("array literal of '" + name +
                                                "' holds NaN or infinity, which HyperFun cannot spell");
                std::optional<std::string> plain = plainSpelling(std::fabs(v));
                if (plain) {
                    items.push_back((std::signbit(v) ? "-" : "") + *plain);
                } else {
                    items.push_back("0");
                    patches.emplace_back(i + 1, v);
                }
            }
            list(depth, name + " = [", items, "];");
            for (const auto& [index, v] : patches)
                line(depth, name + "[" + std::to_string(index) + "] = " + numberText(v).s + ";");
            return;
        }
        case StmtKind::If:
            if (!s.condition) throw std::invalid_argument("if without a condition");
            line(depth, "if " + condition(*s.condition).s + " then");
            statements(s.thenBody, depth + 1);
            if (!s.elseBody.empty()) {
                line(depth, "else");
                statements(s.elseBody, depth + 1);
            }
            line(depth, "endif;");
            return;
        case StmtKind::While:
            if (!s.condition) throw std::invalid_argument("while without a condition");
            line(depth, "while " + condition(*s.condition).s + " loop");
            statements(s.thenBody, depth + 1);
            line(depth, "endloop;");
            return;
    }
    throw std::invalid_argument("unknown statement kind");
}

std::string Writer::body() {
    if (body_.arrays.size() < 3)
        throw std::invalid_argument("body '" + body_.spelling + "' lacks its x, a and s arrays");
    if (!body_.result) throw std::invalid_argument("body '" + body_.spelling + "' has no result");
    auto param = [&](int slot) {
        return arrayName(slot) + "[" + std::to_string(body_.arrays[static_cast<size_t>(slot)].size) + "]";
    };
    std::string head = body_.spelling + "(" + param(kArrayX) + ", " + param(kArrayA);
    if (body_.declaresS) head += ", " + param(kArrayS);
    line(0, head + ")");
    line(0, "{");
    if (body_.arrays.size() > 3) {
        std::vector<std::string> decls;
        for (size_t i = 3; i < body_.arrays.size(); ++i)
            decls.push_back(arrayName(static_cast<int>(i)) + "[" + std::to_string(body_.arrays[i].size) + "]");
        list(1, "array ", decls, ";");
    }
    statements(body_.statements, 1);
    line(1, body_.spelling + " = " + arith(*body_.result).s + ";");
    line(0, "}");
    return std::move(out_);
}

}  // namespace

std::string writeNumber(double v) { return numberText(v).s; }

std::string writeExpression(const Expr& e, const Body& body, const Program& program) {
    WriteOptions options;
    return Writer(program, body, options).expression(e);
}

std::string writeBody(const Body& body, const Program& program, const WriteOptions& options) {
    return Writer(program, body, options).body();
}

std::string writeProgram(const Program& program, const WriteOptions& options) {
    std::string out;
    for (size_t i = 0; i < program.bodies.size(); ++i) {
        if (i) out += '\n';
        out += writeBody(program.bodies[i], program, options);
    }
    return out;
}

}  // namespace hg::frep
