// Values beyond +-kValueLimit: the interpreter gives them as computed (as
// the reference does), and so does the double batch evaluator when asked
// (`hypergarden eval` prints them); sampling keeps the clamp by default.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/language/interpreter.h"
#include "frep/language/parser.h"

namespace hg::frep {
namespace {

// 150 R-function differences: outside the solid each one about doubles
// |f| and adds the terms' size, so the value runs far past 1e30 (the
// reference reads -7.6875879034757266e+45 at (5, 5, 5)).
Program differenceChain() {
    std::string src = "m(x[3], a[1])\n{\n   f = x[1];\n";
    for (int i = 0; i < 150; ++i) src += "   f = f \\ (x[2] - " + std::to_string(i % 7) + ");\n";
    src += "   m = f;\n}\n";
    ParseResult r = parseProgram(src, "chain.hf");
    EXPECT_TRUE(r.ok());
    return std::move(*r.program);
}

TEST(ValueRange, InterpreterKeepsValuesBeyondTheLimit) {
    Program p = differenceChain();
    Interpreter interp(p, 0);
    PointResult r = interp.evaluate(5, 5, 5);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.value, -7.6875879034757266e+45);
    // The evaluator contract used by sampling clamps.
    ErrorReport errors;
    EXPECT_EQ(interp.evaluateSafe(5, 5, 5, errors), -kValueLimit);
    EXPECT_EQ(errors.count, 0u);
}

TEST(ValueRange, DoubleBatchKeepsTheInterpretersValueWhenUnclamped) {
    Program p = differenceChain();
    CompileResult c = compile(p, 0);
    ASSERT_TRUE(c.tape) << c.reason;
    double x[3] = {5, -5, -3}, y[3] = {5, 3, -2}, z[3] = {5, 1, 0};
    double clamped[3], kept[3];
    ErrorReport errors;
    BatchEvaluator<double> ev(*c.tape);
    ev.evaluate(x, y, z, clamped, 3, errors);
    ev.setClamped(false);
    ev.evaluate(x, y, z, kept, 3, errors);
    EXPECT_EQ(errors.count, 0u);
    Interpreter interp(p, 0);
    for (int i = 0; i < 3; ++i) {
        const double want = interp.evaluate(x[i], y[i], z[i]).value;
        ASSERT_LT(want, -kValueLimit);
        EXPECT_EQ(kept[i], want) << "point " << i;
        EXPECT_EQ(clamped[i], -kValueLimit) << "point " << i;
    }
}

TEST(ValueRange, InfinityIsKeptUnclampedAndClampedOtherwise) {
    ParseResult r = parseProgram("m(x[3], a[1]) { m = -exp(1000 * x[1]); }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape) << c.reason;
    double x = 1, y = 0, z = 0, out = 0;
    ErrorReport errors;
    BatchEvaluator<double> ev(*c.tape);
    ev.evaluate(&x, &y, &z, &out, 1, errors);
    EXPECT_EQ(out, -kValueLimit);
    ev.setClamped(false);
    ev.evaluate(&x, &y, &z, &out, 1, errors);
    EXPECT_EQ(out, -std::numeric_limits<double>::infinity());
    EXPECT_EQ(errors.count, 0u);
    EXPECT_EQ(Interpreter(*r.program, 0).evaluate(x, y, z).value, out);
    // The float sampling path clamps.
    float xf = 1, yf = 0, zf = 0, outf = 0;
    BatchEvaluator<float>(*c.tape).evaluate(&xf, &yf, &zf, &outf, 1, errors);
    EXPECT_EQ(outf, static_cast<float>(-kValueLimit));
}

}  // namespace
}  // namespace hg::frep
