// Tests of the HyperFun front end: the conformance and corpus files, the
// reference's first error for every .bad.hf, operator levels, number
// spellings, recovery, diagnostics formatting and resource limits.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frep/language/lexer.h"
#include "frep/kernels/library/library.h"
#include "frep/language/parser.h"

namespace fs = std::filesystem;
using namespace hg::frep;

namespace {

const fs::path kConformance = fs::path(HG_TEST_DATA_DIR) / "hyperfun" / "conformance";
const fs::path kCorpus = fs::path(HG_TEST_DATA_DIR) / "hyperfun" / "corpus";

std::string firstError(const ParseResult& r) {
    return r.errors.empty() ? std::string("(no error)") : formatDiagnostic(r.errors.front());
}

std::vector<fs::path> filesIn(const fs::path& dir, const std::string& suffix, bool bad) {
    std::vector<fs::path> out;
    if (!fs::is_directory(dir)) return out;
    for (const auto& entry : fs::directory_iterator(dir)) {
        std::string name = entry.path().filename().string();
        bool isBad = name.size() > 7 && name.compare(name.size() - 7, 7, ".bad.hf") == 0;
        if (name.size() >= suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 && isBad == bad)
            out.push_back(entry.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Compact prefix form of an expression: names for variables and arrays,
// %g for numbers, (op a b) for operators and calls.
std::string dump(const Expr& e, const Body& b) {
    auto args = [&] {
        std::string s;
        for (const auto& a : e.args) s += " " + dump(*a, b);
        return s;
    };
    switch (e.kind) {
        case ExprKind::Number: {
            std::ostringstream os;
            os << e.number;
            return os.str();
        }
        case ExprKind::Variable: return b.variables[static_cast<size_t>(e.slot)].name;
        case ExprKind::ArrayElement:
            return b.arrays[static_cast<size_t>(e.slot)].name + "[" + dump(*e.args[0], b) + "]";
        case ExprKind::ArrayName: return "&" + b.arrays[static_cast<size_t>(e.slot)].name;
        case ExprKind::Unary: {
            const char* op = e.unaryOp == UnaryOp::Plus    ? "pos"
                             : e.unaryOp == UnaryOp::Minus ? "neg"
                             : e.unaryOp == UnaryOp::Tilde ? "~"
                                                           : "not";
            return std::string("(") + op + args() + ")";
        }
        case ExprKind::Binary: {
            static const char* names[] = {"+", "-", "*", "/", "^", "|", "&", "\\",
                                          "=", "/=", "<", "<=", ">", ">=", "and", "or"};
            return std::string("(") + names[static_cast<int>(e.binaryOp)] + args() + ")";
        }
        case ExprKind::BuiltinCall: return "(builtin" + std::to_string(int(e.builtin)) + args() + ")";
        case ExprKind::LibraryCall:
            return std::string("(") + lib::functions()[static_cast<size_t>(e.function)].name +
                   args() + ")";
        case ExprKind::BodyCall: return "(body" + std::to_string(e.function) + args() + ")";
    }
    return "?";
}

// Parses `r = <expr>;` in a body with u, v, w, p, q assigned; returns the
// dump of the expression or the first error.
std::string expr(const std::string& text) {
    std::string src = "my_model(x[3], a[1])\n{\n u = x[1]; v = x[2]; w = x[3]; p = 1; q = 2;\n r = " +
                      text + ";\n my_model = r;\n}\n";
    ParseResult r = parseProgram(src, "expr.hf");
    if (!r.ok()) return "ERROR " + firstError(r);
    const Body& b = r.program->bodies[0];
    return dump(*b.statements.back().value, b);
}

// The condition of `if <cond> then r = 1; endif;`.
std::string cond(const std::string& text) {
    std::string src = "my_model(x[3], a[1])\n{\n u = x[1]; v = x[2]; w = x[3]; p = 1; q = 2; r = 0;\n"
                      " if " + text + " then r = 1; endif;\n my_model = r;\n}\n";
    ParseResult r = parseProgram(src, "cond.hf");
    if (!r.ok()) return "ERROR " + r.errors[0].message;
    const Body& b = r.program->bodies[0];
    return dump(*b.statements.back().condition, b);
}

double number(const std::string& spelling) {
    ParseResult r = parseProgram("m(x[1], a[1]) { m = " + spelling + "; }", "n.hf");
    EXPECT_TRUE(r.ok()) << spelling << ": " << firstError(r);
    if (!r.ok()) return NAN;
    return r.program->bodies[0].result->number;
}

ParseResult parse(const std::string& src) { return parseProgram(src, "t.hf"); }

}  // namespace

// ---------------------------------------------------------------------------
// Shared conformance data

TEST(ParserConformance, GoodFilesParse) {
    ASSERT_TRUE(fs::is_directory(kConformance)) << kConformance;
    auto files = filesIn(kConformance, ".hf", false);
    auto corpus = filesIn(kCorpus, ".hf", false);
    files.insert(files.end(), corpus.begin(), corpus.end());
    EXPECT_GE(files.size(), 38u + 5u);
    for (const auto& f : files) {
        ParseResult r = parseFile(f.string());
        EXPECT_TRUE(r.ok()) << f << ":\n" << firstError(r);
        if (r.ok()) {
            EXPECT_GE(r.program->defaultBody(), 0);
            EXPECT_EQ(r.program->file, f.string());
        }
    }
}

TEST(ParserConformance, BadFilesGiveTheReferenceFirstError) {
    ASSERT_TRUE(fs::is_directory(kConformance)) << kConformance;
    auto files = filesIn(kConformance, ".bad.hf", true);
    EXPECT_EQ(files.size(), 10u);
    for (const auto& f : files) {
        fs::path expected = f;
        expected.replace_extension(".txt");  // NAME.bad.hf -> NAME.bad.txt
        std::ifstream in(expected);
        ASSERT_TRUE(in) << expected;
        std::string message, line;
        int lineNo = -1, pos = -1;
        while (std::getline(in, line)) {
            if (line.rfind("message: ", 0) == 0) message = line.substr(9);
            if (line.rfind("line: ", 0) == 0) lineNo = std::stoi(line.substr(6));
            if (line.rfind("pos: ", 0) == 0) pos = std::stoi(line.substr(5));
        }
        ParseResult r = parseFile(f.string());
        ASSERT_FALSE(r.ok()) << f;
        ASSERT_FALSE(r.errors.empty()) << f;
        const Diagnostic& d = r.errors.front();
        EXPECT_EQ(d.message, message) << f << "\n" << formatDiagnostic(d);
        EXPECT_EQ(d.loc.line, lineNo) << f << "\n" << formatDiagnostic(d);
        EXPECT_EQ(d.loc.column, pos) << f << "\n" << formatDiagnostic(d);
        EXPECT_EQ(d.file, f.string());
    }
}

TEST(ParserConformance, LexicalFileValues) {
    ASSERT_TRUE(fs::is_directory(kConformance)) << kConformance;
    ParseResult r = parseFile((kConformance / "lexical.hf").string());
    ASSERT_TRUE(r.ok()) << firstError(r);
    const Program& p = *r.program;
    ASSERT_EQ(p.bodies.size(), 1u);
    const Body& b = p.bodies[0];
    EXPECT_EQ(b.name, "my_model");
    EXPECT_EQ(b.spelling, "MY_MODEL");
    EXPECT_EQ(p.defaultBody(), 0);
    EXPECT_EQ(p.findBody("My_Model"), 0);
    ASSERT_EQ(b.arrays.size(), 4u);
    EXPECT_EQ(b.arrays[3].name, "centre");
    EXPECT_EQ(b.arrays[3].spelling, "Centre");
    // centre = [.5, 0., -1.25e-1];
    const Stmt& lit = b.statements[0];
    ASSERT_EQ(lit.kind, StmtKind::AssignArray);
    ASSERT_EQ(lit.literal.size(), 3u);
    EXPECT_EQ(lit.literal[0], 0.5);
    EXPECT_EQ(lit.literal[1], 0.0);
    EXPECT_EQ(lit.literal[2], -((1.0 + 2 / 10.0 + 5 / 100.0) * std::exp(-1.0 * std::log(10.0))));
    // Big = 1e3;
    EXPECT_EQ(b.statements[1].value->number, 1000.0000000000007);
    EXPECT_EQ(b.variables[0].name, "big");
    EXPECT_EQ(b.variables[0].spelling, "Big");
}

// ---------------------------------------------------------------------------
// Operator levels

TEST(ParserPrecedence, AdditiveLevelHoldsSetOperators) {
    EXPECT_EQ(expr("u + v | w"), "(| (+ u v) w)");
    EXPECT_EQ(expr("u | v + w"), "(+ (| u v) w)");
    EXPECT_EQ(expr("u * v | w * 2"), "(| (* u v) (* w 2))");
    EXPECT_EQ(expr("u - v & w - 1"), "(- (& (- u v) w) 1)");
    EXPECT_EQ(expr("u \\ v | w & u"), "(& (| (\\ u v) w) u)");
    EXPECT_EQ(expr("u - v - w + 1"), "(+ (- (- u v) w) 1)");
    EXPECT_EQ(expr("u / 0.5 / 4 * v"), "(* (/ (/ u 0.5) 4) v)");
}

TEST(ParserPrecedence, PowerAndUnary) {
    EXPECT_EQ(expr("-u^2"), "(^ (neg u) 2)");
    EXPECT_EQ(expr("u^2^3"), "(^ (^ u 2) 3)");
    EXPECT_EQ(expr("2 ^ -u"), "(^ 2 (neg u))");
    EXPECT_EQ(expr("-2 ^ 2 * 3 + w"), "(+ (* (^ (neg 2) 2) 3) w)");
    EXPECT_EQ(expr("~u ^ 2 + ~v"), "(+ (^ (~ u) 2) (~ v))");
    EXPECT_EQ(expr("- u * v ^ 2"), "(* (neg u) (^ v 2))");
    EXPECT_EQ(expr("u ^ 2 * 3 ^ 2 - - v"), "(- (* (^ u 2) (^ 3 2)) (neg v))");
    EXPECT_EQ(expr("+u"), "(pos u)");
    EXPECT_EQ(expr("- -2"), "(neg (neg 2))");
    EXPECT_EQ(expr("3 - ~2"), "(- 3 (~ 2))");
    EXPECT_EQ(expr("(u + v) * w"), "(* (+ u v) w)");
}

TEST(ParserPrecedence, AtIsIntersectionAndSpellingsAreKept) {
    ParseResult r = parse("m(x[1], a[1]) { p = 1; m = p @ 2 & 3; }");
    ASSERT_TRUE(r.ok()) << firstError(r);
    const Expr& e = *r.program->bodies[0].result;
    ASSERT_EQ(e.kind, ExprKind::Binary);
    EXPECT_EQ(e.binaryOp, BinaryOp::Intersection);
    EXPECT_EQ(e.spelling, "&");
    EXPECT_EQ(e.args[0]->binaryOp, BinaryOp::Intersection);
    EXPECT_EQ(e.args[0]->spelling, "@");
    EXPECT_EQ(e.loc.column, 34);  // the operator
}

TEST(ParserPrecedence, Conditions) {
    EXPECT_EQ(cond("p or q and u > 0"), "(and (or p q) (> u 0))");
    EXPECT_EQ(cond("not x[1] > 0.5"), "(> (not x[1]) 0.5)");
    EXPECT_EQ(cond("not (u < 0 and v < 0)"), "(not (and (< u 0) (< v 0)))");
    EXPECT_EQ(cond("u < v < w"), "(< (< u v) w)");
    EXPECT_EQ(cond("u = v /= w"), "(/= (= u v) w)");
    EXPECT_EQ(cond("u <= 1 and v >= 2"), "(and (<= u 1) (>= v 2))");
    EXPECT_EQ(cond("(u + 1) > 0"), "(> (+ u 1) 0)");
    EXPECT_EQ(cond("not u + 1 > 0"), "(> (not (+ u 1)) 0)");
    EXPECT_EQ(cond("(u + 1) * 2 > 1"), "ERROR Reserved word \"then\" expected");
    EXPECT_EQ(cond("u xor v"), "ERROR Reserved word \"then\" expected");
}

// ---------------------------------------------------------------------------
// Lexical rules

TEST(ParserNumbers, Spellings) {
    EXPECT_EQ(number("1e3"), std::exp(3 * std::log(10.0)));
    EXPECT_EQ(number("1e3"), 1000.0000000000007);
    EXPECT_EQ(number(".5"), 0.5);
    EXPECT_EQ(number("5."), 5.0);
    EXPECT_EQ(number("0"), 0.0);
    EXPECT_EQ(number("0.25"), 0.0 + 2 / 10.0 + 5 / 100.0);
    EXPECT_EQ(number("12.5e+1"), 12.5 * std::exp(1 * std::log(10.0)));
    EXPECT_EQ(number("2.5E-3"), 2.5 * std::exp(-3 * std::log(10.0)));
    EXPECT_EQ(number("5.e2"), 5 * std::exp(2 * std::log(10.0)));
    // Fraction digits are accumulated as d/10 + d/100 + ... as the reference.
    EXPECT_EQ(number("0.123"), 0.0 + 1 / 10.0 + 2 / 100.0 + 3 / 1000.0);
    // The exponent sign applies to its first digit only, as the reference.
    EXPECT_EQ(number("1e-12"), std::exp(-8 * std::log(10.0)));
}

TEST(ParserNumbers, RejectedSpellings) {
    for (const char* bad : {"05", "1e05", "1e0", "2.5e-01", ".", "1e", "1e+"}) {
        ParseResult r = parse(std::string("m(x[1], a[1])\n{\n   k = ") + bad + ";\n   m = k;\n}\n");
        ASSERT_FALSE(r.ok()) << bad;
        EXPECT_EQ(r.errors[0].message, "Expression expected") << bad;
        EXPECT_EQ(r.errors[0].loc.line, 3) << bad;
        EXPECT_EQ(r.errors[0].loc.column, 8) << bad;
        EXPECT_FALSE(r.errors[0].note.empty()) << bad;
    }
}

TEST(ParserLexical, CommentsAndCase) {
    // "--" starts a comment even right after an operator.
    ParseResult r = parse("m(x[1], a[1])\n{\n r = 3--2;\n m = r;\n}\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Semicolon expected");
    EXPECT_EQ(r.errors[0].loc.line, 4);
    EXPECT_EQ(r.errors[0].loc.column, 2);

    r = parse("M(X[1], A[1]) -- comment\n{ ARRAY V[1]; V = [1]; IF x[1] > 0 THEN M1 = V[1]; "
              "ELSE M1 = 2; ENDIF; WHILE 0 LOOP M1 = 1; ENDLOOP; m = M1; }");
    ASSERT_TRUE(r.ok()) << firstError(r);
    EXPECT_EQ(r.program->bodies[0].variables[0].name, "m1");
}

TEST(ParserLexical, LongCommentIsAnIllegalToken) {
    std::string ok = "m(x[1], a[1])\n{\n--" + std::string(256, 'c') + "\n m = 1;\n}\n";
    EXPECT_TRUE(parse(ok).ok());
    std::string bad = "m(x[1], a[1])\n{\n--" + std::string(257, 'c') + "\n m = 1;\n}\n";
    ParseResult r = parse(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Body name expected");
    EXPECT_EQ(r.errors[0].loc.line, 3);
    EXPECT_EQ(r.errors[0].loc.column, 1);
}

TEST(ParserLexical, CarriageReturnAndNul) {
    ParseResult r = parse("m(x[1], a[1])\r\n{ m = 1; }\r\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Left brace expected");
    EXPECT_EQ(r.errors[0].loc.column, 14);
    EXPECT_NE(r.errors[0].note.find("carriage return"), std::string::npos);
    // A NUL byte ends the program.
    std::string src = "m(x[1], a[1]) { m = 1; }";
    src += '\0';
    src += "garbage";
    EXPECT_TRUE(parse(src).ok());
}

TEST(ParserLexical, ReservedNames) {
    EXPECT_EQ(parse("m(x[1], a[1]) { sin = 1; m = 1; }").errors.at(0).message,
              "Body name expected");
    EXPECT_EQ(parse("hfsphere(x[1], a[1]) { hfsphere = 1; }").errors.at(0).message,
              "Body name expected");
    EXPECT_EQ(parse("m(x[1], a[1]) { array x[2]; m = 1; }").errors.at(0).message,
              "Identifier expected");
    EXPECT_EQ(parse("m(x[1], a[1]) { array hfA_Wave[2]; m = 1; }").errors.at(0).message,
              "Identifier expected");
    EXPECT_EQ(parse("m(x[1], a[1]) { xor = 1; m = 1; }").errors.at(0).message,
              "Body name expected");
    EXPECT_EQ(parse("m(x[1], a[1]) { m = x; }").errors.at(0).message, "Left bracket expected");
}

// ---------------------------------------------------------------------------
// Structure of the AST

TEST(ParserAst, BodiesArraysVariablesAndCalls) {
    const char* src =
        "Helper(x[3], a[2], s[2])\n"
        "{\n"
        "   s[1] = x[1]; s = [1, 2];\n"
        "   helper = a[2];\n"
        "}\n"
        "my_model(x[3], a[2])\n"
        "{\n"
        "   array c[3], q[2.5], t[2];\n"
        "   c = [0, -1, +.5];\n"
        "   t[1] = 1; t[2] = 2;\n"
        "   k = helper(x, a, t) + HELPER(c, t, q);\n"
        "   while k < 3 loop k = k + 1; endloop;\n"
        "   if k > 1 then k = sqrt(k); else k = atan2(k, 1); endif;\n"
        "   my_model = hfSphere(x, c, k);\n"
        "}\n";
    ParseResult r = parse(src);
    ASSERT_FALSE(r.ok());  // q has 3 items but helper's s[] has 2
    EXPECT_EQ(r.errors[0].message, "Wrong number of items in array");
    EXPECT_EQ(r.errors[0].loc.line, 11);
    EXPECT_EQ(r.errors[0].loc.column, 39);

    std::string fixed = src;
    fixed.replace(fixed.find("q[2.5]"), 6, "q[2.4]");
    r = parse(fixed);
    ASSERT_TRUE(r.ok()) << firstError(r);
    const Program& p = *r.program;
    ASSERT_EQ(p.bodies.size(), 2u);
    EXPECT_EQ(p.defaultBody(), 1);
    EXPECT_EQ(p.findBody("HELPER"), 0);
    EXPECT_EQ(p.findBody("nothing"), -1);

    const Body& h = p.bodies[0];
    EXPECT_TRUE(h.declaresS);
    EXPECT_EQ(h.xSize(), 3);
    EXPECT_EQ(h.aSize(), 2);
    EXPECT_EQ(h.sSize(), 2);
    ASSERT_EQ(h.statements.size(), 2u);
    EXPECT_EQ(h.statements[0].kind, StmtKind::AssignElement);
    EXPECT_EQ(h.statements[0].slot, kArrayS);
    EXPECT_EQ(h.statements[1].kind, StmtKind::AssignArray);
    EXPECT_EQ(h.statements[1].slot, kArrayS);
    EXPECT_EQ(dump(*h.result, h), "a[2]");
    EXPECT_EQ(h.resultLoc.line, 4);

    const Body& b = p.bodies[1];
    EXPECT_FALSE(b.declaresS);
    EXPECT_EQ(b.sSize(), 1);
    ASSERT_EQ(b.arrays.size(), 6u);
    EXPECT_EQ(b.arrays[3].name, "c");
    EXPECT_EQ(b.arrays[4].size, 2);  // q[2.4] rounds to 2
    EXPECT_EQ(b.arrays[5].size, 2);
    ASSERT_EQ(b.variables.size(), 1u);
    EXPECT_EQ(b.variables[0].name, "k");
    EXPECT_EQ(b.variables[0].loc.line, 11);
    ASSERT_EQ(b.statements.size(), 6u);
    EXPECT_EQ(b.statements[0].literal, (std::vector<double>{0, -1, 0.5}));
    EXPECT_EQ(dump(*b.statements[3].value, b), "(+ (body0 &x &a &t) (body0 &c &t &q))");
    EXPECT_EQ(b.statements[4].kind, StmtKind::While);
    EXPECT_EQ(b.statements[4].thenBody.size(), 1u);
    const Stmt& ifs = b.statements[5];
    EXPECT_EQ(ifs.kind, StmtKind::If);
    ASSERT_EQ(ifs.thenBody.size(), 1u);
    ASSERT_EQ(ifs.elseBody.size(), 1u);
    EXPECT_EQ(ifs.thenBody[0].value->builtin, Builtin::Sqrt);
    EXPECT_EQ(ifs.elseBody[0].value->builtin, Builtin::Atan2);
    EXPECT_EQ(ifs.elseBody[0].value->args.size(), 2u);
    EXPECT_EQ(dump(*b.result, b), "(hfsphere &x &c k)");
    EXPECT_EQ(b.result->spelling, "hfSphere");
}

TEST(ParserAst, BuiltinsMapToTheEnum) {
    const std::vector<std::pair<std::string, Builtin>> cases = {
        {"sqrt(p)", Builtin::Sqrt}, {"exp(p)", Builtin::Exp},     {"log(p)", Builtin::Log},
        {"logd(p)", Builtin::Logd}, {"sin(p)", Builtin::Sin},     {"cos(p)", Builtin::Cos},
        {"tan(p)", Builtin::Tan},   {"asin(p)", Builtin::Asin},   {"acos(p)", Builtin::Acos},
        {"atan(p)", Builtin::Atan}, {"abs(p)", Builtin::Abs},     {"sinh(p)", Builtin::Sinh},
        {"cosh(p)", Builtin::Cosh}, {"tanh(p)", Builtin::Tanh},   {"sign(p)", Builtin::Sign},
        {"ceil(p)", Builtin::Ceil}, {"floor(p)", Builtin::Floor}, {"int(p)", Builtin::Int},
        {"frac(p)", Builtin::Frac}, {"mod(p, q)", Builtin::Mod},  {"max(p, q)", Builtin::Max},
        {"min(p, q)", Builtin::Min}, {"atan2(p, q)", Builtin::Atan2},
    };
    for (const auto& [text, builtin] : cases) {
        ParseResult r = parse("m(x[1], a[1]) { p = 1; q = 2; m = " + text + "; }");
        ASSERT_TRUE(r.ok()) << text << ": " << firstError(r);
        const Expr& e = *r.program->bodies[0].result;
        EXPECT_EQ(e.kind, ExprKind::BuiltinCall) << text;
        EXPECT_EQ(e.builtin, builtin) << text;
        EXPECT_EQ(e.args.size(), text.find(',') == std::string::npos ? 1u : 2u) << text;
    }
    EXPECT_EQ(parse("m(x[1], a[1]) { m = sqr(2); }").errors.at(0).message,
              "Unassigned identificator used in expression");
    EXPECT_EQ(parse("m(x[1], a[1]) { m = max(1); }").errors.at(0).message, "Comma expected");
    EXPECT_EQ(parse("m(x[1], a[1]) { m = sin(1, 2); }").errors.at(0).message,
              "Right parenthes expected");
}

TEST(ParserAst, LibraryTableMatchesTheReference) {
    const auto& ref = hg::frep::syntax::referenceFunctions();
    for (const auto& f : lib::functions()) {
        auto it = std::find_if(ref.begin(), ref.end(),
                               [&](const auto& r) { return r.name == f.name; });
        ASSERT_NE(it, ref.end()) << f.name;
        std::string params;
        for (auto k : f.params) params += k == lib::ParamKind::Array ? 'A' : 'R';
        EXPECT_EQ(params, it->params) << f.name;
    }
}

TEST(ParserAst, VariableExistsInItsOwnFirstAssignment) {
    // As the reference: the name is registered before its right-hand side.
    EXPECT_TRUE(parse("m(x[1], a[1]) { r = r + 1; m = r; }").ok());
    EXPECT_EQ(parse("m(x[1], a[1]) { r = t + 1; t = 1; m = r; }").errors.at(0).message,
              "Unassigned identificator used in expression");
}

// ---------------------------------------------------------------------------
// Errors of the reference and our own

TEST(ParserErrors, BodyCalls) {
    const std::string helper = "h(x[3], a[1]) { h = x[1]; }\n";
    // Calling itself or a later body.
    ParseResult self = parse("h(x[3], a[1]) { h = h(x, a); }");
    ASSERT_FALSE(self.ok());
    EXPECT_EQ(self.errors[0].message, "Unassigned identificator used in expression");
    EXPECT_EQ(self.errors[0].note, "a body cannot call itself");
    ParseResult later = parse("m(x[3], a[1]) { m = h(x, a); }\n" + helper);
    ASSERT_EQ(later.errors.size(), 1u);
    EXPECT_EQ(later.errors[0].message, "Unassigned identificator used in expression");
    EXPECT_NE(later.errors[0].note.find("defined below (line 2)"), std::string::npos);
    // Wrong sizes.
    ParseResult r = parse(helper + "m(x[2], a[1]) { m = h(x, a); }");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Wrong number of items in array");
    EXPECT_EQ(r.errors[0].loc.column, 23);
    // A scalar variable is not an array.
    EXPECT_EQ(parse(helper + "m(x[3], a[1]) { p = 1; m = h(x, p); }").errors.at(0).message,
              "Only array name expected");
    // A number is accepted by the reference but refused here.
    r = parse(helper + "m(x[3], a[1]) { m = h(x, 5); }");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].message.find("array names"), std::string::npos);
    EXPECT_EQ(r.errors[0].loc.column, 26);
    // Without a third argument the callee must have s of size 1.
    r = parse("h(x[3], a[1], s[2]) { h = 1; }\nm(x[3], a[1]) { m = h(x, a); }");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Wrong number of items in array");
    EXPECT_EQ(r.errors[0].loc.column, 27);  // the ')'
    EXPECT_TRUE(parse("h(x[3], a[1], s[2]) { h = 1; }\nm(x[3], a[1], s[2]) { m = h(x, a, s); }")
                    .ok());
    EXPECT_EQ(parse(helper + "h(x[3], a[1]) { h = 1; }").errors.at(0).message,
              "Body name is not unique");
}

TEST(ParserErrors, LibraryCalls) {
    const std::string head = "m(x[3], a[1]) { array c[3]; c = [0, 0, 0]; p = 1;\n";
    ParseResult r = parse(head + "m = hfSphere(x, c);\n}");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Comma expected");
    EXPECT_EQ(r.errors[0].loc.column, 18);
    EXPECT_NE(r.errors[0].note.find("3 arguments"), std::string::npos);
    EXPECT_EQ(parse(head + "m = hfSphere(x, 1, 2);\n}").errors.at(0).message,
              "Error in argument in function call");
    EXPECT_EQ(parse(head + "m = hfSphere(x, p, 2);\n}").errors.at(0).message,
              "Only array name expected");
    EXPECT_EQ(parse(head + "m = hfSphere(x, c, 1, 2);\n}").errors.at(0).message,
              "Right parenthes expected");
    EXPECT_EQ(parse(head + "m = hfSphere x;\n}").errors.at(0).message,
              "Left parenthes expected");
    EXPECT_TRUE(parse(head + "m = hfSphere(x, c, hfSphere(x, c, 1) * 2);\n}").ok());
    r = parse(head + "m = hfBezierVolume(x, 1, 2, 3, c, c);\n}");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].message.find("not supported"), std::string::npos);
    EXPECT_EQ(r.errors[0].loc.column, 5);
    r = parse(head + "m = HFA_WAVE(1, 2, 3, 4) + hfDUni(1, 2, 3, 4);\n}");
    ASSERT_EQ(r.errors.size(), 1u);  // the first ends the statement
    EXPECT_NE(r.errors[0].message.find("HFA_WAVE"), std::string::npos);
}

