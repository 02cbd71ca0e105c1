// The running garden without a window: a broken sculpture shows as missing
// and the rest opens; a walk-and-morph replay finishes; once its queues
// drain, the morph result is the from-scratch blend at the chosen weights
// bit for bit, and every chunk shows the mesh of that grid; replays are
// deterministic; the tool's ray on the ground triangle picks the blend;
// stats carry every stage.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "garden/app/garden_session.h"
#include "garden/replay/replay_runner.h"
#include "garden/scene/json_reader.h"
#include "session_garden.h"
#include "voxel/volume.h"

namespace hg::garden {
namespace {

class GardenSessionTest : public test::SmallGarden {};

ReplayScript walkAndMorph(const std::string& garden) {
    return parseReplayScript(R"({
      "garden": ")" + garden + R"(",
      "steps": [
        {"frames": 20, "navigation": {"thumbstick": [0, 1]}},
        {"frames": 5, "look": [3, 0]},
        {"commands": [{"morph_weights": [0.2, 0.5, 0.3]}]},
        {"frames": 4, "navigation": {"thumbstick": [0.5, 0.5]}},
        {"until_idle": true, "frames": 2000}
      ]})", "walk.json", "");
}

void expectSameGrid(const voxel::Volume& a, const voxel::Volume& b) {
    ASSERT_EQ(a.frame.indexBox.lo[0], b.frame.indexBox.lo[0]);
    const voxel::IndexBox& box = a.frame.indexBox;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                ASSERT_EQ(a.value(i, j, k), b.value(i, j, k)) << i << "," << j << "," << k;
                ASSERT_EQ(a.active(i, j, k), b.active(i, j, k)) << i << "," << j << "," << k;
            }
}

TEST_F(GardenSessionTest, ABrokenSculptureShowsAsMissingAndTheRestOpens) {
    GardenLoad load = loadGarden(writeGarden());
    ASSERT_TRUE(load.ok()) << load.error;
    GardenSession s(std::move(load), test::smallSessionSettings());
    ASSERT_EQ(s.sculptures().size(), 5u) << "four sculptures and the morph result";
    const Sculpture& lost = s.sculptures()[static_cast<std::size_t>(s.findSculpture("lost"))];
    EXPECT_TRUE(lost.missing());
    EXPECT_NE(lost.error.find("nowhere.hf"), std::string::npos) << lost.error;
    for (const char* name : {"a", "b", "c", "metamorphosis"}) {
        const Sculpture& st = s.sculptures()[static_cast<std::size_t>(s.findSculpture(name))];
        EXPECT_FALSE(st.missing()) << name << ": " << st.error;
        EXPECT_TRUE(st.volume && st.queue) << name;
    }
    EXPECT_TRUE(s.hasMorph());
    ASSERT_TRUE(s.morphWeights());
    for (double w : s.morphWeights()->w) EXPECT_NEAR(w, 1.0 / 3.0, 0.15) << "the selector starts at the centroid";
}

TEST_F(GardenSessionTest, WalkAndMorphReplayDrainsToTheFromScratchBlendAndItsMeshes) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    const ReplayScript script = walkAndMorph(dir.string() + "/garden.json");
    ReplayResult r = runReplay(script, s, nullptr, ReplayOptions{});
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_GT(r.frames, 30);
    EXPECT_LT(r.frames, 2029);
    ASSERT_TRUE(s.idle());
    EXPECT_GT(s.navigator().eye().z, 8.0f - 20 * 1.4f / 90.0f - 0.1f);
    EXPECT_LT(s.navigator().eye().z, 8.0f - 0.1f) << "walked forward";
    // The weights asked for, and the grid they give from scratch.
    ASSERT_TRUE(s.morphWeights());
    EXPECT_NEAR(s.morphWeights()->w[1], 0.5, 1e-12);
    std::unique_ptr<voxel::Volume> scratch = s.blendFromScratch();
    ASSERT_TRUE(scratch && s.morphResult());
    expectSameGrid(*s.morphResult(), *scratch);
    // Every chunk of the result shows the mesh of that grid at its level.
    const Sculpture& result = s.sculptures()[static_cast<std::size_t>(s.findSculpture("metamorphosis"))];
    poly::LodPyramid pyramid(*scratch, s.settings().maxLevel + 1);
    std::size_t triangles = 0;
    for (std::size_t c = 0; c < result.queue->count(); ++c) {
        const poly::Mesh fresh = poly::meshChunk(pyramid, *result.layout, c, result.queue->shownLod(c));
        ASSERT_TRUE(result.queue->mesh(c));
        EXPECT_EQ(result.queue->mesh(c)->positions, fresh.positions) << "chunk " << c;
        EXPECT_EQ(result.queue->mesh(c)->indices, fresh.indices) << "chunk " << c;
        triangles += fresh.triangleCount();
    }
    EXPECT_GT(triangles, 100u);
    // Morph samples were spent in budgeted slices across frames.
    std::size_t framesWithMorph = 0;
    for (const FrameStats& f : r.stats) {
        EXPECT_LE(f.morphSamples, 2000u);
        framesWithMorph += f.morphSamples > 0;
    }
    EXPECT_GT(framesWithMorph, 5u);
}

