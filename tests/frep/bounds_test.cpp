// The model box estimate (frep/eval/bounds.h): it must contain the solid, close
// in on it to within a couple of its cells, and tell empty and unbounded
// solids apart. Solids with known boxes, placed off the origin and off the
// search cube's split planes so nothing lines up by luck.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "frep/eval/bounds.h"
#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/language/parser.h"

namespace hg::frep {
namespace {

struct Shape {
    const char* name;
    const char* source;
    Box3 exact;  // the solid's own bounding box
};

Box3 makeBox(double x0, double y0, double z0, double x1, double y1, double z1) {
    Box3 b;
    b.lo[0] = x0; b.lo[1] = y0; b.lo[2] = z0;
    b.hi[0] = x1; b.hi[1] = y1; b.hi[2] = z1;
    return b;
}

const Shape kShapes[] = {
    {"sphere", "m(x[3], a[1]) { m = 0.49 - ((x[1] - 0.3)^2 + (x[2] + 1.1)^2 + (x[3] - 0.05)^2); }",
     makeBox(-0.4, -1.8, -0.65, 1.0, -0.4, 0.75)},
    // A sphere and an ellipsoid far apart: the box spans both.
    {"two_parts",
     "m(x[3], a[1]) { ball = 0.04 - ((x[1] + 2)^2 + x[2]^2 + x[3]^2); "
     "egg = 1 - ((x[1] - 1)^2 / 0.25 + (x[2] - 0.5)^2 / 2.25 + x[3]^2 / 0.09); m = ball | egg; }",
     makeBox(-2.2, -1.0, -0.3, 1.5, 2.0, 0.3)},
    // A flat slab: thin along y, where most boxes near the surface would
    // otherwise be refined.
    {"slab", "m(x[3], a[1]) { m = (0.02 - abs(x[2] - 0.37)) & (1.3 - abs(x[1])) & (0.7 - abs(x[3] + 0.2)); }",
     makeBox(-1.3, 0.35, -0.9, 1.3, 0.39, 0.5)},
};

std::optional<Tape> compileSource(const char* source) {
    ParseResult r = parseProgram(source, "shape.hf");
    EXPECT_TRUE(r.ok());
    if (!r.ok()) return std::nullopt;
    CompileResult c = compile(*r.program, 0, {0.0});
    EXPECT_TRUE(c.tape) << c.reason;
    return std::move(c.tape);
}

TEST(BoundsEstimate, ContainsTheSolidAndClosesInOnIt) {
    for (const Shape& s : kShapes) {
        SCOPED_TRACE(s.name);
        auto tape = compileSource(s.source);
        ASSERT_TRUE(tape);
        BoundsEstimate est = estimateBounds(*tape);
        ASSERT_FALSE(est.empty);
        EXPECT_FALSE(est.unbounded);
        EXPECT_FALSE(est.budgetSpent);
        double longest = 0.0;
        for (int a = 0; a < 3; ++a) longest = std::max(longest, s.exact.hi[a] - s.exact.lo[a]);
        EXPECT_LE(est.cellSize, longest / kBoundsPrecision * 1.01);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(est.box.lo[a], s.exact.lo[a]) << "axis " << a;
            EXPECT_GE(est.box.hi[a], s.exact.hi[a]) << "axis " << a;
            EXPECT_GE(est.box.lo[a], s.exact.lo[a] - 2.0 * est.cellSize) << "axis " << a;
            EXPECT_LE(est.box.hi[a], s.exact.hi[a] + 2.0 * est.cellSize) << "axis " << a;
        }
    }
}

TEST(BoundsEstimate, NoSampledPointOfTheSolidLiesOutside) {
    // Random points around each shape, evaluated as the sampler would:
    // every one inside the solid is inside the box.
    std::mt19937 rng(3);
    for (const Shape& s : kShapes) {
        SCOPED_TRACE(s.name);
        auto tape = compileSource(s.source);
        ASSERT_TRUE(tape);
        BoundsEstimate est = estimateBounds(*tape);
        const std::size_t n = 200000;
        std::vector<double> x(n), y(n), z(n), f(n);
        std::vector<double>* axes[3] = {&x, &y, &z};
        for (int a = 0; a < 3; ++a) {
            const double pad = 0.5 * (s.exact.hi[a] - s.exact.lo[a]);
            std::uniform_real_distribution<double> u(s.exact.lo[a] - pad, s.exact.hi[a] + pad);
            for (double& v : *axes[a]) v = u(rng);
        }
        ErrorReport errors;
        BatchEvaluator<double>(*tape).evaluate(x.data(), y.data(), z.data(), f.data(), n, errors);
        int inside = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (f[i] < 0.0) continue;
            ++inside;
            const double p[3] = {x[i], y[i], z[i]};
            for (int a = 0; a < 3; ++a)
                ASSERT_TRUE(p[a] >= est.box.lo[a] && p[a] <= est.box.hi[a])
                    << "(" << x[i] << ", " << y[i] << ", " << z[i] << ") is inside the solid, outside the box";
        }
        EXPECT_GT(inside, 100);
    }
}

TEST(BoundsEstimate, TellsEmptyAndUnboundedSolids) {
    auto empty = compileSource("m(x[3], a[1]) { m = -1 - x[1]^2; }");
    ASSERT_TRUE(empty);
    EXPECT_TRUE(estimateBounds(*empty).empty);
    auto halfSpace = compileSource("m(x[3], a[1]) { m = 0.5 - x[2]; }");
    ASSERT_TRUE(halfSpace);
    BoundsEstimate est = estimateBounds(*halfSpace);
    EXPECT_FALSE(est.empty);
    EXPECT_TRUE(est.unbounded);
}

}  // namespace
}  // namespace hg::frep
