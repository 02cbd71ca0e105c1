// Properties of the tape evaluators on every conformance program and
// our own content: interval bounds are sound (dense sampling of random
// boxes), gradients agree with central differences, the compiler reports
// which path a program takes, and no NaN or infinity leaves an evaluator.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "conformance_data.h"
#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_gradient.h"
#include "frep/eval/eval_interval.h"
#include "frep/language/interpreter.h"
#include "frep/language/parser.h"

namespace hg::frep {
namespace {

struct Case {
    std::string name;
    Program program;
    double a1;
};

std::vector<Case> programs() {
    std::vector<Case> out;
    std::vector<std::filesystem::path> files;
    for (const auto& tsv : test::tables()) {
        auto hf = tsv;
        hf.replace_extension(".hf");
        files.push_back(hf);
    }
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(HG_SOURCE_DIR) / "content" / "hyperfun"))
        if (e.path().extension() == ".hf") files.push_back(e.path());
    for (const auto& f : files) {
        ParseResult r = parseFile(f.string());
        if (!r.ok()) continue;
        double a1 = 0.7;
        auto tsv = f;
        tsv.replace_extension(".tsv");
        if (std::filesystem::exists(tsv)) {
            auto rows = test::readTable(tsv);
            if (!rows.empty()) a1 = rows.back().a1;
        }
        out.push_back({f.stem().string(), std::move(*r.program), a1});
    }
    return out;
}