TEST(ParserErrors, Arrays) {
    auto first = [](const std::string& body) {
        ParseResult r = parse("m(x[3], a[1])\n{\n" + body + "\n}");
        return r.errors.empty() ? std::string("ok") : r.errors[0].message;
    };
    EXPECT_EQ(first("array v[2]; v = [1, 2]; m = v[1];"), "ok");
    EXPECT_EQ(first("array v[2]; v = [1];  m = v[1];"), "Comma expected");
    EXPECT_EQ(first("array v[2]; v = [1, 2, 3];  m = v[1];"), "Right bracket expected");
    EXPECT_EQ(first("array v[2]; v = [1, 2 * 3];  m = v[1];"), "Right bracket expected");
    EXPECT_EQ(first("array v[2]; v = [1, --2];\n m = v[1];"), "Real number expected");
    EXPECT_EQ(first("array v[2]; v = [1, - -2];  m = v[1];"), "Real number expected");
    EXPECT_EQ(first("array v[2]; v = [1, p];  m = v[1];"), "Real number expected");
    EXPECT_EQ(first("array v[2]; v 1;  m = v[1];"), "Left bracket or assign mark expected");
    EXPECT_EQ(first("p = 1; array v[2]; m = p;"), "Body name expected");
    EXPECT_EQ(first("array v[0.4]; m = 1;"), "Array size must be greater zero");
    EXPECT_EQ(first("array v[-1]; m = 1;"), "Real number expected");
    EXPECT_EQ(first("array v[1e10]; m = 1;"), "Array size must be greater zero");
    EXPECT_NE(first("array v[2000000]; m = 1;").find("too large"), std::string::npos);
    EXPECT_NE(first("array v[1000000], w[1000000], u[1000000], z[1000000], y[1000000]; m = 1;")
                  .find("too large"),
              std::string::npos);
    EXPECT_EQ(first("array v[2] m = 1;"), "Semicolon expected");
    EXPECT_EQ(first("x[1] = 1; m = 1;"), "Body name expected");
    EXPECT_EQ(first("s[1] = 1; s = [2]; m = s[1];"), "ok");
    EXPECT_EQ(first("s = [2, 3]; m = s[1];"), "Right bracket expected");
    EXPECT_EQ(first("m = 1; p = 2;"), "Right brace expected");
    EXPECT_EQ(first("m = 1;"), "ok");
    EXPECT_EQ(first("m 1;"), "Assign mark expected");
    // Repeated names keep the first declaration.
    ParseResult r = parse("m(x[1], a[1]) { array v[2], v[3]; v = [1, 2]; m = v[2]; }");
    ASSERT_TRUE(r.ok()) << firstError(r);
    EXPECT_EQ(r.program->bodies[0].arrays.size(), 4u);
}

