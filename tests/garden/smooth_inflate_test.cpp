// The smooth and inflate stroke tools in a running session
// (garden/sculpt/edit_field.h, smooth_fit.*; docs/sculpting.md "Smooth and
// inflate"): inflate raises the field by its strength on its path and moves
// the surface that far; smooth takes bumps off a patch and leaves a smooth
// surface where it was; neither changes a voxel beyond its radius; both are
// undone exactly, journal with their fits and play back bit for bit; the
// pen's pressure scales the strength the journal keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "garden/action/action.h"
#include "garden/app/garden_session.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/stroke_segments.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

// One ball of radius 0.5 about (0, 0.5, 0) at 96^3 over a 1.2 m box: 80
// voxels across the ball, 12.5 mm each; placed at the origin, so model and
// world coordinates are the same.
class SmoothInflateTest : public test::ScratchDir {
protected:
    void SetUp() override {
        ScratchDir::SetUp();
        std::ofstream(dir / "ball.hf") << "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n";
        std::ofstream(dir / "garden.json") << R"({
          "version": 1, "name": "one ball",
          "sculptures": [{"name": "ball", "file": "ball.hf", "a": [0.25], "resolution": 96,
                          "box": {"min": [-0.6, -0.1, -0.6], "max": [0.6, 1.1, 0.6]}}],
          "start": {"position": [0, 1.7, 3], "look_at": [0, 0.5, 0]}
        })";
        session = open();
        ball = session->findSculpture("ball");
        ASSERT_GE(ball, 0);
    }
    std::unique_ptr<GardenSession> open() {
        return std::make_unique<GardenSession>(loadGarden((dir / "garden.json").string()), test::smallSessionSettings());
    }
    const voxel::Volume& grid(const GardenSession& s) const { return *s.sculptures()[static_cast<std::size_t>(ball)].volume; }
    double voxel() const { return grid(*session).frame.voxelSize; }

    // The height (world y) where the column through (x, z) leaves the solid,
    // between voxel centres by linear interpolation, searched down from the top.
    static double surfaceHeight(const voxel::Volume& v, double x, double z) {
        const voxel::VolumeFrame& f = v.frame;
        const int i = f.indexOf(0, x), k = f.indexOf(2, z);
        for (int j = f.indexBox.hi[1]; j > f.indexBox.lo[1]; --j) {
            const double above = v.value(i, j, k), below = v.value(i, j - 1, k);
            if (above < 0.0 && below >= 0.0) {
                const double t = below / (below - above);
                return f.position(i, j - 1, k)[1] + t * f.voxelSize;
            }
        }
        return std::nan("");
    }
    // The distance from a voxel centre to the segment a-b.
    static double distanceToSegment(const std::array<double, 3>& p, const std::array<double, 3>& a,
                                    const std::array<double, 3>& b) {
        double ab[3], ap[3], l2 = 0.0, t = 0.0;
        for (int i = 0; i < 3; ++i) {
            ab[i] = b[i] - a[i];
            ap[i] = p[i] - a[i];
            l2 += ab[i] * ab[i];
            t += ap[i] * ab[i];
        }
        t = l2 > 0.0 ? std::clamp(t / l2, 0.0, 1.0) : 0.0;
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i) d2 += (ap[i] - t * ab[i]) * (ap[i] - t * ab[i]);
        return std::sqrt(d2);
    }

    std::unique_ptr<GardenSession> session;
    int ball = -1;
};

TEST_F(SmoothInflateTest, InflateMovesTheSurfaceByItsStrengthAndNothingBeyondItsRadius) {
    const voxel::Volume before = grid(*session).clone();
    const double v = voxel(), radius = 0.08;
    const std::array<double, 3> a{-0.1, 1.0, 0.0}, b{0.1, 1.0, 0.0};
    // The stroke's first segment reaches half a step back from its first
    // point (its round start: stroke_segments.cpp).
    const std::array<double, 3> start{a[0] - 0.5 * strokeStep(radius, v), a[1], a[2]};
    const double h0 = surfaceHeight(before, 0.0, 0.0);
    ASSERT_NEAR(h0, 1.0, 0.5 * v);
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Inflate, {a, b}, radius, 2.0, 1.5, Falloff::Constant), "");
    const voxel::Volume& after = grid(*session);
    // The surface on the path moved out by the strength, in voxels.
    EXPECT_NEAR((surfaceHeight(after, 0.0, 0.0) - h0) / v, 1.5, 0.15);
    EXPECT_NEAR((surfaceHeight(after, 0.05, 0.02) - surfaceHeight(before, 0.05, 0.02)) / v, 1.5, 0.15);
    // Well inside the radius the field rose by the strength (to the band);
    // beyond the radius no voxel changed at all.
    const voxel::IndexBox& box = before.frame.indexBox;
    int inside = 0, beyond = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const double d = distanceToSegment(before.frame.position(i, j, k), start, b);
                const double f = before.value(i, j, k), g = after.value(i, j, k);
                if (d < radius - 1.5 * v) {
                    ASSERT_NEAR(g, std::min(f + 1.5, 3.0), 1e-4) << i << " " << j << " " << k;
                    inside += f < 1.5;
                } else if (d > radius) {
                    ASSERT_EQ(g, f) << "changed beyond the radius at " << i << " " << j << " " << k;
                    ++beyond;
                }
            }
    EXPECT_GT(inside, 300);
    EXPECT_GT(beyond, 800000);
    // Undone: the grid as it was, bit for bit. Reversed (deflate): in by as much.
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(test::differingVoxels(grid(*session), before), 0);
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Inflate, {a, b}, radius, 2.0, -1.5, Falloff::Constant), "");
    EXPECT_NEAR((surfaceHeight(grid(*session), 0.0, 0.0) - h0) / v, -1.5, 0.15);
    // One stroke stays under the band either way: a surface never appears in the air.
    EXPECT_NE(session->applyStroke(ball, StrokeTool::Inflate, {a, b}, radius, 2.0, 3.0), "");
    EXPECT_EQ(session->editCount(ball), 1u);
}

