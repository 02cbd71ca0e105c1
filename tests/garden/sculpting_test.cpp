// Sculpting (garden/sculpt, voxel/edit_region): the edit expression on the
// tape equals its double reference; each tool changes the field inside its
// reach and nowhere else; the field stays bounded at any edit count; box
// updates equal a from-scratch rebuild bit for bit, through undo and redo.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frep/eval/eval_batch.h"
#include "garden/sculpt/edit_field.h"
#include "garden/sculpt/edit_list.h"
#include "garden/sculpt/impacts.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/sculpt/stroke_segments.h"
#include "tests/test_models.h"
#include "garden_test_util.h"
#include "voxel/sampler.h"

namespace hg::garden {
namespace {

constexpr double kVoxel = 1.0 / 64.0;
const FieldUnits kUnits{kVoxel, 3.0};

Edit strokeEdit(StrokeTool tool, double radius, std::vector<ModelPoint> path, double softness = 2.0) {
    Stroke s;
    s.tool = tool;
    s.radius = radius;
    s.softness = softness;
    s.path = std::move(path);
    extendStrokeSegments(s, 0, kUnits);
    Edit e;
    e.op = std::move(s);
    return e;
}

// A smooth stroke with a hand-made quadric per segment (the session fits
// them to its grid: smooth_inflate_test.cpp), so the field has a target
// that differs from the sphere it smooths.
Edit smoothEdit(double radius, std::vector<ModelPoint> path, Falloff falloff, double strength) {
    Edit e = strokeEdit(StrokeTool::Smooth, radius, std::move(path));
    Stroke& s = std::get<Stroke>(e.op);
    s.falloff = falloff;
    s.strength = strength;
    for (const StrokeSegment& g : s.segments) {
        SegmentFit q;
        for (int a = 0; a < 3; ++a) q.centre[static_cast<std::size_t>(a)] = 0.5 * (g.begin[a] + g.end[a]);
        q.scale = radius;
        q.c = {0.5, 1.0, -0.5, 0.25, -0.75, 0.1, 0.2, 0.3, -0.2, 0.05};
        s.fits.push_back(q);
    }
    s.fits.back().reset();  // a segment without a fit leaves the field as it is
    return e;
}

Edit inflateEdit(double radius, std::vector<ModelPoint> path, Falloff falloff, double strength) {
    Edit e = strokeEdit(StrokeTool::Inflate, radius, std::move(path));
    Stroke& s = std::get<Stroke>(e.op);
    s.falloff = falloff;
    s.strength = strength;
    return e;
}

Edit perturbEdit(QuadricShape shape, ModelPoint c, ModelPoint radii, double k) {
    Perturbation p;
    p.shape = shape;
    p.center = c;
    p.radii = radii;
    p.strength = k;
    const double a = 0.6, ca = std::cos(a), sa = std::sin(a);  // a turned frame
    p.axes = {{{ca, sa, 0.0}, {-sa, ca, 0.0}, {0.0, 0.0, 1.0}}};
    Edit e;
    e.op = p;
    return e;
}

bool inside(const frep::Box3& b, double x, double y, double z) {
    return x >= b.lo[0] && x <= b.hi[0] && y >= b.lo[1] && y <= b.hi[1] && z >= b.lo[2] && z <= b.hi[2];
}

// A base field in [-band, band]: a sphere of radius 0.5 in voxels.
double sphereBase(double x, double y, double z) {
    const double f = (0.5 - std::sqrt(x * x + y * y + z * z)) / kVoxel;
    return std::clamp(f, -3.0, 3.0);
}

Edit impactEdit() {
    ImpactSeries series;
    for (ImpactShape shape : {ImpactShape::Sphere, ImpactShape::Chisel, ImpactShape::Square}) {
        Impact m;
        m.shape = shape;
        m.size = 0.06;
        m.tip = {shape == ImpactShape::Sphere ? -0.2 : shape == ImpactShape::Chisel ? 0.0 : 0.2, 0.46, 0.0};
        m.direction = {0.0, -1.0, 0.0};
        m.across = {1.0, 0.0, 0.0};
        m.depth = 0.02;
        m.reach = impactReach(m, kUnits);
        series.impacts.push_back(m);
    }
    Edit e;
    e.op = series;
    return e;
}

std::vector<Edit> everyTool() {
    return {impactEdit(), strokeEdit(StrokeTool::Carve, 0.1, {{0.4, 0.0, 0.0}, {0.45, 0.2, 0.1}, {0.3, 0.4, 0.2}}),
            strokeEdit(StrokeTool::Add, 0.05, {{-0.5, 0.0, 0.0}, {-0.5, -0.3, 0.0}}),
            strokeEdit(StrokeTool::Melt, 0.08, {{0.0, 0.5, 0.0}, {0.2, 0.45, 0.0}}, 3.0),
            perturbEdit(QuadricShape::Ellipsoid, {0.0, 0.0, 0.5}, {0.15, 0.08, 0.1}, 4.0),
            perturbEdit(QuadricShape::Torus, {0.0, -0.5, 0.0}, {0.1, 0.04, 0.0}, -3.0),
            inflateEdit(0.09, {{0.0, 0.0, 0.5}, {0.1, 0.05, 0.48}}, Falloff::Smooth, 1.5),
            inflateEdit(0.07, {{-0.3, 0.38, 0.1}, {-0.35, 0.3, 0.2}}, Falloff::Constant, -2.0),
            smoothEdit(0.1, {{0.0, -0.49, 0.0}, {0.05, -0.48, 0.1}, {0.1, -0.45, 0.15}}, Falloff::Linear, 0.8),
            smoothEdit(0.08, {{0.48, 0.0, 0.1}, {0.47, 0.1, 0.1}}, Falloff::Sharp, 1.0)};
}

TEST(EditField, TapeEqualsTheDoubleExpression) {
    EditList list(kUnits, 32 * kVoxel);
    for (Edit& e : everyTool()) list.append(std::move(e));
    const frep::Tape tape = editTape(list, list.all());
    frep::BatchEvaluator<double> eval(tape);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    std::vector<double> x(4000), y(4000), z(4000), w(4000), out(4000);
    for (std::size_t i = 0; i < x.size(); ++i) {
        x[i] = u(rng); y[i] = u(rng); z[i] = u(rng);
        w[i] = sphereBase(x[i], y[i], z[i]);
    }
    frep::ErrorReport errors;
    eval.evaluate(x.data(), y.data(), z.data(), w.data(), out.data(), x.size(), errors);
    EXPECT_EQ(errors.count, 0u);
    int changed = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double ref = editedValue(list, w[i], x[i], y[i], z[i]);
        ASSERT_EQ(out[i], ref) << i;
        changed += ref != w[i];
    }
    EXPECT_GT(changed, 50);  // the edits did something
}

TEST(EditField, EachToolChangesTheFieldInsideItsReachOnly) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Edit& e : everyTool()) {
        EditList list(kUnits, 32 * kVoxel);
        list.append(std::move(e));
        const Edit& edit = list.edits()[0];
        SCOPED_TRACE(describe(edit));
        int in = 0, changedInside = 0;
        for (int i = 0; i < 200000; ++i) {
            const double x = u(rng), y = u(rng), z = u(rng);
            const double f = sphereBase(x, y, z);
            const double g = editedValue(list, f, x, y, z);
            EXPECT_LE(std::fabs(g), 3.0);
            if (inside(edit.reach, x, y, z)) {
                ++in;
                changedInside += g != f;
            } else if (g != f) {
                ADD_FAILURE() << "changed outside its reach at (" << x << ", " << y << ", " << z << "): " << f
                              << " -> " << g;
                return;
            }
        }
        EXPECT_GT(in, 0);
        EXPECT_GT(changedInside, 0);
    }
}