TEST(ParserErrors, Header) {
    auto first = [](const std::string& src) {
        ParseResult r = parse(src);
        return r.errors.empty() ? std::string("ok") : r.errors[0].message;
    };
    EXPECT_EQ(first("m[x[1], a[1]) { m = 1; }"), "Left parenthes expected");
    EXPECT_EQ(first("m(y[1], a[1]) { m = 1; }"), "\"X\" expected");
    EXPECT_EQ(first("m(x[1]; a[1]) { m = 1; }"), "Comma expected");
    EXPECT_EQ(first("m(x[1], b[1]) { m = 1; }"), "\"A\" expected");
    EXPECT_EQ(first("m(x[1], a[1], t[1]) { m = 1; }"), "\"S\" expected");
    EXPECT_EQ(first("m(x[1], a[1], s[1] { m = 1; }"), "Right parenthes expected");
    EXPECT_EQ(first("m(x[1], a[1]) m = 1; }"), "Left brace expected");
    EXPECT_EQ(first("m(x(1), a[1]) { m = 1; }"), "Left bracket expected");
    EXPECT_EQ(first("m(x[p], a[1]) { m = 1; }"), "Real number expected");
    EXPECT_EQ(first("m(x[1}, a[1]) { m = 1; }"), "Right bracket expected");
    EXPECT_EQ(first("3"), "Body name expected");
    EXPECT_NE(first("").find("no body"), std::string::npos);
    EXPECT_NE(first("-- only a comment\n").find("no body"), std::string::npos);
    EXPECT_NE(first("m(x[5000000], a[1]) { m = 1; }").find("too large"), std::string::npos);
}

