// The fused convolution kernels of the tape (Op::ConvArc, Op::ConvSegment)
// on arcs chosen to cover their cases: which calls compile to them, the
// double path bit for bit with the interpreter, the float path close to it,
// interval bounds sound on small boxes around the skeleton (which the random
// boxes of evaluators_test rarely hit) yet tight enough to prove boxes, and
// gradients against differences; and the float loops' two builds (baseline
// and AVX2) agree bit for bit.
#include <gtest/gtest.h>

#include <cmath>
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
#include "frep/kernels/simd.h"
#include "kernel_checks.h"

namespace hg::frep {
namespace {

struct ArcCase {
    const char* name;
    const char* arrays;  // cen, rad, span, axis, turn, w
    int pieces;          // fused kernels expected on the tape
    double centre[3];
    double reach;        // half-size of the cube the tests sample
};

// Threshold 0.1, so that the surface runs through the sampled cubes.
const ArcCase kArcs[] = {
    {"flat", "cen = [0, 0, 0]; rad = [1]; span = [120]; axis = [0, 0, 1]; turn = [30]; w = [3];", 1, {0, 0, 0}, 1.5},
    {"beyond_half_turn", "cen = [0.5, 0.5, 0.3]; rad = [0.6]; span = [270]; axis = [1, 0, 0]; turn = [0]; w = [4];",
     2, {0.5, 0.5, 0.3}, 1.0},
    {"tilted", "cen = [-0.4, 0.2, -0.3]; rad = [0.8]; span = [90]; axis = [0.3, 0.5, 0.8]; turn = [45]; w = [2.5];",
     1, {-0.4, 0.2, -0.3}, 1.3},
    {"full_circle", "cen = [0, 0, 0]; rad = [0.38]; span = [400]; axis = [0, 1, 0]; turn = [10]; w = [8];", 2,
     {0, 0, 0}, 0.7},
    {"thin_sweep", "cen = [0.2, 1.85, 0]; rad = [0.38]; span = [150]; axis = [0, 0, 1]; turn = [0]; w = [14];", 1,
     {0.2, 1.85, 0}, 0.6},
    // Axis of length below EPS: the rotation degenerates to cos(angle) I.
    {"no_axis", "cen = [0, 0, 0]; rad = [1]; span = [200]; axis = [-1e-6, -1e-6, -1e-6]; turn = [60]; w = [-3];",
     2, {0, 0, 0}, 1.5},
};

Program parseArc(const ArcCase& c) {
    std::string text = std::string("m(x[3], a[1]) { array cen[3], rad[1], span[1], axis[3], turn[1], w[1];\n") +
                       c.arrays + "\n m = hfConvArc(x, cen, rad, span, axis, turn, w, 0.1); }";
    ParseResult r = parseProgram(text, std::string(c.name) + ".hf");
    EXPECT_TRUE(r.ok()) << c.name;
    return std::move(*r.program);
}

int countOps(const Tape& t, Op op) {
    int n = 0;
    for (const Instr& in : t.code) n += in.op == op;
    return n;
}

std::vector<double> samplePoints(const ArcCase& c, std::mt19937& rng, size_t n) {
    std::uniform_real_distribution<double> u(-c.reach, c.reach);
    std::vector<double> p;
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) p.push_back(c.centre[k] + u(rng));
    return p;
}

TEST(FusedArc, OneKernelPerPieceWithConstantParameters) {
    for (const ArcCase& c : kArcs) {
        Program p = parseArc(c);
        CompileResult cr = compile(p, 0);
        ASSERT_TRUE(cr.tape) << c.name << ": " << cr.reason;
        EXPECT_EQ(countOps(*cr.tape, Op::ConvArc), c.pieces) << c.name;
        EXPECT_LT(cr.tape->size(), 30u) << c.name << "\n" << cr.tape->dump();
    }
    // A span that depends on the point keeps the generic expansion.
    ParseResult r = parseProgram(
        "m(x[3], a[1]) { array cen[3], rad[1], span[1], axis[3], turn[1], w[1]; cen = [0, 0, 0]; rad = [1];"
        " span[1] = 100 + x[1]; axis = [0, 0, 1]; turn = [0]; w = [3];"
        " m = hfConvArc(x, cen, rad, span, axis, turn, w, 0.1); }",
        "t.hf");
    ASSERT_TRUE(r.ok());
    CompileResult cr = compile(*r.program, 0);
    ASSERT_TRUE(cr.tape);
    EXPECT_EQ(countOps(*cr.tape, Op::ConvArc), 0);
}

TEST(FusedArc, DoublePathIsBitExactFloatPathClose) {
    std::mt19937 rng(3);
    for (const ArcCase& c : kArcs) {
        Program p = parseArc(c);
        CompileResult cr = compile(p, 0);
        ASSERT_TRUE(cr.tape);
        const size_t n = 2000;
        std::vector<double> pts = samplePoints(c, rng, n);
        std::vector<double> x(n), y(n), z(n), out(n);
        std::vector<float> xf(n), yf(n), zf(n), outf(n);
        for (size_t i = 0; i < n; ++i) {
            x[i] = pts[3 * i]; y[i] = pts[3 * i + 1]; z[i] = pts[3 * i + 2];
            // The float path gets the same points.
            xf[i] = static_cast<float>(x[i]); yf[i] = static_cast<float>(y[i]); zf[i] = static_cast<float>(z[i]);
            x[i] = xf[i]; y[i] = yf[i]; z[i] = zf[i];
        }
        std::vector<std::uint8_t> failed(n);
        ErrorReport errs, errsf;
        BatchEvaluator<double>(*cr.tape).evaluate(x.data(), y.data(), z.data(), out.data(), n, errs, failed.data());
        BatchEvaluator<float>(*cr.tape).evaluate(xf.data(), yf.data(), zf.data(), outf.data(), n, errsf);
        Interpreter interp(p, 0, {});
        for (size_t i = 0; i < n; ++i) {
            PointResult r = interp.evaluate(x[i], y[i], z[i]);
            ASSERT_EQ(r.ok(), !failed[i]) << c.name;
            if (!r.ok()) continue;
            ASSERT_EQ(std::memcmp(&r.value, &out[i], sizeof(double)), 0)
                << c.name << " at " << x[i] << ", " << y[i] << ", " << z[i] << ": " << r.value << " vs " << out[i];
            EXPECT_NEAR(outf[i], r.value, 2e-5 * std::max(1.0, std::fabs(r.value))) << c.name;
        }
    }
}

TEST(FusedArc, BoundsAreSoundOnSmallBoxesAndProveSome) {
    std::mt19937 rng(5);
    for (const ArcCase& c : kArcs) {
        Program p = parseArc(c);
        CompileResult cr = compile(p, 0);
        ASSERT_TRUE(cr.tape);
        IntervalEvaluator iv(*cr.tape);
        BatchEvaluator<double> ev(*cr.tape);
        int proven = 0;
        const int boxes = 400;
        for (int b = 0; b < boxes; ++b) {
            const double size = c.reach * std::pow(10.0, std::uniform_real_distribution<double>(-4.0, -0.3)(rng));
            std::vector<double> lo = samplePoints(c, rng, 1);
            Interval bounds = iv.evaluate(Interval(lo[0], lo[0] + size), Interval(lo[1], lo[1] + size),
                                          Interval(lo[2], lo[2] + size));
            proven += bounds.lo > 0.0 || bounds.hi < 0.0;
            std::vector<double> x, y, z;
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < 8; ++j)
                    for (int k = 0; k < 8; ++k) {
                        x.push_back(std::min(lo[0] + size * i / 7.0, lo[0] + size));
                        y.push_back(std::min(lo[1] + size * j / 7.0, lo[1] + size));
                        z.push_back(std::min(lo[2] + size * k / 7.0, lo[2] + size));
                    }
            std::vector<double> out(x.size());
            ErrorReport errs;
            ev.evaluate(x.data(), y.data(), z.data(), out.data(), out.size(), errs);
            for (size_t i = 0; i < out.size(); ++i)
                ASSERT_TRUE(bounds.contains(out[i])) << c.name << ": f(" << x[i] << ", " << y[i] << ", " << z[i]
                                                     << ") = " << out[i] << " outside [" << bounds.lo << ", "
                                                     << bounds.hi << "]";
        }
        EXPECT_GT(proven, boxes / 2) << c.name;
    }
}