TEST(IntervalEvaluator, BoundsContainEverySampledValue) {
    auto cases = programs();
    ASSERT_FALSE(cases.empty());
    std::mt19937 rng(7);
    int checked = 0;
    for (const Case& c : cases) {
        CompileResult cr = compile(c.program, c.program.defaultBody(), {c.a1});
        if (!cr.tape) continue;
        IntervalEvaluator iv(*cr.tape);
        BatchEvaluator<double> ev(*cr.tape);
        for (int box = 0; box < 60; ++box) {
            double lo[3], size[3];
            const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-3, 0.5)(rng));
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::uniform_real_distribution<double>(-2.0, 2.0)(rng);
                size[k] = scale * std::uniform_real_distribution<double>(0.2, 1.0)(rng);
            }
            double hi[3];
            for (int k = 0; k < 3; ++k) hi[k] = lo[k] + size[k];
            Interval bounds = iv.evaluate(Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2]));
            ASSERT_LE(bounds.lo, bounds.hi) << c.name;
            // 8^3 samples including the faces and corners of the box.
            std::vector<double> x, y, z;
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < 8; ++j)
                    for (int k = 0; k < 8; ++k) {
                        // Stay inside the box even where t * size rounds up.
                        x.push_back(std::min(lo[0] + size[0] * i / 7.0, hi[0]));
                        y.push_back(std::min(lo[1] + size[1] * j / 7.0, hi[1]));
                        z.push_back(std::min(lo[2] + size[2] * k / 7.0, hi[2]));
                    }
            std::vector<double> out(x.size());
            ErrorReport errs;
            ev.evaluate(x.data(), y.data(), z.data(), out.data(), out.size(), errs);
            for (size_t i = 0; i < out.size(); ++i) {
                ASSERT_TRUE(std::isfinite(out[i])) << c.name;
                ASSERT_TRUE(bounds.contains(out[i]))
                    << c.name << ": f(" << x[i] << ", " << y[i] << ", " << z[i] << ") = " << out[i]
                    << " outside [" << bounds.lo << ", " << bounds.hi << "]";
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(IntervalEvaluator, ProvesFarSpaceEmpty) {
    ParseResult r = parseProgram("m(x[3], a[1]) { array c[3]; c = [0, 0, 0]; m = hfSphere(x, c, 1); }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape);
    IntervalEvaluator iv(*c.tape);
    EXPECT_LT(iv.evaluate(Interval(2, 3), Interval(2, 3), Interval(2, 3)).hi, 0.0);
    EXPECT_GT(iv.evaluate(Interval(-0.1, 0.1), Interval(-0.1, 0.1), Interval(-0.1, 0.1)).lo, 0.0);
}

TEST(IntervalEvaluator, ComposedLinearMapsAreBoundedExactly) {
    // A rotation, a shift and the opposite rotation: the value is an affine
    // function of the point. Plain interval arithmetic counts x and y twice
    // in the second rotation and widens the bounds (by 0.42 on each side
    // here).
    ParseResult r = parseProgram(
        "m(x[3], a[1]) { array p[3]; p[1] = x[1]; p[2] = x[2]; p[3] = x[3];"
        " t = hfRotate3DZ(p, 0.5); t = hfShift3D(p, 0.25, 0, 0); t = hfRotate3DZ(p, -0.5);"
        " m = p[1] - 0.25 * cos(0.5); }",
        "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape);
    IntervalEvaluator iv(*c.tape);
    BatchEvaluator<double> ev(*c.tape);
    const double xs[2] = {0.0, 1.0}, ys[2] = {2.0, 3.0};
    double lo = 1e300, hi = -1e300;
    for (double x : xs)
        for (double y : ys) {
            double z = 0.0, f = 0.0;
            ErrorReport errs;
            ev.evaluate(&x, &y, &z, &f, 1, errs);
            lo = std::min(lo, f);
            hi = std::max(hi, f);
        }
    const Interval b = iv.evaluate(Interval(0, 1), Interval(2, 3), Interval(0, 0));
    // An affine function takes its range at the box's corners.
    EXPECT_NEAR(b.lo, lo, 1e-9);
    EXPECT_NEAR(b.hi, hi, 1e-9);
}

TEST(GradientEvaluator, MatchesCentralDifferences) {
    auto cases = programs();
    std::mt19937 rng(11);
    int checked = 0;
    for (const Case& c : cases) {
        CompileResult cr = compile(c.program, c.program.defaultBody(), {c.a1});
        if (!cr.tape) continue;
        GradientEvaluator grad(*cr.tape);
        Interpreter interp(c.program, c.program.defaultBody(), {c.a1});
        for (int n = 0; n < 40; ++n) {
            double p[3];
            for (double& v : p) v = std::uniform_real_distribution<double>(-1.5, 1.5)(rng);
            ErrorReport errs;
            Gradient g = grad.evaluate(p[0], p[1], p[2], errs);
            const double h = 1e-6;
            double d[3];
            bool smooth = errs.count == 0;
            for (int k = 0; k < 3 && smooth; ++k) {
                double q1[3] = {p[0], p[1], p[2]}, q2[3] = {p[0], p[1], p[2]};
                q1[k] += h;
                q2[k] -= h;
                PointResult f1 = interp.evaluate(q1[0], q1[1], q1[2]);
                PointResult f2 = interp.evaluate(q2[0], q2[1], q2[2]);
                smooth = f1.ok() && f2.ok();
                d[k] = (f1.value - f2.value) / (2 * h);
            }
            if (!smooth) continue;
            const double gk[3] = {g.dx, g.dy, g.dz};
            // Kinks (selects, abs, min/max, R-functions at f = g = 0) make the
            // difference quotient jump; compare only where it is consistent.
            for (int k = 0; k < 3; ++k) {
                double tol = 1e-4 * std::max(1.0, std::fabs(d[k]));
                if (std::fabs(gk[k] - d[k]) > tol) {
                    double q1[3] = {p[0], p[1], p[2]};
                    q1[k] += 2 * h;
                    double again = (interp.evaluate(q1[0], q1[1], q1[2]).value - interp.evaluate(p[0], p[1], p[2]).value) / (2 * h);
                    if (std::fabs(again - d[k]) > tol) continue;  // kink
                }
                EXPECT_NEAR(gk[k], d[k], tol) << c.name << " d/d" << "xyz"[k] << " at " << p[0] << "," << p[1] << "," << p[2];
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(Compiler, ReportsWhyAProgramRunsOnTheInterpreter) {
    ParseResult r = parseProgram(
        "m(x[3], a[1]) { k = 0; while k < x[1] loop k = k + 1; endloop; m = k; }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    EXPECT_FALSE(c.tape);
    EXPECT_NE(c.reason.find("while condition depends on the point"), std::string::npos);
    EXPECT_EQ(c.reasonLoc.line, 1);
}

TEST(Compiler, UnrollsConstantLoopsAndFoldsParameters) {
    ParseResult r = parseProgram(
        "m(x[3], a[1]) { k = 0; t = 0; while k < a[1] loop k = k + 1; t = t + x[1] * k; endloop; m = t; }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0, {4});
    ASSERT_TRUE(c.tape) << c.reason;
    BatchEvaluator<double> ev(*c.tape);
    double x = 2, y = 0, z = 0, out = 0;
    ErrorReport errs;
    ev.evaluate(&x, &y, &z, &out, 1, errs);
    EXPECT_EQ(out, 2.0 * 1 + 2.0 * 2 + 2.0 * 3 + 2.0 * 4);
}

TEST(Compiler, PointDependentIfBecomesSelectWithGuardedErrors) {
    // sqrt(x) only runs where x > 0: no error at negative x.
    ParseResult r = parseProgram(
        "m(x[3], a[1]) { r = 0; if x[1] > 0 then r = sqrt(x[1]); endif; m = r; }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape) << c.reason;
    BatchEvaluator<double> ev(*c.tape);
    double x[2] = {-4, 4}, y[2] = {0, 0}, z[2] = {0, 0}, out[2];
    std::uint8_t failed[2];
    ErrorReport errs;
    ev.evaluate(x, y, z, out, 2, errs, failed);
    EXPECT_EQ(errs.count, 0u);
    EXPECT_EQ(out[0], 0.0);
    EXPECT_EQ(out[1], 2.0);
}

TEST(BatchEvaluator, DomainErrorsAreCountedLocatedAndOutside) {
    ParseResult r = parseProgram("m(x[3], a[1])\n{\n   m = 1 / x[1];\n}\n", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape);
    BatchEvaluator<float> ev(*c.tape);
    float x[3] = {0.0f, 2.0f, 0.0f}, y[3] = {}, z[3] = {}, out[3];
    ErrorReport errs;
    ev.evaluate(x, y, z, out, 3, errs);
    EXPECT_EQ(errs.count, 2u);
    EXPECT_EQ(errs.first, DomainError::DivisionByZero);
    EXPECT_EQ(errs.firstLoc.line, 3);
    EXPECT_EQ(out[0], static_cast<float>(kOutsideValue));
    EXPECT_EQ(out[1], 0.5f);
}

TEST(BatchEvaluator, InfinityIsClampedNeverReturned) {
    ParseResult r = parseProgram("m(x[3], a[1]) { m = exp(x[1]); }", "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult c = compile(*r.program, 0);
    ASSERT_TRUE(c.tape);
    BatchEvaluator<float> ev(*c.tape);
    float x = 1000.0f, y = 0, z = 0, out = 0;
    ErrorReport errs;
    ev.evaluate(&x, &y, &z, &out, 1, errs);
    EXPECT_TRUE(std::isfinite(out));
    EXPECT_GT(out, 1e29f);
}

}  // namespace
}  // namespace hg::frep