TEST(Impacts, DepthRemovesTheCompactionVolumeFromAFlatSurface) {
    const double kPi = 3.14159265358979323846;
    for (double v : {1e-7, 1e-6, 1e-5}) {
        const double r = 0.02, d = impactDepth(ImpactShape::Sphere, r, v);
        EXPECT_NEAR(kPi * d * d * (3 * r - d) / 3, v, 1e-9 * v + 1e-15);
        const double c = impactDepth(ImpactShape::Chisel, 0.03, v);
        EXPECT_NEAR(0.03 * c * c, v, 1e-12);
        EXPECT_NEAR(impactDepth(ImpactShape::Square, 0.04, v) * 0.04 * 0.04, v, 1e-15);
    }
    // Too much for the tool: it goes in all the way, no further.
    EXPECT_EQ(impactDepth(ImpactShape::Sphere, 0.01, 1.0), 0.02);
}

TEST(Impacts, RaysAreDrawnFromTheSeedAndTheSpread) {
    ImpactTool t;
    t.count = 500;
    t.spreadSize = 0.1;
    const ImpactRay aim{{0, 0, 1}, {0, 0, -1}};
    const auto a = drawImpactRays(aim, t), b = drawImpactRays(aim, t);
    ASSERT_EQ(a.size(), 500u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].origin, b[i].origin);
        EXPECT_LE(std::hypot(a[i].origin[0], a[i].origin[1]), 0.1 + 1e-12);  // a disc across the aim
    }
    t.seed = 2;
    EXPECT_NE(drawImpactRays(aim, t)[0].origin, a[0].origin);
    t.spread = ImpactSpread::Cone;
    t.spreadSize = 0.2;
    for (const ImpactRay& r : drawImpactRays(aim, t)) {
        EXPECT_EQ(r.origin, aim.origin);
        EXPECT_GE(-r.direction[2], std::cos(0.2) - 1e-12);
    }
    t.spread = ImpactSpread::Gaussian;
    t.spreadSize = 0.05;
    double sum2 = 0.0;
    const auto g = drawImpactRays(aim, t);
    for (const ImpactRay& r : g) sum2 += r.origin[0] * r.origin[0] + r.origin[1] * r.origin[1];
    EXPECT_NEAR(std::sqrt(sum2 / (2.0 * static_cast<double>(g.size()))), 0.05, 0.006);  // sigma per axis
}

