// The tape specialized to a box (frep/eval/tape_specializer.h) computes the
// full tape's values bit for bit, in float, in double and in gradients
// (derivatives equal, magnitudes bit for bit), with the same
// failures, the first one named alike: every conformance program, corpus
// program and our own content over random boxes of every size, boxes nested
// inside specialized boxes, and a program of many bounded edits (min and
// max against clamped pieces, the shape an exported sculpture has), where it
// must also shorten the tape a lot.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <utility>

#include "conformance_data.h"
#include "frep/compiler/compiler.h"
#include "frep/eval/eval_batch.h"
#include "frep/eval/eval_gradient.h"
#include "frep/eval/eval_interval.h"
#include "frep/language/parser.h"
#include "frep/eval/tape_specializer.h"

namespace hg::frep {
namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    Tape tape;
};

std::vector<Case> programs() {
    std::vector<fs::path> files;
    for (const auto& tsv : test::tables()) {
        auto hf = tsv;
        hf.replace_extension(".hf");
        files.push_back(hf);
    }
    for (const fs::path& dir : {fs::path(HG_TEST_DATA_DIR) / "hyperfun" / "corpus", fs::path(HG_TEST_DATA_DIR) / "bounded",
                               fs::path(HG_SOURCE_DIR) / "content" / "hyperfun"})
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".hf") files.push_back(e.path());
    std::vector<Case> out;
    for (const auto& f : files) {
        ParseResult r = parseFile(f.string());
        if (!r.ok()) continue;
        CompileResult c = compile(*r.program, r.program->defaultBody(), {0.7, 0.3, 0.2, 0.1});
        if (c.tape) out.push_back({f.stem().string(), std::move(*c.tape)});
    }
    return out;
}

// Many bounded pieces on a base field: carves and adds as min and max
// against fields clamped to [-3, 3], the base clamped too (what the export
// of an edited sculpture looks like), perturbations as max(Q, 0)^3 terms.
std::string editedProgram(int edits, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-0.9, 0.9), r(0.03, 0.12);
    std::string body = "  f = max(min((0.8 - (x[1]^2 + x[2]^2 + x[3]^2)) * 40, 3), -3);\n";
    for (int i = 0; i < edits; ++i) {
        const double cx = pos(rng), cy = pos(rng), cz = pos(rng), rad = r(rng);
        const std::string d = "((x[1] - " + std::to_string(cx) + ")^2 + (x[2] - " + std::to_string(cy) + ")^2 + (x[3] - " +
                              std::to_string(cz) + ")^2)";
        const std::string g = "max(min((" + std::to_string(rad * rad) + " - " + d + ") * 400, 3), -3)";
        switch (i % 3) {
            case 0: body += "  f = min(f, -" + g + ");\n"; break;
            case 1: body += "  f = max(f, " + g + ");\n"; break;
            default: {
                const std::string q = "max(1 - " + d + " / " + std::to_string(rad * rad) + ", 0)";
                body += "  q = " + q + ";\n  f = max(min(f + 2 * q * q * q, 3), -3);\n";
            }
        }
    }
    return "edited(x[3], a[1]) {\n" + body + "  edited = f;\n}\n";
}

