// The running garden working off the frame thread (the scheduler's
// allowances, SessionSettings::workOffFrameThread): a walk, a morph and
// strokes made while chunks and blend batches are with the workers settle
// on the grids and meshes of working within the frame (the morph result's
// grid bit for bit that of the blend from scratch), and the frames keep
// running while the workers work; and a slow machine settles on the same
// levels as a fast one.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "garden/app/garden_session.h"
#include "garden/replay/replay_runner.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class BackgroundRemeshSession : public test::SmallGarden {};

// Frames as a display paces them (here 2 ms apart): frames run back to
// back would spin while the worker meshes, and could use up the replay's
// frames first on a slow machine (a sanitizer build, valgrind).
class PacedSink : public FrameRenderer {
public:
    ViewUpload upload(GardenSession&, double) override { return {}; }
    ViewDraw render(GardenSession&) override {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        return {};
    }
    std::string screenshot(const std::string&) override { return ""; }
};

ReplayScript walkMorphAndCarve(const std::string& garden) {
    return parseReplayScript(R"({
      "garden": ")" + garden + R"(",
      "steps": [
        {"frames": 10, "navigation": {"thumbstick": [0, 1]}},
        {"commands": [{"morph_weights": [0.2, 0.5, 0.3]}]},
        {"commands": [{"stroke": {"sculpture": "c", "tool": "carve", "radius": 0.1,
                                  "path": [[2.45, 0.9, 1.3], [2.5, 0.6, 1.4]]}}]},
        {"frames": 1},
        {"commands": [{"stroke": {"sculpture": "c", "tool": "add", "radius": 0.08,
                                  "path": [[1.45, 0.5, 1.2], [1.5, 0.8, 1.2]]}}]},
        {"frames": 3, "navigation": {"thumbstick": [0.5, 0.5]}},
        {"until_idle": true, "frames": 20000}
      ]})", "walk.json", "");
}

// The walk's session settings: the scheduler's allowances, in the frame or
// off it.
SessionSettings walkSettings(bool offThread) {
    SessionSettings settings = test::smallSessionSettings();
    settings.remeshChunksPerFrame = 0;  // the scheduler's allowance
    settings.workOffFrameThread = offThread;
    return settings;
}

struct Shown {
    std::vector<std::vector<float>> positions;
    std::vector<std::vector<std::uint32_t>> indices;
};

Shown shownMeshes(const GardenSession& s) {
    Shown out;
    for (const Sculpture& sc : s.sculptures()) {
        if (!sc.onShow()) continue;
        for (std::size_t c = 0; c < sc.queue->count(); ++c) {
            const auto m = sc.queue->mesh(c);
            out.positions.push_back(m ? m->positions : std::vector<float>{});
            out.indices.push_back(m ? m->indices : std::vector<std::uint32_t>{});
        }
    }
    return out;
}

// What a settled garden shows does not depend on how fast the machine is:
// chunk errors measured one small batch a frame (a slow machine, a
// sanitizer build) settle on the levels of errors measured half a
// millisecond a frame. Idle waits for every error and for a level choice
// the busy queue put off, in the frame and off it.
TEST_F(BackgroundRemeshSession, ASlowMachineSettlesOnTheSameLevels) {
    const ReplayScript script = walkMorphAndCarve(dir.string() + "/garden.json");
    const std::string garden = writeGarden();
    for (const bool offThread : {false, true}) {
        std::string levels[2];  // each chunk's level and transition faces
        for (int slow = 0; slow < 2; ++slow) {
            SessionSettings settings = walkSettings(offThread);
            if (slow) settings.errorRefreshMs = 1e-6;
            GardenSession s(loadGarden(garden), settings);
            PacedSink paced;
            const ReplayResult r = runReplay(script, s, offThread ? &paced : nullptr, ReplayOptions{});
            ASSERT_TRUE(r.ok()) << r.error;
            ASSERT_TRUE(s.idle());
            for (const Sculpture& sc : s.sculptures()) {
                if (!sc.onShow()) continue;
                if (sc.errors) {
                    EXPECT_EQ(sc.errors->unknown(), 0u) << sc.name;
                }
                levels[slow] += "\n" + sc.name + ":";
                for (std::size_t c = 0; c < sc.queue->count(); ++c) {
                    const poly::ChunkLod& lod = sc.queue->shownLod(c);
                    levels[slow] += " " + std::to_string(lod.level) + "/" + std::to_string(lod.transitionFaces);
                }
            }
        }
        EXPECT_EQ(levels[0], levels[1]) << (offThread ? "off the frame thread" : "in the frame");
    }
}

