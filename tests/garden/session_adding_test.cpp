// Sculptures brought into a running garden (garden/app/session_adding.cpp,
// the AddAction): a HyperFun file or a sketch in mode `new` becomes a new
// sculpture that is sampled like the garden's own, edited, undone (hidden)
// and redone, journalled with its program's text (so a session plays back
// after the file is gone) and exported; broken files and taken names are
// refused with nothing changed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "frep/language/parser.h"
#include "garden/app/garden_session.h"
#include "garden/export/hyperfun_export.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "session_garden.h"
#include "voxel/sampler.h"

namespace hg::garden {
namespace {

class SessionAddingTest : public test::SmallGardenSession {
protected:
    // A rounded box of half-size 0.3 standing on y = 0.
    std::string writeCube(const std::string& file = "cube.hf") {
        const std::string path = (dir / file).string();
        std::ofstream(path) << "my_model(x[3], a[1]) {\n"
                               "  my_model = 0.3 - max(max(abs(x[1]), abs(x[2] - 0.3)), abs(x[3]));\n}\n";
        return path;
    }
    static Placement at(double x, double z) {
        Placement p;
        p.position = {x, 0.0, z};
        return p;
    }
    const Sculpture& sculpture(int i) const { return session->sculptures()[static_cast<std::size_t>(i)]; }
};

// Is the world point inside sculpture i's grid?
bool insideAt(const Sculpture& s, const glm::vec3& world) {
    const glm::vec4 m = glm::inverse(s.modelToWorld()) * glm::vec4(world, 1.0f);
    const voxel::Volume& v = *s.volume;
    return v.value(v.frame.indexOf(0, m.x), v.frame.indexOf(1, m.y), v.frame.indexOf(2, m.z)) > 0.0f;
}

TEST_F(SessionAddingTest, AFileBecomesASculptureThatUndoHidesAndRedoShows) {
    const std::size_t before = session->sculptures().size();
    const int morphBefore = session->findSculpture("metamorphosis");
    ASSERT_EQ(session->addSculptureFile(writeCube(), "", at(0.0, 4.0), 40), "");
    const int i = session->findSculpture("cube");  // the file's stem
    ASSERT_EQ(static_cast<std::size_t>(i), before);
    EXPECT_EQ(session->findSculpture("metamorphosis"), morphBefore);  // nothing moved
    EXPECT_FALSE(sculpture(i).missing());
    // Its grid is the file's, sampled as `voxelize` samples it, placed.
    EXPECT_TRUE(insideAt(sculpture(i), {0.0f, 0.3f, 4.0f}));
    EXPECT_FALSE(insideAt(sculpture(i), {0.0f, 0.7f, 4.0f}));
    EXPECT_EQ(sculpture(i).volume->frame.resolution, 40);
    // The tool's ray finds it.
    Pose aim;
    aim.position = {0.0f, 0.3f, 6.0f};
    aim.orientation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);  // looking down -z
    auto hit = session->toolHit(aim);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->first, i);
    // It takes edits like the others.
    ASSERT_EQ(session->applyStroke(i, StrokeTool::Carve, {{0.0, 0.3, 4.3}, {0.1, 0.3, 4.3}}, 0.08), "");
    EXPECT_EQ(session->editCount(i), 1u);

    ASSERT_TRUE(session->undo());  // the stroke
    ASSERT_TRUE(session->undo());  // the adding
    EXPECT_TRUE(sculpture(i).removed);
    EXPECT_EQ(session->findSculpture("cube"), -1);
    hit = session->toolHit(aim);
    EXPECT_TRUE(!hit || hit->first != i);
    EXPECT_NE(session->applyStroke(i, StrokeTool::Carve, {{0.0, 0.3, 4.3}}, 0.08), "");
    session->select(i);
    EXPECT_EQ(session->selected(), -1);

    ASSERT_TRUE(session->redo());
    EXPECT_EQ(session->findSculpture("cube"), i);
    ASSERT_TRUE(session->redo());
    EXPECT_EQ(session->editCount(i), 1u);
}