TEST(ParserErrors, ControlFlow) {
    auto first = [](const std::string& body) {
        ParseResult r = parse("m(x[3], a[1])\n{\n r = 0;\n" + body + "\n m = r;\n}");
        return r.errors.empty() ? std::string("ok") : r.errors[0].message;
    };
    EXPECT_EQ(first("if r > 0 then r = 1; endif;"), "ok");
    EXPECT_EQ(first("if r > 0 r = 1; endif;"), "Reserved word \"then\" expected");
    EXPECT_EQ(first("if r > 0 then r = 1; endif"), "Semicolon expected");
    EXPECT_EQ(first("if r > 0 then r = 1; else r = 2; m = 3;"),
              "Reserved word \"endif\" expected");
    EXPECT_EQ(first("while r > 0 r = 1; endloop;"), "Reserved word \"loop\" expected");
    EXPECT_EQ(first("while r > 0 loop r = 1; endif;"), "Reserved word \"endloop\" expected");
    EXPECT_EQ(first("if (r > 0 then r = 1; endif;"), "Right parenthes expected");
    EXPECT_EQ(first("r = (1 + 2;"), "Right parenthes expected");
    EXPECT_EQ(first("r = x[1;"), "Right bracket expected");
    EXPECT_EQ(first("r = ;"), "Expression expected");
}

