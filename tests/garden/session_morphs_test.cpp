// Several metamorphoses in one garden (GardenSession's morphs): each result
// holds its own sources, weights and blend; the selector's setters act on
// the active one (the first, or the result selected, or the triangle a drag
// on the ground began on); each drains to its own from-scratch blend; the
// journal names the morph it weighs, and a journal from before gardens had
// several weighs the first.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include "garden/app/garden_session.h"
#include "garden/morph/morph_state.h"
#include "garden/replay/replay_runner.h"
#include "two_morph_garden.h"
#include "voxel/volume.h"

namespace hg::garden {
namespace {

class SessionMorphs : public test::SmallGarden {
protected:
    std::unique_ptr<GardenSession> open() {
        return std::make_unique<GardenSession>(loadGarden(test::writeTwoMorphGarden(dir)), test::smallSessionSettings());
    }
    static void drain(GardenSession& s) {
        for (int f = 0; f < 3000 && !s.idle(); ++f) s.frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(s.idle());
    }
    // content/gardens/two-morphs.json at 24^3, settling in a few frames.
    static SessionSettings contentGardenSettings() {
        SessionSettings settings = test::smallSessionSettings();
        settings.sculptureResolution = 24;
        settings.morphResolution = 24;
        settings.morphSamplesPerFrame = 20000;
        settings.remeshChunksPerFrame = 64;
        return settings;
    }
    // Voxels whose value or activity differs.
    static int differing(const voxel::Volume& a, const voxel::Volume& b) { return test::differingVoxels(a, b); }
};

TEST_F(SessionMorphs, EachMorphBlendsItsOwnSourcesAndTheSelectorActsOnTheActiveOne) {
    auto s = open();
    const int first = s->findSculpture("metamorphosis");
    const int second = s->findSculpture("second");
    ASSERT_GE(first, 0);
    ASSERT_GE(second, 0);
    EXPECT_EQ(s->morphResults(), (std::vector<int>{first, second}));
    EXPECT_EQ(s->activeMorph(), first) << "the garden's first morph is active at the start";
    ASSERT_TRUE(s->morphWeights(first) && s->morphWeights(second));
    EXPECT_NEAR(s->morphWeights(second)->point[0], 10.5, 1e-9) << "the second starts at its own selector";
    EXPECT_EQ(s->morphSpec(second)->sources[0], "d");
    EXPECT_NE(s->morphSources(first), s->morphSources(second));

    s->setMorphWeights({0.6, 0.2, 0.2});
    const MorphWeights secondBefore = *s->morphWeights(second);
    EXPECT_NEAR(s->morphWeights(first)->w[0], 0.6, 1e-12);
    EXPECT_EQ(s->morphWeights(second)->w, secondBefore.w) << "the other morph keeps its weights";

    s->select(second);
    EXPECT_EQ(s->activeMorph(), second) << "selecting a morph result makes it the one the selector steers";
    s->setMorphWeights({0.1, 0.1, 0.8});
    EXPECT_NEAR(s->morphWeights(second)->w[2], 0.8, 1e-12);
    EXPECT_NEAR(s->morphWeights(first)->w[0], 0.6, 1e-12);
    s->select(s->findSculpture("a"));
    EXPECT_EQ(s->activeMorph(), second) << "selecting another sculpture leaves the active morph";

    // Both blends run (sharing the stage's budget) and each ends equal to
    // its own blend from scratch, bit for bit.
    drain(*s);
    for (int r : {first, second}) {
        std::unique_ptr<voxel::Volume> scratch = s->blendFromScratch(r);
        ASSERT_TRUE(scratch && s->morphResult(r));
        EXPECT_EQ(differing(*s->morphResult(r), *scratch), 0) << s->sculptures()[static_cast<std::size_t>(r)].name;
    }
    EXPECT_GT(differing(*s->morphResult(first), *s->morphResult(second)), 0) << "two blends, two grids";
}

TEST_F(SessionMorphs, OffTheFrameThreadEachMorphDrainsToItsOwnBlend) {
    // The window's and the headset's settings: the blends' batches on a job
    // thread, written by the frames within the stage's share.
    SessionSettings settings = test::smallSessionSettings();
    settings.morphSamplesPerFrame = 0;
    settings.workOffFrameThread = true;
    GardenSession s(loadGarden(test::writeTwoMorphGarden(dir)), settings);
    const int first = s.findSculpture("metamorphosis");
    const int second = s.findSculpture("second");
    s.setMorphWeights({0.2, 0.2, 0.6});
    s.select(second);
    s.setMorphWeights({0.7, 0.2, 0.1});
    std::size_t framesWriting = 0;
    for (int f = 0; f < 20000 && !s.idle(); ++f) {
        const FrameStats& stats = s.frame(FrameInput(Hands{}, 1.0 / 90.0));
        framesWriting += stats.morphSamples > 0;
        std::this_thread::sleep_for(std::chrono::microseconds(200));  // as a display paces frames
    }
    ASSERT_TRUE(s.idle());
    EXPECT_GT(framesWriting, 1u);
    for (int r : {first, second}) {
        std::unique_ptr<voxel::Volume> scratch = s.blendFromScratch(r);
        ASSERT_TRUE(scratch && s.morphResult(r));
        EXPECT_EQ(differing(*s.morphResult(r), *scratch), 0) << s.sculptures()[static_cast<std::size_t>(r)].name;
    }
}

TEST_F(SessionMorphs, TheActiveMorphBlendsFirstAndTheOthersTakeWhatItLeaves) {
    auto s = open();
    drain(*s);
    const int first = s->findSculpture("metamorphosis");
    const int second = s->findSculpture("second");
    const auto remaining = [&s](int r) { return s->sculptures()[static_cast<std::size_t>(r)].morph->blender->remainingSamples(); };
    s->setMorphWeights({0.7, 0.2, 0.1});
    s->setActiveMorph(second);
    s->setMorphWeights({0.1, 0.2, 0.7});
    s->settings().morphSamplesPerFrame = 500;
    const std::uint64_t firstBefore = remaining(first), secondBefore = remaining(second);
    ASSERT_GT(firstBefore, 500u);
    ASSERT_GT(secondBefore, 500u);
    s->frame(FrameInput(Hands{}, 1.0 / 90.0));
    EXPECT_EQ(remaining(second), secondBefore - 500) << "the morph being steered goes first";
    EXPECT_EQ(remaining(first), firstBefore) << "nothing was left of the frame's samples for the other";
    // With room for both, the other takes what the active one leaves.
    s->settings().morphSamplesPerFrame = secondBefore + 300;
    s->frame(FrameInput(Hands{}, 1.0 / 90.0));
    EXPECT_EQ(remaining(second), 0u);
    EXPECT_EQ(remaining(first), firstBefore - 800);
}

TEST_F(SessionMorphs, TheJournalNamesTheMorphItWeighsAndAnOldRecordWeighsTheFirst) {
    auto s = open();
    test::ActionList journal;
    s->setJournal(&journal);
    const int first = s->findSculpture("metamorphosis");
    const int second = s->findSculpture("second");
    s->setMorphBarycentric({0.5, 0.3, 0.2});
    s->setActiveMorph(second);
    s->setMorphBarycentric({0.2, 0.2, 0.6});
    ASSERT_EQ(journal.actions.size(), 2u);
    EXPECT_EQ(std::get<MorphWeightsAction>(journal.actions[0]).sculpture, "metamorphosis");
    EXPECT_EQ(std::get<MorphWeightsAction>(journal.actions[1]).sculpture, "second");

    // Played into a fresh session, each record reaches its own morph.
    auto again = open();
    ASSERT_EQ(again->restore(journal.actions), "");
    for (int r : {first, second}) {
        EXPECT_EQ(again->morphWeights(r)->w, s->morphWeights(r)->w) << r;
        EXPECT_EQ(again->morphWeights(r)->barycentric, s->morphWeights(r)->barycentric) << r;
    }
    // A record without a name (a journal from before) weighs the first morph.
    MorphWeightsAction old{{0.1, 0.8, 0.1}, s->morphWeights(first)->balance, ""};
    ASSERT_EQ(again->apply(old), "");
    EXPECT_EQ(again->morphWeights(first)->barycentric, old.barycentric);
    EXPECT_EQ(again->morphWeights(second)->w, s->morphWeights(second)->w);
    // A record naming what is no morph is refused with the name.
    MorphWeightsAction wrong{{0.3, 0.3, 0.4}, {1.0, 1.0, 1.0}, "a"};
    EXPECT_EQ(again->apply(wrong), "no metamorphosis named 'a'");
}

TEST_F(SessionMorphs, ADragOnTheGroundSteersTheMorphWhoseTriangleItBeganOn) {
    auto s = open();
    const int first = s->findSculpture("metamorphosis");
    const int second = s->findSculpture("second");
    const MorphWeights firstBefore = *s->morphWeights(first);
    test::ActionList journal;
    s->setJournal(&journal);
    Hands h;
    h.tool.tracked = true;
    h.tool.trigger = 1.0f;
    // Pointing straight down at (9.5, 0, 0.5), inside the second triangle.
    h.tool.aim.position = glm::vec3(9.5f, 2.0f, 0.5f);
    h.tool.aim.orientation = glm::quatLookAt(glm::vec3(0, -1, 0), glm::vec3(0, 0, -1));
    s->frame(FrameInput(h, 1.0 / 90.0));
    EXPECT_EQ(s->activeMorph(), second);
    EXPECT_NEAR(s->morphWeights(second)->point[0], 9.5, 1e-5);
    EXPECT_NEAR(s->morphWeights(second)->point[1], 0.5, 1e-5);
    // Dragged on past the first triangle's reach it stays with the second
    // (clamped to its edge), and the first is untouched.
    h.tool.aim.position = glm::vec3(8.3f, 2.0f, 1.0f);
    s->frame(FrameInput(h, 1.0 / 90.0));
    EXPECT_NEAR(s->morphWeights(second)->point[0], 8.3, 1e-5);
    EXPECT_EQ(s->morphWeights(first)->barycentric, firstBefore.barycentric);
    EXPECT_TRUE(journal.actions.empty()) << "a drag is journalled when the hand lets go";
    h.tool.trigger = 0.0f;
    s->frame(FrameInput(h, 1.0 / 90.0));
    ASSERT_EQ(journal.actions.size(), 1u);
    EXPECT_EQ(std::get<MorphWeightsAction>(journal.actions[0]).sculpture, "second");
    // A new drag that begins on the first triangle steers the first.
    h.tool.trigger = 1.0f;
    h.tool.aim.position = glm::vec3(-1.0f, 2.0f, 0.5f);
    s->frame(FrameInput(h, 1.0 / 90.0));
    EXPECT_EQ(s->activeMorph(), first);
    EXPECT_NEAR(s->morphWeights(first)->point[0], -1.0, 1e-5);
}

TEST_F(SessionMorphs, AMorphWithAMissingSourceIsMissingAndTheOtherRuns) {
    std::filesystem::path garden = test::writeTwoMorphGarden(dir);
    nlohmann::json j = nlohmann::json::parse(std::ifstream(garden));
    j["sculptures"][4]["file"] = "gone.hf";  // d
    std::ofstream(garden) << j.dump();
    const GardenLoad load = loadGarden(garden.string());
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_EQ(load.morphErrors.size(), 2u);
    EXPECT_TRUE(load.morphErrors[0].empty());
    EXPECT_EQ(load.morphErrors[1], "morph source 'd' is missing, so there is no metamorphosis");
    GardenSession s(load, test::smallSessionSettings());
    const Sculpture& second = s.sculptures()[static_cast<std::size_t>(s.findSculpture("second"))];
    EXPECT_TRUE(second.missing());
    EXPECT_EQ(second.error, load.morphErrors[1]);
    EXPECT_TRUE(s.morphTriangle(s.findSculpture("second"))) << "its triangle still stands on the ground";
    EXPECT_FALSE(s.morphWeights(s.findSculpture("second")));
    s.setActiveMorph(s.findSculpture("second"));
    EXPECT_EQ(s.activeMorph(), s.findSculpture("metamorphosis")) << "a missing morph cannot be made active";
    EXPECT_EQ(s.apply(MorphWeightsAction{{0.3, 0.3, 0.4}, {1.0, 1.0, 1.0}, "second"}),
              "the metamorphosis 'second' is missing");
    drain(s);
    EXPECT_EQ(differing(*s.morphResult(), *s.blendFromScratch()), 0);
}

TEST_F(SessionMorphs, TheTwoMorphsGardenInContentOpensWithBothBlending) {
    const GardenLoad load = loadGarden(std::string(HG_SOURCE_DIR) + "/content/gardens/two-morphs.json");
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_EQ(load.garden->morphs.size(), 2u);
    for (const std::string& why : load.morphErrors) EXPECT_EQ(why, "");
    const SessionSettings settings = contentGardenSettings();
    GardenSession s(load, settings);
    ASSERT_EQ(s.morphResults().size(), 2u);
    s.setActiveMorph(s.findSculpture("second metamorphosis"));
    s.setMorphPoint(12.5, -1.5);
    drain(s);
    for (int r : s.morphResults()) {
        ASSERT_TRUE(s.morphWeights(r)) << r;
        EXPECT_EQ(differing(*s.morphResult(r), *s.blendFromScratch(r)), 0) << r;
    }
}

TEST_F(SessionMorphs, TheTwoMorphsReplayWeighsEachMorphOnItsOwn) {
    const ReplayScript script = loadReplayScript(std::string(HG_SOURCE_DIR) + "/content/replays/two_morphs.json");
    const SessionSettings settings = contentGardenSettings();
    GardenSession s(loadGarden(script.garden), settings);
    ASSERT_TRUE(runReplay(script, s, nullptr, ReplayOptions{}).ok());
    ASSERT_TRUE(s.idle());
    const int first = s.findSculpture("metamorphosis");
    const int second = s.findSculpture("second metamorphosis");
    EXPECT_NEAR(s.morphWeights(first)->w[0], 0.6, 1e-12) << "the first morph's weights, set while it was active";
    EXPECT_EQ(s.activeMorph(), second) << "selected, then steered";
    EXPECT_NEAR(s.morphWeights(second)->point[0], 12.5, 1e-9);
    EXPECT_NEAR(s.morphWeights(second)->point[1], -1.5, 1e-9);
    for (int r : {first, second}) EXPECT_EQ(differing(*s.morphResult(r), *s.blendFromScratch(r)), 0) << r;
}

}  // namespace
}  // namespace hg::garden