TEST_F(SessionAddingTest, BrokenFilesAndTakenNamesAreRefusedWithNothingChanged) {
    const std::string broken = (dir / "broken.hf").string();
    std::ofstream(broken) << "my_model(x[3], a[1]) {\n  my_model = 1 - ;\n}\n";
    const std::size_t before = session->sculptures().size();
    const std::string why = session->addSculptureFile(broken, "", at(0.0, 4.0));
    EXPECT_NE(why.find("broken.hf:2:"), std::string::npos) << why;  // file:line:column
    EXPECT_NE(session->addSculptureFile((dir / "none.hf").string(), "", at(0.0, 4.0)).find("cannot open"),
              std::string::npos);
    EXPECT_NE(session->addSculptureFile(writeCube(), "c", at(0.0, 4.0)).find("already"), std::string::npos);
    Placement bad = at(0.0, 4.0);
    bad.scale = 5000.0;  // beyond kMaxSculptureScale (0 would mean: sized to the garden)
    EXPECT_NE(session->addSculptureFile(writeCube(), "", bad), "");
    EXPECT_EQ(session->sculptures().size(), before);
    // A second file with a taken stem gets a free name.
    ASSERT_EQ(session->addSculptureFile(writeCube("c.hf"), "", at(0.0, 4.0), 24), "");
    EXPECT_GE(session->findSculpture("c-2"), 0);
}

TEST_F(SessionAddingTest, TheJournalHoldsTheSourceSoASessionPlaysBackWithoutTheFile) {
    test::ActionList journal;
    session->setJournal(&journal);
    const std::string cube = writeCube();
    ASSERT_EQ(session->addSculptureFile(cube, "block", at(1.0, 4.0), 40), "");
    const int i = session->findSculpture("block");
    ASSERT_EQ(session->applyStroke(i, StrokeTool::Carve, {{1.0, 0.3, 4.3}, {1.1, 0.35, 4.3}}, 0.08), "");
    Placement moved = at(1.5, 4.5);
    moved.yawDegrees = 30.0;
    ASSERT_EQ(session->moveSculpture(i, moved), "");
    ASSERT_EQ(journal.actions.size(), 3u);
    const auto& added = std::get<AddAction>(journal.actions[0]);
    EXPECT_EQ(added.sculpture, "block");
    EXPECT_EQ(added.origin, cube);
    EXPECT_NE(added.source.find("my_model = 0.3"), std::string::npos);

    std::filesystem::remove(cube);
    std::vector<Action> read;
    for (const Action& a : journal.actions) read.push_back(parseAction(actionJson(a), "journal"));
    GardenSession again(loadGarden((dir / "garden.json").string()), test::smallSessionSettings());
    ASSERT_EQ(again.restore(read), "");
    const int j = again.findSculpture("block");
    ASSERT_GE(j, 0);
    EXPECT_EQ(test::differingVoxels(*sculpture(i).volume, *again.sculptures()[static_cast<std::size_t>(j)].volume), 0);
    EXPECT_EQ(again.sculptures()[static_cast<std::size_t>(j)].placement.yawDegrees, 30.0);

    // A record that names a program that does not parse says so.
    AddAction bad = added;
    bad.sculpture = "bad";
    bad.source = "my_model(x[3], a[1]) { my_model = ; }";
    EXPECT_NE(again.apply(bad), "");
    EXPECT_EQ(again.findSculpture("bad"), -1);
}

TEST_F(SessionAddingTest, AnAddedSculptureExportsAsItsProgramAndEdits) {
    ASSERT_EQ(session->addSculptureFile(writeCube(), "block", at(0.0, 4.0), 40), "");
    const int i = session->findSculpture("block");
    HyperFunExport plain = exportHyperFun(*session, i);
    ASSERT_EQ(plain.error, "");
    EXPECT_NE(plain.text.find("0.3 - max("), std::string::npos);
    ASSERT_EQ(session->applyStroke(i, StrokeTool::Carve, {{0.0, 0.3, 4.3}, {0.1, 0.3, 4.3}}, 0.08), "");
    HyperFunExport edited = exportHyperFun(*session, i);
    ASSERT_EQ(edited.error, "");
    EXPECT_EQ(edited.edits, 1u);
    const frep::ParseResult parsed = frep::parseProgram(edited.text, "export.hf");
    EXPECT_TRUE(parsed.ok());
}

