// Tool settings (garden/sculpt/tool_settings.h): what the tool hand works
// with, and scaleToolSize, the desktop's [ and ] (x1.25 a press), which
// scales the size of the tool in hand only (the stroke radius for carve,
// add and melt; the perturbation's scale; the impact size), kept within
// the bounds; none and move have no size. What is tested:
//  * the defaults lie inside the bounds; perturbRadii is the radii times
//    the scale, perturbStrength the strength reversed by `reverse`;
//  * each press multiplies the size in hand by the factor and changes no
//    other setting; presses up then as many down come back to the start
//    while inside the bounds;
//  * any number of presses, or any factor, stops exactly at a bound, and
//    the next press the other way leaves it by one step;
//  * the perturbation's size step scales its radii together (the ratio
//    kept) and stops where its largest or smallest live radius meets a
//    size bound;
//  * scaleToolStrength steps the perturbation's strength (sign kept) or
//    the compaction volume within their bounds; a step never moves a value
//    set outside the bounds farther out;
//  * clampToolSettings brings every bounded setting inside;
//  * toolKindName's names, one per kind, all different.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <utility>

#include "garden/sculpt/tool_settings.h"

namespace hg::garden {
namespace {

using Kind = ToolSettings::Kind;
constexpr double kStep = 1.25;  // the desktop's [ and ] (garden/window/desktop_keys.h)
const Kind kAllKinds[] = {Kind::None, Kind::Carve, Kind::Add, Kind::Melt, Kind::Perturb, Kind::Impacts, Kind::Move};

// The one size each kind scales (null for none and move), as a member.
double ToolSettings::*sizeMember(Kind k) {
    switch (k) {
        case Kind::Carve:
        case Kind::Add:
        case Kind::Melt: return &ToolSettings::radius;
        case Kind::Perturb: return &ToolSettings::perturbScale;
        case Kind::Impacts: return &ToolSettings::impactSize;
        default: return nullptr;
    }
}
double* sizeOf(ToolSettings& t) { return &(t.*sizeMember(t.kind)); }
std::pair<double, double> boundsOf(Kind k) {
    if (k == Kind::Perturb) return {kMinPerturbScale, kMaxPerturbScale};
    if (k == Kind::Impacts) return {kMinImpactSize, kMaxImpactSize};
    return {kMinToolSize, kMaxToolSize};
}

// Every setting but `except` (the scaled size, or null) is the same in a and b.
void expectSameOtherwise(const ToolSettings& a, const ToolSettings& b, double ToolSettings::*except) {
    for (auto [member, name] : {std::pair{&ToolSettings::radius, "radius"},
                                std::pair{&ToolSettings::perturbScale, "perturbScale"},
                                std::pair{&ToolSettings::impactSize, "impactSize"}})
        if (member != except) {
            EXPECT_EQ(a.*member, b.*member) << name;
        }
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.softness, b.softness);
    EXPECT_EQ(a.shape, b.shape);
    EXPECT_EQ(a.radii, b.radii);
    EXPECT_EQ(a.strength, b.strength);
    EXPECT_EQ(a.reverse, b.reverse);
    EXPECT_EQ(a.impactShape, b.impactShape);
    EXPECT_EQ(a.compactionCm3, b.compactionCm3);
    EXPECT_EQ(a.spread, b.spread);
    EXPECT_EQ(a.spreadSize, b.spreadSize);
    EXPECT_EQ(a.impactCount, b.impactCount);
    EXPECT_EQ(a.seed, b.seed);
}

TEST(ToolSettings, DefaultsLieInsideTheBoundsAndDeriveTheLiveQuadric) {
    const ToolSettings t;
    EXPECT_EQ(t.kind, Kind::None);
    EXPECT_GE(t.radius, kMinToolSize);
    EXPECT_LE(t.radius, kMaxToolSize);
    EXPECT_GE(t.perturbScale, kMinPerturbScale);
    EXPECT_LE(t.perturbScale, kMaxPerturbScale);
    EXPECT_GE(t.impactSize, kMinImpactSize);
    EXPECT_LE(t.impactSize, kMaxImpactSize);
    EXPECT_LT(kMinToolSize, kMaxToolSize);
    EXPECT_LT(kMinPerturbScale, kMaxPerturbScale);
    EXPECT_LT(kMinImpactSize, kMaxImpactSize);

    ToolSettings p;
    p.radii = {0.1, 0.05, 0.02};
    p.perturbScale = 1.5;
    p.strength = 2.5;
    const auto r = p.perturbRadii();
    for (std::size_t a = 0; a < 3; ++a) EXPECT_EQ(r[a], p.radii[a] * 1.5);
    EXPECT_EQ(p.perturbStrength(), 2.5);
    p.reverse = true;
    EXPECT_EQ(p.perturbStrength(), -2.5) << "reversed: a pull pushes";
    p.strength = -1.0;
    EXPECT_EQ(p.perturbStrength(), 1.0) << "reversed: a push pulls";
    // Scaling the perturbation scales its live radii, not the radii.
    p.kind = Kind::Perturb;
    scaleToolSize(p, kStep);
    EXPECT_EQ(p.radii, (std::array<double, 3>{0.1, 0.05, 0.02}));
    for (std::size_t a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(p.perturbRadii()[a], r[a] * kStep);
}

TEST(ToolSettings, APressScalesTheSizeInHandOnly) {
    for (Kind k : kAllKinds) {
        SCOPED_TRACE(toolKindName(k));
        ToolSettings t;
        t.kind = k;
        t.radius = 0.07;
        t.perturbScale = 0.8;
        t.impactSize = 0.03;
        t.reverse = true;
        for (double factor : {kStep, 1.0 / kStep, 2.0, 0.5}) {
            const ToolSettings before = t;
            scaleToolSize(t, factor);
            const auto size = sizeMember(k);
            if (size) {
                EXPECT_EQ(t.*size, before.*size * factor);
            }
            expectSameOtherwise(t, before, size);
        }
    }
}

TEST(ToolSettings, PressesUpThenDownComeBackInsideTheBounds) {
    for (Kind k : {Kind::Carve, Kind::Add, Kind::Melt, Kind::Perturb, Kind::Impacts}) {
        SCOPED_TRACE(toolKindName(k));
        ToolSettings t;
        t.kind = k;
        const double start = *sizeOf(t);
        const auto [lo, hi] = boundsOf(k);
        // As many presses as stay inside the bounds each way.
        const int up = static_cast<int>(std::floor(std::log(hi / start) / std::log(kStep)));
        const int down = static_cast<int>(std::floor(std::log(start / lo) / std::log(kStep)));
        ASSERT_GT(up, 2);
        ASSERT_GT(down, 2);
        double expect = start;
        for (int i = 0; i < up; ++i) {
            scaleToolSize(t, kStep);
            expect *= kStep;
            ASSERT_EQ(*sizeOf(t), expect) << "press " << i + 1;
        }
        EXPECT_LE(*sizeOf(t), hi);
        for (int i = 0; i < up + down; ++i) scaleToolSize(t, 1.0 / kStep);
        EXPECT_NEAR(*sizeOf(t), start * std::pow(kStep, -down), 1e-12 * start);
        EXPECT_GE(*sizeOf(t), lo);
        for (int i = 0; i < down; ++i) scaleToolSize(t, kStep);
        EXPECT_NEAR(*sizeOf(t), start, 1e-12 * start) << "back where it started";
    }
}

TEST(ToolSettings, SizesStopExactlyAtTheBounds) {
    for (Kind k : {Kind::Carve, Kind::Add, Kind::Melt, Kind::Perturb, Kind::Impacts}) {
        SCOPED_TRACE(toolKindName(k));
        const auto [lo, hi] = boundsOf(k);
        ToolSettings t;
        t.kind = k;
        for (int i = 0; i < 200; ++i) scaleToolSize(t, kStep);
        EXPECT_EQ(*sizeOf(t), hi);
        scaleToolSize(t, 1.0 / kStep);
        EXPECT_DOUBLE_EQ(*sizeOf(t), hi / kStep) << "one step back from the bound";
        for (int i = 0; i < 200; ++i) scaleToolSize(t, 1.0 / kStep);
        EXPECT_EQ(*sizeOf(t), lo);
        scaleToolSize(t, kStep);
        EXPECT_DOUBLE_EQ(*sizeOf(t), lo * kStep);
        // Any factor, however large or small: inside the bounds.
        for (double f : {1e300, 1e-300, 0.0, 1e6, 1e-6}) {
            scaleToolSize(t, f);
            EXPECT_GE(*sizeOf(t), lo) << f;
            EXPECT_LE(*sizeOf(t), hi) << f;
        }
        scaleToolSize(t, 0.0);
        EXPECT_EQ(*sizeOf(t), lo);
        scaleToolSize(t, 1e300);
        EXPECT_EQ(*sizeOf(t), hi);
        // A NaN factor (a broken stick reading) leaves the size alone.
        scaleToolSize(t, std::nan(""));
        EXPECT_EQ(*sizeOf(t), hi);
    }
    // None and move have no size: nothing changes, whatever the factor.
    for (Kind k : {Kind::None, Kind::Move}) {
        ToolSettings t;
        t.kind = k;
        const ToolSettings before = t;
        for (double f : {kStep, 1.0 / kStep, 1e9, 0.0}) scaleToolSize(t, f);
        expectSameOtherwise(t, before, nullptr);
    }
}

TEST(ToolSettings, APerturbationsRadiiScaleTogetherWithinTheSizeBounds) {
    ToolSettings t;
    t.kind = Kind::Perturb;
    t.radii = {0.5, 0.05, 0.01};
    const auto ratio = [&t] { return t.perturbRadii()[0] / t.perturbRadii()[2]; };
    const double r0 = ratio();
    for (int i = 0; i < 200; ++i) scaleToolSize(t, kStep);
    EXPECT_DOUBLE_EQ(t.perturbRadii()[0], kMaxToolSize) << "the largest radius meets the bound first";
    EXPECT_LT(t.perturbScale, kMaxPerturbScale);
    EXPECT_DOUBLE_EQ(ratio(), r0);
    for (int i = 0; i < 200; ++i) scaleToolSize(t, 1.0 / kStep);
    EXPECT_DOUBLE_EQ(t.perturbRadii()[2], kMinToolSize) << "the smallest radius meets the bound first";
    EXPECT_GT(t.perturbScale, kMinPerturbScale);
    EXPECT_DOUBLE_EQ(ratio(), r0);
    EXPECT_EQ(t.radii, (std::array<double, 3>{0.5, 0.05, 0.01})) << "the radii themselves stay";
    // A torus uses R and r only: its third radius bounds nothing.
    t.shape = QuadricShape::Torus;
    t.radii = {0.1, 0.01, 1e-9};
    t.perturbScale = 1.0;
    for (int i = 0; i < 200; ++i) scaleToolSize(t, 1.0 / kStep);
    EXPECT_DOUBLE_EQ(t.perturbScale, kMinToolSize / 0.01);
}

TEST(ToolSettings, StrengthStepsKeepTheSignAndTheBounds) {
    ToolSettings t;
    t.kind = Kind::Perturb;
    t.strength = -4.0;
    scaleToolStrength(t, 0.5);
    EXPECT_EQ(t.strength, -2.0) << "a push stays a push";
    for (int i = 0; i < 100; ++i) scaleToolStrength(t, 2.0);
    EXPECT_EQ(t.strength, -kMaxPerturbStrength);
    for (int i = 0; i < 100; ++i) scaleToolStrength(t, 0.5);
    EXPECT_EQ(t.strength, -kMinPerturbStrength);
    const double compaction = t.compactionCm3;
    EXPECT_EQ(compaction, ToolSettings{}.compactionCm3) << "the perturbation's step leaves the impacts' volume";
    t.kind = Kind::Impacts;
    for (int i = 0; i < 100; ++i) scaleToolStrength(t, 2.0);
    EXPECT_EQ(t.compactionCm3, kMaxCompactionCm3);
    for (int i = 0; i < 100; ++i) scaleToolStrength(t, 0.5);
    EXPECT_EQ(t.compactionCm3, kMinCompactionCm3);
    EXPECT_EQ(t.strength, -kMinPerturbStrength);
    // Strokes have no strength.
    for (Kind k : {Kind::None, Kind::Carve, Kind::Add, Kind::Melt, Kind::Move}) {
        ToolSettings s;
        s.kind = k;
        const ToolSettings before = s;
        scaleToolStrength(s, 4.0);
        expectSameOtherwise(s, before, nullptr);
    }
    // A value a script set outside the bounds: a step towards them moves
    // it in, a step away leaves it.
    ToolSettings far;
    far.kind = Kind::Carve;
    far.radius = 20.0;
    scaleToolSize(far, kStep);
    EXPECT_EQ(far.radius, 20.0);
    scaleToolSize(far, 0.5);
    EXPECT_EQ(far.radius, 10.0);
}

TEST(ToolSettings, ClampBringsEverySettingInside) {
    ToolSettings t;
    t.radius = 9.0;
    t.perturbScale = 50.0;
    t.radii = {1.0, 1e-6, 0.01};
    t.strength = -200.0;
    t.impactSize = 3.0;
    t.compactionCm3 = 1e-5;
    clampToolSettings(t);
    EXPECT_EQ(t.radius, kMaxToolSize);
    EXPECT_EQ(t.perturbScale, kMaxPerturbScale);
    for (double r : t.perturbRadii()) {
        EXPECT_GE(r, kMinToolSize * (1 - 1e-12));
        EXPECT_LE(r, kMaxToolSize * (1 + 1e-12));
    }
    EXPECT_DOUBLE_EQ(t.perturbRadii()[2], 0.2) << "a radius inside stays";
    EXPECT_EQ(t.strength, -kMaxPerturbStrength);
    EXPECT_EQ(t.impactSize, kMaxImpactSize);
    EXPECT_EQ(t.compactionCm3, kMinCompactionCm3);
    ToolSettings d;
    clampToolSettings(d);
    EXPECT_EQ(d.radius, ToolSettings{}.radius) << "the defaults are inside";
    EXPECT_EQ(d.radii, ToolSettings{}.radii);
    EXPECT_EQ(d.strength, ToolSettings{}.strength);
}

TEST(ToolSettings, EachKindHasItsOwnName) {
    const char* names[] = {"none", "carve", "add", "melt", "perturb", "impacts", "move"};
    std::set<std::string> seen;
    for (std::size_t i = 0; i < std::size(kAllKinds); ++i) {
        EXPECT_STREQ(toolKindName(kAllKinds[i]), names[i]);
        seen.insert(toolKindName(kAllKinds[i]));
    }
    EXPECT_EQ(seen.size(), std::size(kAllKinds));
}

}  // namespace
}  // namespace hg::garden
