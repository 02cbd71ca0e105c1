// Tests of the HyperFun writer (frep/language/writer.h): every conformance and
// corpus program and the content/hyperfun models written, parsed back and
// evaluated bit for bit against the original (errors included), idempotence
// of the output, the tree the parse gives back, operator levels, conditions,
// statements, multi-body programs, and the spelling of numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "conformance_data.h"
#include "frep/language/interpreter.h"
#include "frep/language/lexer.h"
#include "frep/language/parser.h"
#include "frep/language/writer.h"

namespace fs = std::filesystem;

namespace hg::frep {
namespace {

bool sameBits(double a, double b) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    return x == y;
}

// Same value bit for bit (any NaN matches any NaN), or the same error.
bool sameResult(const PointResult& p, const PointResult& q) {
    if (p.ok() != q.ok()) return false;
    if (!p.ok()) return p.error == q.error;
    return sameBits(p.value, q.value) || (std::isnan(p.value) && std::isnan(q.value));
}

std::string show(const PointResult& p) {
    if (!p.ok()) return std::string("error: ") + describe(p.error);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", p.value);
    return buf;
}

Program parseOrFail(const std::string& text, const std::string& what) {
    ParseResult r = parseProgram(text, what);
    if (!r.ok()) {
        ADD_FAILURE() << what << " does not parse: "
                      << (r.errors.empty() ? std::string("?") : formatDiagnostic(r.errors[0]))
                      << "\n--- text ---\n" << text;
        return Program{};
    }
    return std::move(*r.program);
}

// Value of a number spelling as the interpreter computes it.
std::optional<double> evalNumberText(const std::string& text) {
    ParseResult r = parseProgram("n(x[1], a[1]) { n = " + text + "; }", "<number>");
    if (!r.ok()) return std::nullopt;
    Interpreter interp(*r.program, 0);
    PointResult p = interp.evaluate(0, 0, 0);
    if (!p.ok()) return std::nullopt;
    return p.value;
}

// --- the tree the parse gives back -----------------------------------------

bool constantTree(const Expr& e) {
    if (e.kind == ExprKind::Number) return true;
    if (e.kind != ExprKind::Unary && e.kind != ExprKind::Binary) return false;
    for (const auto& a : e.args)
        if (!constantTree(*a)) return false;
    return true;
}

// `back` is `orig` except for what the writer is documented to change: a
// unary plus in front of a condition operand that starts with '(', and a
// number written as unary minus or as an exact constant expression.
bool sameTree(const Expr& orig, const Expr& back, std::string& why) {
    if (back.kind == ExprKind::Unary && back.unaryOp == UnaryOp::Plus &&
        !(orig.kind == ExprKind::Unary && orig.unaryOp == UnaryOp::Plus))
        return sameTree(orig, *back.args[0], why);
    if (orig.kind == ExprKind::Number) {
        if (back.kind == ExprKind::Number && sameBits(orig.number, back.number)) return true;
        if (back.kind == ExprKind::Unary && back.unaryOp == UnaryOp::Minus &&
            back.args[0]->kind == ExprKind::Number && sameBits(orig.number, -back.args[0]->number))
            return true;
        if (back.kind != ExprKind::Number && constantTree(back)) return true;  // values checked elsewhere
        why = "number " + std::to_string(orig.number) + " came back differently";
        return false;
    }
    if (orig.kind != back.kind || orig.slot != back.slot || orig.args.size() != back.args.size()) {
        why = "node '" + orig.spelling + "' came back as '" + back.spelling + "'";
        return false;
    }
    if ((orig.kind == ExprKind::Unary && orig.unaryOp != back.unaryOp) ||
        (orig.kind == ExprKind::Binary && orig.binaryOp != back.binaryOp) ||
        (orig.kind == ExprKind::BuiltinCall && orig.builtin != back.builtin) ||
        ((orig.kind == ExprKind::LibraryCall || orig.kind == ExprKind::BodyCall) &&
         orig.function != back.function)) {
        why = "operator '" + orig.spelling + "' came back as '" + back.spelling + "'";
        return false;
    }
    for (size_t i = 0; i < orig.args.size(); ++i)
        if (!sameTree(*orig.args[i], *back.args[i], why)) return false;
    return true;
}

bool sameStatements(const std::vector<Stmt>& a, const std::vector<Stmt>& b, std::string& why);

bool sameStatement(const Stmt& a, const Stmt& b, std::string& why) {
    if (a.kind != b.kind || a.slot != b.slot) {
        why = "statement kind or target changed";
        return false;
    }
    auto same = [&](const ExprPtr& p, const ExprPtr& q) {
        if (!p || !q) return !p && !q;
        return sameTree(*p, *q, why);
    };
    if (!same(a.index, b.index) || !same(a.value, b.value) || !same(a.condition, b.condition))
        return false;
    if (a.literal.size() != b.literal.size()) {
        why = "array literal size changed";
        return false;
    }
    for (size_t i = 0; i < a.literal.size(); ++i)
        if (!sameBits(a.literal[i], b.literal[i])) {
            why = "array literal item changed";
            return false;
        }
    return sameStatements(a.thenBody, b.thenBody, why) && sameStatements(a.elseBody, b.elseBody, why);
}

bool sameStatements(const std::vector<Stmt>& a, const std::vector<Stmt>& b, std::string& why) {
    if (a.size() != b.size()) {
        why = "statement count changed";
        return false;
    }
    for (size_t i = 0; i < a.size(); ++i)
        if (!sameStatement(a[i], b[i], why)) return false;
    return true;
}

void expectSameStructure(const Program& p, const Program& q) {
    ASSERT_EQ(p.bodies.size(), q.bodies.size());
    for (size_t i = 0; i < p.bodies.size(); ++i) {
        const Body& a = p.bodies[i];
        const Body& b = q.bodies[i];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.spelling, b.spelling);
        EXPECT_EQ(a.declaresS, b.declaresS);
        ASSERT_EQ(a.arrays.size(), b.arrays.size()) << a.name;
        for (size_t k = 0; k < a.arrays.size(); ++k) {
            EXPECT_EQ(a.arrays[k].name, b.arrays[k].name);
            EXPECT_EQ(a.arrays[k].size, b.arrays[k].size);
        }
        ASSERT_EQ(a.variables.size(), b.variables.size()) << a.name;
        for (size_t k = 0; k < a.variables.size(); ++k) EXPECT_EQ(a.variables[k].name, b.variables[k].name);
        std::string why;
        EXPECT_TRUE(sameStatements(a.statements, b.statements, why)) << a.name << ": " << why;
        EXPECT_TRUE(sameTree(*a.result, *b.result, why)) << a.name << " result: " << why;
    }
}

