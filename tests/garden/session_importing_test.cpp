// Meshes and volumes added inside a session, and added HyperFun files read
// again when they change (issue 23, garden/app/session_adding.cpp and
// session_added_reloading.cpp): real session folders in a scratch folder,
// real grids compared voxel by voxel. An added mesh or .vdb is copied into
// DIR/imports/ and its record names the copy, so the session reopens with
// the same grids after the originals are deleted; a bad file is refused
// with its name and line and nothing is journalled; journals written before
// imports read as they did; a changed .hf becomes a journalled reload that
// plays back without the file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "garden/export/hyperfun_export.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/scene/json_reader.h"
#include "garden/session/journal.h"
#include "garden/session/open_session.h"
#include "polygonizer/export/mesh_read.h"
#include "session_garden.h"
#include "voxel/mesh_volume.h"
#include "voxel/vdb_io.h"

namespace hg::garden {
namespace {

namespace fs = std::filesystem;

// A box 0.6 wide and 0.6 tall standing on y = 0, centred on the y axis, as
// OBJ quads turning counter-clockwise seen from outside.
constexpr const char* kBlockObj =
    "v -0.3 0 -0.3\nv 0.3 0 -0.3\nv 0.3 0 0.3\nv -0.3 0 0.3\n"
    "v -0.3 0.6 -0.3\nv 0.3 0.6 -0.3\nv 0.3 0.6 0.3\nv -0.3 0.6 0.3\n"
    "f 1 2 3 4\nf 5 8 7 6\nf 4 3 7 8\nf 1 5 6 2\nf 2 6 7 3\nf 1 4 8 5\n";

class SessionImporting : public test::SmallGarden {
protected:
    void SetUp() override {
        SmallGarden::SetUp();
        garden = writeGarden();
        folder = (dir / "session").string();
    }
    OpenedSession open() {
        OpenedSession o = openSession({folder, garden}, test::smallSessionSettings());
        EXPECT_EQ(o.error, "");
        return o;
    }
    static Placement at(double x, double z, double scale = 1.0) {
        Placement p;
        p.position = {x, 0.0, z};
        p.scale = scale;
        return p;
    }
    // The block's level set written by OpenVDB (a volume whose zero is the block).
    std::string writeBlockVdb(const std::string& name) {
        const poly::MeshReadResult block = poly::readMeshFile(write("for-vdb.obj", kBlockObj));
        voxel::MeshLevelSetRequest request;
        request.resolution = 24;
        const voxel::VoxelizeResult r = voxel::levelSetFromMesh(block.mesh.positions, block.mesh.indices, request);
        EXPECT_TRUE(r.volume) << r.error;
        const std::string path = (dir / name).string();
        EXPECT_EQ(voxel::writeLevelSet(*r.volume, path), "");
        return path;
    }
    // `text` written to `name`, its file's time moved on (a file system's
    // clock may not tick between two writes in a test).
    std::string rewrite(const std::string& name, const std::string& text) {
        const fs::path p = dir / name;
        const bool existed = fs::exists(p);
        const auto before = existed ? fs::last_write_time(p) : fs::file_time_type{};
        std::ofstream(p) << text;
        if (existed) fs::last_write_time(p, before + std::chrono::seconds(1));
        return p.string();
    }
    static std::string cube(double half) {
        return "my_model(x[3], a[1]) {\n  my_model = " + std::to_string(half) +
               " - max(max(abs(x[1]), abs(x[2] - 0.3)), abs(x[3]));\n}\n";
    }
    std::string journalText() const {
        std::string text;
        std::ifstream in(fs::path(folder) / "journal.hgj", std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), {});
        return text;
    }
    static const Sculpture& of(const GardenSession& s, const std::string& name) {
        return s.sculptures()[static_cast<std::size_t>(s.findSculpture(name))];
    }
    std::string garden, folder;
};

TEST_F(SessionImporting, AMeshAndAVolumeAreCopiedInAndReopenBitForBitWithoutTheOriginals) {
    const std::string obj = write("block.obj", kBlockObj);
    const std::string vdb = writeBlockVdb("slab.vdb");
    std::unique_ptr<voxel::Volume> meshGrid, volumeGrid;
    {
        OpenedSession o = open();
        GardenSession& s = *o.session;
        ASSERT_EQ(s.addSculptureFile(obj, "", at(0.0, 4.0), 32), "");
        ASSERT_EQ(s.addSculptureFile(vdb, "", at(2.0, 4.0), 32), "");
        const int m = s.findSculpture("block"), v = s.findSculpture("slab");
        ASSERT_GE(m, 0);
        ASSERT_GE(v, 0);
        EXPECT_TRUE(of(s, "block").meshed());
        EXPECT_TRUE(of(s, "slab").scanned());
        // Sculpted like any other.
        ASSERT_EQ(s.applyStroke(m, StrokeTool::Carve, {{0.0, 0.3, 4.3}, {0.1, 0.35, 4.3}}, 0.08), "");
        ASSERT_EQ(s.applyStroke(v, StrokeTool::Add, {{2.0, 0.3, 4.3}, {2.1, 0.35, 4.3}}, 0.06), "");
        EXPECT_EQ(s.editCount(m), 1u);
        meshGrid = std::make_unique<voxel::Volume>(of(s, "block").volume->clone());
        volumeGrid = std::make_unique<voxel::Volume>(of(s, "slab").volume->clone());
        // The block's level set: inside at its middle, outside above it.
        const voxel::Volume& g = *meshGrid;
        EXPECT_GT(g.value(g.frame.indexOf(0, 0.0), g.frame.indexOf(1, 0.3), g.frame.indexOf(2, 0.0)), 0.0f);
        EXPECT_LT(g.value(g.frame.indexOf(0, 0.0), g.frame.indexOf(1, 0.64), g.frame.indexOf(2, 0.0)), 0.0f);
        // The export refuses HyperFun as for a garden's mesh entry.
        EXPECT_NE(exportHyperFun(s, m).error.find("made from a mesh (" + obj + ")"), std::string::npos)
            << exportHyperFun(s, m).error;
        EXPECT_NE(exportHyperFun(s, v).error.find("cannot be written as exact HyperFun"), std::string::npos);
        EXPECT_EQ(o.recorder->records(), 4u);
    }
    // The copies, named by the records.
    EXPECT_TRUE(fs::exists(fs::path(folder) / "imports" / "block.obj"));
    EXPECT_TRUE(fs::exists(fs::path(folder) / "imports" / "slab.vdb"));
    EXPECT_NE(journalText().find(R"("mesh":{"file":"imports/block.obj"})"), std::string::npos) << journalText();
    EXPECT_NE(journalText().find(R"("volume":{"file":"imports/slab.vdb","inside":"below","iso":0.0})"),
              std::string::npos)
        << journalText();
    fs::remove(obj);
    fs::remove(vdb);
#ifdef HG_HYPERGARDEN_EXE
    // The command line finds the copies from any folder: the session
    // verified against its snapshot, the mesh exported read-only.
    const test::ShellRun verify = test::shell("cd / && $HG session '" + folder + "' --verify");
    EXPECT_EQ(verify.status, 0) << verify.output;
    const test::ShellRun exported = test::shell("cd / && $HG export '" + folder + "' --sculpture block -o '" +
                                                (dir / "block.stl").string() + "'");
    EXPECT_EQ(exported.status, 0) << exported.output;
    EXPECT_TRUE(fs::exists(dir / "block.stl")) << exported.output;
#endif

    OpenedSession o = open();
    GardenSession& s = *o.session;
    ASSERT_EQ(o.warning, "");
    ASSERT_GE(s.findSculpture("block"), 0);
    ASSERT_GE(s.findSculpture("slab"), 0);
    EXPECT_TRUE(of(s, "block").meshed());
    EXPECT_EQ(s.editCount(s.findSculpture("block")), 1u);
    EXPECT_EQ(test::differingVoxels(*of(s, "block").volume, *meshGrid), 0);
    EXPECT_EQ(test::differingVoxels(*of(s, "slab").volume, *volumeGrid), 0);
    // Undone like a HyperFun add: the two strokes, then the slab.
    for (int n = 0; n < 3; ++n) ASSERT_TRUE(s.undo());
    EXPECT_EQ(s.findSculpture("slab"), -1);
    ASSERT_TRUE(s.redo());
    EXPECT_GE(s.findSculpture("slab"), 0);
}

TEST_F(SessionImporting, ABadFileIsRefusedWithItsNameAndLineAndNothingIsJournalled) {
    const std::string bad = write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    write("x.raw", std::string(8, '\0'));
    OpenedSession o = open();
    GardenSession& s = *o.session;
    const std::size_t before = s.sculptures().size();
    const std::string why = s.addSculptureFile(bad, "", at(0.0, 4.0), 32);
    EXPECT_NE(why.find("bad.obj:4: "), std::string::npos) << why;
    EXPECT_NE(why.find("out of range"), std::string::npos) << why;
    EXPECT_NE(s.addSculptureFile((dir / "x.raw").string(), "", at(0.0, 4.0)).find("a raw volume needs its dimensions"),
              std::string::npos);
    EXPECT_NE(s.addSculptureFile((dir / "gone.stl").string(), "", at(0.0, 4.0)).find("gone.stl"), std::string::npos);
    EXPECT_NE(s.addSculptureFile(write("b.obj", kBlockObj), "c", at(0.0, 4.0)).find("already"), std::string::npos);
    EXPECT_EQ(s.sculptures().size(), before);
    EXPECT_EQ(o.recorder->records(), 0u);
    EXPECT_EQ(journalText().find("\"add\""), std::string::npos);
    std::error_code ec;
    EXPECT_TRUE(!fs::exists(fs::path(folder) / "imports") || fs::is_empty(fs::path(folder) / "imports", ec));
}

TEST_F(SessionImporting, AReplayAddsAMeshIntoItsSession) {
    write("block.obj", kBlockObj);
    OpenedSession o = open();
    const ReplayScript script = parseReplayScript(R"({"garden": ")" + garden + R"(", "steps": [{"commands": [
        {"add": {"file": "block.obj", "name": "plinth", "position": [0, 0, 4], "resolution": 24}}]},
        {"until_idle": true, "frames": 2000}]})",
                                                  (dir / "add.json").string(), dir.string());
    const ReplayResult r = runReplay(script, *o.session, nullptr, {});
    ASSERT_EQ(r.error, "");
    ASSERT_GE(o.session->findSculpture("plinth"), 0);
    EXPECT_TRUE(of(*o.session, "plinth").meshed());
    EXPECT_EQ(of(*o.session, "plinth").volume->frame.resolution, 24);
    EXPECT_TRUE(fs::exists(fs::path(folder) / "imports" / "block.obj"));
    EXPECT_GT(o.session->trianglesShown(), 0u);
}

