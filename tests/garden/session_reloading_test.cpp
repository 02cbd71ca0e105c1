// Sources edited on disk (issue 23): a sculpture whose HyperFun file changed
// is read again, its grid replaced and its edits applied again (the same
// grid as a garden opened on the new file with the same edits, bit for
// bit); a broken file keeps the last good grid and the parser's message
// with its line; a file whose solid moved out of its box is kept as it was
// and says why; a file that did not change is not read again.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

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

TEST_F(SessionReloading, ASolidThatLeftItsFoundBoxIsKeptAsItWasAndSaysWhy) {
    GardenSession session(loadGarden(writeGarden()), settings());
    const int t = session.findSculpture("t");
    const voxel::Volume before = session.sculptures()[static_cast<std::size_t>(t)].volume->clone();
    writeBall("t.hf", 0.64);  // its box is found from the model: it grows
    const std::vector<GardenSession::SourceReload> r = session.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NE(r[0].problem.find("model box"), std::string::npos) << r[0].problem;
    EXPECT_EQ(test::differingVoxels(*session.sculptures()[static_cast<std::size_t>(t)].volume, before), 0);
}

}  // namespace
}  // namespace hg::garden
