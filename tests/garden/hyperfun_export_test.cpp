// Exact HyperFun export (garden/export/hyperfun_export.h): the exported
// text of real sessions parses without a diagnostic and our interpreter
// evaluates its my_model to the sculpture's field in double, value for
// value (every tool, mirror, moves, the morph result); an unedited
// sculpture evaluates like its source; thousands of edits stay bounded and
// give the session's surface; a garden opened on the exported file gives
// the same sculpture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>

#include "frep/language/interpreter.h"
#include "frep/eval/model.h"
#include "frep/language/parser.h"
#include "frep/eval/tape_specializer.h"
#include "voxel/sampler.h"
#include "garden/app/garden_session.h"
#include "garden/export/export_field.h"
#include "garden/export/hyperfun_export.h"
#include "garden/morph/morph_sources.h"
#include "garden/sculpt/edit_list.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"
#include "two_morph_garden.h"

namespace hg::garden {
namespace {

class HyperFunExportTest : public test::SmallGarden {};

// Every sample of a blend in one frame, every chunk remeshed, one level.
SessionSettings smallSettings() {
    SessionSettings s = test::smallSessionSettings();
    s.morphSamplesPerFrame = 200000;
    s.remeshChunksPerFrame = 64;
    s.maxLevel = 0;
    return s;
}

void finishMorph(GardenSession& s) {
    for (int f = 0; f < 4000 && !s.idle(); ++f) {
        s.frame(FrameInput(Hands{}, 1.0 / 90.0));
    }
    ASSERT_TRUE(s.idle());
}

const frep::Model& sourceModel(const GardenSession& s, std::size_t index) { return *s.load().sculptures[index].model; }

// The field the export must give, in double: the source's value (as its
// file gives it when unedited; normalized and clamped as the grid holds it
// when edited) or the morph's blend, then every edit in order through the
// edit list's own double reference.
class ReferenceField {
public:
    ReferenceField(const GardenSession& s, int index) : s_(s), sculpture_(s.sculptures()[static_cast<std::size_t>(index)]) {
        edited_ = sculpture_.edits && !sculpture_.edits->list().empty();
        if (sculpture_.morphResult()) {
            const MorphSpec& m = *s.morphSpec(index);
            for (std::size_t i = 0; i < 3; ++i) add(sourceModel(s, m.sourceIndex[i]));
            blend_.normalization = s.morphSources(index)->normalization;
            blend_.w = s.morphWeights(index)->w;
            blend_.band = s.morphSources(index)->frame.band;
        } else {
            add(sourceModel(s, static_cast<std::size_t>(index)));
        }
    }
    // False when a source fails at the point (none of the tests' shapes do).
    bool operator()(double x, double y, double z, double& out) {
        std::vector<double> f;
        for (auto& in : sources_) {
            const frep::PointResult r = in->evaluate(x, y, z);
            if (!r.ok()) return false;
            f.push_back(r.value);
        }
        double base;
        if (sculpture_.morphResult()) base = morphBlendField(f[0], f[1], f[2], blend_);
        else if (edited_) base = normalizedSourceField(f[0], sculpture_.edits->base().normalization, sculpture_.edits->units().band);
        else base = f[0];
        out = edited_ ? editedValue(sculpture_.edits->list(), base, x, y, z) : base;
        return true;
    }

private:
    void add(const frep::Model& m) {
        sources_.push_back(std::make_unique<frep::Interpreter>(m.program(), m.bodyIndex(), m.parameters()));
    }
    const GardenSession& s_;
    const Sculpture& sculpture_;
    bool edited_ = false;
    std::vector<std::unique_ptr<frep::Interpreter>> sources_;
    MorphBlendConstants blend_;
};

struct Parsed {
    std::unique_ptr<frep::Program> program;
    int body = -1;
};

Parsed parseExport(const std::string& text) {
    frep::ParseResult r = frep::parseProgram(text, "export.hf");
    Parsed p;
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.errors) ADD_FAILURE() << "diagnostic: line " << d.loc.line << ": " << d.message;
    if (!r.ok()) return p;
    p.program = std::make_unique<frep::Program>(std::move(*r.program));
    p.body = p.program->findBody("my_model");
    EXPECT_GE(p.body, 0);
    return p;
}

HyperFunExport exportOf(const GardenSession& s, int index) {
    HyperFunExport r = exportHyperFun(s, index);
    EXPECT_EQ(r.error, "");
    EXPECT_FALSE(r.text.empty());
    return r;
}

// Random points in the sculpture's model box grown by a quarter on each side.
std::vector<std::array<double, 3>> pointsAround(const Sculpture& s, int n, unsigned seed) {
    const frep::Box3& b = s.volume->frame.modelBox;
    std::mt19937 rng(seed);
    std::vector<std::array<double, 3>> out;
    for (int i = 0; i < n; ++i) {
        std::array<double, 3> p{};
        for (int a = 0; a < 3; ++a) {
            const double w = b.hi[a] - b.lo[a];
            p[a] = std::uniform_real_distribution<double>(b.lo[a] - 0.25 * w, b.hi[a] + 0.25 * w)(rng);
        }
        out.push_back(p);
    }
    return out;
}

// The exported my_model equals the reference at `n` random points, ==.
void expectExact(const GardenSession& s, int index, int n, unsigned seed = 1) {
    const HyperFunExport e = exportOf(s, index);
    const Parsed p = parseExport(e.text);
    ASSERT_TRUE(p.program && p.body >= 0);
    frep::Interpreter exported(*p.program, p.body);
    ReferenceField reference(s, index);
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(index)];
    int differing = 0, inside = 0, outside = 0;
    for (const auto& q : pointsAround(sc, n, seed)) {
        double want = 0.0;
        ASSERT_TRUE(reference(q[0], q[1], q[2], want));
        const frep::PointResult got = exported.evaluate(q[0], q[1], q[2]);
        ASSERT_TRUE(got.ok()) << "runtime error at " << q[0] << " " << q[1] << " " << q[2] << " line " << got.loc.line;
        if (got.value != want && ++differing <= 5)
            ADD_FAILURE() << "at (" << q[0] << ", " << q[1] << ", " << q[2] << "): exported " << got.value
                          << ", field " << want;
        (want > 0 ? inside : outside) += 1;
    }
    EXPECT_EQ(differing, 0) << sc.name;
    // The points saw both sides of the surface.
    EXPECT_GT(inside, n / 50) << sc.name;
    EXPECT_GT(outside, n / 50) << sc.name;
}

