// What a running garden holds (garden/app/memory_report.h): each kind is
// counted from the parts themselves, the coarse levels hold less than the
// grids they sample (the pyramid's small trees), an edit adds its base, and
// the watch reads again only when its period has passed.
#include <gtest/gtest.h>

#include "garden/app/garden_session.h"
#include "garden/app/memory_report.h"
#include "garden/sculpt/sculpture_edits.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "session_garden.h"
#include "voxel/volume.h"

namespace hg::garden {
namespace {

class MemoryReportTest : public test::SmallGardenSession {
protected:
    void settle() {
        for (int f = 0; f < 3000 && !session->idle(); ++f) session->frame(FrameInput(Hands{}, 1.0 / 90.0));
        ASSERT_TRUE(session->idle());
    }
};

TEST_F(MemoryReportTest, CountsEachKindFromItsParts) {
    settle();
    const MemoryReport r = memoryReport(*session);
    std::size_t grids = 0, levels = 0, withGrid = 0;
    for (const Sculpture& s : session->sculptures()) {
        if (!s.volume) continue;
        ++withGrid;
        grids += s.volume->memoryBytes();
        levels += s.pyramid->memoryBytes();
    }
    EXPECT_EQ(r.sculptures, withGrid);
    EXPECT_EQ(r.grids, grids);
    EXPECT_EQ(r.levels, levels);
    EXPECT_GT(r.meshes, 0u) << "the settled garden shows meshes";
    EXPECT_GT(r.morphSources, 3u * 32 * 32 * 32 * sizeof(float)) << "three source caches of the 32^3 blend";
    EXPECT_EQ(r.editBases, 0u) << "nothing edited yet";
    EXPECT_EQ(r.total(), r.grids + r.levels + r.meshes + r.editBases + r.morphSources);
    // The coarse levels (an eighth of the voxels, then a 64th...) hold less
    // than the grids: with OpenVDB's standard tree their node tables alone
    // held more.
    EXPECT_LT(r.levels, r.grids / 2);
}

TEST_F(MemoryReportTest, AnEditAddsItsBaseAndTheWatchReadsAgainOnlyWhenDue) {
    settle();
    MemoryWatch slow(std::chrono::hours(1));
    MemoryWatch always(std::chrono::milliseconds(0));
    const MemoryReport before = slow.read(*session);
    EXPECT_EQ(always.read(*session).editBases, 0u);
    const Sculpture& ball = session->sculptures()[static_cast<std::size_t>(c)];
    const glm::vec3 at = ball.worldCentre();
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{at.x, at.y, at.z + 0.2}, {at.x + 0.05, at.y, at.z + 0.2}}, 0.05),
              "");
    const MemoryReport now = memoryReport(*session);
    EXPECT_GT(now.editBases, 0u) << "the edited sculpture keeps its grid before the edits";
    ASSERT_TRUE(ball.edits);
    EXPECT_EQ(now.editBases, ball.edits->base().memoryBytes());
    EXPECT_EQ(slow.read(*session).editBases, before.editBases) << "within its period the watch keeps its report";
    EXPECT_EQ(always.read(*session).editBases, now.editBases);
}

}  // namespace
}  // namespace hg::garden