template <class T>
void expectSameValues(const Tape& full, const Tape& shorter, const double lo[3], const double hi[3], std::mt19937& rng,
                      const std::string& what) {
    std::vector<T> x, y, z;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        // Corners, faces and the inside.
        const int c = i < 8 ? i : -1;
        T p[3];
        for (int k = 0; k < 3; ++k) {
            const double t = c >= 0 ? ((c >> k) & 1) : (i % 5 == 0 ? std::round(u(rng)) : u(rng));
            p[k] = static_cast<T>(std::min(lo[k] + (hi[k] - lo[k]) * t, hi[k]));
            // Rounding to float may step outside the box: the sampler rounds
            // its corners too, so the box it specializes to holds them.
            if (static_cast<double>(p[k]) < lo[k] || static_cast<double>(p[k]) > hi[k]) p[k] = static_cast<T>(lo[k]);
        }
        if (static_cast<double>(p[0]) < lo[0] || static_cast<double>(p[1]) < lo[1] || static_cast<double>(p[2]) < lo[2])
            continue;
        x.push_back(p[0]);
        y.push_back(p[1]);
        z.push_back(p[2]);
    }
    std::vector<T> a(x.size()), b(x.size());
    std::vector<std::uint8_t> fa(x.size()), fb(x.size());
    ErrorReport ea, eb;
    BatchEvaluator<T> full_(full), short_(shorter);
    full_.evaluate(x.data(), y.data(), z.data(), a.data(), a.size(), ea, fa.data());
    short_.evaluate(x.data(), y.data(), z.data(), b.data(), b.size(), eb, fb.data());
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(T)), 0) << what;
    ASSERT_EQ(fa, fb) << what;
    EXPECT_EQ(ea.count, eb.count) << what;
    // The first failure is named alike: a specialized tape keeps only its
    // own instructions' failure sites, renumbered.
    EXPECT_EQ(ea.first, eb.first) << what;
    EXPECT_EQ(ea.firstLoc.line, eb.firstLoc.line) << what;
    EXPECT_EQ(ea.firstLoc.column, eb.firstLoc.column) << what;
}

// The gradient evaluator on the specialized tape: the same values bit for
// bit, the same derivatives (a zero may have the other sign, where a tie
// between two flat operands was pruned) and so the same magnitudes bit for
// bit, at the same kind of points as above.
void expectSameGradients(const Tape& full, const Tape& shorter, const double lo[3], const double hi[3], std::mt19937& rng,
                         const std::string& what) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    GradientEvaluator fullGrad(full), shortGrad(shorter);
    ErrorReport ea, eb;
    for (int i = 0; i < 200; ++i) {
        const int c = i < 8 ? i : -1;
        double p[3];
        for (int k = 0; k < 3; ++k) {
            const double t = c >= 0 ? ((c >> k) & 1) : (i % 5 == 0 ? std::round(u(rng)) : u(rng));
            p[k] = std::min(lo[k] + (hi[k] - lo[k]) * t, hi[k]);
        }
        const Gradient a = fullGrad.evaluate(p[0], p[1], p[2], ea);
        const Gradient b = shortGrad.evaluate(p[0], p[1], p[2], eb);
        ASSERT_EQ(std::memcmp(&a.value, &b.value, sizeof a.value), 0) << what << " point " << i;
        for (const auto& [da, db] : {std::pair{a.dx, b.dx}, std::pair{a.dy, b.dy}, std::pair{a.dz, b.dz}})
            ASSERT_TRUE(da == db || (std::isnan(da) && std::isnan(db))) << what << " point " << i << ": " << da << " " << db;
        const double ma = std::sqrt(a.dx * a.dx + a.dy * a.dy + a.dz * a.dz);
        const double mb = std::sqrt(b.dx * b.dx + b.dy * b.dy + b.dz * b.dz);
        ASSERT_EQ(std::memcmp(&ma, &mb, sizeof ma), 0) << what << " point " << i;
    }
    EXPECT_EQ(ea.count, eb.count) << what;
}

void expectSame(Precision precision, const Tape& full, const Tape& shorter, const double lo[3], const double hi[3],
                std::mt19937& rng, const std::string& what) {
    switch (precision) {
        case Precision::Float: expectSameValues<float>(full, shorter, lo, hi, rng, what); break;
        case Precision::Double: expectSameValues<double>(full, shorter, lo, hi, rng, what); break;
        case Precision::Gradient: expectSameGradients(full, shorter, lo, hi, rng, what); break;
    }
}

struct Shortening {
    double sum = 0.0;
    std::size_t boxes = 0, specialized = 0, shortest = SIZE_MAX;
};