// Writes `p`, parses the text back, checks the tree and idempotence.
// Returns the reparsed program (empty on failure).
Program roundTrip(const Program& p, const std::string& what, std::string* textOut = nullptr,
                  bool sameStructure = true) {
    std::string text = writeProgram(p);
    if (textOut) *textOut = text;
    Program back = parseOrFail(text, what + " (written)");
    if (back.bodies.empty()) return back;
    if (sameStructure) expectSameStructure(p, back);
    EXPECT_EQ(writeProgram(back), text) << what << ": writing is not idempotent";
    return back;
}

// --- the conformance and corpus tables (tests/data/hyperfun) ------------------------------

TEST(WriterConformance, EveryTableRowIdenticalAfterRoundTrip) {
    ASSERT_TRUE(fs::is_directory(test::hyperfunDir() / "conformance")) << test::hyperfunDir();
    auto tables = test::tables();
    ASSERT_FALSE(tables.empty());
    int programs = 0;
    long long rows = 0;
    for (const fs::path& tsv : tables) {
        SCOPED_TRACE(tsv.string());
        fs::path hf = tsv;
        hf.replace_extension(".hf");
        ParseResult parsed = parseFile(hf.string());
        ASSERT_TRUE(parsed.ok()) << hf;
        const Program& orig = *parsed.program;
        std::string text;
        Program back = roundTrip(orig, hf.filename().string(), &text);
        ASSERT_FALSE(back.bodies.empty());
        const int body = orig.defaultBody();
        ASSERT_EQ(back.defaultBody(), body);
        int failures = 0;
        for (const auto& r : test::readTable(tsv)) {
            Interpreter a(orig, body, {r.a1});
            Interpreter b(back, body, {r.a1});
            PointResult pa = a.evaluate(r.x, r.y, r.z);
            PointResult pb = b.evaluate(r.x, r.y, r.z);
            ++rows;
            if (!sameResult(pa, pb) && ++failures <= 5)
                ADD_FAILURE() << "row " << r.line << ": original " << show(pa) << ", written "
                              << show(pb) << "\n--- written text ---\n" << text;
        }
        ++programs;
    }
    EXPECT_GE(programs, 38);
    EXPECT_GE(rows, 38 * 200);
}

// --- the project's own models ------------------------------------------------

TEST(WriterContent, ModelsIdenticalAtRandomPoints) {
    const fs::path dir = fs::path(HG_SOURCE_DIR) / "content" / "hyperfun";
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    std::mt19937_64 rng(20240611);
    int models = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".hf") continue;
        SCOPED_TRACE(entry.path().string());
        ParseResult parsed = parseFile(entry.path().string());
        ASSERT_TRUE(parsed.ok()) << (parsed.errors.empty() ? "" : formatDiagnostic(parsed.errors[0]));
        const Program& orig = *parsed.program;
        Program back = roundTrip(orig, entry.path().filename().string());
        ASSERT_FALSE(back.bodies.empty());
        for (int body = 0; body < static_cast<int>(orig.bodies.size()); ++body) {
            int failures = 0;
            for (int i = 0; i < 400; ++i) {
                const double range = i % 3 == 0 ? 2.0 : i % 3 == 1 ? 10.0 : 50.0;
                std::uniform_real_distribution<double> u(-range, range);
                const double x = u(rng), y = u(rng), z = u(rng);
                std::vector<double> a;
                if (i % 2) a = {u(rng), u(rng), u(rng)};
                Interpreter ia(orig, body, a);
                Interpreter ib(back, body, a);
                PointResult pa = ia.evaluate(x, y, z);
                PointResult pb = ib.evaluate(x, y, z);
                if (!sameResult(pa, pb) && ++failures <= 5)
                    ADD_FAILURE() << "body " << orig.bodies[static_cast<size_t>(body)].spelling << " at ("
                                  << x << ", " << y << ", " << z << "): " << show(pa) << " vs " << show(pb);
            }
        }
        ++models;
    }
    EXPECT_GE(models, 1);
}