TEST(ParserErrors, SeveralErrorsAreReported) {
    const char* src =
        "m(x[3], a[1])\n"
        "{\n"
        "   p = 1 +;\n"
        "   q = 2;\n"
        "   r = (3;\n"
        "   t = 4;\n"
        "   u = q + v;\n"
        "   m = p;\n"
        "}\n"
        "n(x[3], a[1])\n"
        "{\n"
        "   n = zz;\n"
        "}\n";
    ParseResult r = parse(src);
    ASSERT_FALSE(r.ok());
    EXPECT_FALSE(r.program.has_value());
    ASSERT_GE(r.errors.size(), 3u);
    EXPECT_EQ(r.errors[0].message, "Expression expected");
    EXPECT_EQ(r.errors[0].loc.line, 3);
    EXPECT_EQ(r.errors[0].loc.column, 11);
    // As the reference, recovery skips to the next ';' after the one that
    // ended the bad statement ("q = 2;" is skipped), then goes on.
    EXPECT_EQ(r.errors[1].message, "Right parenthes expected");
    EXPECT_EQ(r.errors[1].loc.line, 5);
    EXPECT_EQ(r.errors[2].message, "Unassigned identificator used in expression");
    EXPECT_EQ(r.errors[2].loc.line, 7);
    EXPECT_EQ(r.errors[2].loc.column, 8);  // q: its assignment was skipped
    // The next body is read too.
    ASSERT_EQ(r.errors.size(), 4u);
    EXPECT_EQ(r.errors[3].loc.line, 12);
}