// Random boxes in [-2, 2]^3 of sizes from a thousandth to the whole, each
// specialized, checked, and its halves specialized again from it.
void checkProgram(const Case& c, Precision precision, std::mt19937& rng, Shortening& s) {
    IntervalEvaluator full(c.tape);
    TapeSpecializer specializer;
    IntervalTrace trace;
    for (int box = 0; box < 24; ++box) {
        double lo[3], hi[3];
        const double scale = std::pow(10.0, std::uniform_real_distribution<double>(-3, 0.6)(rng));
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::uniform_real_distribution<double>(-2.0, 2.0)(rng);
            hi[k] = lo[k] + scale * std::uniform_real_distribution<double>(0.2, 1.0)(rng);
        }
        full.evaluate(Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2]), &trace);
        SpecializedTape one;
        ++s.boxes;
        if (!specializer.specialize(c.tape, full.affine(), trace, precision, one)) continue;
        ++s.specialized;
        s.sum += static_cast<double>(one.tape.size()) / static_cast<double>(c.tape.size());
        s.shortest = std::min(s.shortest, one.tape.size());
        const std::string what = c.name + " box " + std::to_string(box);
        expectSame(precision, c.tape, one.tape, lo, hi, rng, what);
        // A half of it, specialized from the specialized tape.
        double lo2[3], hi2[3];
        for (int k = 0; k < 3; ++k) {
            lo2[k] = lo[k];
            hi2[k] = k == box % 3 ? 0.5 * (lo[k] + hi[k]) : hi[k];
        }
        IntervalEvaluator nested(one.tape, one.affine);
        IntervalTrace trace2;
        const Interval v1 = nested.evaluate(Interval(lo2[0], hi2[0]), Interval(lo2[1], hi2[1]), Interval(lo2[2], hi2[2]), &trace2);
        // The specialized tape bounds the half exactly as the full one does.
        const Interval v0 = full.evaluate(Interval(lo2[0], hi2[0]), Interval(lo2[1], hi2[1]), Interval(lo2[2], hi2[2]));
        EXPECT_EQ(v0.lo, v1.lo) << what;
        EXPECT_EQ(v0.hi, v1.hi) << what;
        SpecializedTape two;
        if (!specializer.specialize(one.tape, one.affine, trace2, precision, two)) continue;
        EXPECT_LT(two.tape.size(), one.tape.size());
        expectSame(precision, c.tape, two.tape, lo2, hi2, rng, what + " half");
    }
}

TEST(TapeSpecializer, EveryProgramGivesTheSameValuesOnEveryBoxInFloatAndDouble) {
    const std::vector<Case> cases = programs();
    ASSERT_GT(cases.size(), 40u);
    std::mt19937 rng(11);
    Shortening f, d, g;
    for (const Case& c : cases) {
        checkProgram(c, Precision::Float, rng, f);
        checkProgram(c, Precision::Double, rng, d);
        checkProgram(c, Precision::Gradient, rng, g);
    }
    // Programs with min and max do get shortened somewhere.
    EXPECT_GT(f.specialized, 20u);
    std::printf("content: %zu of %zu boxes specialized in float (mean %.2f of the tape), %zu in double\n", f.specialized,
                f.boxes, f.specialized ? f.sum / static_cast<double>(f.specialized) : 1.0, d.specialized);
}

TEST(TapeSpecializer, ManyBoundedEditsShortenToTheFewThatReachTheBox) {
    ParseResult r = parseProgram(editedProgram(300, 5), "edited.hf");
    ASSERT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors.front().message);
    CompileResult cr = compile(*r.program, 0, {0.0});
    ASSERT_TRUE(cr.tape);
    const Case c{"edited", std::move(*cr.tape)};
    std::mt19937 rng(3);
    for (Precision p : {Precision::Float, Precision::Double, Precision::Gradient}) {
        Shortening s;
        for (int i = 0; i < 4; ++i) checkProgram(c, p, rng, s);
        ASSERT_GT(s.specialized, 40u);
        // Small boxes meet a handful of the 300 edits.
        EXPECT_LT(s.shortest, c.tape.size() / 10) << "full " << c.tape.size();
        EXPECT_LT(s.sum / static_cast<double>(s.specialized), 0.6);
    }
}