TEST_F(GardenSessionTest, ReplaysAreDeterministicAndStatsHaveEveryStage) {
    const ReplayScript script = walkAndMorph(dir.string() + "/garden.json");
    std::vector<std::vector<std::size_t>> runs;
    std::vector<std::vector<float>> meshes;
    for (int run = 0; run < 2; ++run) {
        GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
        ReplayResult r = runReplay(script, s, nullptr, ReplayOptions{});
        ASSERT_TRUE(r.ok()) << r.error;
        std::vector<std::size_t> trace;
        for (const FrameStats& f : r.stats) {
            trace.push_back(f.morphSamples);
            trace.push_back(f.chunksMeshed);
            trace.push_back(f.chunksShown);
        }
        runs.push_back(trace);
        std::vector<float> all;
        for (const Sculpture& st : s.sculptures())
            if (!st.missing())
                for (std::size_t c = 0; c < st.queue->count(); ++c)
                    if (auto m = st.queue->mesh(c)) all.insert(all.end(), m->positions.begin(), m->positions.end());
        meshes.push_back(all);
        if (run == 0) {
            nlohmann::json j = nlohmann::json::parse(statsJson(script, r));
            ASSERT_EQ(j["frames"].size(), static_cast<std::size_t>(r.frames));
            for (const auto& frame : j["frames"])
                for (const char* stage : {"input", "lod", "morph", "remesh", "upload", "render"})
                    ASSERT_TRUE(frame["stages_ms"].contains(stage)) << stage;
            for (const char* key : {"morph_samples", "chunks_meshed", "remesh_pending", "triangles_drawn", "total_ms"})
                EXPECT_TRUE(j["frames"][0].contains(key)) << key;
            EXPECT_TRUE(j["summary"]["mean_stage_ms"].contains("remesh"));
        }
    }
    EXPECT_EQ(runs[0], runs[1]);
    EXPECT_EQ(meshes[0], meshes[1]);
}

TEST_F(GardenSessionTest, TheToolRayOnTheGroundTrianglePicksTheBlend) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    Hands h;
    h.tool.tracked = true;
    h.tool.trigger = 1.0f;
    // From above corner b's side, pointing down at (-1, 0, 0.5).
    h.tool.aim.position = glm::vec3(-1.0f, 2.0f, 0.5f);
    h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
    s.frame(FrameInput(h, 1.0 / 90.0));
    ASSERT_TRUE(s.morphWeights());
    EXPECT_NEAR(s.morphWeights()->point[0], -1.0, 1e-5);
    EXPECT_NEAR(s.morphWeights()->point[1], 0.5, 1e-5);
    EXPECT_GT(s.morphWeights()->barycentric[1], s.morphWeights()->barycentric[2]) << "nearer b than c";
    // Without the trigger nothing changes.
    const auto before = s.morphWeights()->point;
    h.tool.trigger = 0.0f;
    h.tool.aim.position = glm::vec3(1.0f, 2.0f, 0.5f);
    s.frame(FrameInput(h, 1.0 / 90.0));
    EXPECT_EQ(s.morphWeights()->point, before);
}

TEST_F(GardenSessionTest, LevelsFollowTheViewerDuringALongReBlend) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    auto frame = [&s] {
        s.frame(FrameInput(Hands{}, 1.0 / 90.0));
    };
    const Sculpture& result = s.sculptures()[static_cast<std::size_t>(s.findSculpture("metamorphosis"))];
    auto finest = [&result] {
        int level = 99;
        for (std::size_t c = 0; c < result.queue->count(); ++c) level = std::min(level, result.queue->shownLod(c).level);
        return level;
    };
    // Far away: every chunk of the result coarse.
    s.navigator().setPose({0.0f, 1.7f, 40.0f}, 0.0f, 0.0f);
    for (int f = 0; f < 400 && !s.idle(); ++f) frame();
    ASSERT_TRUE(s.idle());
    ASSERT_EQ(finest(), 1);
    // A new blend that will take thousands of frames; walk up to the result.
    s.settings().morphSamplesPerFrame = 20;
    s.setMorphWeights({0.1, 0.1, 0.8});
    s.navigator().setPose({0.0f, 1.7f, 1.0f}, 0.0f, 0.0f);
    for (int f = 0; f < 150 && finest() > 0; ++f) frame();
    EXPECT_GT(s.morphRemaining(), 0u) << "still blending";
    EXPECT_EQ(finest(), 0) << "the result's levels followed the viewer";
}