TEST(EditField, StrokeSurfaceHasTheToolRadius) {
    for (double radiusVoxels : {2.0, 8.0, 16.0, 32.0}) {
        const double r = radiusVoxels * kVoxel;
        Stroke s;
        s.radius = r;
        s.path = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}};
        extendStrokeSegments(s, 0, kUnits);
        ASSERT_GT(s.segments.size(), 8u);
        // The union of segment fields across the stroke's middle.
        const auto field = [&](double x, double d) {
            double g = strokeFloor(s, kUnits);
            for (const StrokeSegment& seg : s.segments) g = std::max(g, segmentField(x, d, 0.0, seg, strokeFloor(s, kUnits), 3.0));
            return g;
        };
        for (double x : {0.0, 0.013, 0.5 * strokeStep(r, kVoxel)}) {
            const double onSurface = field(x, r);
            EXPECT_NEAR(onSurface, 0.0, 0.3) << radiusVoxels << " voxels at x " << x;  // within a third of a voxel
            EXPECT_GT(field(x, r - kVoxel), onSurface);
            EXPECT_LT(field(x, r + kVoxel), onSurface);
        }
        // About one unit per voxel at the surface.
        const double slope = field(0.0, r - 0.5 * kVoxel) - field(0.0, r + 0.5 * kVoxel);
        EXPECT_NEAR(slope, 1.0, 0.1) << radiusVoxels;
    }
}

TEST(EditField, FieldStaysBoundedAtAThousandEdits) {
    EditList list(kUnits, 32 * kVoxel);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.6, 0.6);
    for (int i = 0; i < 1000; ++i) {
        const StrokeTool tool = i % 3 == 0 ? StrokeTool::Carve : i % 3 == 1 ? StrokeTool::Add : StrokeTool::Melt;
        const ModelPoint a{u(rng), u(rng), u(rng)};
        list.append(strokeEdit(tool, 0.03, {a, {a[0] + 0.02, a[1], a[2]}}));
    }
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        const double x = u(rng), y = u(rng), z = u(rng);
        const double v = editedValue(list, sphereBase(x, y, z), x, y, z);
        ASSERT_TRUE(std::isfinite(v));
        worst = std::max(worst, std::fabs(v));
    }
    EXPECT_LE(worst, 3.0);
    // The spatial index hands a small box a few pieces of the thousand.
    frep::Box3 small;
    for (int a = 0; a < 3; ++a) { small.lo[a] = 0.0; small.hi[a] = 0.05; }
    std::size_t pieces = 0;
    for (const EditPick& p : list.reaching(small)) pieces += p.pieces.size();
    EXPECT_LT(pieces, list.indexedPieces() / 20);
}

// --- the grid ------------------------------------------------------------