// For gradients, max(f, c) where f reaches c at the box's edge may become f
// only where f's derivative is zero wherever it equals c (a clamp at its
// floor): at x = 0.5, max(x, 0.5) returns the constant, whose derivative is
// 0, not x's 1. A running field clamped to -3 against a piece at its floor
// -3 is pruned: both are flat there.
TEST(TapeSpecializer, GradientsPruneATieOnlyWhereBothSidesAreFlat) {
    const auto tapeOf = [](const char* source) {
        ParseResult r = parseProgram(source, "tie.hf");
        EXPECT_TRUE(r.ok());
        CompileResult c = compile(*r.program, 0, {0.0});
        EXPECT_TRUE(c.tape);
        return std::move(*c.tape);
    };
    std::mt19937 rng(2);
    TapeSpecializer specializer;
    IntervalTrace trace;
    {
        const Tape steep = tapeOf("m(x[3], a[1]) { m = max(x[1], 0.5) * (1 + x[2] * x[2]); }");
        const double lo[3] = {0.5, 0.0, 0.0}, hi[3] = {0.7, 1.0, 1.0};
        IntervalEvaluator interval(steep);
        interval.evaluate(Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2]), &trace);
        SpecializedTape out;
        EXPECT_FALSE(specializer.specialize(steep, interval.affine(), trace, Precision::Gradient, out));
        // Double has no derivatives to keep: the tie is taken there.
        ASSERT_TRUE(specializer.specialize(steep, interval.affine(), trace, Precision::Double, out));
        GradientEvaluator full(steep), shorter(out.tape);
        ErrorReport errors;
        EXPECT_EQ(full.evaluate(0.5, 0.5, 0.5, errors).dx, 0.0);
        EXPECT_EQ(shorter.evaluate(0.5, 0.5, 0.5, errors).dx, 1.25);
    }
    {
        const Tape clamped = tapeOf(
            "m(x[3], a[1]) { f = max(min(x[1] * 10, 3), -3); p = max(min((0.01 - (x[2] - 5)^2) * 100, 3), -3);"
            " m = max(f, p); }");
        const double lo[3] = {-1.0, -1.0, -1.0}, hi[3] = {1.0, 1.0, 1.0};
        IntervalEvaluator interval(clamped);
        interval.evaluate(Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2]), &trace);
        SpecializedTape out;
        ASSERT_TRUE(specializer.specialize(clamped, interval.affine(), trace, Precision::Gradient, out));
        EXPECT_LT(out.tape.size(), clamped.size() / 2) << clamped.dump() << out.tape.dump();
        expectSameGradients(clamped, out.tape, lo, hi, rng, "clamped");
    }
}

// Float rounds where the double bounds do not: min(x * 0.1, c) with c a
// hair above 0.3 * 0.1 is the product in double at x = 0.3, but float may
// round the product above c. Only a winner by a margin is pruned in float.
TEST(TapeSpecializer, FloatNeedsAWinnerByAMargin) {
    int pruned = 0;
    std::mt19937 rng(1);
    for (int k = -60; k <= 60; ++k) {
        char source[160];
        std::snprintf(source, sizeof source, "m(x[3], a[1]) { m = min(x[1] * 0.1, %.17g) + x[2] * 0; }", 0.03 + k * 1e-10);
        ParseResult r = parseProgram(source, "tie.hf");
        ASSERT_TRUE(r.ok());
        CompileResult cr = compile(*r.program, 0, {0.0});
        ASSERT_TRUE(cr.tape);
        IntervalEvaluator iv(*cr.tape);
        IntervalTrace trace;
        const double lo[3] = {0.3, 0.0, 0.0}, hi[3] = {0.3, 0.0, 0.0};
        iv.evaluate(Interval(0.3), Interval(0.0), Interval(0.0), &trace);
        TapeSpecializer sp;
        SpecializedTape d, f;
        pruned += sp.specialize(*cr.tape, iv.affine(), trace, Precision::Double, d);
        if (sp.specialize(*cr.tape, iv.affine(), trace, Precision::Float, f))
            expectSameValues<float>(*cr.tape, f.tape, lo, hi, rng, source);
    }
    EXPECT_GT(pruned, 100);  // double prunes nearly all of them, exactly
}

}  // namespace
}  // namespace hg::frep
