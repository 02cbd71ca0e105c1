// Discarding a sculpture's edits loses nothing (issue 23): "discard edits"
// is one action in the history, undo puts every edit back (the grid bit for
// bit as before, the edits' own undo history too), redo takes them out
// again, and a session played from its journal does the same. A journal
// written before discards could be undone plays its discards for good, as
// they were made.
#include <gtest/gtest.h>

#include "garden/app/garden_session.h"
#include "garden/scene/json_reader.h"
#include "garden/sculpt/sculpture_edits.h"
#include "session_garden.h"

namespace hg::garden {
namespace {

class DiscardUndo : public test::SmallGardenSession {
protected:
    voxel::Volume grid(int i) { return session->sculptures()[static_cast<std::size_t>(i)].volume->clone(); }
    const Sculpture& sculpture(int i) { return session->sculptures()[static_cast<std::size_t>(i)]; }
};

TEST_F(DiscardUndo, UndoPutsEveryEditBackAndRedoTakesThemOutAgain) {
    test::ActionList journal;
    session->setJournal(&journal);
    const int a = session->findSculpture("a");
    const voxel::Volume cOriginal = grid(c);
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    ASSERT_EQ(session->applyStroke(a, StrokeTool::Carve, {{0.1, 0.9, -2.2}, {0.2, 0.7, -2.1}}, 0.1), "");
    const voxel::Volume aCarved = grid(a);
    ASSERT_EQ(session->applyPerturbation(c, QuadricShape::Ellipsoid, {2.0, 0.3, 1.7}, {0.1, 0.08, 0.1}, 2.5), "");
    const auto picked = session->pickPerturbation(c, {2.0, 0.3, 1.7});
    ASSERT_TRUE(picked);
    ASSERT_EQ(session->editPerturbation(c, *picked, -1.5, {0.12, 0.1, 0.12}), "");
    const voxel::Volume cEdited = grid(c);
    ASSERT_GT(test::differingVoxels(cEdited, cOriginal), 100);

    session->discardEdits(c);
    EXPECT_EQ(session->editCount(c), 0u);
    EXPECT_EQ(test::differingVoxels(grid(c), cOriginal), 0) << "back to the unedited sculpture";
    EXPECT_EQ(test::differingVoxels(grid(a), aCarved), 0) << "a is not touched";
    std::vector<HistoryItem> h = session->history();
    ASSERT_EQ(h.size(), 2u) << "a's stroke and the discard; c's edits are inside the discard";
    EXPECT_EQ(h[1].action, "discard");
    EXPECT_EQ(h[1].name, "c");

    // Undo (the last action of all): every edit of c back, bit for bit.
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(session->editCount(c), 3u - 1u) << "the stroke and the perturbation (replaced in place)";
    EXPECT_EQ(test::differingVoxels(grid(c), cEdited), 0);
    EXPECT_EQ(test::differingVoxels(grid(c), *sculpture(c).edits->rebuild()), 0);
    h = session->history();
    ASSERT_EQ(h.size(), 5u) << "c's three entries back, and the discard waiting for redo";
    EXPECT_EQ(h[4].action, "discard");
    EXPECT_TRUE(h[4].undone);

    // Redo takes them out again; undo on the selection alone brings them back.
    ASSERT_TRUE(session->redo());
    EXPECT_EQ(test::differingVoxels(grid(c), cOriginal), 0);
    ASSERT_TRUE(session->applyStroke(a, StrokeTool::Add, {{0.3, 0.9, -2.2}, {0.35, 0.7, -2.1}}, 0.08).empty());
    const voxel::Volume aTwice = grid(a);
    ASSERT_TRUE(session->undoSculpture(c));
    EXPECT_EQ(test::differingVoxels(grid(c), cEdited), 0);
    EXPECT_EQ(test::differingVoxels(grid(a), aTwice), 0) << "a's later stroke stays";

    // c's own history came back with its edits: undo steps through them.
    ASSERT_TRUE(session->undoSculpture(c));  // the replacement
    ASSERT_TRUE(session->undoSculpture(c));  // the perturbation
    ASSERT_TRUE(session->undoSculpture(c));  // the stroke
    EXPECT_EQ(test::differingVoxels(grid(c), cOriginal), 0);
    EXPECT_FALSE(session->undoSculpture(c));
    ASSERT_TRUE(session->redo());
    ASSERT_TRUE(session->redo());
    ASSERT_TRUE(session->redo());
    EXPECT_EQ(test::differingVoxels(grid(c), cEdited), 0);

    // Written as undoable, and played from the journal it gives the same grids.
    bool sawDiscard = false;
    for (const Action& act : journal.actions)
        if (const auto* d = std::get_if<DiscardAction>(&act)) sawDiscard = d->undoable;
    EXPECT_TRUE(sawDiscard);
    EXPECT_EQ(actionJson(DiscardAction{"c"}), R"({"action":"discard","sculpture":"c","undoable":true})");
    GardenSession again(loadGarden(writeGarden()), test::smallSessionSettings());
    ASSERT_EQ(again.restore(journal.actions), "");
    for (const int i : {a, c})
        EXPECT_EQ(test::differingVoxels(*again.sculptures()[static_cast<std::size_t>(i)].volume, grid(i)), 0)
            << sculpture(i).name;
    EXPECT_EQ(again.history().size(), session->history().size());
    ASSERT_TRUE(again.undo());
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(test::differingVoxels(*again.sculptures()[static_cast<std::size_t>(c)].volume, grid(c)), 0);
    session->setJournal(nullptr);
}

TEST_F(DiscardUndo, AJournalsDiscardWithoutUndoablePlaysForGoodAsItWasMade) {
    const int a = session->findSculpture("a");
    const Action old = parseAction(R"({"action":"discard","sculpture":"c"})", "journal.hgj:4");
    ASSERT_TRUE(std::holds_alternative<DiscardAction>(old));
    EXPECT_FALSE(std::get<DiscardAction>(old).undoable);
    EXPECT_THROW(parseAction(R"({"action":"discard","sculpture":"c","undoable":3})", "journal.hgj:4"), JsonError);

    const voxel::Volume aOriginal = grid(a);
    const voxel::Volume cOriginal = grid(c);
    // Model frame: both balls' centres are at (0, 0.5, 0), c's radius 0.6, a's 0.5.
    ASSERT_EQ(session->apply(StrokeAction{"c", StrokeTool::Carve, 0.1, 2.0, {{0.45, 0.9, 0.1}, {0.5, 0.6, 0.2}}, {}, 1.0, Falloff::Smooth, {}}), "");
    ASSERT_EQ(session->apply(StrokeAction{"a", StrokeTool::Carve, 0.1, 2.0, {{0.1, 0.9, 0.2}, {0.2, 0.7, 0.3}}, {}, 1.0, Falloff::Smooth, {}}), "");
    ASSERT_GT(test::differingVoxels(grid(c), cOriginal), 10);
    ASSERT_GT(test::differingVoxels(grid(a), aOriginal), 10);
    ASSERT_EQ(session->restore({old, UndoAction{}}), "");
    // The undo took back a's stroke, as it did when the journal was written;
    // c's edits are gone for good.
    EXPECT_EQ(test::differingVoxels(grid(a), aOriginal), 0);
    EXPECT_EQ(test::differingVoxels(grid(c), cOriginal), 0);
    EXPECT_TRUE(session->redo());
    EXPECT_FALSE(session->undo() && session->undo()) << "nothing of c's to undo";
    EXPECT_EQ(test::differingVoxels(grid(c), cOriginal), 0);
}

}  // namespace
}  // namespace hg::garden