TEST(FusedArc, ProvesFarSpaceEmptyAndTheCoreFull) {
    Program p = parseArc(kArcs[0]);  // radius 1 about the origin, from 30 to 150 degrees
    CompileResult cr = compile(p, 0);
    ASSERT_TRUE(cr.tape);
    IntervalEvaluator iv(*cr.tape);
    EXPECT_LT(iv.evaluate(Interval(2, 3), Interval(2, 3), Interval(2, 3)).hi, 0.0);
    EXPECT_LT(iv.evaluate(Interval(-0.2, 0.2), Interval(-1.5, -0.9), Interval(-0.2, 0.2)).hi, 0.0);
    // Around the point at 90 degrees.
    EXPECT_GT(iv.evaluate(Interval(-0.02, 0.02), Interval(0.98, 1.02), Interval(-0.02, 0.02)).lo, 0.0);
}

TEST(FusedArc, GradientMatchesDifferences) {
    std::mt19937 rng(9);
    int checked = 0;
    for (const ArcCase& c : kArcs) {
        Program p = parseArc(c);
        CompileResult cr = compile(p, 0);
        ASSERT_TRUE(cr.tape);
        GradientEvaluator grad(*cr.tape);
        Interpreter interp(p, 0, {});
        for (int n = 0; n < 50; ++n)
            checked += test::expectGradientMatchesDifferences(grad, interp, samplePoints(c, rng, 1), c.name);
    }
    EXPECT_GT(checked, 600);
}

TEST(FusedKernels, BaselineAndAvx2BuildsAgreeBitForBit) {
    if (!simd::avx2()) GTEST_SKIP() << "no AVX2 build or processor here";
    std::vector<Program> programs;
    for (const ArcCase& c : kArcs) programs.push_back(parseArc(c));
    ParseResult dancer = parseFile(std::string(HG_SOURCE_DIR) + "/content/hyperfun/dancer.hf");
    ASSERT_TRUE(dancer.ok());
    programs.push_back(std::move(*dancer.program));
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> u(-2.0f, 2.5f);
    const size_t n = 1000;  // not a multiple of either vector width
    std::vector<float> x(n), y(n), z(n), wide(n), narrow(n);
    for (size_t i = 0; i < n; ++i) { x[i] = u(rng); y[i] = u(rng); z[i] = u(rng); }
    for (const Program& p : programs) {
        CompileResult cr = compile(p, p.defaultBody(), {0.4});
        ASSERT_TRUE(cr.tape);
        ErrorReport errs;
        BatchEvaluator<float> ev(*cr.tape);
        ev.evaluate(x.data(), y.data(), z.data(), wide.data(), n, errs);
        simd::baselineOnly() = true;
        ev.evaluate(x.data(), y.data(), z.data(), narrow.data(), n, errs);
        simd::baselineOnly() = false;
        EXPECT_EQ(std::memcmp(wide.data(), narrow.data(), n * sizeof(float)), 0);
    }
}

}  // namespace
}  // namespace hg::frep