TEST_F(SmoothInflateTest, SmoothTakesTheBumpsOffAPatchAndKeepsASmoothSurfaceWhereItWas) {
    const double v = voxel();
    const voxel::Volume sphere = grid(*session).clone();
    // How far the surface lies from the ball's, in voxels, over the columns
    // within 5 cm of the top: root mean square and worst.
    const auto deviation = [&](const voxel::Volume& g) {
        double sum = 0.0, worst = 0.0;
        int n = 0;
        for (double x = -0.05; x <= 0.05 + 1e-9; x += v)
            for (double z = -0.05; z <= 0.05 + 1e-9; z += v) {
                if (x * x + z * z > 0.05 * 0.05) continue;
                const double d = (surfaceHeight(g, x, z) - surfaceHeight(sphere, x, z)) / v;
                sum += d * d;
                worst = std::max(worst, std::fabs(d));
                ++n;
            }
        return std::make_pair(std::sqrt(sum / n), worst);
    };
    // Bumps and dents a few voxels wide all over the top.
    int n = 0;
    for (double x = -0.06; x <= 0.061; x += 0.03)
        for (double z = -0.06; z <= 0.061; z += 0.03) {
            const double y = 0.5 + std::sqrt(0.25 - x * x - z * z);
            ASSERT_EQ(session->applyPerturbation(ball, QuadricShape::Ellipsoid, {x, y, z}, {0.02, 0.02, 0.02},
                                                 n++ % 2 ? 2.0 : -2.0),
                      "");
        }
    const voxel::Volume bumpy = grid(*session).clone();
    const auto [roughRms, roughWorst] = deviation(bumpy);
    ASSERT_GT(roughRms, 0.3) << "the bumps are there";
    test::ActionList journal;
    session->setJournal(&journal);
    const std::array<double, 3> a{-0.04, 1.0, 0.0}, b{0.04, 1.0, 0.0};
    const double radius = 0.15;
    const std::array<double, 3> start{a[0] - 0.5 * strokeStep(radius, v), a[1], a[2]};
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Smooth, {a, b}, radius, 2.0, 1.0, Falloff::Smooth), "");
    ASSERT_EQ(journal.actions.size(), 1u);
    const auto& made = std::get<StrokeAction>(journal.actions[0]);
    ASSERT_FALSE(made.fits.empty());
    for (const auto& fit : made.fits) EXPECT_TRUE(fit) << "every segment met enough of the surface to fit";
    const auto [smoothRms, smoothWorst] = deviation(grid(*session));
    std::printf("smooth: surface off the ball's by %.2f voxels rms (%.2f worst) with bumps, %.2f (%.2f) smoothed\n",
                roughRms, roughWorst, smoothRms, smoothWorst);
    EXPECT_LT(smoothRms, 0.3 * roughRms);
    EXPECT_LT(smoothWorst, 0.5 * roughWorst);
    // Beyond the radius nothing changed.
    const voxel::IndexBox& box = bumpy.frame.indexBox;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                if (distanceToSegment(bumpy.frame.position(i, j, k), start, b) <= radius) continue;
                ASSERT_EQ(grid(*session).value(i, j, k), bumpy.value(i, j, k)) << i << " " << j << " " << k;
            }
    // Undone: the bumps, bit for bit.
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(test::differingVoxels(grid(*session), bumpy), 0);

    // On a surface that is already smooth (the untouched side of the ball)
    // a full-strength smooth leaves it within a fraction of a voxel.
    const voxel::Volume side = grid(*session).clone();
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Smooth, {{0.5, 0.45, -0.03}, {0.5, 0.55, 0.03}}, radius, 2.0, 1.0,
                                   Falloff::Smooth),
              "");
    double moved = 0.0;
    int near = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const double f = side.value(i, j, k);
                if (std::fabs(f) > 1.0) continue;
                if (distanceToSegment(side.frame.position(i, j, k), {0.5, 0.45, -0.03}, {0.5, 0.55, 0.03}) > 0.5 * radius)
                    continue;
                moved = std::max(moved, std::fabs(grid(*session).value(i, j, k) - f));
                ++near;
            }
    std::printf("smooth on a smooth surface: %d voxels near it moved %.3f voxels at most\n", near, moved);
    EXPECT_GT(near, 100);
    EXPECT_LT(moved, 0.3);
}

