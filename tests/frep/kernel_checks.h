// Checks shared by the fused kernels' tests: points of a box as the float
// sampler sees them, and a gradient against central differences of the
// interpreter.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "frep/eval/eval_gradient.h"
#include "frep/language/interpreter.h"

namespace hg::frep::test {

// An 8^3 grid over the cube [lo, lo + size], corners and faces included,
// rounded to float and kept only where the rounding stays inside the cube;
// the same points in float and in double.
struct BoxSamples {
    std::vector<double> x, y, z;
    std::vector<float> xf, yf, zf;
};

inline BoxSamples floatPointsInBox(const double lo[3], double size) {
    BoxSamples b;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k) {
                const int at[3] = {i, j, k};
                float p[3];
                bool inside = true;
                for (int a = 0; a < 3; ++a) {
                    p[a] = static_cast<float>(std::min(lo[a] + size * at[a] / 7.0, lo[a] + size));
                    inside = inside && p[a] >= lo[a] && p[a] <= lo[a] + size;
                }
                if (!inside) continue;
                b.xf.push_back(p[0]); b.yf.push_back(p[1]); b.zf.push_back(p[2]);
                b.x.push_back(p[0]); b.y.push_back(p[1]); b.z.push_back(p[2]);
            }
    return b;
}

// The gradient evaluator at q against central differences of the
// interpreter (step 1e-6); returns how many partials were compared.
inline int expectGradientMatchesDifferences(GradientEvaluator& grad, Interpreter& interp, const std::vector<double>& q,
                                            const std::string& what) {
    ErrorReport errs;
    const Gradient g = grad.evaluate(q[0], q[1], q[2], errs);
    if (errs.count) return 0;
    EXPECT_EQ(g.value, interp.evaluate(q[0], q[1], q[2]).value) << what;
    const double h = 1e-6, gk[3] = {g.dx, g.dy, g.dz};
    for (int k = 0; k < 3; ++k) {
        std::vector<double> a = q, b = q;
        a[static_cast<size_t>(k)] += h;
        b[static_cast<size_t>(k)] -= h;
        const double d = (interp.evaluate(a[0], a[1], a[2]).value - interp.evaluate(b[0], b[1], b[2]).value) / (2 * h);
        EXPECT_NEAR(gk[k], d, 1e-5 * std::max(1.0, std::fabs(d))) << what << " d/d" << "xyz"[k];
    }
    return 3;
}

}  // namespace hg::frep::test
