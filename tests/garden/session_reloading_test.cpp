// Sources edited on disk (issue 23): a sculpture whose HyperFun file changed
// is read again, its grid replaced and its edits applied again (the same
// grid as a garden opened on the new file with the same edits, bit for
// bit); a broken file keeps the last good grid and the parser's message
// with its line; a solid without a box in the garden that grew is rebuilt
// in its new frame, its edits derived again; a changed source of the
// metamorphosis is read again and the result blended again with its own
// edits (each as a fresh open of the changed files); a file that did not
// change is not read again.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionReloading : public test::ScratchDir {
protected:
    // Two balls, no morph: "s" with a box in the garden, "t" without one.
    std::string writeGarden() {
        writeBall("s.hf", 0.36);
        writeBall("t.hf", 0.25);
        std::ofstream(dir / "garden.json") << R"({"version": 1, "name": "reload", "sculptures": [
            {"name": "s", "file": "s.hf", "resolution": 32, "box": {"min": [-0.8, -0.3, -0.8], "max": [0.8, 1.3, 0.8]},
             "placement": {"position": [0, 0, 0]}},
            {"name": "t", "file": "t.hf", "resolution": 32, "placement": {"position": [3, 0, 0]}}],
            "start": {"position": [0, 1.7, 5], "look_at": [0, 0.5, 0]}})";
        return (dir / "garden.json").string();
    }
    // A ball of radius sqrt(r2) about (0, 0.5, 0), its file's time moved on
    // (a file system's clock may not tick between two writes in a test).
    void writeBall(const std::string& name, double r2) { rewrite(name, "b(x[3], a[1]) { b = " + std::to_string(r2) + " - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n"); }
    void rewrite(const std::string& name, const std::string& text) {
        const std::filesystem::path p = dir / name;
        const bool existed = std::filesystem::exists(p);
        const auto before = existed ? std::filesystem::last_write_time(p) : std::filesystem::file_time_type{};
        std::ofstream(p) << text;
        if (existed) std::filesystem::last_write_time(p, before + std::chrono::seconds(1));
    }
    static SessionSettings settings() {
        SessionSettings s = test::smallSessionSettings();
        s.maxLevel = 0;
        return s;
    }
    static constexpr std::array<std::array<double, 3>, 2> kStroke{{{0.45, 0.9, 0.4}, {0.55, 0.6, 0.3}}};
};

TEST_F(SessionReloading, AChangedFileIsReadAgainWithTheEditsAndABrokenOneKeepsTheLastGood) {
    GardenSession session(loadGarden(writeGarden()), settings());
    const int s = session.findSculpture("s");
    const std::vector<std::array<double, 3>> path(kStroke.begin(), kStroke.end());
    ASSERT_EQ(session.applyStroke(s, StrokeTool::Carve, path, 0.1), "");
    EXPECT_TRUE(session.reloadChangedSources().empty()) << "nothing changed on disk";

    // A bigger ball: read again, the stroke applied on it.
    writeBall("s.hf", 0.49);
    std::vector<GardenSession::SourceReload> r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].sculpture, "s");
    EXPECT_EQ(r[0].problem, "");
    EXPECT_EQ(session.editCount(s), 1u) << "the edits stay";
    const Sculpture& shown = session.sculptures()[static_cast<std::size_t>(s)];
    EXPECT_EQ(test::differingVoxels(*shown.volume, *shown.edits->rebuild()), 0);
    GardenSession fresh(loadGarden((dir / "garden.json").string()), settings());
    ASSERT_EQ(fresh.applyStroke(s, StrokeTool::Carve, path, 0.1), "");
    EXPECT_EQ(test::differingVoxels(*shown.volume, *fresh.sculptures()[static_cast<std::size_t>(s)].volume), 0)
        << "as a garden opened on the new file with the same stroke";
    // The meshes follow: every chunk waits for a new mesh, and settles.
    EXPECT_GT(session.remeshPending(), 0u);
    for (int f = 0; f < 500 && !session.idle(); ++f) session.frame(FrameInput{});
    EXPECT_TRUE(session.idle());
    // Undo takes the stroke off the new ball.
    ASSERT_TRUE(session.undo());
    EXPECT_EQ(test::differingVoxels(*shown.volume, shown.edits->base()), 0);
    ASSERT_TRUE(session.redo());
    const voxel::Volume good = shown.volume->clone();

    // Broken: the parser's message with its place; the last good grid stays.
    rewrite("s.hf", "b(x[3], a[1]) {\n  b = 0.49 - ;\n}\n");
    r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NE(r[0].problem.find("s.hf:2:"), std::string::npos) << r[0].problem;
    EXPECT_EQ(shown.sourceProblem, r[0].problem);
    EXPECT_EQ(test::differingVoxels(*shown.volume, good), 0);
    EXPECT_EQ(session.editCount(s), 1u);
    // Mended: read again, the message gone.
    writeBall("s.hf", 0.36);
    r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].problem, "");
    EXPECT_EQ(shown.sourceProblem, "");
    EXPECT_GT(test::differingVoxels(*shown.volume, good), 100) << "the smaller ball again";
}