// Strokes made in the session journal their strength, falloff and (smooth)
// fits; the records survive the journal's JSON exactly and play back in a
// fresh session bit for bit. A hand-written smooth record without fits is
// fitted to the grid as the edits before it leave it, whether played one by
// one or as a journal in one go (where the grid updates wait).
TEST_F(SmoothInflateTest, StrokesJournalWithTheirFitsAndPlayBackBitForBit) {
    test::ActionList journal;
    session->setJournal(&journal);
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Carve, {{-0.05, 1.0, 0.0}, {0.05, 1.0, 0.02}}, 0.03), "");
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Smooth, {{-0.06, 1.0, -0.02}, {0.0, 1.0, 0.0}, {0.06, 0.99, 0.03}},
                                   0.08, 2.0, 0.7, Falloff::Linear),
              "");
    ASSERT_EQ(session->applyStroke(ball, StrokeTool::Inflate, {{0.45, 0.7, 0.1}, {0.4, 0.8, 0.2}}, 0.06, 2.0, -2.0,
                                   Falloff::Sharp),
              "");
    ASSERT_EQ(journal.actions.size(), 3u);
    for (const Action& act : journal.actions) {
        const std::string text = actionJson(act);
        const Action back = readAction(nlohmann::json::parse(text), "$");
        EXPECT_EQ(actionJson(back), text);
    }
    const auto& smooth = std::get<StrokeAction>(journal.actions[1]);
    EXPECT_EQ(smooth.strength, 0.7);
    EXPECT_EQ(smooth.falloff, Falloff::Linear);
    ASSERT_FALSE(smooth.fits.empty());
    EXPECT_NE(actionJson(journal.actions[1]).find("\"fits\""), std::string::npos);
    EXPECT_EQ(std::get<StrokeAction>(journal.actions[2]).strength, -2.0);

    auto again = open();
    ASSERT_EQ(again->restore(journal.actions), "");
    EXPECT_EQ(test::differingVoxels(grid(*again), grid(*session)), 0);

    std::vector<Action> unfitted = journal.actions;
    std::get<StrokeAction>(unfitted[1]).fits.clear();
    auto oneByOne = open(), inOneGo = open();
    for (const Action& act : unfitted) ASSERT_EQ(oneByOne->apply(act), "");
    ASSERT_EQ(inOneGo->restore(unfitted), "");
    EXPECT_EQ(test::differingVoxels(grid(*oneByOne), grid(*inOneGo)), 0);
    EXPECT_GT(test::differingVoxels(grid(*oneByOne), grid(*open())), 100);
}

// The pressure a device gives scales the strength the stroke is made and
// journalled with (a replay needs no pressure); reverse deflates.
TEST_F(SmoothInflateTest, PressureScalesTheStrengthTheJournalKeeps) {
    test::ActionList journal;
    session->setJournal(&journal);
    Hands h;
    h.tool.tracked = true;
    h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
    const auto stroke = [&](float pressure) {
        h.tool.pressure = pressure;
        h.tool.trigger = 1.0f;
        for (int f = 0; f < 4; ++f) {
            h.tool.aim.position = glm::vec3(-0.05f + 0.03f * static_cast<float>(f), 3.0f, 0.0f);
            session->frame(FrameInput(h, 1.0 / 90.0));
        }
        h.tool.trigger = 0.0f;
        session->frame(FrameInput(h, 1.0 / 90.0));
    };
    session->tool().kind = ToolSettings::Kind::Inflate;
    session->tool().radius = 0.05;
    session->tool().inflateStrength = 2.0;
    stroke(0.5f);
    session->tool().reverse = true;
    stroke(1.0f);
    selectTool(session->tool(), ToolSettings::Kind::Smooth);
    session->tool().smoothStrength = 0.6;
    stroke(0.5f);
    ASSERT_EQ(journal.actions.size(), 3u);
    const auto& light = std::get<StrokeAction>(journal.actions[0]);
    EXPECT_EQ(light.tool, StrokeTool::Inflate);
    EXPECT_EQ(light.strength, 1.0);
    EXPECT_GT(light.path.size(), 2u);
    EXPECT_EQ(std::get<StrokeAction>(journal.actions[1]).strength, -2.0);
    const auto& smooth = std::get<StrokeAction>(journal.actions[2]);
    EXPECT_EQ(smooth.tool, StrokeTool::Smooth);
    EXPECT_DOUBLE_EQ(smooth.strength, 0.3);
}

}  // namespace
}  // namespace hg::garden
