// A point whose value is NaN is a runtime error like the others, reported at
// the operation or library call that produced the NaN, on every path: the
// interpreter, the double and float batch evaluators, and a batch where the
// NaN point is not the first.
#include <gtest/gtest.h>

#include <string>

#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/language/interpreter.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"

namespace hg::frep {
namespace {

// Line and column (from 1) of the first occurrence of `what` in `source`.
SourceLoc locOf(const std::string& source, const std::string& what) {
    const size_t at = source.find(what);
    SourceLoc loc{1, 1};
    for (size_t i = 0; i < at; ++i) {
        if (source[i] == '\n') { ++loc.line; loc.column = 1; }
        else ++loc.column;
    }
    return loc;
}

// hfConvArc divides by the point's coordinate along the arc's start
// direction: at the arc's centre its value is 0/0 (on the double path; the
// float kernel is a rewrite without that division).
const std::string kArcSetup =
    "   array cen[3], rad[1], rad2[1], span[1], axis[3], turn[1], w[1];\n"
    "   cen = [0, 0, 0]; rad = [1]; rad2 = [2]; span = [120]; axis = [0, 0, 1]; turn = [30]; w = [3];\n";

struct Located {
    DomainError error = DomainError::None;
    SourceLoc loc;
};

Located interpreterAt(const Program& p, double x, double y, double z) {
    Interpreter interp(p, p.defaultBody());
    PointResult r = interp.evaluate(x, y, z);
    return {r.error, r.loc};
}

// The error a batch evaluator reports for points (px[i], 0, 0), and whether
// point `nanPoint` is the one marked failed.
template <class T>
Located batchAt(const Tape& tape, std::vector<T> px, size_t nanPoint) {
    const size_t n = px.size();
    std::vector<T> py(n, T(0)), pz(n, T(0)), out(n);
    std::vector<std::uint8_t> failed(n);
    ErrorReport errors;
    BatchEvaluator<T> ev(tape);
    ev.evaluate(px.data(), py.data(), pz.data(), out.data(), n, errors, failed.data());
    EXPECT_EQ(errors.count, 1u);
    EXPECT_TRUE(failed[nanPoint]);
    EXPECT_EQ(out[nanPoint], static_cast<T>(kOutsideValue));
    return {errors.first, errors.firstLoc};
}

void expectAt(const Located& got, SourceLoc want, const char* path) {
    EXPECT_EQ(got.error, DomainError::NotANumber) << path;
    EXPECT_EQ(got.loc.line, want.line) << path;
    EXPECT_EQ(got.loc.column, want.column) << path;
}

// Every path, at the point x = (x0, 0, 0), reports NaN at `want` (the float
// batch evaluator too when `floatNan`).
void expectNanAt(const std::string& source, double x0, SourceLoc want, bool floatNan) {
    ParseResult r = parseProgram(source, "t.hf");
    ASSERT_TRUE(r.ok());
    const Program& p = *r.program;
    expectAt(interpreterAt(p, x0, 0, 0), want, "interpreter");
    CompileResult c = compile(p, p.defaultBody());
    ASSERT_TRUE(c.tape) << c.reason;
    expectAt(batchAt<double>(*c.tape, {x0}, 0), want, "double tape");
    if (floatNan) expectAt(batchAt<float>(*c.tape, {static_cast<float>(x0)}, 0), want, "float tape");
    // Points before it evaluate normally; the report still names the call.
    expectAt(batchAt<double>(*c.tape, {x0 - 0.5, x0 - 0.75, x0}, 2), want, "double tape, third point");
}

TEST(NanLocation, LibraryRoutineNamesItsCall) {
    const std::string src = "m(x[3], a[1])\n{\n" + kArcSetup +
                            "   m = 2 * hfConvArc(x, cen, rad, span, axis, turn, w, 0.5);\n}\n";
    expectNanAt(src, 0.0, locOf(src, "hfConvArc"), false);
}

TEST(NanLocation, OperatorNamesItself) {
    // exp overflows to infinity at x = 1, and inf - inf is NaN.
    const std::string src = "m(x[3], a[1])\n{\n   e = exp(1000 * x[1]);\n   m = (e - e) * 2;\n}\n";
    expectNanAt(src, 1.0, locOf(src, "- e"), true);
}

TEST(NanLocation, TheTakenBranchNamesItsCall) {
    // Both branches make a NaN at the centre; the tape computes both and
    // selects one, and the report must name the one the point takes. (The
    // arcs differ: two calls computing the same value share one tape
    // instruction, which carries the first call's location.)
    const std::string src = "m(x[3], a[1])\n{\n" + kArcSetup +
                            "   if x[1] > 0.5 then\n"
                            "      f = hfConvArc(x, cen, rad, span, axis, turn, w, 0.5);\n"
                            "   else\n"
                            "      f = 3 + hfConvArc(x, cen, rad2, span, axis, turn, w, 0.25);\n"
                            "   endif;\n"
                            "   m = f;\n}\n";
    expectNanAt(src, 0.0, locOf(src, "hfConvArc(x, cen, rad2"), false);
}

TEST(NanLocation, NanGivenInParametersIsAtTheBodysAssignment) {
    // No operation made the NaN: it came in with a[1].
    const std::string src = "m(x[3], a[1])\n{\n   t = a[1] + x[1];\n   m = t;\n}\n";
    ParseResult r = parseProgram(src, "t.hf");
    ASSERT_TRUE(r.ok());
    const std::vector<double> a{std::nan("")};
    const SourceLoc want = locOf(src, "m = t");
    Interpreter interp(*r.program, 0, a);
    PointResult p = interp.evaluate(1, 0, 0);
    expectAt({p.error, p.loc}, want, "interpreter");
    CompileResult c = compile(*r.program, 0, a);
    ASSERT_TRUE(c.tape) << c.reason;
    expectAt(batchAt<double>(*c.tape, {1.0}, 0), want, "double tape");
}

TEST(NanLocation, ModelOnTheInterpreterPathCountsItAtTheCall) {
    // A point-dependent loop keeps this body on the interpreter; PointSampler
    // reports the NaN as evaluators do.
    const std::string src = "m(x[3], a[1])\n{\n" + kArcSetup +
                            "   k = 0;\n   while k < x[2] loop k = k + 1; endloop;\n"
                            "   m = k + hfConvArc(x, cen, rad, span, axis, turn, w, 0.5);\n}\n";
    ParseResult r = parseProgram(src, "t.hf");
    ASSERT_TRUE(r.ok());
    auto program = std::make_shared<const Program>(std::move(*r.program));
    Model model(program, 0);
    ASSERT_FALSE(model.compiled());
    PointSampler<double> sampler(model);
    double x = 0, y = 0, z = 0, out = 0;
    ErrorReport errors;
    sampler.evaluate(&x, &y, &z, &out, 1, errors);
    EXPECT_EQ(errors.count, 1u);
    EXPECT_EQ(out, kOutsideValue);
    expectAt({errors.first, errors.firstLoc}, locOf(src, "hfConvArc"), "interpreter sampler");
}

}  // namespace
}  // namespace hg::frep