// --- operator levels -----------------------------------------------------------

// The written form of the result expression of a one-body program with
// u, v, w (= x[1..3]) defined.
std::string written(const std::string& expr) {
    const std::string src = "m(x[3], a[1])\n{\n   u = x[1]; v = x[2]; w = x[3];\n   m = " + expr + ";\n}\n";
    Program p = parseOrFail(src, expr);
    if (p.bodies.empty()) return "<parse error>";
    Program back = roundTrip(p, expr);
    // Values: identical at a few points, errors included.
    if (!back.bodies.empty()) {
        for (double t : {-1.5, -0.25, 0.0, 0.5, 2.0, 3.25}) {
            Interpreter a(p, 0), b(back, 0);
            PointResult pa = a.evaluate(t, 0.75 - t, t * t - 1);
            PointResult pb = b.evaluate(t, 0.75 - t, t * t - 1);
            EXPECT_TRUE(sameResult(pa, pb)) << expr << " at " << t << ": " << show(pa) << " vs " << show(pb);
        }
    }
    return writeExpression(*p.bodies[0].result, p.bodies[0], p);
}

TEST(WriterExpression, PrecedenceCases) {
    // precedence.hf
    EXPECT_EQ(written("-u^2"), "-u ^ 2");
    EXPECT_EQ(written("u^2^3"), "u ^ 2 ^ 3");
    EXPECT_EQ(written("u + v | w"), "u + v | w");
    EXPECT_EQ(written("u | v + w"), "u | v + w");
    EXPECT_EQ(written("u * v | w * 2"), "u * v | w * 2");
    EXPECT_EQ(written("u - v & w - 1"), "u - v & w - 1");
    EXPECT_EQ(written("~u ^ 2 + ~v"), "~u ^ 2 + ~v");
    EXPECT_EQ(written("2 ^ -u"), "2 ^ -u");
    EXPECT_EQ(written("-2 ^ 2 * 3 + w"), "-2 ^ 2 * 3 + w");
    EXPECT_EQ(written("u / 0.5 / 4 * v"), "u / 0.5 / 4 * v");
    EXPECT_EQ(written("u - v - w + 1"), "u - v - w + 1");
    EXPECT_EQ(written("u \\ v | w & u"), "u \\ v | w & u");
    EXPECT_EQ(written("- u * v ^ 2"), "-u * v ^ 2");
    EXPECT_EQ(written("u ^ 2 * 3 ^ 2 - - v"), "u ^ 2 * 3 ^ 2 - -v");
    // Right operands of the same level, redundant parentheses, @.
    EXPECT_EQ(written("u - (v + w)"), "u - (v + w)");
    EXPECT_EQ(written("(u - v) + w"), "u - v + w");
    EXPECT_EQ(written("u | (v & w)"), "u | (v & w)");
    EXPECT_EQ(written("u \\ (v \\ w)"), "u \\ (v \\ w)");
    EXPECT_EQ(written("u @ v"), "u & v");
    EXPECT_EQ(written("u * (v * w)"), "u * (v * w)");
    EXPECT_EQ(written("u / (v / w)"), "u / (v / w)");
    EXPECT_EQ(written("u / (v * w)"), "u / (v * w)");
    EXPECT_EQ(written("(u * v) / w"), "u * v / w");
    EXPECT_EQ(written("u * (v + w)"), "u * (v + w)");
    EXPECT_EQ(written("(u + v) * w"), "(u + v) * w");
    EXPECT_EQ(written("u ^ (2 ^ 3)"), "u ^ (2 ^ 3)");
    EXPECT_EQ(written("(u ^ 2) ^ 3"), "u ^ 2 ^ 3");
    EXPECT_EQ(written("(u * 2) ^ 3"), "(u * 2) ^ 3");
    EXPECT_EQ(written("-(u ^ 2)"), "-(u ^ 2)");
    EXPECT_EQ(written("(-u) ^ 2"), "-u ^ 2");
    EXPECT_EQ(written("-(u + v)"), "-(u + v)");
    EXPECT_EQ(written("~(u | v)"), "~(u | v)");
    EXPECT_EQ(written("2 ^ -(u ^ 3)"), "2 ^ -(u ^ 3)");
    EXPECT_EQ(written("2 ^ -u ^ 3"), "2 ^ -u ^ 3");
    EXPECT_EQ(written("- -u"), "- -u");
    EXPECT_EQ(written("-(-u)"), "- -u");
    EXPECT_EQ(written("-(-2)"), "- -2");
    EXPECT_EQ(written("3 - -2"), "3 - -2");
    EXPECT_EQ(written("3 - ~2"), "3 - ~2");
    EXPECT_EQ(written("+u - +v"), "+u - +v");
    EXPECT_EQ(written("-~-u"), "-~-u");
    EXPECT_EQ(written("x[1 + 1] * X[3]"), "x[1 + 1] * x[3]");
    EXPECT_EQ(written("max(u, -v) + atan2(u + 1, w) - HFSPHERE(x, x, 1) * sin(u)"),
              "max(u, -v) + atan2(u + 1, w) - hfSphere(x, x, 1) * sin(u)");
}