// The largest difference between the exported field and the session's grid
// (float: the sampler and the edit tape run in float) over `n` random voxel
// centres, in voxels.
double gridDifference(const GardenSession& s, int index, int n) {
    const Parsed p = parseExport(exportOf(s, index).text);
    if (!p.program || p.body < 0) return 1e30;
    frep::Interpreter exported(*p.program, p.body);
    const voxel::Volume& v = *s.sculptures()[static_cast<std::size_t>(index)].volume;
    const voxel::IndexBox& box = v.frame.indexBox;
    std::mt19937 rng(21);
    double worst = 0.0;
    for (int m = 0; m < n; ++m) {
        int ijk[3];
        for (int a = 0; a < 3; ++a) ijk[a] = std::uniform_int_distribution<int>(box.lo[a], box.hi[a])(rng);
        const auto q = v.frame.position(ijk[0], ijk[1], ijk[2]);
        const double e = exported.evaluate(q[0], q[1], q[2]).value;
        worst = std::max(worst, std::fabs(e - static_cast<double>(v.value(ijk[0], ijk[1], ijk[2]))));
    }
    return worst;
}

TEST_F(HyperFunExportTest, AnUneditedSculptureEvaluatesLikeItsSourceFile) {
    // A source of two bodies, the second calling the first, without a[].
    write("plain.hf",
          "inner(x[3], a[1]) { inner = 0.36 - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n"
          "my_model(x[3], a[1]) { array c[3]; c = [0.2, 0.5, 0]; my_model = inner(x, a) | hfSphere(x, c, 0.3); }\n");
    // A source that declares s[] and whose body's value depends on it.
    write("withs.hf",
          "helper(x[3], a[1], s[2]) { s[1] = x[1] * 2; s[2] = a[1] + 1; helper = x[2]; }\n"
          "my_model(x[3], a[1], s[2]) { s = [0.5, -2]; before = s[1] + s[2]; v = helper(x, a, s);\n"
          "   my_model = 0.3 - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2) + 0.01 * (v + s[1] + s[2] + before); }\n");
    GardenSession s(loadGarden(writeGarden(nlohmann::json::parse(R"({"sculptures": [
        {"name": "plain", "file": "plain.hf", "resolution": 32, "box": {"min": [-0.7, -0.2, -0.7], "max": [0.7, 1.2, 0.7]}},
        {"name": "withs", "file": "withs.hf", "a": [0.2], "resolution": 32, "box": {"min": [-0.7, -0.2, -0.7], "max": [0.7, 1.2, 0.7]}},
        {"name": "a", "file": "ball.hf", "a": [0.25], "resolution": 32,
         "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}}], "morph": null})"))),
                    smallSettings());
    const int plain = s.findSculpture("plain"), a = s.findSculpture("a");
    // Without a[] the source body itself is my_model; the body it calls
    // comes first, renamed.
    const HyperFunExport e = exportOf(s, plain);
    EXPECT_NE(e.text.find("src_inner(x[3], a[1])"), std::string::npos) << e.text;
    EXPECT_NE(e.text.find("my_model = src_inner(x, a) | hfSphere(x, c, 0.3);"), std::string::npos) << e.text;
    EXPECT_LT(e.text.find("src_inner("), e.text.find("my_model("));
    expectExact(s, plain, 2000);
    // With a[] my_model calls it with the garden's values.
    EXPECT_NE(exportOf(s, a).text.find("sa = [0.25]"), std::string::npos);
    expectExact(s, a, 2000);
    // A body with s[] gets a fresh s[] of its size, unedited and edited.
    const int withs = s.findSculpture("withs");
    EXPECT_NE(exportOf(s, withs).text.find("src_my_model(x, sa, ss)"), std::string::npos);
    expectExact(s, withs, 2000);
    const glm::vec3 c = s.sculptures()[static_cast<std::size_t>(withs)].worldCentre();
    ASSERT_EQ(s.applyPerturbation(withs, QuadricShape::Ellipsoid, {c.x, c.y + 0.5, c.z}, {0.2, 0.1, 0.2}, 3.0), "");
    expectExact(s, withs, 2000);
}

TEST_F(HyperFunExportTest, EveryToolMirrorAndMoveExportExactly) {
    GardenSession s(loadGarden(writeGarden()), smallSettings());
    const int c = s.findSculpture("c");  // a ball of radius 0.6 about (2, 0.5, 1.1547)
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{1.7, 0.9, 1.5}, {2.0, 1.0, 1.6}, {2.3, 0.9, 1.5}}, 0.1), "");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Add, {{2.6, 0.5, 1.15}, {2.8, 0.6, 1.15}}, 0.1), "");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Melt, {{2.0, 1.05, 1.0}, {2.1, 1.1, 1.2}}, 0.12, 2.5), "");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 0.0, 1.15}, {0.15, 0.1, 0.2}, 2.0), "");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Torus, {1.5, 0.5, 1.15}, {0.15, 0.05, 0.0}, -2.0), "");
    ImpactTool t;
    t.shape = ImpactShape::Chisel;
    t.size = 0.05;
    t.volume = 8e-6;
    t.count = 4;
    t.spreadSize = 0.2;
    t.seed = 3;
    ASSERT_EQ(s.applyImpacts(c, {2.0, 0.5, 4.0}, {0.0, 0.0, -1.0}, t), "");
    t.shape = ImpactShape::Square;
    ASSERT_EQ(s.applyImpacts(c, {2.0, 3.0, 1.1547}, {0.0, -1.0, 0.0}, t), "");
    t.shape = ImpactShape::Sphere;
    ASSERT_EQ(s.applyImpacts(c, {4.0, 0.5, 1.1547}, {-1.0, 0.0, 0.0}, t), "");
    // Moved, turned and scaled: later edits are in the same model frame.
    Placement p = s.sculptures()[static_cast<std::size_t>(c)].placement;
    p.position = {2.5, 0.0, 1.0};
    p.yawDegrees = 30.0;
    p.scale = 1.5;
    ASSERT_EQ(s.moveSculpture(c, p), "");
    s.setMirror(c, MirrorPlane{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    const glm::vec3 centre = s.sculptures()[static_cast<std::size_t>(c)].worldCentre();
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{centre.x + 0.5, centre.y + 0.6, centre.z}, {centre.x + 0.6, centre.y + 0.3, centre.z + 0.3}}, 0.12), "");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {centre.x + 0.7, centre.y - 0.2, centre.z}, {0.12, 0.12, 0.12}, 2.5), "");
    // Smooth (its fits journalled with it) and inflate, mirrored too.
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Smooth, {{centre.x - 0.2, centre.y + 0.85, centre.z}, {centre.x + 0.1, centre.y + 0.85, centre.z + 0.2}},
                            0.15, 2.0, 0.8, Falloff::Linear), "");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Inflate, {{centre.x, centre.y, centre.z + 0.85}, {centre.x + 0.2, centre.y + 0.2, centre.z + 0.8}},
                            0.12, 2.0, -1.5, Falloff::Sharp), "");
    ASSERT_EQ(s.editCount(c), 12u);
    const HyperFunExport e = exportOf(s, c);
    EXPECT_EQ(e.edits, 12u);
    for (const char* what : {"smooth stroke", "strength 0.8, linear falloff", "inflate stroke", "strength -1.5 voxels, sharp falloff",
                             "carve stroke", "add stroke", "melt stroke", "softness 2.5", "ellipsoid perturbation",
                             "torus perturbation", "impacts of a chisel", "impacts of a square", "impacts of a sphere",
                             "mirrored across", "turned 30 degrees", "1.5 m per model unit", "hfConvLine(x, segb, sege, segs, 0)"})
        EXPECT_NE(e.text.find(what), std::string::npos) << what;
    expectExact(s, c, 4000);
    // And the grid the session shows, to float rounding (a few 1e-6 voxels).
    EXPECT_LT(gridDifference(s, c, 4000), 1e-4);
}

