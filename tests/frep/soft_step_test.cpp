// The fused step of hfSoft's sum (Op::SoftStep): which calls compile to it,
// the double path bit for bit with the interpreter (which runs the library
// routine itself) and the float path close to it, interval bounds sound on
// boxes across the balls' reach (where the kernel cancels to 0) yet tight
// enough to prove most boxes there, and gradients against differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_gradient.h"
#include "frep/eval/eval_interval.h"
#include "frep/language/interpreter.h"
#include "frep/language/parser.h"
#include "kernel_checks.h"

namespace hg::frep {
namespace {

// Three overlapping balls of different reach around (0.1, 0.2, -0.1).
constexpr const char* kSoft =
    "m(x[3], a[1]) { array cx[3], cy[3], cz[3], d[3];"
    " cx = [0.1, 0.5, -0.2]; cy = [0.2, 0.3, 0.1]; cz = [-0.1, 0.0, 0.2]; d = [0.6, 0.35, 0.45];"
    " m = hfSoft(x, cx, cy, cz, d, 0.3); }";

Program parse(const char* text) {
    ParseResult r = parseProgram(text, "soft.hf");
    EXPECT_TRUE(r.ok());
    return std::move(*r.program);
}

int countOps(const Tape& t, Op op) {
    int n = 0;
    for (const Instr& in : t.code) n += in.op == op;
    return n;
}

// Points in the cube [-0.8, 1.0]^3, which holds every ball's reach.
std::vector<double> samplePoints(std::mt19937& rng, size_t n) {
    std::uniform_real_distribution<double> u(-0.8, 1.0);
    std::vector<double> p(3 * n);
    for (double& v : p) v = u(rng);
    return p;
}

TEST(SoftStep, OneKernelPerBallWithConstantRadius) {
    CompileResult cr = compile(parse(kSoft), 0);
    ASSERT_TRUE(cr.tape) << cr.reason;
    EXPECT_EQ(countOps(*cr.tape, Op::SoftStep), 3);
    // A radius that depends on the point keeps the generic expansion.
    CompileResult generic = compile(parse("m(x[3], a[1]) { array cx[1], cy[1], cz[1], d[1];"
                                          " cx = [0]; cy = [0]; cz = [0]; d[1] = 0.5 + 0.1 * x[1];"
                                          " m = hfSoft(x, cx, cy, cz, d, 0.3); }"),
                                    0);
    ASSERT_TRUE(generic.tape);
    EXPECT_EQ(countOps(*generic.tape, Op::SoftStep), 0);
}

TEST(SoftStep, DoublePathIsBitExactFloatPathClose) {
    Program p = parse(kSoft);
    CompileResult cr = compile(p, 0);
    ASSERT_TRUE(cr.tape);
    std::mt19937 rng(3);
    const size_t n = 4000;
    std::vector<double> pts = samplePoints(rng, n);
    std::vector<double> x(n), y(n), z(n), out(n);
    std::vector<float> xf(n), yf(n), zf(n), outf(n);
    for (size_t i = 0; i < n; ++i) {
        xf[i] = static_cast<float>(pts[3 * i]); yf[i] = static_cast<float>(pts[3 * i + 1]);
        zf[i] = static_cast<float>(pts[3 * i + 2]);
        x[i] = xf[i]; y[i] = yf[i]; z[i] = zf[i];
    }
    ErrorReport errs, errsf;
    BatchEvaluator<double>(*cr.tape).evaluate(x.data(), y.data(), z.data(), out.data(), n, errs);
    BatchEvaluator<float>(*cr.tape).evaluate(xf.data(), yf.data(), zf.data(), outf.data(), n, errsf);
    Interpreter interp(p, 0, {});
    for (size_t i = 0; i < n; ++i) {
        PointResult r = interp.evaluate(x[i], y[i], z[i]);
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(std::memcmp(&r.value, &out[i], sizeof(double)), 0)
            << "at " << x[i] << ", " << y[i] << ", " << z[i] << ": " << r.value << " vs " << out[i];
        EXPECT_NEAR(outf[i], r.value, 2e-6 * std::max(1.0, std::fabs(r.value)));
    }
}

TEST(SoftStep, BoundsAreSoundAcrossTheReachAndProveMostBoxes) {
    CompileResult cr = compile(parse(kSoft), 0);
    ASSERT_TRUE(cr.tape);
    IntervalEvaluator iv(*cr.tape);
    BatchEvaluator<double> ev(*cr.tape);
    BatchEvaluator<float> evf(*cr.tape);
    std::mt19937 rng(5);
    int proven = 0;
    const int boxes = 600;
    for (int b = 0; b < boxes; ++b) {
        const double size = std::pow(10.0, std::uniform_real_distribution<double>(-4.0, -1.3)(rng));
        std::vector<double> lo = samplePoints(rng, 1);
        Interval bounds = iv.evaluate(Interval(lo[0], lo[0] + size), Interval(lo[1], lo[1] + size),
                                      Interval(lo[2], lo[2] + size));
        proven += bounds.lo > 0.0 || bounds.hi < 0.0;
        const test::BoxSamples p = test::floatPointsInBox(lo.data(), size);
        const std::vector<double>& x = p.x;
        const std::vector<double>& y = p.y;
        const std::vector<double>& z = p.z;
        std::vector<double> out(x.size());
        std::vector<float> outf(x.size());
        ErrorReport errs;
        ev.evaluate(x.data(), y.data(), z.data(), out.data(), out.size(), errs);
        evf.evaluate(p.xf.data(), p.yf.data(), p.zf.data(), outf.data(), outf.size(), errs);
        for (size_t i = 0; i < out.size(); ++i) {
            ASSERT_TRUE(bounds.contains(out[i]))
                << "f(" << x[i] << ", " << y[i] << ", " << z[i] << ") = " << out[i] << " outside [" << bounds.lo
                << ", " << bounds.hi << "]";
            ASSERT_TRUE(bounds.contains(outf[i]))
                << "float f(" << x[i] << ", " << y[i] << ", " << z[i] << ") = " << outf[i] << " outside ["
                << bounds.lo << ", " << bounds.hi << "]";
        }
    }
    // Boxes up to 5 cm, mostly away from the surface (the next test takes
    // boxes near it).
    EXPECT_GT(proven, boxes * 9 / 10);
}

// The same balls with radii the compiler cannot see as constants (0 * x[1]
// is not folded away), so hfSoft keeps its generic expansion.
constexpr const char* kSoftGeneric =
    "m(x[3], a[1]) { array cx[3], cy[3], cz[3], d[3];"
    " cx = [0.1, 0.5, -0.2]; cy = [0.2, 0.3, 0.1]; cz = [-0.1, 0.0, 0.2];"
    " d[1] = 0.6 + 0 * x[1]; d[2] = 0.35 + 0 * x[1]; d[3] = 0.45 + 0 * x[1];"
    " m = hfSoft(x, cx, cy, cz, d, 0.3); }";

TEST(SoftStep, ProvesMoreBoxesNearTheSurfaceThanTheGenericExpansion) {
    CompileResult fused = compile(parse(kSoft), 0);
    CompileResult generic = compile(parse(kSoftGeneric), 0);
    ASSERT_TRUE(fused.tape);
    ASSERT_TRUE(generic.tape);
    ASSERT_EQ(countOps(*generic.tape, Op::SoftStep), 0);
    IntervalEvaluator fusedBounds(*fused.tape), genericBounds(*generic.tape);
    BatchEvaluator<double> ev(*fused.tape);
    std::mt19937 rng(21);
    int boxes = 0, provenFused = 0, provenGeneric = 0;
    const double half = 0.01;  // 2 cm boxes
    while (boxes < 400) {
        std::vector<double> c = samplePoints(rng, 1);
        double f = 0.0;
        ErrorReport errs;
        ev.evaluate(&c[0], &c[1], &c[2], &f, 1, errs);
        // Centres 2-5 box widths' worth of field from the surface.
        if (std::fabs(f) < 0.06 || std::fabs(f) > 0.15) continue;
        ++boxes;
        const Interval x(c[0] - half, c[0] + half), y(c[1] - half, c[1] + half), z(c[2] - half, c[2] + half);
        const Interval a = fusedBounds.evaluate(x, y, z), b = genericBounds.evaluate(x, y, z);
        provenFused += a.lo > 0.0 || a.hi < 0.0;
        provenGeneric += b.lo > 0.0 || b.hi < 0.0;
    }
    std::printf("boxes near the surface proven: fused %d, generic %d of %d\n", provenFused, provenGeneric, boxes);
    EXPECT_GT(provenFused, boxes * 9 / 10);
    EXPECT_GT(provenFused, provenGeneric + boxes / 5);
}

TEST(SoftStep, GradientMatchesDifferences) {
    Program p = parse(kSoft);
    CompileResult cr = compile(p, 0);
    ASSERT_TRUE(cr.tape);
    GradientEvaluator grad(*cr.tape);
    Interpreter interp(p, 0, {});
    std::mt19937 rng(9);
    int checked = 0;
    for (int n = 0; n < 300; ++n)
        checked += test::expectGradientMatchesDifferences(grad, interp, samplePoints(rng, 1), "soft");
    EXPECT_EQ(checked, 900);
}

}  // namespace
}  // namespace hg::frep