TEST(WriterExpression, Powers) {
    // powers.hf
    EXPECT_EQ(written("x[1] ^ 3"), "x[1] ^ 3");
    EXPECT_EQ(written("x[1] ^ -2"), "x[1] ^ -2");
    EXPECT_EQ(written("x[1] ^ 0.5"), "x[1] ^ 0.5");
    EXPECT_EQ(written("x[1] ^ x[2]"), "x[1] ^ x[2]");
    EXPECT_EQ(written("abs(x[1]) ^ x[2]"), "abs(x[1]) ^ x[2]");
    EXPECT_EQ(written("(x[1] * 0.000001) ^ 2 + x[2]"), "(x[1] * 0.000001) ^ 2 + x[2]");
    EXPECT_EQ(written("x[1] ^ 0"), "x[1] ^ 0");
    EXPECT_EQ(written("0 ^ x[1]"), "0 ^ x[1]");
    EXPECT_EQ(written("(x[1] * 4) ^ (x[3] * 0 + 2.0000004)"), "(x[1] * 4) ^ (x[3] * 0 + 2.0000004)");
}

// The written condition of `if COND then r = 1; endif;`.
std::string writtenCondition(const std::string& cond) {
    const std::string src = "m(x[3], a[1])\n{\n   u = x[1]; v = x[2];\n   r = 0;\n   if " + cond +
                            " then r = 1; endif;\n   m = r;\n}\n";
    Program p = parseOrFail(src, cond);
    if (p.bodies.empty()) return "<parse error>";
    Program back = roundTrip(p, cond);
    if (!back.bodies.empty()) {
        for (double t : {-1.5, -0.25, 0.0, 0.5, 1.0, 2.0}) {
            for (double s : {-1.0, 0.0, 0.5, 1.0}) {
                Interpreter a(p, 0), b(back, 0);
                PointResult pa = a.evaluate(t, s, 0);
                PointResult pb = b.evaluate(t, s, 0);
                EXPECT_TRUE(sameResult(pa, pb)) << cond << ": " << show(pa) << " vs " << show(pb);
            }
        }
    }
    const Body& b = p.bodies[0];
    return writeExpression(*b.statements[3].condition, b, p);
}

TEST(WriterCondition, Levels) {
    EXPECT_EQ(writtenCondition("u > 0"), "u > 0");
    EXPECT_EQ(writtenCondition("not u > 0.5"), "not u > 0.5");
    EXPECT_EQ(writtenCondition("not (u > 0.5)"), "not (u > 0.5)");
    EXPECT_EQ(writtenCondition("u > 0 or v > 0 and u < 1"), "u > 0 or v > 0 and u < 1");
    EXPECT_EQ(writtenCondition("u > 0 or (v > 0 and u < 1)"), "u > 0 or (v > 0 and u < 1)");
    EXPECT_EQ(writtenCondition("(u > 0 or v > 0) and u < 1"), "u > 0 or v > 0 and u < 1");
    EXPECT_EQ(writtenCondition("(u > 0) = (v > 0)"), "u > 0 = (v > 0)");
    EXPECT_EQ(writtenCondition("u < v < 1"), "u < v < 1");
    EXPECT_EQ(writtenCondition("u < (v < 1)"), "u < (v < 1)");
    EXPECT_EQ(writtenCondition("(u and v) < 1"), "(u and v) < 1");
    EXPECT_EQ(writtenCondition("u /= v and not not u <= 2"), "u /= v and not not u <= 2");
    EXPECT_EQ(writtenCondition("u >= -v"), "u >= -v");
    EXPECT_EQ(writtenCondition("u"), "u");
    EXPECT_EQ(writtenCondition("not (u)"), "not u");
    EXPECT_EQ(writtenCondition("((u > 0))"), "u > 0");
    EXPECT_EQ(writtenCondition("u = 1 + (v - 1) * 2"), "u = 1 + (v - 1) * 2");
    // Operands that start with a parenthesis keep a unary plus.
    EXPECT_EQ(writtenCondition("+(u + 1) * 2 > 1"), "+(u + 1) * 2 > 1");
    EXPECT_EQ(writtenCondition("u < +(v - 1) ^ 2"), "u < +(v - 1) ^ 2");
    EXPECT_EQ(writtenCondition("not +(u + v) / 2"), "not +(u + v) / 2");
}