// Sketches joined, cut and mirrored export to the same values: the export
// writes each cone piece with the same template the grid's tape uses.
TEST_F(HyperFunExportTest, SketchesExportExactly) {
    GardenSession s(loadGarden(writeGarden()), smallSettings());
    const int c = s.findSculpture("c");
    std::vector<std::array<double, 3>> round, oval;
    for (int i = 0; i < 48; ++i) {
        const double t = 2.0 * 3.14159265358979323846 * i / 48;
        round.push_back({2.0 + 0.25 * std::cos(t), 0.5 + 0.25 * std::sin(t), 1.65});
        oval.push_back({2.0 + 0.35 * std::cos(t), 1.1, 1.1547 + 0.12 * std::sin(t)});
    }
    ASSERT_EQ(s.applySketch(c, SketchMode::Add, round, {0.0, 0.0, 1.0}), "");
    ASSERT_EQ(s.applySketch(c, SketchMode::Cut, oval, {0.0, 1.0, 0.0}, 0.6), "");
    s.setMirror(c, MirrorPlane{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}});
    std::vector<std::array<double, 3>> side;
    for (const auto& p : round) side.push_back({p[0] + 0.3 + 0.4 * (p[0] - 2.0), p[1] - 0.2, p[2] - 0.1});
    ASSERT_EQ(s.applySketch(c, SketchMode::Cut, side, {0.2, 0.0, 1.0}), "");
    const HyperFunExport e = exportOf(s, c);
    EXPECT_NE(e.text.find("sketch joined"), std::string::npos);
    EXPECT_NE(e.text.find("sketch cut"), std::string::npos);
    expectExact(s, c, 4000);
    expectExact(s, c, 4000, 7);
    EXPECT_LT(gridDifference(s, c, 4000), 1e-4);
}

