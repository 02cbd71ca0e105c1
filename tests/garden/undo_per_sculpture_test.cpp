// Undo you can see (issue 23): the history lists every action with its
// sculpture; undo on one sculpture takes back its last action and leaves
// the others' as they are; it is journalled (an UndoAction naming the
// sculpture), so a session played from its journal has the same grids bit
// for bit; redo brings it back.
#include <gtest/gtest.h>

#include "garden/app/garden_session.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class UndoPerSculpture : public test::SmallGardenSession {
protected:
    voxel::Volume grid(int i) { return session->sculptures()[static_cast<std::size_t>(i)].volume->clone(); }
};

TEST_F(UndoPerSculpture, TakesBackOneSculpturesLastActionAndPlaysBackExactly) {
    test::ActionList journal;
    session->setJournal(&journal);
    const int a = session->findSculpture("a"), b = session->findSculpture("b");
    const voxel::Volume aOriginal = grid(a);
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    const voxel::Volume cOnce = grid(c);
    ASSERT_EQ(session->applyStroke(a, StrokeTool::Carve, {{0.1, 0.9, -2.2}, {0.2, 0.7, -2.1}}, 0.1), "");
    const voxel::Volume aCarved = grid(a);
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Add, {{1.6, 0.5, 1.3}, {1.5, 0.4, 1.2}}, 0.1), "");
    const voxel::Volume cTwice = grid(c);
    ASSERT_EQ(session->applyStroke(b, StrokeTool::Carve, {{-2.1, 0.8, 1.0}, {-1.9, 0.7, 1.2}}, 0.08), "");
    const voxel::Volume bCarved = grid(b);

    std::vector<HistoryItem> h = session->history();
    ASSERT_EQ(h.size(), 4u);
    EXPECT_EQ(h[1].name, "a");
    EXPECT_EQ(h[1].action, "stroke");
    EXPECT_FALSE(h[1].undone);

    // c's last action (the add, not the last action of all: b's carve).
    EXPECT_TRUE(session->undoSculpture(c));
    EXPECT_EQ(test::differingVoxels(grid(c), cOnce), 0) << "c as after its first stroke";
    EXPECT_EQ(test::differingVoxels(grid(b), bCarved), 0) << "b's later carve stays";
    EXPECT_EQ(test::differingVoxels(grid(a), aCarved), 0);
    // a's only action.
    EXPECT_TRUE(session->undoSculpture(a));
    EXPECT_EQ(test::differingVoxels(grid(a), aOriginal), 0);
    EXPECT_FALSE(session->undoSculpture(a)) << "nothing left on a";
    EXPECT_EQ(test::differingVoxels(grid(c), cOnce), 0) << "a's undo left c alone";
    h = session->history();
    ASSERT_EQ(h.size(), 4u);
    EXPECT_EQ(h[2].name, "a");
    EXPECT_TRUE(h[2].undone);
    // Redo brings back the last undone, a's carve.
    EXPECT_TRUE(session->redo());
    EXPECT_EQ(test::differingVoxels(grid(a), aCarved), 0);
    // And global undo still takes the last action of all: the redone carve on a.
    EXPECT_TRUE(session->undo());
    EXPECT_EQ(test::differingVoxels(grid(a), aOriginal), 0);
    EXPECT_EQ(test::differingVoxels(grid(b), bCarved), 0);

    // The journal names the sculpture of each per-sculpture undo, and says so in JSON.
    int named = 0;
    for (const Action& act : journal.actions)
        if (const auto* u = std::get_if<UndoAction>(&act)) named += !u->sculpture.empty();
    EXPECT_EQ(named, 2);
    const Action back = parseAction(actionJson(UndoAction{"c"}), "$");
    ASSERT_TRUE(std::holds_alternative<UndoAction>(back));
    EXPECT_EQ(std::get<UndoAction>(back).sculpture, "c");
    EXPECT_EQ(actionJson(UndoAction{}), R"({"action":"undo"})") << "a global undo is written as before";

    // Played from its journal, a session has the same grids, voxel for voxel.
    GardenSession again(loadGarden(writeGarden()), test::smallSessionSettings());
    ASSERT_EQ(again.restore(journal.actions), "");
    for (const int i : {a, b, c})
        EXPECT_EQ(test::differingVoxels(*again.sculptures()[static_cast<std::size_t>(i)].volume, grid(i)), 0)
            << session->sculptures()[static_cast<std::size_t>(i)].name;
    EXPECT_EQ(again.history().size(), session->history().size());
    // An undo naming a sculpture that is not there is refused with its name.
    EXPECT_EQ(again.apply(UndoAction{"nowhere"}), "no sculpture named 'nowhere'");
    session->setJournal(nullptr);
}

}  // namespace
}  // namespace hg::garden