// A condition whose first operand is (u + 1) * 2 exists only as a tree (no
// text parses to it); the writer adds a unary plus that changes no value.
TEST(WriterCondition, ParenthesisedOperandGetsUnaryPlus) {
    const std::string src =
        "m(x[3], a[1])\n{\n   u = x[1];\n   r = 0;\n"
        "   if +(u + 1) * 2 > 1 and +(u - 3) * (u + 3) < 0 then r = 1; endif;\n"
        "   while +(r - 5) * 1 < 0 loop r = r + 1; endloop;\n   m = r;\n}\n";
    Program p = parseOrFail(src, "plus");
    ASSERT_EQ(p.bodies.size(), 1u);
    Body& b = p.bodies[0];
    // Strip the unary pluses: Mul(Plus(Add), 2) -> Mul(Add, 2).
    auto strip = [](Expr& mul) {
        ASSERT_EQ(mul.kind, ExprKind::Binary);
        ASSERT_EQ(mul.args[0]->kind, ExprKind::Unary);
        ASSERT_EQ(mul.args[0]->unaryOp, UnaryOp::Plus);
        ExprPtr inner = std::move(mul.args[0]->args[0]);
        mul.args[0] = std::move(inner);
    };
    Expr& andNode = *b.statements[2].condition;
    strip(*andNode.args[0]->args[0]);
    strip(*andNode.args[1]->args[0]);
    strip(*b.statements[3].condition->args[0]);
    const std::string text = writeProgram(p);
    EXPECT_NE(text.find("if +(u + 1) * 2 > 1 and +(u - 3) * (u + 3) < 0 then"), std::string::npos) << text;
    EXPECT_NE(text.find("while +(r - 5) * 1 < 0 loop"), std::string::npos) << text;
    Program back = roundTrip(p, "plus");
    ASSERT_EQ(back.bodies.size(), 1u);
    for (double t : {-4.0, -1.0, -0.5, 0.0, 0.5, 2.5, 3.0, 10.0}) {
        Interpreter ia(p, 0), ib(back, 0);
        PointResult pa = ia.evaluate(t, 0, 0);
        PointResult pb = ib.evaluate(t, 0, 0);
        EXPECT_TRUE(sameResult(pa, pb)) << t << ": " << show(pa) << " vs " << show(pb);
    }
}

TEST(WriterExpression, UnwritableTreesThrow) {
    Program p = parseOrFail("m(x[3], a[1])\n{\n   u = x[1];\n   if u > 1 then u = 2; endif;\n   m = u;\n}\n",
                            "unwritable");
    ASSERT_EQ(p.bodies.size(), 1u);
    Body& b = p.bodies[0];
    // A comparison as the result (outside a condition); the if gets `u`.
    b.result.swap(b.statements[1].condition);
    EXPECT_THROW(writeProgram(p), std::invalid_argument);
    // A number that is not finite.
    auto inf = std::make_unique<Expr>();
    inf->kind = ExprKind::Number;
    inf->number = std::numeric_limits<double>::infinity();
    b.result = std::move(inf);
    EXPECT_THROW(writeProgram(p), std::invalid_argument);
    // A literal that overflows to infinity parses, but cannot be written.
    Program big = parseOrFail("m(x[3], a[1]) { m = 1e400; }", "inf");
    EXPECT_THROW(writeProgram(big), std::invalid_argument);
}

// --- statements, arrays, several bodies ------------------------------------