TEST_F(SessionReloading, ASolidThatGrewIsRebuiltInItsNewFrameAsAFreshOpenWouldBe) {
    GardenSession session(loadGarden(writeGarden()), settings());
    const int t = session.findSculpture("t");
    // An added stroke, a perturbation, and a second stroke undone (waiting
    // in the redo list): all in model units, all derived again.
    const StrokeAction add{"t", StrokeTool::Add, 0.08, 2.0, {{0.3, 0.8, 0.3}, {0.35, 0.5, 0.35}, {0.3, 0.3, 0.4}}, std::nullopt, 1.0, Falloff::Smooth, {}};
    Perturbation p;
    p.center = {-0.4, 0.6, 0.0};
    p.radii = {0.15, 0.15, 0.15};
    const PerturbAction bump{"t", p};
    const StrokeAction carve{"t", StrokeTool::Carve, 0.1, 2.0, {{-0.1, 1.0, 0.0}, {0.1, 0.95, 0.0}}, std::nullopt, 1.0, Falloff::Smooth, {}};
    const auto edit = [&](GardenSession& on) {
        ASSERT_EQ(on.apply(add), "");
        ASSERT_EQ(on.apply(bump), "");
        ASSERT_EQ(on.apply(carve), "");
        ASSERT_TRUE(on.undo());
    };
    edit(session);
    for (int f = 0; f < 500 && !session.idle(); ++f) session.frame(FrameInput{});
    const Sculpture& shown = session.sculptures()[static_cast<std::size_t>(t)];
    const voxel::VolumeFrame before = shown.volume->frame;
    const std::uint64_t generation = shown.frameGeneration;

    writeBall("t.hf", 0.64);  // its box is found from the model: it grows
    const std::vector<GardenSession::SourceReload> r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].problem, "");
    EXPECT_GT(shown.volume->frame.modelBox.hi[0], before.modelBox.hi[0] + 0.1) << "the new, larger frame";
    EXPECT_NE(shown.volume->frame.voxelSize, before.voxelSize);
    EXPECT_EQ(shown.frameGeneration, generation + 1) << "the view drops the old chunks";
    EXPECT_EQ(shown.edits->units().voxelSize, shown.volume->frame.voxelSize) << "the edits in the new grid's units";
    EXPECT_EQ(test::differingVoxels(*shown.volume, *shown.edits->rebuild()), 0);

    GardenSession fresh(loadGarden((dir / "garden.json").string()), settings());
    edit(fresh);
    const Sculpture& opened = fresh.sculptures()[static_cast<std::size_t>(t)];
    EXPECT_EQ(test::differingVoxels(*shown.volume, *opened.volume), 0) << "as a garden opened on the grown file";
    EXPECT_EQ(shown.layout->count(), opened.layout->count());
    // The meshes settle in the new chunks; redo brings the carve back on both.
    for (int f = 0; f < 500 && !session.idle(); ++f) session.frame(FrameInput{});
    EXPECT_TRUE(session.idle());
    EXPECT_GT(session.trianglesShown(), 0u);
    ASSERT_TRUE(session.redo());
    ASSERT_TRUE(fresh.redo());
    EXPECT_EQ(test::differingVoxels(*shown.volume, *opened.volume), 0) << "the redone stroke, derived again";
    ASSERT_TRUE(session.undo());
    ASSERT_TRUE(session.undo());
    EXPECT_EQ(session.editCount(t), 1u);
    ASSERT_TRUE(fresh.undo());
    ASSERT_TRUE(fresh.undo());
    EXPECT_EQ(test::differingVoxels(*shown.volume, *opened.volume), 0);
}