TEST(SculptureEdits, BoxUpdatesEqualARebuildThroughUndoAndRedo) {
    voxel::Volume shown = test::ballVolume();
    const voxel::Volume untouched = shown.clone();
    SculptureEdits edits(shown);
    const double v = shown.frame.voxelSize;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    for (int i = 0; i < 40; ++i) {
        const ModelPoint a{u(rng), u(rng), u(rng)};
        if (i % 5 == 4) {
            Perturbation p;
            p.center = a;
            p.radii = {6 * v, 4 * v, 5 * v};
            p.strength = (i % 2 ? 1.0 : -1.0) * 2.5;
            Edit e;
            e.op = p;
            edits.append(std::move(e));
        } else {
            const StrokeTool tools[] = {StrokeTool::Carve, StrokeTool::Add, StrokeTool::Melt, StrokeTool::Smooth,
                                        StrokeTool::Inflate};
            const StrokeTool tool = tools[(i + i / 5) % 5];
            Stroke s;
            s.tool = tool;
            // Smooth fits its segments to the grid as they are drawn (the
            // first point, then the rest a frame later): the rebuild must
            // use those fits, not fit again.
            if (tool == StrokeTool::Smooth) s.strength = 0.9;
            if (tool == StrokeTool::Inflate) s.strength = i % 2 ? 1.5 : -2.0;
            s.falloff = static_cast<Falloff>(i % 4);
            s.radius = (2.0 + i % 4 * 3.0) * v;
            s.path = {a, {a[0] + 0.1, a[1] + 0.05, a[2]}};
            Edit e;
            e.op = s;
            // Live: the first point, then the rest of the path a frame later.
            auto& st = std::get<Stroke>(e.op);
            const ModelPoint last = st.path[1];
            st.path.pop_back();
            extendStrokeSegments(st, 0, edits.units());
            edits.append(std::move(e));
            // (the stroke grows as the hand moves)
            edits.extendLastStroke({last});
        }
        if (i % 7 == 6) {
            ASSERT_TRUE(edits.undo());
            if (i % 2) {
                ASSERT_TRUE(edits.redo());
            }
        }
    }
    EXPECT_EQ(test::differingVoxels(shown, *edits.rebuild()), 0);
    EXPECT_GT(test::differingVoxels(shown, untouched), 1000);
    // Undo everything: the grid of a session that never edited.
    while (edits.undo()) {}
    EXPECT_EQ(test::differingVoxels(shown, untouched), 0);
    // Redo everything: back to the edited grid.
    while (edits.redo()) {}
    EXPECT_EQ(test::differingVoxels(shown, *edits.rebuild()), 0);
}

TEST(SculptureEdits, AStrokeChangesTheGridInsideItsBoxOnly) {
    voxel::Volume shown = test::ballVolume();
    const voxel::Volume before = shown.clone();
    SculptureEdits edits(shown);
    Stroke s;
    s.tool = StrokeTool::Carve;
    s.radius = 6 * shown.frame.voxelSize;
    s.path = {{0.5, 0.0, 0.0}, {0.45, 0.15, 0.0}};
    extendStrokeSegments(s, 0, edits.units());
    Edit e;
    e.op = s;
    const voxel::IndexBox box = edits.append(std::move(e));
    int changedInside = 0;
    const voxel::IndexBox& all = shown.frame.indexBox;
    for (int i = all.lo[0]; i <= all.hi[0]; ++i)
        for (int j = all.lo[1]; j <= all.hi[1]; ++j)
            for (int k = all.lo[2]; k <= all.hi[2]; ++k) {
                const bool changed = shown.value(i, j, k) != before.value(i, j, k);
                if (box.contains(i, j, k)) changedInside += changed;
                else ASSERT_FALSE(changed) << i << " " << j << " " << k;
            }
    EXPECT_GT(changedInside, 100);
    // The box is about the stroke: its radius plus a few voxels around the path.
    EXPECT_LT(box.extent(0), 40);
    // The carve cut into the sphere: a voxel on the path inside the sphere is now outside.
    const int ci = shown.frame.indexOf(0, 0.47), cj = shown.frame.indexOf(1, 0.0), ck = shown.frame.indexOf(2, 0.0);
    EXPECT_GT(before.value(ci, cj, ck), 0.0f);
    EXPECT_LT(shown.value(ci, cj, ck), 0.0f);
}

}  // namespace
}  // namespace hg::garden