TEST(WriterProgram, MultiBodyWithArraysLoopsAndS) {
    const std::string src =
        "-- comment\n"
        "Helper(x[3], a[1], s[2])\n"
        "{\n"
        "  s[1] = x[1] * 2;  s[2] = s[1] + a[1];\n"
        "  Helper = s[2] - 1;\n"
        "}\n"
        "other(X[3], A[1]) { other = X[1]^2 + X[2]^2 - 1; }\n"
        "my_model(x[3], a[1])\n"
        "{\n"
        "  ARRAY T[2], p[3];\n"
        "  array q[1];\n"
        "  t = [+0, -.5];  P = [1, 2., 3.];  q = [-0];\n"
        "  K = 0;\n"
        "  while k < 3 loop\n"
        "    k = k + 1;\n"
        "    p[k] = p[k] * x[k];\n"
        "    if p[k] > 0 then t[1] = t[1] + 1;\n"
        "    else if p[k] < -1 then t[2] = t[2] - 1; endif;\n"
        "    endif;\n"
        "  endloop;\n"
        "  if k then endif;\n"
        "  v = helper(P, a, t) + OTHER(x, a);\n"
        "  my_model = v + t[1] + t[2] | hfsphere(x, p, 1.5) + q[1];\n"
        "}\n";
    ParseResult r0 = parseProgram(src, "multi");
    if (!r0.ok()) FAIL() << formatDiagnostic(r0.errors[0]);
    Program p = std::move(*r0.program);
    const std::string expected =
        "Helper(x[3], a[1], s[2])\n"
        "{\n"
        "   s[1] = x[1] * 2;\n"
        "   s[2] = s[1] + a[1];\n"
        "   Helper = s[2] - 1;\n"
        "}\n"
        "\n"
        "other(X[3], A[1])\n"
        "{\n"
        "   other = X[1] ^ 2 + X[2] ^ 2 - 1;\n"
        "}\n"
        "\n"
        "my_model(x[3], a[1])\n"
        "{\n"
        "   array T[2], p[3], q[1];\n"
        "   T = [0, -0.5];\n"
        "   p = [1, 2, 3];\n"
        "   q = [-0];\n"
        "   K = 0;\n"
        "   while K < 3 loop\n"
        "      K = K + 1;\n"
        "      p[K] = p[K] * x[K];\n"
        "      if p[K] > 0 then\n"
        "         T[1] = T[1] + 1;\n"
        "      else\n"
        "         if p[K] < -1 then\n"
        "            T[2] = T[2] - 1;\n"
        "         endif;\n"
        "      endif;\n"
        "   endloop;\n"
        "   if K then\n"
        "   endif;\n"
        "   v = Helper(p, a, T) + other(x, a);\n"
        "   my_model = v + T[1] + T[2] | hfSphere(x, p, 1.5) + q[1];\n"
        "}\n";
    EXPECT_EQ(writeProgram(p), expected);
    WriteOptions two;
    two.indent = 2;
    EXPECT_NE(writeBody(p.bodies[2], p, two).find("\n    K = K + 1;\n"), std::string::npos);
    Program back = roundTrip(p, "multi");
    ASSERT_EQ(back.bodies.size(), 3u);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int body = 0; body < 3; ++body) {
        for (int i = 0; i < 200; ++i) {
            double x = u(rng), y = u(rng), z = u(rng), a1 = u(rng);
            Interpreter ia(p, body, {a1}), ib(back, body, {a1});
            PointResult pa = ia.evaluate(x, y, z);
            PointResult pb = ib.evaluate(x, y, z);
            EXPECT_TRUE(sameResult(pa, pb)) << show(pa) << " vs " << show(pb);
        }
    }
    // q[1] is -0.0 in both.
    EXPECT_TRUE(std::signbit(back.bodies[2].statements[2].literal[0]));
}

TEST(WriterProgram, LiteralItemsWithoutPlainSpellingBecomeAssignments) {
    // 10^30 written out (not exactly 1e30) and a 1e-40 that the lexer reaches
    // only approximately: no plain decimal for either.
    const std::string src = "m(x[3], a[1])\n{\n   array t[3];\n   t = [1" + std::string(30, '0') +
                            ", -0." + std::string(39, '0') + "1, 2];\n   m = t[1] * x[1] + t[2] + t[3];\n}\n";
    Program p = parseOrFail(src, "literal");
    ASSERT_EQ(p.bodies.size(), 1u);
    std::string text;
    Program back = roundTrip(p, "literal", &text, /*sameStructure=*/false);
    ASSERT_EQ(back.bodies.size(), 1u);
    EXPECT_NE(text.find("   t = [0, 0, 2];\n   t[1] = "), std::string::npos) << text;
    // Only the values matter here: the patched items are assignments now.
    for (double x : {-1.0, 0.0, 0.5, 3.0}) {
        Interpreter ia(p, 0), ib(back, 0);
        PointResult pa = ia.evaluate(x, 0, 0);
        PointResult pb = ib.evaluate(x, 0, 0);
        EXPECT_TRUE(sameResult(pa, pb)) << show(pa) << " vs " << show(pb);
    }
}

// --- random trees ------------------------------------------------------------

class TreeMaker {
public:
    explicit TreeMaker(std::uint64_t seed) : rng_(seed) {}