// The morph's sources: three balls with a box each (the morph's frame stays)
// and a fourth garden where source "a" has no box and grows (the morph's
// frame grows with it).
class MorphSourceReloading : public test::SmallGarden {
protected:
    static constexpr const char* kBall = "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n";
    void rewrite(const std::string& name, const std::string& text) {
        const std::filesystem::path p = dir / name;
        const auto before = std::filesystem::last_write_time(p);
        std::ofstream(p) << text;
        std::filesystem::last_write_time(p, before + std::chrono::seconds(1));
    }
    // Source "a" from its own file a.hf, found without a box.
    std::string writeUnboxedGarden() {
        writeGarden();
        std::ofstream(dir / "a.hf") << kBall;
        nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "garden.json"));
        j["sculptures"][0].erase("box");
        j["sculptures"][0]["file"] = "a.hf";
        std::ofstream(dir / "garden.json") << j.dump(2);
        return (dir / "garden.json").string();
    }
    static void settle(GardenSession& s) {
        for (int f = 0; f < 2000 && !s.idle(); ++f) s.frame(FrameInput{});
        ASSERT_TRUE(s.idle());
    }
    // An added stroke on the morph result (model frame), and the weights
    // moved off the garden's selector.
    static void edit(GardenSession& s) {
        const std::string result = s.garden().morphs[0].resultName;
        ASSERT_EQ(s.apply(StrokeAction{result, StrokeTool::Add, 0.08, 2.0, {{0.45, 0.95, 0.3}, {0.5, 0.7, 0.3}}, std::nullopt, 1.0, Falloff::Smooth, {}}), "");
        s.setMorphBarycentric({0.5, 0.3, 0.2});
    }
    static const Sculpture& result(const GardenSession& s) {
        return s.sculptures()[static_cast<std::size_t>(s.findSculpture(s.garden().morphs[0].resultName))];
    }
    // The session as a fresh open of the garden's files now, with the same edits.
    void expectAsFreshOpen(GardenSession& session) {
        GardenSession fresh(loadGarden((dir / "garden.json").string()), test::smallSessionSettings());
        edit(fresh);
        settle(fresh);
        for (const char* name : {"a", "b", "c"})
            EXPECT_EQ(test::differingVoxels(*session.sculptures()[static_cast<std::size_t>(session.findSculpture(name))].volume,
                                            *fresh.sculptures()[static_cast<std::size_t>(fresh.findSculpture(name))].volume),
                      0)
                << name;
        EXPECT_EQ(session.morphWeights()->w, fresh.morphWeights()->w);
        const Sculpture& r = result(session);
        EXPECT_EQ(r.volume->frame.voxelSize, result(fresh).volume->frame.voxelSize);
        EXPECT_EQ(test::differingVoxels(*r.volume, *result(fresh).volume), 0) << "the result blended again, its stroke on it";
        EXPECT_EQ(test::differingVoxels(*r.volume, *r.edits->rebuild()), 0);
        EXPECT_EQ(r.edits->list().edits().size(), 1u);
        EXPECT_GT(test::differingVoxels(*r.volume, r.edits->base()), 10) << "the stroke shows on the result";
    }
};

TEST_F(MorphSourceReloading, AChangedSourceIsBlendedAgainWithTheResultsEditsAsAFreshOpenWould) {
    GardenSession session(loadGarden(writeGarden()), test::smallSessionSettings());
    edit(session);
    settle(session);
    const voxel::Volume blended = result(session).volume->clone();
    const voxel::VolumeFrame frame = result(session).volume->frame;

    // Flattened balls: every source reads ball.hf.
    rewrite("ball.hf", "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + 2*(x[2]-0.5)^2 + x[3]^2); }\n");
    const std::vector<GardenSession::SourceReload> r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 3u);
    for (const auto& one : r) EXPECT_EQ(one.problem, "") << one.sculpture;
    EXPECT_GT(session.morphRemaining(), 0u) << "blended again frame by frame, with the budget";
    settle(session);
    EXPECT_EQ(result(session).volume->frame.modelBox.hi[1], frame.modelBox.hi[1]) << "the boxed sources keep the frame";
    EXPECT_GT(test::differingVoxels(*result(session).volume, blended), 100);
    expectAsFreshOpen(session);

    // Broken: the parser's place; the sources and the blend stay.
    const voxel::Volume good = result(session).volume->clone();
    rewrite("ball.hf", "ball(x[3], a[1]) {\n  ball = a[1] - ;\n}\n");
    const std::vector<GardenSession::SourceReload> broken = session.reloadChangedSources();
    ASSERT_EQ(broken.size(), 3u);
    EXPECT_NE(broken[0].problem.find("ball.hf:2:"), std::string::npos) << broken[0].problem;
    EXPECT_EQ(session.sculptures()[static_cast<std::size_t>(session.findSculpture("a"))].sourceProblem, broken[0].problem);
    settle(session);
    EXPECT_EQ(test::differingVoxels(*result(session).volume, good), 0);
}

TEST_F(MorphSourceReloading, ASourceWithoutABoxThatGrewGivesTheResultItsNewFrame) {
    GardenSession session(loadGarden(writeUnboxedGarden()), test::smallSessionSettings());
    edit(session);
    settle(session);
    const voxel::VolumeFrame frame = result(session).volume->frame;
    const std::uint64_t generation = result(session).frameGeneration;

    rewrite("a.hf", "ball(x[3], a[1]) { ball = a[1] + 0.6 - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n");  // radius 0.5 -> 0.92
    const std::vector<GardenSession::SourceReload> r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].problem, "");
    EXPECT_GT(result(session).volume->frame.modelBox.hi[0], frame.modelBox.hi[0] + 0.1) << "the union of the sources' boxes grew";
    EXPECT_EQ(result(session).frameGeneration, generation + 1);
    settle(session);
    expectAsFreshOpen(session);
}
}  // namespace
}  // namespace hg::garden
