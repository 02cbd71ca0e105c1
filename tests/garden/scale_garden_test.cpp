// The generated scale garden (garden/scene/scale_garden.h) and the session at
// scale: copies of the default garden's sculptures on a grid; the session's
// hierarchical level selection shows, once settled, exactly the levels the
// per-chunk selection gives, and a far viewer costs no chunk tests.
#include <gtest/gtest.h>

#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "garden/app/garden_session.h"
#include "garden/scene/scale_garden.h"
#include "polygonizer/realtime/lod_selection.h"

namespace hg::garden {
namespace {

std::string defaultGarden() { return std::string(HG_SOURCE_DIR) + "/content/gardens/default.json"; }

GardenLoad scaleGarden(int count, int resolution) {
    ScaleGardenSpec spec;
    spec.count = count;
    spec.resolution = resolution;
    return loadScaleGarden(defaultGarden(), spec);
}

SessionSettings scaleSettings() {
    SessionSettings s;
    s.chunkSize = 16;
    s.maxLevel = 2;
    s.remeshChunksPerFrame = 64;
    s.viewportHeight = 60;  // small: levels change within a few metres, inside the grid
    return s;
}

// At least one frame (it selects the levels for the pose), then until idle.
void settle(GardenSession& session) {
    session.frame(FrameInput{});
    for (int f = 0; f < 5000 && !session.idle(); ++f) session.frame(FrameInput{});
    ASSERT_TRUE(session.idle());
}

TEST(ScaleGarden, CopiesTheTemplatesSculpturesOnAGrid) {
    GardenLoad load = scaleGarden(11, 24);
    ASSERT_TRUE(load.ok()) << load.error;
    const Garden& g = *load.garden;
    ASSERT_EQ(g.sculptures.size(), 11u);
    ASSERT_EQ(load.sculptures.size(), 11u);
    EXPECT_EQ(scaleGardenColumns(11), 4);
    EXPECT_TRUE(g.morphs.empty()) << "copies only: the morph's sources are not doubled";
    std::set<std::string> names, files;
    for (std::size_t i = 0; i < g.sculptures.size(); ++i) {
        const SculptureSpec& s = g.sculptures[i];
        EXPECT_TRUE(load.sculptures[i].ok()) << s.name << ": " << load.sculptures[i].error;
        EXPECT_EQ(s.resolution, 24);
        names.insert(s.name);
        files.insert(s.file);
        const int column = static_cast<int>(i) % 4, row = static_cast<int>(i) / 4;
        EXPECT_DOUBLE_EQ(s.placement.position[0], (column - 1.5) * 3.0) << s.name;
        EXPECT_DOUBLE_EQ(s.placement.position[2], -row * 3.0) << s.name;
    }
    EXPECT_EQ(names.size(), 11u) << "every copy has its own name";
    EXPECT_GE(files.size(), 5u) << "the template's sculptures taken in turn";
    // The ninth copy is the first template sculpture again, sharing its parse.
    EXPECT_EQ(load.sculptures[9].program, load.sculptures[0].program);
}

TEST(ScaleGarden, ABrokenTemplateIsRefusedWithItsName) {
    GardenLoad load = loadScaleGarden("/nonexistent/garden.json", ScaleGardenSpec{});
    EXPECT_FALSE(load.ok());
    EXPECT_NE(load.error.find("/nonexistent/garden.json"), std::string::npos) << load.error;
}

// Settled at several poses inside and outside the grid, every sculpture
// shows the per-chunk selection's levels chunk for chunk (with its measured
// errors); and again, standing still, once the viewport's pixels change (the
// automatic quality's render and detail scales do that).
TEST(ScaleGarden, SessionLevelsEqualThePerChunkSelection) {
    GardenLoad load = scaleGarden(12, 48);
    ASSERT_TRUE(load.ok()) << load.error;
    GardenSession session(std::move(load), scaleSettings());
    const SessionSettings& st = session.settings();
    std::size_t uniform = 0, mixed = 0;
    const std::vector<glm::vec3> poses{glm::vec3(0.0f, 1.7f, 6.0f), glm::vec3(1.5f, 1.2f, -3.0f),
                                       glm::vec3(-4.0f, 1.0f, -0.8f), glm::vec3(30.0f, 2.0f, 40.0f)};
    std::size_t coarser = 0;  // chunks shown coarser once the viewport shrank
    for (std::size_t pose = 0; pose <= poses.size(); ++pose) {
        std::vector<std::vector<int>> before;
        if (pose < poses.size()) {
            session.navigator().setPose(poses[pose], 0.0f, 0.0f);
        } else {
            // Back at the first pose, settled, then the same eye with two thirds of the
            // pixels (half would take these sculptures to one level each, which is
            // chosen every frame anyway).
            session.navigator().setPose(poses[0], 0.0f, 0.0f);
            settle(session);
            for (const Sculpture& s : session.sculptures()) {
                before.emplace_back();
                for (std::size_t c = 0; c < s.queue->count(); ++c) before.back().push_back(s.queue->shownLod(c).level);
            }
            session.settings().viewportHeight = session.settings().viewportHeight * 2 / 3;
        }
        settle(session);
        const glm::vec3 at = session.navigator().eye();  // walking keeps the eye above the ground
        for (const Sculpture& s : session.sculptures()) {
            ASSERT_FALSE(s.missing()) << s.name << ": " << s.error;
            poly::Camera cam;
            const glm::vec4 m = glm::inverse(s.modelToWorld()) * glm::vec4(at, 1.0f);
            cam.position = {m.x, m.y, m.z};
            cam.fovY = st.fovY;
            cam.viewportHeight = st.viewportHeight;
            poly::LodSettings lod;
            lod.pixelError = st.pixelError;
            lod.maxLevel = st.maxLevel;
            lod.errorPixels = st.levelErrorPixels;
            ASSERT_TRUE(s.errors) << "levels by measured error, on by default";
            const std::vector<int> flat = poly::selectLevelsPerChunk(*s.layout, cam, lod, s.errors.get());
            std::set<int> levels;
            for (std::size_t c = 0; c < flat.size(); ++c) {
                ASSERT_EQ(s.queue->shownLod(c).level, flat[c]) << s.name << ", chunk " << c << ", pose " << pose;
                levels.insert(flat[c]);
                if (!before.empty()) coarser += flat[c] > before[static_cast<std::size_t>(&s - &session.sculptures()[0])][c];
            }
            (levels.size() == 1 ? uniform : mixed) += 1;
        }
    }
    EXPECT_GT(uniform, 0u);
    EXPECT_GT(mixed, 0u) << "some sculptures straddle a level's distance";
    EXPECT_GT(coarser, 0u) << "fewer pixels, coarser levels, without a step";
}

TEST(ScaleGarden, AFarViewerTestsNoChunk) {
    GardenLoad load = scaleGarden(12, 48);
    ASSERT_TRUE(load.ok()) << load.error;
    GardenSession session(std::move(load), scaleSettings());
    std::size_t chunks = 0;
    for (const Sculpture& s : session.sculptures()) chunks += s.layout->count();
    session.navigator().setPose(glm::vec3(0.0f, 1.7f, 2.0f), 0.0f, 0.0f);
    const std::size_t nearVisited = session.frame(FrameInput{}).lodChunksVisited;
    EXPECT_GT(nearVisited, 0u);
    EXPECT_LT(nearVisited, chunks) << "only sculptures whose chunks differ are visited";
    settle(session);
    session.navigator().setPose(glm::vec3(0.0f, 1.7f, 900.0f), 0.0f, 0.0f);
    EXPECT_EQ(session.frame(FrameInput{}).lodChunksVisited, 0u);
    settle(session);
    for (const Sculpture& s : session.sculptures())
        for (std::size_t c = 0; c < s.queue->count(); ++c) ASSERT_EQ(s.queue->shownLod(c).level, 2) << s.name;
    EXPECT_EQ(session.frame(FrameInput{}).lodChunksVisited, 0u);
}

}  // namespace
}  // namespace hg::garden