TEST_F(HyperFunExportTest, TheMorphResultExportsItsBlendAndItsEditsExactly) {
    GardenSession s(loadGarden(writeGarden()), smallSettings());
    finishMorph(s);
    const int m = s.findSculpture("metamorphosis");
    s.setMorphWeights({0.5, 0.3, 0.2});
    finishMorph(s);
    const HyperFunExport plain = exportOf(s, m);
    EXPECT_NE(plain.text.find("m1_ball(x[3], a[1])"), std::string::npos);
    EXPECT_NE(plain.text.find("m3_ball(x[3], a[1])"), std::string::npos);
    expectExact(s, m, 2000);
    EXPECT_LT(gridDifference(s, m, 4000), 1e-4);
    const glm::vec3 c = s.sculptures()[static_cast<std::size_t>(m)].worldCentre();
    ASSERT_EQ(s.applyStroke(m, StrokeTool::Carve, {{c.x - 0.4, c.y + 0.1, c.z}, {c.x + 0.4, c.y + 0.1, c.z}}, 0.12), "");
    ASSERT_EQ(s.applyPerturbation(m, QuadricShape::Ellipsoid, {c.x, c.y + 0.5, c.z}, {0.2, 0.1, 0.2}, 3.0), "");
    const HyperFunExport edited = exportOf(s, m);
    // The sources do not declare s[]: the blend sets its own back to 0
    // between their calls, as a Model starts each with s[] at 0.
    EXPECT_NE(edited.text.find("hg_morph(x[3], a[1], s[1])"), std::string::npos);
    EXPECT_NE(edited.text.find("s = [0];"), std::string::npos);
    EXPECT_NE(edited.text.find("= hg_morph(x, a);"), std::string::npos);
    expectExact(s, m, 3000);
    EXPECT_LT(gridDifference(s, m, 4000), 1e-4);
}