TEST_F(GardenSessionTest, ReplayCommandsThatCannotRunStopWithTheirPath) {
    GardenSession s(loadGarden(writeGarden()), test::smallSessionSettings());
    ReplayScript script = parseReplayScript(R"({"garden": "g.json", "steps": [
        {"frames": 2}, {"commands": [{"select": "a"}, {"select": "nobody"}]}]})", "bad.json", "");
    ReplayResult r = runReplay(script, s, nullptr, ReplayOptions{});
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("bad.json: $.steps[1].commands[1]: no sculpture named 'nobody'"), std::string::npos) << r.error;
    EXPECT_EQ(r.frames, 2);
    // Screenshots headless are skipped and said so.
    ReplayScript shots = parseReplayScript(R"({"garden": "g.json", "steps": [{"commands": [{"screenshot": "x.png"}]}]})",
                                           "shots.json", "");
    ReplayResult rs = runReplay(shots, s, nullptr, ReplayOptions{});
    EXPECT_TRUE(rs.ok());
    ASSERT_EQ(rs.notes.size(), 1u);
    EXPECT_NE(rs.notes[0].find("skipped (headless)"), std::string::npos);
}

TEST(ReplayScript, BadScriptsAreRefusedWithTheirJsonPath) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"steps": [{}]})", "$: missing key 'garden'"},
        {R"({"garden": "g.json", "steps": []})", "$.steps: expected a non-empty array of steps"},
        {R"({"garden": "g.json", "steps": [{"frame": 3}]})", "$.steps[0].frame: unknown key"},
        {R"({"garden": "g.json", "steps": [{"navigation": {"thumbstick": [0, 2]}}]})",
         "$.steps[0].navigation.thumbstick[1]: expected a number in [-1, 1]"},
        {R"({"garden": "g.json", "steps": [{"tool": {"buttons": ["primery"]}}]})",
         "$.steps[0].tool.buttons[0]: unknown button 'primery' (did you mean 'primary'?)"},
        {R"({"garden": "g.json", "steps": [{"commands": [{"morph_weights": [0, 0, 0]}]}]})",
         "$.steps[0].commands[0].morph_weights: the weights must not all be zero"},
        {R"({"garden": "g.json", "steps": [{"commands": [{"teleport": 1}]}]})", "$.steps[0].commands[0].teleport: unknown key"},
        {R"({"garden": "g.json", "steps": [{"commands": [{"morph": [0, 0], "orbit": true}]}]})",
         "$.steps[0].commands[0]: expected an object with one command"},
        {R"({"garden": "g.json", "viewport": [640.5, 480], "steps": [{}]})", "$.viewport[0]: expected a whole number"},
        {R"({"garden": "g.json", "steps": [{"frames": 0}]})", "$.steps[0].frames"},
        {R"({"garden": "g.json", "steps": [{}],})", "line 1"},
    };
    for (const auto& [text, expected] : cases) {
        try {
            parseReplayScript(text, "s.json", "");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const JsonError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what() << "\nexpected: " << expected;
        }
    }
    const ReplayScript ok = parseReplayScript(
        R"({"garden": "gardens/g.json", "timestep": 0.02, "steps": [{"frames": 3, "look": [90, 0],
            "tool": {"aim": {"position": [0, 1, 0], "direction": [0, 0, -2]}, "trigger": 1, "buttons": ["undo"]}},
            {"until_idle": true}]})",
        "s.json", "/scripts");
    EXPECT_EQ(ok.garden, "/scripts/gardens/g.json");
    EXPECT_EQ(ok.timestep, 0.02);
    EXPECT_NEAR(ok.steps[0].hands.look.x, 3.14159265f / 2, 1e-6f);
    EXPECT_TRUE(ok.steps[0].hands.tool.pressed(kButtonUndo));
    EXPECT_NEAR(ok.steps[0].hands.tool.aim.forward().z, -1.0f, 1e-6f);
    EXPECT_EQ(ok.steps[1].frames, 10000);
    EXPECT_EQ(ok.totalFrames(), 10003);
}

}  // namespace
}  // namespace hg::garden