    ExprPtr arith(int depth) {
        int pick = depth <= 0 ? static_cast<int>(rng_() % 3) : static_cast<int>(rng_() % 12);
        switch (pick) {
            case 0: return number();
            case 1: return variable();
            case 2: {
                auto e = node(ExprKind::ArrayElement);
                e->slot = kArrayX;
                auto i = node(ExprKind::Number);
                i->number = static_cast<double>(1 + rng_() % 3);
                e->args.push_back(std::move(i));
                return e;
            }
            case 3: case 4: {
                auto e = node(ExprKind::Unary);
                const UnaryOp ops[] = {UnaryOp::Plus, UnaryOp::Minus, UnaryOp::Tilde};
                e->unaryOp = ops[rng_() % 3];
                e->args.push_back(arith(depth - 1));
                return e;
            }
            case 5: {
                auto e = node(ExprKind::BuiltinCall);
                const Builtin fs[] = {Builtin::Sin, Builtin::Max, Builtin::Atan2, Builtin::Abs, Builtin::Sqrt};
                e->builtin = fs[rng_() % 5];
                int n = (e->builtin == Builtin::Max || e->builtin == Builtin::Atan2) ? 2 : 1;
                for (int i = 0; i < n; ++i) e->args.push_back(arith(depth - 1));
                return e;
            }
            default: {
                auto e = node(ExprKind::Binary);
                const BinaryOp ops[] = {BinaryOp::Add, BinaryOp::Sub, BinaryOp::Mul, BinaryOp::Div,
                                        BinaryOp::Pow, BinaryOp::Union, BinaryOp::Intersection,
                                        BinaryOp::Difference};
                e->binaryOp = ops[rng_() % 8];
                e->args.push_back(arith(depth - 1));
                if (e->binaryOp == BinaryOp::Pow) {
                    // Integer exponents loop |e| times: keep them small.
                    if (rng_() % 2) {
                        // u, v or w (from x[]), never r, which may be huge.
                        auto var = node(ExprKind::Variable);
                        var->slot = static_cast<int>(rng_() % 3);
                        e->args.push_back(std::move(var));
                    } else {
                        static const double exps[] = {2, 3, -1, 0.5, 1.5, 0};
                        auto n = node(ExprKind::Number);
                        n->number = exps[rng_() % 6];
                        e->args.push_back(std::move(n));
                    }
                } else {
                    e->args.push_back(arith(depth - 1));
                }
                return e;
            }
        }
    }

    ExprPtr condition(int depth) {
        int pick = depth <= 0 ? 0 : static_cast<int>(rng_() % 6);
        switch (pick) {
            case 0: case 1: {
                if (rng_() % 3 == 0) return arith(depth);
                auto e = node(ExprKind::Binary);
                const BinaryOp ops[] = {BinaryOp::Equal, BinaryOp::NotEqual, BinaryOp::Less,
                                        BinaryOp::LessEqual, BinaryOp::Greater, BinaryOp::GreaterEqual};
                e->binaryOp = ops[rng_() % 6];
                e->args.push_back(rng_() % 4 == 0 ? condition(depth - 1) : arith(depth));
                e->args.push_back(rng_() % 4 == 0 ? condition(depth - 1) : arith(depth));
                return e;
            }
            case 2: {
                auto e = node(ExprKind::Unary);
                e->unaryOp = UnaryOp::Not;
                e->args.push_back(condition(depth - 1));
                return e;
            }
            default: {
                auto e = node(ExprKind::Binary);
                e->binaryOp = rng_() % 2 ? BinaryOp::And : BinaryOp::Or;
                e->args.push_back(condition(depth - 1));
                e->args.push_back(condition(depth - 1));
                return e;
            }
        }
    }

private:
    ExprPtr node(ExprKind k) {
        auto e = std::make_unique<Expr>();
        e->kind = k;
        return e;
    }
    ExprPtr variable() {
        auto e = node(ExprKind::Variable);
        e->slot = static_cast<int>(rng_() % 4);
        return e;
    }
    ExprPtr number() {
        auto e = node(ExprKind::Number);
        static const double pool[] = {0.0, -0.0, 1.0, 2.0, 0.5, -3.0, 0.1, 1e-7, 1e22, -1e30,
                                      5e-324, 1e-40, 123456.789, 1000.0000000000007, -2.5};
        if (rng_() % 2) {
            e->number = pool[rng_() % (sizeof pool / sizeof pool[0])];
        } else {
            std::uniform_real_distribution<double> u(-4, 4);
            e->number = u(rng_);
        }
        return e;
    }
    std::mt19937_64 rng_;
};

TEST(WriterRandom, TreesSurviveWriteAndParse) {
    const std::string src =
        "m(x[3], a[1])\n{\n   u = x[1]; v = x[2]; w = x[3]; r = 0;\n"
        "   if u > 0 then r = 1; else r = 2; endif;\n   m = r + u;\n}\n";
    TreeMaker maker(12345);
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> coord(-2, 2);
    for (int iter = 0; iter < 1500; ++iter) {
        Program p = parseOrFail(src, "template");
        ASSERT_EQ(p.bodies.size(), 1u);
        Body& b = p.bodies[0];
        b.statements[4].condition = maker.condition(3);
        b.statements[4].thenBody[0].value = maker.arith(3);
        b.result = maker.arith(4);
        std::string text;
        Program back = roundTrip(p, "random tree " + std::to_string(iter), &text);
        if (::testing::Test::HasFailure()) {
            ADD_FAILURE() << "iteration " << iter << ":\n" << text;
            return;
        }
        for (int i = 0; i < 8; ++i) {
            double x = coord(rng), y = coord(rng), z = coord(rng);
            if (i == 0) x = y = z = 0.0;
            Interpreter ia(p, 0), ib(back, 0);
            PointResult pa = ia.evaluate(x, y, z);
            PointResult pb = ib.evaluate(x, y, z);
            if (!sameResult(pa, pb)) {
                ADD_FAILURE() << "iteration " << iter << ": " << show(pa) << " vs " << show(pb) << "\n" << text;
                return;
            }
        }
    }
}