TEST_F(HyperFunExportTest, EachMorphOfAGardenExportsItsOwnSourcesAndWeights) {
    GardenSession s(loadGarden(test::writeTwoMorphGarden(dir)), smallSettings());
    const int second = s.findSculpture("second");
    s.select(second);
    s.setMorphWeights({0.2, 0.5, 0.3});
    finishMorph(s);
    const HyperFunExport e = exportOf(s, second);
    EXPECT_NE(e.text.find("sculpture 'd'"), std::string::npos) << "the second morph's sources, not the first's";
    EXPECT_EQ(e.text.find("sculpture 'a'"), std::string::npos);
    expectExact(s, second, 2000);
    EXPECT_LT(gridDifference(s, second, 4000), 1e-4);
    const int first = s.findSculpture("metamorphosis");
    EXPECT_NE(exportOf(s, first).text.find("sculpture 'a'"), std::string::npos);
    expectExact(s, first, 1000);
}

// Edits in the model frame of ball c (radius 0.6 about (0, 0.5, 0)): short
// strokes of every tool and perturbations all over its surface.
std::vector<Action> manyEdits(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Action> out;
    for (int i = 0; i < n; ++i) {
        std::array<double, 3> d{u(rng), u(rng), u(rng)};
        const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-9;
        const double r = 0.55 + 0.1 * u(rng);
        const ModelPoint p{r * d[0] / l, 0.5 + r * d[1] / l, r * d[2] / l};
        if (i % 3 == 2) {
            PerturbAction rec;
            rec.sculpture = "c";
            rec.perturbation.center = p;
            rec.perturbation.radii = {0.08, 0.06, 0.07};
            rec.perturbation.strength = u(rng) > 0 ? 2.0 : -2.0;
            out.push_back(rec);
        } else {
            StrokeAction rec;
            rec.sculpture = "c";
            rec.tool = i % 3 == 0 ? StrokeTool::Carve : (i % 2 ? StrokeTool::Add : StrokeTool::Melt);
            rec.radius = 0.05;
            rec.path = {p, {p[0] + 0.03, p[1] + 0.02, p[2]}};
            out.push_back(rec);
        }
    }
    return out;
}

