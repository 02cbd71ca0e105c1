// The session keeps each sculpture's level errors (polygonizer/realtime/
// chunk_errors.h) true as it is edited: a stroke leaves its chunks unknown
// (they take the voxel-size rule's levels meanwhile), the LOD stage
// measures them again within a few frames, and then they equal measuring
// the carved sculpture from scratch.
#include <gtest/gtest.h>

#include "garden/app/garden_session.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionLevelErrors : public test::SmallGardenSession {};

TEST_F(SessionLevelErrors, AStrokesChunksAreMeasuredAgainWithinAFewFrames) {
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(c)];
    ASSERT_TRUE(s.errors) << "on by default";
    ASSERT_EQ(s.errors->unknown(), 0u);
    const std::uint64_t before = s.errors->version();
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    const std::size_t waiting = s.errors->unknown();
    EXPECT_GT(waiting, 0u) << "the stroke's chunks wait to be measured";
    int frames = 0;
    for (; frames < 200 && s.errors->unknown() > 0; ++frames) session->frame(FrameInput(Hands{}, 1.0 / 90.0));
    std::printf("%zu chunks measured again in %d frames\n", waiting, frames);
    EXPECT_EQ(s.errors->unknown(), 0u);
    EXPECT_GT(s.errors->version(), before);
    const poly::ChunkErrors fresh(*s.pyramid, *s.layout);
    for (std::size_t chunk = 0; chunk < fresh.count(); ++chunk)
        for (int l = 1; l < fresh.levels(); ++l)
            ASSERT_EQ(s.errors->error(chunk, l), fresh.error(chunk, l)) << "chunk " << chunk << " level " << l;
}

}  // namespace
}  // namespace hg::garden
