// Duplicate and Save As (issue 23): a session's folder copied whole into a
// new or empty folder, without the writer's lock; the copy opens as a
// session of its own with the same grids; folders that are not new or
// empty, or inside the session, are refused and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>

#include "garden/session/open_session.h"
#include "garden/session/session_copy.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class SessionCopyTest : public test::SmallGarden {};

TEST_F(SessionCopyTest, TheCopyOpensWithTheSameGridsAndWithoutTheLock) {
    const std::string garden = writeGarden();
    const std::string original = (dir / "week1").string();
    OpenedSession opened = openSession({original, garden}, test::smallSessionSettings());
    ASSERT_EQ(opened.error, "");
    GardenSession& s = *opened.session;
    const int c = s.findSculpture("c");
    ASSERT_EQ(s.applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    ASSERT_EQ(s.applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 0.3, 1.7}, {0.1, 0.08, 0.1}, 2.5), "");
    std::filesystem::create_directories(dir / "empty");
    const std::string copy = (dir / "empty").string();
    ASSERT_EQ(copySession(*opened.recorder, copy), "");
    EXPECT_FALSE(std::filesystem::exists(dir / "empty" / "session.lock")) << "the lock is the writer's, not copied";
    EXPECT_TRUE(std::filesystem::exists(dir / "empty" / "journal.hgj"));
    for (const auto& e : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << "no temporary left";

    // The copy is a session of its own: it opens (its own lock) beside the
    // original, with the same grids, and goes its own way.
    OpenedSession again = openSession({copy, garden}, test::smallSessionSettings());
    ASSERT_EQ(again.error, "");
    EXPECT_EQ(again.session->editCount(c), 2u);
    EXPECT_EQ(test::differingVoxels(*again.session->sculptures()[static_cast<std::size_t>(c)].volume,
                                    *s.sculptures()[static_cast<std::size_t>(c)].volume),
              0);
    ASSERT_TRUE(again.session->undo());
    EXPECT_EQ(s.editCount(c), 2u) << "the original is not touched";

    // Refused: a folder with something in it, the session itself, a folder inside it.
    write("busy/notes.txt", "mine");
    EXPECT_NE(copySession(*opened.recorder, (dir / "busy").string()).find("not a new or empty folder"), std::string::npos);
    EXPECT_NE(copySession(*opened.recorder, original), "");
    EXPECT_NE(copySession(*opened.recorder, original + "/inner").find("inside the session"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(original + "/inner"));
    EXPECT_NE(copySession(*opened.recorder, ""), "");
    // A missing folder is made, its parents too.
    ASSERT_EQ(copySession(*opened.recorder, (dir / "later" / "week2").string()), "");
    EXPECT_EQ(folderKind((dir / "later" / "week2").string()), FolderKind::Session);
}

}  // namespace
}  // namespace hg::garden