// The grid updates and the rebuild run each leaf with the edit tape
// specialized to it (voxel/edit_region.cpp): the grids are the ones the
// full tapes give, bit for bit, and so is the exported file's sampling.
TEST(SpecializedEdits, GridsAndTheExportedFileAreTheSameWithAndWithoutSpecialization) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hg_spec_edits_" + std::to_string(::getpid()));
    const std::string garden = test::writeSmallGarden(dir, nlohmann::json::parse(R"({"morph": null})"));
    std::unique_ptr<GardenSession> with, without;
    frep::setSpecialization(false);
    without = std::make_unique<GardenSession>(loadGarden(garden), smallSettings());
    ASSERT_EQ(without->restore(manyEdits(400, 3)), "");
    frep::setSpecialization(true);
    with = std::make_unique<GardenSession>(loadGarden(garden), smallSettings());
    ASSERT_EQ(with->restore(manyEdits(400, 3)), "");
    std::filesystem::remove_all(dir);
    const int c = with->findSculpture("c");
    const Sculpture& a = with->sculptures()[static_cast<std::size_t>(c)];
    const Sculpture& b = without->sculptures()[static_cast<std::size_t>(c)];
    EXPECT_EQ(test::differingVoxels(*a.volume, *b.volume), 0);
    EXPECT_EQ(test::differingVoxels(*a.edits->rebuild(), *b.volume), 0);
    // The exported file voxelized both ways.
    const HyperFunExport e = exportOf(*with, c);
    const Parsed p = parseExport(e.text);
    ASSERT_TRUE(p.program && p.body >= 0);
    const frep::Model model(std::shared_ptr<const frep::Program>(p.program.get(), [](const frep::Program*) {}), p.body);
    voxel::VolumeRequest req;
    req.resolution = 48;
    req.box = a.volume->frame.modelBox;
    frep::setSpecialization(false);
    const voxel::VoxelizeResult full = voxel::voxelize(model, req);
    frep::setSpecialization(true);
    const voxel::VoxelizeResult fast = voxel::voxelize(model, req);
    ASSERT_TRUE(full.volume && fast.volume);
    EXPECT_EQ(test::differingVoxels(*full.volume, *fast.volume), 0);
    EXPECT_LT(fast.stats.leafTapeMean, 0.5 * full.stats.leafTapeMean);
}

