// hfexport::HfText (garden/export/hf_text.h), the value type that writes
// HyperFun: the text it writes evaluates, in our interpreter, to exactly
// what the same template computes on double, including the corners the
// export relies on (constants that need an expression, divisions by
// constants HyperFun would refuse, a segment's hfConvLine call), and a long
// chain of operations reuses a handful of temporaries.
#include "garden/export/hf_text.h"

#include <gtest/gtest.h>

#include <random>

#include "frep/language/interpreter.h"
#include "frep/language/parser.h"
#include "garden/sculpt/edit_field.h"

namespace hg::garden {
namespace {

using hfexport::HfStatements;
using hfexport::HfText;

template <class V>
V mixed(const V& x, const V& y, const V& z) {
    using namespace editops;
    const V a = (x - V(0.1)) / V(3.7e-9);               // HyperFun refuses to divide by 3.7e-9 directly
    const V b = V(1e25) * y + V(1.5e-310) - V(-0.0);    // constants that need an expression
    const V c = vsqrt(x * x + y * y) - vabs(z) / V(0.3);
    const V folded = V(0.1) + V(0.2);                   // folded: 0.30000000000000004
    StrokeSegment g;
    g.begin = {1e-40, -0.2, 0.05};                      // an item that needs an expression in the literal
    g.end = {0.3, 0.25, -0.1};
    g.s = 7.5;
    g.t = 0.02;
    g.scale = 40.0;
    const V seg = segmentField(x, y, z, g, -3.0, 3.0);
    return vmax(vmin(a * V(1e-12) + b * V(1e-26), c * folded), -x) + seg;
}

struct Written {
    frep::Program program;
    int body = -1;
};

Written parse(const HfStatements& st, const HfText& result) {
    std::string text = "my_model(x[3], a[1])\n{\n";
    if (st.usesSegmentArrays()) text += "   array segb[3], sege[3], segs[1];\n";
    text += st.text() + "   my_model = " + result.operand() + ";\n}\n";
    frep::ParseResult r = frep::parseProgram(text, "hf_text.hf");
    for (const auto& d : r.errors) ADD_FAILURE() << "line " << d.loc.line << ": " << d.message << "\n" << text;
    Written w;
    if (!r.ok()) return w;
    w.program = std::move(*r.program);
    w.body = 0;
    return w;
}

TEST(HfText, WritesHyperFunThatEvaluatesLikeTheTemplateOnDouble) {
    HfStatements st;
    const HfText x = HfText::named(st, "x[1]"), y = HfText::named(st, "x[2]"), z = HfText::named(st, "x[3]");
    const HfText r = mixed(x, y, z);
    EXPECT_NE(st.text().find("hfConvLine(x, segb, sege, segs, 0)"), std::string::npos);
    EXPECT_NE(st.text().find("segb[1] = "), std::string::npos) << st.text();  // 1e-40 assigned after the literal
    EXPECT_NE(st.text().find("0.30000000000000004"), std::string::npos);
    EXPECT_EQ(st.text().find("/ 0.0000000037"), std::string::npos) << st.text();  // scaled by a power of two
    const Written w = parse(st, r);
    ASSERT_EQ(w.body, 0);
    frep::Interpreter in(w.program, w.body);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const double px = u(rng), py = u(rng), pz = u(rng);
        const frep::PointResult got = in.evaluate(px, py, pz);
        ASSERT_TRUE(got.ok()) << "runtime error on line " << got.loc.line;
        EXPECT_EQ(got.value, mixed(px, py, pz)) << px << " " << py << " " << pz;
    }
}

TEST(HfText, ALongChainIsLinearAndReusesItsTemporaries) {
    HfStatements st;
    const HfText x = HfText::named(st, "x[1]");
    HfText f = x;
    double g = 0.37;
    for (int i = 0; i < 3000; ++i) {
        f = editops::vmax(editops::vmin(f * HfText(1.0001) - x, HfText(3.0)), HfText(-3.0));
        g = editops::vmax(editops::vmin(g * 1.0001 - 0.37, 3.0), -3.0);
    }
    EXPECT_EQ(st.statementCount(), 4u * 3000u);
    EXPECT_LE(st.temporariesUsed(), 8u);  // not growing with the chain
    const Written w = parse(st, f);
    ASSERT_EQ(w.body, 0);
    frep::Interpreter in(w.program, w.body);
    EXPECT_EQ(in.evaluate(0.37, 0.0, 0.0).value, g);
}

}  // namespace
}  // namespace hg::garden