TEST_F(BackgroundRemeshSession, SettlesOnTheSameMeshesAsRemeshingInTheFrame) {
    const ReplayScript script = walkMorphAndCarve(dir.string() + "/garden.json");
    Shown in[2];
    std::size_t framesWhileMeshing = 0;
    std::size_t blendedInFrames = 0;
    for (int offThread = 0; offThread < 2; ++offThread) {
        GardenSession s(loadGarden(writeGarden()), walkSettings(offThread != 0));
        PacedSink paced;
        const ReplayResult r = runReplay(script, s, offThread ? &paced : nullptr, ReplayOptions{});
        ASSERT_TRUE(r.ok()) << r.error;
        ASSERT_TRUE(s.idle());
        in[offThread] = shownMeshes(s);
        if (offThread) {
            // Frames that showed nothing new while chunks were pending: the
            // frame ran on while the worker meshed.
            for (const FrameStats& f : r.stats) {
                framesWhileMeshing += f.remeshPending > 0 && f.chunksMeshed == 0;
                blendedInFrames += f.morphSamples > 0;
            }
        }
        // The morph result shows the mesh of its from-scratch grid.
        const Sculpture& result = s.sculptures()[static_cast<std::size_t>(s.findSculpture("metamorphosis"))];
        const std::unique_ptr<voxel::Volume> scratch = s.blendFromScratch();
        EXPECT_EQ(test::differingVoxels(*result.volume, *scratch), 0);
        poly::LodPyramid pyramid(*scratch, s.settings().maxLevel + 1);
        for (std::size_t c = 0; c < result.queue->count(); ++c) {
            const poly::Mesh fresh = poly::meshChunk(pyramid, *result.layout, c, result.queue->shownLod(c));
            ASSERT_TRUE(result.queue->mesh(c));
            EXPECT_EQ(result.queue->mesh(c)->positions, fresh.positions) << "chunk " << c;
        }
        // Ball c, carved and added to, shows its grid's meshes.
        const Sculpture& c = s.sculptures()[static_cast<std::size_t>(s.findSculpture("c"))];
        poly::LodPyramid cp(*c.volume, s.settings().maxLevel + 1);
        for (std::size_t k = 0; k < c.queue->count(); ++k) {
            const poly::Mesh fresh = poly::meshChunk(cp, *c.layout, k, c.queue->shownLod(k));
            ASSERT_TRUE(c.queue->mesh(k));
            EXPECT_EQ(c.queue->mesh(k)->positions, fresh.positions) << "chunk " << k;
            EXPECT_EQ(c.queue->mesh(k)->indices, fresh.indices) << "chunk " << k;
        }
    }
    ASSERT_EQ(in[0].positions.size(), in[1].positions.size());
    for (std::size_t i = 0; i < in[0].positions.size(); ++i) {
        EXPECT_EQ(in[0].positions[i], in[1].positions[i]) << "chunk " << i;
        EXPECT_EQ(in[0].indices[i], in[1].indices[i]) << "chunk " << i;
    }
    EXPECT_GT(framesWhileMeshing, 0u) << "off the frame thread, a frame does not wait for the worker";
    EXPECT_GT(blendedInFrames, 1u) << "the blend's batches were written over several frames";
}

}  // namespace
}  // namespace hg::garden