// Thousands of edits: the exported values stay finite and within the band,
// and have the grid's sign at voxel centres away from its surface.
void expectBoundedAndOnTheGrid(int edits) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("hg_export_many_" + std::to_string(::getpid()) + "_" + std::to_string(edits));
    GardenSession s(loadGarden(test::writeSmallGarden(dir, nlohmann::json::parse(R"({"morph": null})"))), smallSettings());
    std::filesystem::remove_all(dir);
    ASSERT_EQ(s.restore(manyEdits(edits, 11)), "");
    const int c = s.findSculpture("c");
    ASSERT_EQ(s.editCount(c), static_cast<std::size_t>(edits));
    const HyperFunExport e = exportOf(s, c);
    EXPECT_EQ(e.edits, static_cast<std::size_t>(edits));
    const Parsed p = parseExport(e.text);
    ASSERT_TRUE(p.program && p.body >= 0);
    // The batch evaluator (the interpreter's values, faster) over voxel
    // centres picked at random.
    const frep::Model model(std::shared_ptr<const frep::Program>(p.program.get(), [](const frep::Program*) {}), p.body);
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(c)];
    const voxel::VolumeFrame& fr = sc.volume->frame;
    const double band = sc.edits->units().band;
    std::mt19937 rng(5);
    std::vector<double> xs, ys, zs;
    std::vector<float> grid;
    for (int n = 0; n < 4000; ++n) {
        int ijk[3];
        for (int a = 0; a < 3; ++a) ijk[a] = std::uniform_int_distribution<int>(fr.indexBox.lo[a], fr.indexBox.hi[a])(rng);
        const auto q = fr.position(ijk[0], ijk[1], ijk[2]);
        xs.push_back(q[0]);
        ys.push_back(q[1]);
        zs.push_back(q[2]);
        grid.push_back(sc.volume->value(ijk[0], ijk[1], ijk[2]));
    }
    std::vector<double> v(xs.size());
    frep::ErrorReport errors;
    frep::PointSampler<double>(model).evaluate(xs.data(), ys.data(), zs.data(), v.data(), v.size(), errors);
    int compared = 0, inside = 0, wrongSign = 0, unbounded = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i]) || std::fabs(v[i]) > band) ++unbounded;
        if (std::fabs(grid[i]) <= 0.5f) continue;
        ++compared;
        inside += grid[i] > 0;
        if ((v[i] > 0) != (grid[i] > 0)) ++wrongSign;
    }
    EXPECT_EQ(unbounded, 0);
    EXPECT_EQ(wrongSign, 0) << "of " << compared;
    EXPECT_GT(compared, 3000);
    EXPECT_GT(inside, 300);
    // And exactly the field at a few points (the scalar interpreter).
    frep::Interpreter exported(*p.program, p.body);
    ReferenceField reference(s, c);
    for (const auto& q : pointsAround(sc, edits > 1000 ? 20 : 200, 9)) {
        double want = 0.0;
        ASSERT_TRUE(reference(q[0], q[1], q[2], want));
        EXPECT_EQ(exported.evaluate(q[0], q[1], q[2]).value, want);
    }
}

TEST(HyperFunExportMany, AThousandEditsStayBoundedAndGiveTheGridsSurface) { expectBoundedAndOnTheGrid(1000); }

TEST(HyperFunExportMany, TenThousandEditsStayBoundedAndGiveTheGridsSurface) { expectBoundedAndOnTheGrid(10000); }

// A garden of one sculpture, the exported file, in the frame of ball c.
std::string gardenOn(const std::filesystem::path& dir, const std::string& file) {
    std::ofstream(dir / "roundtrip.json") << R"({"version": 1, "name": "roundtrip", "sculptures": [
        {"name": "back", "file": ")" + file + R"(", "resolution": 32,
         "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}}]})";
    return (dir / "roundtrip.json").string();
}

TEST_F(HyperFunExportTest, OpeningTheExportInAGardenGivesTheSameSculpture) {
    GardenSession s(loadGarden(writeGarden(nlohmann::json::parse(R"({"morph": null})"))), smallSettings());
    const int a = s.findSculpture("a"), c = s.findSculpture("c");
    ASSERT_EQ(s.restore(manyEdits(60, 3)), "");
    ASSERT_EQ(exportSculptureHyperFun(s, a, (dir / "a.hf").string()), "");
    ASSERT_EQ(exportSculptureHyperFun(s, c, (dir / "c.hf").string()), "");
    // Unedited: the same grid, value for value.
    {
        GardenSession back(loadGarden(gardenOn(dir, "a.hf")), smallSettings());
        const Sculpture& b = back.sculptures()[0];
        ASSERT_FALSE(b.missing()) << b.error;
        EXPECT_EQ(test::differingVoxels(*s.sculptures()[static_cast<std::size_t>(a)].volume, *b.volume), 0);
    }
    // Edited: the same surface (the grid holds the field in voxels already,
    // so the new grid's normalization is about 1 and its values close).
    GardenSession back(loadGarden(gardenOn(dir, "c.hf")), smallSettings());
    const Sculpture& b = back.sculptures()[0];
    ASSERT_FALSE(b.missing()) << b.error;
    const voxel::Volume& original = *s.sculptures()[static_cast<std::size_t>(c)].volume;
    const voxel::IndexBox& box = original.frame.indexBox;
    int compared = 0, wrongSign = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const float v = original.value(i, j, k);
                if (std::fabs(v) <= 0.5f) continue;
                ++compared;
                wrongSign += (v > 0) != (b.volume->value(i, j, k) > 0);
            }
    EXPECT_GT(compared, 10000);
    EXPECT_EQ(wrongSign, 0);
    EXPECT_NEAR(b.volume->normalization, 1.0, 0.2);
}