TEST(ParserErrors, ErrorCountIsCapped) {
    std::string src = "m(x[3], a[1])\n{\n";
    for (int i = 0; i < 500; ++i) src += " p = ;\n q = 1;\n";
    src += " m = 1;\n}\n";
    ParseResult r = parse(src);
    ASSERT_EQ(r.errors.size(), static_cast<size_t>(ParseLimits::kMaxErrors) + 1);
    EXPECT_NE(r.errors.back().message.find("too many errors"), std::string::npos);
}

// ---------------------------------------------------------------------------
// Diagnostics

TEST(ParserDiagnostics, FormatShowsLineAndCaret) {
    ParseResult r = parse("m(x[3], a[1])\n{\n\tr = 1 +\t;\n m = r;\n}\n");
    ASSERT_FALSE(r.ok());
    const Diagnostic& d = r.errors[0];
    EXPECT_EQ(d.loc.line, 3);
    EXPECT_EQ(d.loc.column, 10);
    EXPECT_EQ(d.sourceLine, "\tr = 1 +\t;");
    EXPECT_EQ(formatDiagnostic(d),
              "t.hf:3:10: error: Expression expected\n"
              "    \tr = 1 +\t;\n"
              "    \t       \t^\n");
}

TEST(ParserDiagnostics, NotesAndEndOfFile) {
    ParseResult r = parse("m(x[3], a[1])\n{\n m = 1 # 2;\n}\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Semicolon expected");
    EXPECT_EQ(r.errors[0].note, "unknown character '#'");
    EXPECT_NE(formatDiagnostic(r.errors[0]).find("    note: unknown character '#'\n"),
              std::string::npos);

    r = parse("m(x[3], a[1])\n{\n m = 1;\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "Right brace expected");
    EXPECT_EQ(r.errors[0].loc.line, 4);
    EXPECT_EQ(r.errors[0].loc.column, 1);
    EXPECT_EQ(r.errors[0].sourceLine, "");
}

TEST(ParserDiagnostics, LongLinesAreWindowed) {
    std::string src = "m(x[3], a[1]) { r = 1" + std::string(100000, ' ') + "+ ; m = r; }";
    ParseResult r = parse(src);
    ASSERT_FALSE(r.ok());
    const Diagnostic& d = r.errors[0];
    EXPECT_LT(d.sourceLine.size(), 400u);
    std::string text = formatDiagnostic(d);
    // The caret sits under the ';'.
    size_t lineStart = text.find('\n') + 1;
    size_t caretStart = text.find('\n', lineStart) + 1;
    size_t caret = text.find('^', caretStart) - caretStart;
    EXPECT_EQ(text[lineStart + caret], ';');
}

TEST(ParserDiagnostics, MissingFile) {
    ParseResult r = parseFile("/nonexistent/dir/model.hf");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_FALSE(r.program.has_value());
    EXPECT_EQ(r.errors[0].loc.line, 0);
    EXPECT_NE(r.errors[0].message.find("cannot open"), std::string::npos);
    EXPECT_EQ(formatDiagnostic(r.errors[0]),
              "/nonexistent/dir/model.hf: error: " + r.errors[0].message + "\n");
    r = parseFile("/");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].message.find("directory"), std::string::npos);
}