TEST_F(SessionImporting, OldAddRecordsReadAsBeforeAndImportRecordsRoundTrip) {
    // An add record as journals held it before imports: read and written
    // back byte for byte, with no imported file.
    const std::string old =
        R"({"action":"add","body":"b","box":[[-0.5,-0.5,-0.5],[0.5,0.5,0.5]],"origin":"cube.hf","position":[1.0,0.0,4.0],)"
        R"("resolution":40,"scale":1.0,"sculpture":"block","source":"b(x[3], a[1]) { b = 1; }","yaw":30.0})";
    const Action a = parseAction(old, "journal");
    const auto& add = std::get<AddAction>(a);
    EXPECT_FALSE(add.imported);
    EXPECT_EQ(add.source, "b(x[3], a[1]) { b = 1; }");
    EXPECT_EQ(actionJson(a), old);
    const std::string mesh =
        R"({"action":"add","mesh":{"file":"imports/a.stl"},"origin":"/x/a.stl","position":[0.0,0.0,0.0],)"
        R"("resolution":64,"scale":2.0,"sculpture":"a","yaw":0.0})";
    const Action m = parseAction(mesh, "journal");
    ASSERT_TRUE(std::get<AddAction>(m).imported);
    EXPECT_EQ(std::get<AddAction>(m).imported->file, "imports/a.stl");
    EXPECT_EQ(actionJson(m), mesh);
    const std::string reload = R"({"action":"reload","sculpture":"a","source":"b(x[3], a[1]) { b = 2; }"})";
    EXPECT_EQ(actionJson(parseAction(reload, "journal")), reload);
    // One source only; a volume says its side.
    const auto refused = [](const std::string& text) {
        try {
            parseAction(text, "$");
        } catch (const JsonError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refused(R"({"action":"add","source":"x","mesh":{"file":"a.stl"},"origin":"o","resolution":64,)"
                      R"("position":[0,0,0],"yaw":0,"scale":1,"sculpture":"a"})")
                  .find("one of"),
              std::string::npos);
    EXPECT_NE(refused(R"({"action":"add","volume":{"file":"a.vdb","iso":0,"inside":"in"},"origin":"o","resolution":64,)"
                      R"("position":[0,0,0],"yaw":0,"scale":1,"sculpture":"a"})")
                  .find("$.volume.inside"),
              std::string::npos);
}

TEST_F(SessionImporting, AnAddedHyperFunFileIsReadAgainWhenItChangesAndTheJournalPlaysWithoutIt) {
    const std::string file = rewrite("cube.hf", cube(0.3));
    std::unique_ptr<voxel::Volume> reloaded;
    {
        OpenedSession o = open();
        GardenSession& s = *o.session;
        ASSERT_EQ(s.addSculptureFile(file, "", at(0.0, 4.0), 32), "");
        const int i = s.findSculpture("cube");
        ASSERT_EQ(s.applyStroke(i, StrokeTool::Carve, {{0.0, 0.3, 4.3}, {0.1, 0.35, 4.3}}, 0.08), "");
        EXPECT_TRUE(s.reloadChangedSources().empty()) << "nothing changed on disk";
        const auto inside = [&](double y) {
            const voxel::Volume& g = *of(s, "cube").volume;
            return y < g.frame.modelBox.hi[1] &&
                   g.value(g.frame.indexOf(0, 0.0), g.frame.indexOf(1, y), g.frame.indexOf(2, 0.0)) > 0.0f;
        };
        EXPECT_FALSE(inside(0.75));

        // A larger cube: read again (its box found anew), the stroke applied again.
        rewrite("cube.hf", cube(0.5));
        std::vector<GardenSession::SourceReload> r = s.reloadChangedSources();
        ASSERT_EQ(r.size(), 1u);
        EXPECT_EQ(r[0].sculpture, "cube");
        EXPECT_EQ(r[0].problem, "");
        EXPECT_TRUE(inside(0.75));
        EXPECT_EQ(s.editCount(i), 1u);
        EXPECT_EQ(o.recorder->records(), 3u);  // add, stroke, reload
        reloaded = std::make_unique<voxel::Volume>(of(s, "cube").volume->clone());
        // It is what adding the new file and making the stroke gives.
        GardenSession fresh(loadGarden(garden), test::smallSessionSettings());
        ASSERT_EQ(fresh.addSculptureFile(file, "", at(0.0, 4.0), 32), "");
        ASSERT_EQ(fresh.applyStroke(fresh.findSculpture("cube"), StrokeTool::Carve, {{0.0, 0.3, 4.3}, {0.1, 0.35, 4.3}},
                                    0.08),
                  "");
        EXPECT_EQ(test::differingVoxels(*of(fresh, "cube").volume, *reloaded), 0);

        // A broken file keeps the last good grid and says where.
        rewrite("cube.hf", "my_model(x[3], a[1]) {\n  my_model = 1 - ;\n}\n");
        r = s.reloadChangedSources();
        ASSERT_EQ(r.size(), 1u);
        EXPECT_NE(r[0].problem.find("cube.hf:2:"), std::string::npos) << r[0].problem;
        EXPECT_EQ(test::differingVoxels(*of(s, "cube").volume, *reloaded), 0);
        EXPECT_EQ(o.recorder->records(), 3u);
        // Mended to the last good text: the message goes, nothing is journalled.
        rewrite("cube.hf", cube(0.5));
        r = s.reloadChangedSources();
        ASSERT_EQ(r.size(), 1u);
        EXPECT_EQ(r[0].problem, "");
        EXPECT_EQ(o.recorder->records(), 3u);
    }
    // Reopened with the file as it was: the same grid, nothing read again.
    {
        OpenedSession o = open();
        EXPECT_EQ(test::differingVoxels(*of(*o.session, "cube").volume, *reloaded), 0);
        EXPECT_TRUE(o.session->reloadChangedSources().empty());
    }
    // Without the file the journal plays the reload from its own text.
    fs::remove(file);
    OpenedSession o = open();
    ASSERT_EQ(o.warning, "");
    EXPECT_EQ(test::differingVoxels(*of(*o.session, "cube").volume, *reloaded), 0);
    EXPECT_EQ(o.session->editCount(o.session->findSculpture("cube")), 1u);
    EXPECT_TRUE(o.session->reloadChangedSources().empty());
}

}  // namespace
}  // namespace hg::garden