// --- numbers -----------------------------------------------------------------

double lexed(const std::string& s) {
    syntax::Lexer lexer(s);
    syntax::Token t = lexer.next();
    EXPECT_EQ(t.kind, syntax::TokenKind::Number) << s;
    EXPECT_EQ(t.length, s.size()) << s;
    return t.number;
}

void expectNumberRoundTrip(double v) {
    std::string s = writeNumber(v);
    std::optional<double> back = evalNumberText(s);
    ASSERT_TRUE(back.has_value()) << s;
    EXPECT_TRUE(sameBits(*back, v)) << "writeNumber(" << v << ") = " << s;
    EXPECT_EQ(s.find_first_of("eE"), std::string::npos) << s;
    EXPECT_EQ(s.find("--"), std::string::npos) << s;
}

TEST(WriterNumber, TrickyValues) {
    EXPECT_EQ(writeNumber(0.0), "0");
    EXPECT_EQ(writeNumber(-0.0), "-0");  // unary minus on 0 gives -0.0
    EXPECT_EQ(writeNumber(0.1), "0.1");
    EXPECT_EQ(writeNumber(0.5), "0.5");
    EXPECT_EQ(writeNumber(-2.5), "-2.5");
    EXPECT_EQ(writeNumber(1e-7), "0.0000001");
    EXPECT_EQ(writeNumber(0.000001), "0.000001");
    EXPECT_EQ(writeNumber(123456.789), "123456.789");
    EXPECT_EQ(writeNumber(123456789012.0), "123456789012");
    EXPECT_EQ(writeNumber(3.0), "3");
    // 1e3 as the lexer reads it: 1000.0000000000007, spelled without exponent.
    const double e3 = lexed("1e3");
    EXPECT_NE(e3, 1000.0);
    EXPECT_EQ(writeNumber(e3), "1000.0000000000007");
    EXPECT_TRUE(sameBits(lexed(writeNumber(e3)), e3));
    // Huge and tiny: exact arithmetic.
    EXPECT_EQ(writeNumber(1e22), "10 ^ 22");
    EXPECT_EQ(writeNumber(-1e22), "-1 * 10 ^ 22");
    EXPECT_EQ(writeNumber(1.5e21), "1.5 * 10 ^ 21");
    EXPECT_EQ(writeNumber(5e-324), "1 / 2 ^ 1023 / 2 ^ 51");
    EXPECT_EQ(writeNumber(-5e-324), "-1 / 2 ^ 1023 / 2 ^ 51");
    for (double v : {0.1, 0.2, 0.3, 1.0 / 3.0, 2.0 / 3.0, 3.141592653589793, 1e-7, 1e-30, 9.99e-31, 1e21, 1e22, 1e23, 1e100,
                     1e300, 1.7976931348623157e308, 2.2250738585072014e-308, 4.9e-324, 1e-310, 1e-40,
                     9007199254740993.0, 9007199254740992.0 * 3, 0.30000000000000004, 1e15 + 0.3, 5e-324,
                     123456.789, e3, lexed("2.5E-3"), lexed("12.5e+1"), lexed("1.25e-1"), lexed("1e-12")}) {
        expectNumberRoundTrip(v);
        expectNumberRoundTrip(-v);
    }
    EXPECT_THROW(writeNumber(std::nan("")), std::invalid_argument);
    EXPECT_THROW(writeNumber(std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_THROW(writeNumber(-std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(WriterNumber, PlainSpellingIsShortest) {
    // Decimals that the lexer reads exactly come back as written.
    for (const char* s : {"0.25", "7", "0.001", "1.5", "42.125", "0.7", "12.34", "99.9"}) {
        EXPECT_EQ(writeNumber(lexed(s)), s);
    }
}

TEST(WriterNumber, RandomValuesRoundTrip) {
    std::mt19937_64 rng(4242);
    int fallbacks = 0;
    for (int i = 0; i < 10000; ++i) {
        double v = 0;
        if (i % 2 == 0) {
            std::uint64_t bits = rng();
            std::memcpy(&v, &bits, sizeof v);
            if (!std::isfinite(v)) continue;
        } else {
            // Values of everyday magnitude.
            std::uniform_real_distribution<double> mant(-10, 10);
            std::uniform_int_distribution<int> ex(-12, 12);
            v = mant(rng) * std::pow(10.0, ex(rng));
        }
        std::string s = writeNumber(v);
        std::optional<double> back = evalNumberText(s);
        ASSERT_TRUE(back.has_value()) << s;
        ASSERT_TRUE(sameBits(*back, v)) << v << " -> " << s;
        if (s.find(' ') != std::string::npos && std::fabs(v) >= 1e-30 && std::fabs(v) < 1e21) ++fallbacks;
    }
    // Almost every value of ordinary size has a plain spelling.
    EXPECT_LT(fallbacks, 10);
}

}  // namespace
}  // namespace hg::frep