TEST(ParserDiagnostics, MakeDiagnosticFromLocation) {
    std::string src = "line one\n\tline two\n";
    Diagnostic d = makeDiagnostic("f.hf", src, SourceLoc{2, 3}, "Division by zero");
    EXPECT_EQ(d.sourceLine, "\tline two");
    EXPECT_EQ(formatDiagnostic(d),
              "f.hf:2:3: error: Division by zero\n    \tline two\n    \t ^\n");
}

// ---------------------------------------------------------------------------
// Robustness

TEST(ParserLimits, DeepNestingIsAnError) {
    for (const std::string& open : {std::string("("), std::string("- "), std::string("~"),
                                    std::string("sin("), std::string("x[")}) {
        std::string src = "m(x[3], a[1]) { m = ";
        for (int i = 0; i < 100000; ++i) src += open;
        src += "1; }";
        ParseResult r = parse(src);
        ASSERT_FALSE(r.ok()) << open;
        EXPECT_NE(r.errors[0].message.find("nesting too deep"), std::string::npos) << open;
    }
    std::string src = "m(x[3], a[1]) { r = 0; ";
    for (int i = 0; i < 100000; ++i) src += "if r then ";
    src += "m = 1; }";
    ParseResult r = parse(src);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errors[0].message.find("nesting too deep"), std::string::npos);

    src = "m(x[3], a[1]) { r = 0; if ";
    for (int i = 0; i < 100000; ++i) src += "not (";
    src += "r then r = 1; endif; m = r; }";
    r = parse(src);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errors[0].message.find("nesting too deep"), std::string::npos);

    // Moderate nesting is fine.
    src = "m(x[3], a[1]) { m = " + std::string(200, '(') + "1" + std::string(200, ')') + "; }";
    EXPECT_TRUE(parse(src).ok()) << firstError(parse(src));
}