TEST_F(HyperFunExportTest, TheEditedMorphResultOpensInAGardenWithTheSameSurface) {
    GardenSession s(loadGarden(writeGarden()), smallSettings());
    finishMorph(s);
    const int m = s.findSculpture("metamorphosis");
    const glm::vec3 c = s.sculptures()[static_cast<std::size_t>(m)].worldCentre();
    ASSERT_EQ(s.applyStroke(m, StrokeTool::Carve, {{c.x - 0.4, c.y + 0.1, c.z}, {c.x + 0.4, c.y + 0.1, c.z}}, 0.12), "");
    ASSERT_EQ(s.applyStroke(m, StrokeTool::Add, {{c.x, c.y + 0.3, c.z + 0.5}, {c.x, c.y + 0.5, c.z + 0.6}}, 0.1), "");
    ASSERT_EQ(exportSculptureHyperFun(s, m, (dir / "m.hf").string()), "");
    const voxel::Volume& original = *s.sculptures()[static_cast<std::size_t>(m)].volume;
    const frep::Box3& b = original.frame.modelBox;
    nlohmann::json g = {{"version", 1},
                        {"name", "roundtrip"},
                        {"sculptures", {{{"name", "back"},
                                         {"file", "m.hf"},
                                         {"resolution", original.frame.resolution},
                                         {"box", {{"min", {b.lo[0], b.lo[1], b.lo[2]}}, {"max", {b.hi[0], b.hi[1], b.hi[2]}}}}}}}};
    std::ofstream(dir / "m.json") << g.dump();
    GardenSession back(loadGarden((dir / "m.json").string()), smallSettings());
    const Sculpture& r = back.sculptures()[0];
    ASSERT_FALSE(r.missing()) << r.error;
    for (int a = 0; a < 3; ++a) {  // the same frame
        ASSERT_EQ(r.volume->frame.indexBox.lo[a], original.frame.indexBox.lo[a]);
        ASSERT_EQ(r.volume->frame.indexBox.hi[a], original.frame.indexBox.hi[a]);
    }
    ASSERT_EQ(r.volume->frame.voxelSize, original.frame.voxelSize);
    const voxel::IndexBox& box = original.frame.indexBox;
    int compared = 0, wrongSign = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const float v = original.value(i, j, k);
                if (std::fabs(v) <= 0.5f) continue;
                ++compared;
                wrongSign += (v > 0) != (r.volume->value(i, j, k) > 0);
            }
    EXPECT_GT(compared, 10000);
    EXPECT_EQ(wrongSign, 0);
}

TEST_F(HyperFunExportTest, AFailedWriteLeavesNoFileAndBadIndicesAreRefused) {
    GardenSession s(loadGarden(writeGarden()), smallSettings());
    EXPECT_NE(exportSculptureHyperFun(s, 0, (dir / "no" / "such" / "dir.hf").string()), "");
    EXPECT_FALSE(std::filesystem::exists(dir / "no"));
    EXPECT_NE(exportHyperFun(s, 99).error, "");
    EXPECT_NE(exportHyperFun(s, s.findSculpture("lost")).error.find("missing"), std::string::npos);
}

}  // namespace
}  // namespace hg::garden
