// content/replays/first_hour.json, the README's "First steps": a new user's
// first hour scripted. A HyperFun file of one's own (content/first-hour/
// pot.hf) is brought into the default garden, given a material, and
// sculpted with the tools a beginner reaches for (carve, add, soft carve,
// inflate, smooth); a slip is undone on that sculpture alone; a mesh of
// one's own is brought in and carved. Played here at a low resolution, the way the README's
// screenshots are made at a high one.
#include <gtest/gtest.h>

#include "garden/app/garden_session.h"
#include "garden/export/part_export.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

TEST(FirstHourReplay, TheContentReplayBringsInAPotAndSculptsIt) {
    const ReplayScript script = loadReplayScript(std::string(HG_SOURCE_DIR) + "/content/replays/first_hour.json");
    SessionSettings settings = test::smallSessionSettings();
    settings.sculptureResolution = 48;
    settings.morphResolution = 32;
    settings.remeshChunksPerFrame = 0;
    GardenSession s(loadGarden(script.garden), settings);
    const std::size_t before = s.sculptures().size();
    ReplayOptions options;
    options.extractor = extractPart;
    const ReplayResult r = runReplay(script, s, nullptr, options);
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(s.sculptures().size(), before + 2) << "the pot and the pebble were brought in";
    const int pot = s.findSculpture("pot");
    ASSERT_GE(pot, 0);
    const Sculpture& sc = s.sculptures()[static_cast<std::size_t>(pot)];
    EXPECT_EQ(sc.material.kind, MaterialKind::Clay);
    // The carved band, two handles, five thumb prints, the belly inflated
    // and smoothed in stay: eleven made, the slip on the rim undone on the
    // pot alone (and the thumb prints made after it dropped it from the
    // redo list).
    ASSERT_EQ(s.editCount(pot), 10u);
    EXPECT_EQ(sc.edits->redoCount(), 0u);
    const auto& edits = sc.edits->list().edits();
    EXPECT_EQ(std::get<Stroke>(edits[8].op).tool, StrokeTool::Inflate);
    const Stroke& smooth = std::get<Stroke>(edits[9].op);
    EXPECT_EQ(smooth.tool, StrokeTool::Smooth);
    int fitted = 0;
    for (const auto& fit : smooth.fits) fitted += fit.has_value();
    EXPECT_GT(fitted, 0) << "the smooth stroke met the pot's surface";
    // A mesh of one's own (content/first-hour/pebble.obj) comes in too, as a
    // level set, and takes a stroke like any sculpture.
    const int pebble = s.findSculpture("pebble");
    ASSERT_GE(pebble, 0);
    EXPECT_EQ(s.sculptures()[static_cast<std::size_t>(pebble)].source.kind, SculptureSource::Kind::Mesh);
    EXPECT_EQ(s.editCount(pebble), 1u);
    EXPECT_EQ(s.selected(), pot) << "the script selected the pot; its strokes and the add change no selection";
    for (std::size_t i = 0; i < before; ++i)
        EXPECT_EQ(s.editCount(static_cast<int>(i)), 0u) << s.sculptures()[i].name << " was not touched";
    // It stands on the ground where the script put it.
    const frep::Box3& box = sc.volume->frame.modelBox;
    EXPECT_LT(box.lo[1], 0.01);
    EXPECT_GT(box.hi[1], 0.75);
}

}  // namespace
}  // namespace hg::garden