TEST(ParserLimits, LongOperatorChains) {
    auto chain = [](int n) {
        std::string src = "m(x[3], a[1]) { m = 1";
        for (int i = 0; i < n; ++i) src += "+1";
        return src + "; }";
    };
    EXPECT_TRUE(parse(chain(1500)).ok());
    ParseResult r = parse(chain(100000));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errors[0].message.find("expression too long"), std::string::npos);
}

TEST(ParserLimits, SourceSize) {
    std::string big(ParseLimits::kMaxSourceBytes + 1, ' ');
    ParseResult r = parse(big);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_NE(r.errors[0].message.find("too large"), std::string::npos);
}

TEST(ParserLimits, GarbageDoesNotCrash) {
    // A few hostile inputs; the fuzz target covers many more.
    const char* inputs[] = {
        "", "(", ")", "m(", "m(x[", "m(x[1], a[1]) {", "m(x[1], a[1]) { m = ",
        "m(x[1], a[1]) { if", "m(x[1], a[1]) { array", "\"abc", "\"abc\"",
        "m(x[1], a[1]) { m = \"str\"; }", "m(x[1], a[1]) { m = 0e999 * 1e999; }",
        "m(x[1], a[1], s[0]) { s = [1]; m = 1; }",
        "m(x[0], a[0]) { m = 1; }",
    };
    for (const char* in : inputs) {
        ParseResult r = parse(in);
        if (!r.ok()) {
            EXPECT_FALSE(r.errors.empty()) << in;
        }
        for (const auto& d : r.errors) EXPECT_FALSE(formatDiagnostic(d).empty());
    }
    EXPECT_TRUE(parse("m(x[0], a[0]) { m = 1; }").ok());
    EXPECT_FALSE(parse("m(x[1], a[1], s[0]) { s = [1]; m = 1; }").ok());
}