// A circle of radius r about `centre` in the plane z = centre.z.
std::vector<std::array<double, 3>> circleXY(const std::array<double, 3>& centre, double r, int n = 48) {
    std::vector<std::array<double, 3>> out;
    for (int k = 0; k < n; ++k) {
        const double t = 2.0 * 3.14159265358979323846 * k / n;
        out.push_back({centre[0] + r * std::cos(t), centre[1] + r * std::sin(t), centre[2]});
    }
    return out;
}

TEST_F(SessionAddingTest, ASketchInModeNewStandsWhereItWasDrawnAndIsRound) {
    const std::string garden = (dir / "garden.json").string();
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [
        {"sketch": {"sculpture": "pebble", "mode": "new", "normal": [0, 0, 1],
                    "points": )" + nlohmann::json(circleXY({0.0, 1.0, 3.0}, 0.25)).dump() + R"(}}]},
        {"until_idle": true, "frames": 2000}]})",
                                                  "new.json", "");
    test::ActionList journal;
    session->setJournal(&journal);
    const ReplayResult r = runReplay(script, *session, nullptr, {});
    ASSERT_EQ(r.error, "");
    const int i = session->findSculpture("pebble");
    ASSERT_GE(i, 0);
    const Sculpture& s = sculpture(i);
    // A circle inflates to a ball of about its radius, about its centre.
    EXPECT_TRUE(insideAt(s, {0.0f, 1.0f, 3.0f}));
    EXPECT_TRUE(insideAt(s, {0.2f, 1.0f, 3.0f}));
    EXPECT_TRUE(insideAt(s, {0.0f, 1.0f, 3.18f}));
    EXPECT_FALSE(insideAt(s, {0.0f, 1.32f, 3.0f}));
    EXPECT_FALSE(insideAt(s, {0.0f, 1.0f, 3.35f}));
    ASSERT_EQ(journal.actions.size(), 1u);
    const auto& added = std::get<AddAction>(journal.actions[0]);
    EXPECT_EQ(added.origin, "sketch");
    ASSERT_TRUE(added.box);
    // Its export is the inflated solid's program.
    EXPECT_EQ(exportHyperFun(*session, i).error, "");
    // Too few points is refused with the reason; so is a taken name.
    const auto few = session->sketchNewFromWorld("x", {{0, 1, 3}, {0.1, 1, 3}}, {0, 0, 1});
    EXPECT_FALSE(few.action);
    EXPECT_NE(few.why.find("3 points"), std::string::npos);
    EXPECT_FALSE(session->sketchNewFromWorld("pebble", circleXY({0.0, 1.0, 3.0}, 0.25), {0, 0, 1}).action);
}

TEST_F(SessionAddingTest, AReplayAddsAFileNamedRelativeToTheScript) {
    writeCube("shapes-cube.hf");
    const std::string garden = (dir / "garden.json").string();
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [
        {"add": {"file": "shapes-cube.hf", "name": "plinth", "position": [0, 0, 4], "yaw": 45, "resolution": 24}}]},
        {"until_idle": true, "frames": 2000}]})",
                                                  (dir / "add.json").string(), dir.string());
    const ReplayResult r = runReplay(script, *session, nullptr, {});
    ASSERT_EQ(r.error, "");
    const int i = session->findSculpture("plinth");
    ASSERT_GE(i, 0);
    EXPECT_EQ(sculpture(i).placement.yawDegrees, 45.0);
    EXPECT_EQ(sculpture(i).volume->frame.resolution, 24);
    EXPECT_GT(session->trianglesShown(), 0u);
    // An unknown field is refused at its path.
    try {
        parseReplayScript(R"({"garden": "g.json", "steps": [{"commands": [{"add": {"file": "x.hf", "size": 2}}]}]})",
                          "bad.json", "");
        ADD_FAILURE() << "an unknown field was read";
    } catch (const JsonError& e) {
        EXPECT_EQ(e.path(), "$.steps[0].commands[0].add.size");
    }
}

}  // namespace
}  // namespace hg::garden
