// Scanned volumes as sculptures (issue 22; docs/volumes.md, "Scanned
// volumes"): a garden entry naming a raw volume and an iso-value is read,
// refused with the entry's location when it is wrong, sampled into a grid
// that is sculpted, undone, journalled and reopened like any other, meshed
// from its grid into watertight files, and refused as HyperFun with the
// reason and what to use instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>

#include "garden/export/export_file.h"
#include "garden/export/hyperfun_export.h"
#include "garden/replay/replay_runner.h"
#include "garden/replay/replay_script.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/export/part_export.h"
#include "garden/session/open_session.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "session_garden.h"
#include "tests/cli_fixture.h"
#include "tests/scan_volumes.h"
#include "tools/scan_phantom.h"

namespace hg::garden {
namespace {

// A ball of radius 0.6 sampled 40^3 at 0.05 (centre (1, 1, 1) in model
// units), standing 3 m to the right of a HyperFun ball.
class ScannedSculpture : public test::ScratchDir {
protected:
    ::hg::test::ScanBall ball;
    std::string writeGarden(const nlohmann::json& volume = nlohmann::json::object(), bool sixteen = false) {
        ball.write((dir / "ball.raw").string(), sixteen);
        std::ofstream(dir / "ball.hf") << "ball(x[3], a[1]) { ball = a[1] - (x[1]^2 + (x[2]-0.5)^2 + x[3]^2); }\n";
        nlohmann::json scan = {{"file", "ball.raw"}, {"dims", {40, 40, 40}}, {"type", "u8"}, {"spacing", 0.05}, {"iso", 128}};
        scan.merge_patch(volume);
        nlohmann::json g = {
            {"version", 1},
            {"sculptures",
             {{{"name", "hf"}, {"file", "ball.hf"}, {"a", {0.25}}, {"resolution", 32}},
              {{"name", "scan"}, {"volume", scan}, {"resolution", 48}, {"placement", {{"position", {3, 0, 0}}}}}}}};
        std::ofstream(dir / "garden.json") << g.dump(2);
        return (dir / "garden.json").string();
    }
    static SessionSettings settings() {
        SessionSettings s = test::smallSessionSettings();
        s.maxLevel = 0;
        return s;
    }
};

TEST_F(ScannedSculpture, TheEntryIsReadWithItsFields) {
    const GardenLoad load = loadGarden(writeGarden({{"spacing", {0.05, 0.05, 0.05}}, {"inside", "above"}}));
    ASSERT_TRUE(load.ok()) << load.error;
    const SculptureSpec& spec = load.garden->sculptures[1];
    ASSERT_TRUE(spec.scan);
    EXPECT_EQ(spec.fileAsWritten, "ball.raw");
    EXPECT_EQ(spec.scan->dims, (std::array<int, 3>{40, 40, 40}));
    EXPECT_FALSE(spec.scan->sixteenBit);
    EXPECT_EQ(spec.scan->iso, 128.0);
    EXPECT_TRUE(spec.scan->insideAbove);
    EXPECT_EQ(spec.scan->at, (dir / "garden.json").string() + ": $.sculptures[1].volume");
    EXPECT_TRUE(load.sculptures[1].ok()) << load.sculptures[1].error;
    EXPECT_TRUE(load.sculptures[1].scan);
}

TEST_F(ScannedSculpture, BadEntriesAreRefusedWithTheirPath) {
    const std::string file = (dir / "garden.json").string();
    struct Case {
        nlohmann::json volume;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{{"type", "u12"}}, "$.sculptures[1].volume.type: expected \"u8\" or \"u16\""},
        {{{"dims", {40, 40}}}, "$.sculptures[1].volume.dims: expected an array of 3 integers"},
        {{{"dims", {40, 1, 40}}}, "$.sculptures[1].volume.dims[1]:"},
        {{{"file", "ball.nrrd"}}, "$.sculptures[1].volume.file: expected a raw volume (.raw) or an OpenVDB file (.vdb)"},
        {{{"grid", "density"}}, "$.sculptures[1].volume.grid: 'grid' applies to a .vdb file"},
        {{{"inside", "out"}}, "$.sculptures[1].volume.inside: expected \"above\""},
        {{{"iso", nullptr}}, "$.sculptures[1].volume: missing key 'iso'"},
        {{{"spacing", {0.05, 0, 0.05}}}, "$.sculptures[1].volume.spacing[1]: expected a positive number"},
        {{{"iso_value", 3}}, "$.sculptures[1].volume.iso_value: unknown key"},
    };
    for (const Case& c : cases) {
        const GardenLoad load = loadGarden(writeGarden(c.volume));
        EXPECT_FALSE(load.ok()) << c.message;
        EXPECT_NE(load.error.find(file + ": " + c.message), std::string::npos) << load.error;
    }
    // A .vdb has its own dims.
    GardenLoad vdb = loadGarden(writeGarden({{"file", "ball.vdb"}}));
    EXPECT_NE(vdb.error.find("$.sculptures[1].volume.dims: 'dims' applies to a raw volume"), std::string::npos) << vdb.error;
    // "file" and "volume" together, or "body" with a volume.
    nlohmann::json g = nlohmann::json::parse(R"({"version": 1, "sculptures": [
        {"name": "s", "file": "ball.hf", "volume": {"file": "ball.raw", "dims": [40, 40, 40], "iso": 128}}]})");
    std::ofstream(dir / "both.json") << g.dump();
    GardenLoad both = loadGarden((dir / "both.json").string());
    EXPECT_NE(both.error.find("$.sculptures[0]: give one of 'file' (a HyperFun program), 'volume'"), std::string::npos)
        << both.error;
    g["sculptures"][0].erase("file");
    g["sculptures"][0]["body"] = "ball";
    std::ofstream(dir / "body.json") << g.dump();
    GardenLoad body = loadGarden((dir / "body.json").string());
    EXPECT_NE(body.error.find("$.sculptures[0].body: 'body' applies to a HyperFun file, not to a volume"),
              std::string::npos) << body.error;
}

TEST_F(ScannedSculpture, AWrongFileMarksTheSculptureMissingWithTheEntrysLocation) {
    const std::string at = (dir / "garden.json").string() + ": $.sculptures[1].volume: ";
    struct Case {
        nlohmann::json volume;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{{"file", "gone.raw"}}, "gone.raw: cannot open: No such file or directory"},
        {{{"dims", {40, 40, 41}}}, "64000 bytes, but dims 40 x 40 x 41 of u8 need 65600 bytes"},
        {{{"type", "u16"}}, "64000 bytes, but dims 40 x 40 x 40 of u16 need 128000 bytes"},
        {{{"iso", 300}}, "iso 300 is outside the data's range (0 to 255)"},
        {{{"iso", 0}}, "iso 0 is outside the data's range (0 to 255)"},
    };
    for (const Case& c : cases) {
        const GardenLoad load = loadGarden(writeGarden(c.volume));
        ASSERT_TRUE(load.ok()) << load.error;
        EXPECT_TRUE(load.sculptures[0].ok());
        ASSERT_FALSE(load.sculptures[1].ok()) << c.message;
        EXPECT_EQ(load.sculptures[1].error.rfind(at, 0), 0u) << load.sculptures[1].error;
        EXPECT_NE(load.sculptures[1].error.find(c.message), std::string::npos) << load.sculptures[1].error;
        // The garden opens; the scan is shown missing with that message.
        GardenSession s(load, settings());
        EXPECT_TRUE(s.sculptures()[1].missing());
        EXPECT_NE(s.sculptures()[1].error.find(c.message), std::string::npos);
    }
}

TEST_F(ScannedSculpture, ItOpensAsAScanWhoseSurfaceIsTheIsoSurface) {
    GardenSession s(loadGarden(writeGarden()), settings());
    const Sculpture& scan = s.sculptures()[1];
    ASSERT_FALSE(scan.missing()) << scan.error;
    EXPECT_TRUE(scan.scanned());
    EXPECT_FALSE(s.sculptures()[0].scanned());
    const voxel::VolumeFrame& f = scan.volume->frame;
    EXPECT_EQ(f.resolution, 48);
    // Centre inside, a point a voxel outside the sphere outside, and the
    // zero crossing along +x within half a voxel of the radius.
    EXPECT_EQ(scan.volume->value(f.indexOf(0, 1.0), f.indexOf(1, 1.0), f.indexOf(2, 1.0)), f.band);
    const int j = f.indexOf(1, 1.0), k = f.indexOf(2, 1.0);
    double crossing = 0.0;
    for (int i = f.indexOf(0, 1.0); i < f.indexBox.hi[0]; ++i) {
        const float a = scan.volume->value(i, j, k), b = scan.volume->value(i + 1, j, k);
        if (a >= 0.0f && b < 0.0f) {
            crossing = f.coordinate(0, i) + f.voxelSize * static_cast<double>(a / (a - b));
            break;
        }
    }
    EXPECT_NEAR(crossing, 1.0 + ball.radius, 0.5 * f.voxelSize);
    // The same grid whether sampled at the start or in the background.
    SessionSettings progressive = settings();
    progressive.progressiveLoading = true;
    GardenSession later(loadGarden(writeGarden()), progressive);
    later.finishLoading();
    ASSERT_TRUE(later.sculptures()[1].volume);
    EXPECT_EQ(test::differingVoxels(*later.sculptures()[1].volume, *scan.volume), 0);
}

TEST_F(ScannedSculpture, AStrokeChangesItAndUndoRestoresItBitForBit) {
    GardenSession s(loadGarden(writeGarden()), settings());
    const int scan = s.findSculpture("scan");
    Sculpture& st = s.sculptures()[static_cast<std::size_t>(scan)];
    const voxel::Volume original = st.volume->clone();
    // Across the top of the ball: world (3 + 1, 1.6, 1) is its top point.
    ASSERT_EQ(s.applyStroke(scan, StrokeTool::Carve, {{3.8, 1.6, 1.0}, {4.2, 1.6, 1.0}}, 0.1), "");
    ASSERT_EQ(s.editCount(scan), 1u);
    EXPECT_GT(test::differingVoxels(*st.volume, original), 100);
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    const voxel::Volume carved = st.volume->clone();
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(*st.volume, original), 0);
    ASSERT_TRUE(s.redo());
    EXPECT_EQ(test::differingVoxels(*st.volume, carved), 0);
    // A sketch joined to it (a disc drawn on the plane z = 1.6 in front of
    // the ball, world (4, 1, 1.6)) is an edit like the stroke.
    std::vector<std::array<double, 3>> disc;
    for (int n = 0; n < 32; ++n) {
        const double t = 2.0 * 3.14159265358979 * n / 32.0;
        disc.push_back({4.0 + 0.15 * std::cos(t), 1.0 + 0.15 * std::sin(t), 1.6});
    }
    ASSERT_EQ(s.applySketch(scan, SketchMode::Add, disc, {0.0, 0.0, 1.0}), "");
    EXPECT_EQ(s.editCount(scan), 2u);
    EXPECT_GT(test::differingVoxels(*st.volume, carved), 50);
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(*st.volume, carved), 0);
}

// A scanned volume is the thing selected (issue 22): a model sketched
// around the scanned ball shrinks onto it, its selection keeps a stroke
// inside it, and extracting a part of a scan is refused with the reason.
TEST_F(ScannedSculpture, AModelShrinksOntoItAndItsSelectionLimitsTheTools) {
    GardenSession s(loadGarden(writeGarden()), settings());
    const int scan = s.findSculpture("scan");
    Sculpture& st = s.sculptures()[static_cast<std::size_t>(scan)];
    // Around the ball's upper half: a circle of 0.5 m about world (4, 1.5, 1).
    std::vector<std::array<double, 3>> circle;
    for (int n = 0; n < 40; ++n) {
        const double t = 2.0 * 3.14159265358979 * n / 40.0;
        circle.push_back({4.0 + 0.5 * std::cos(t), 1.5 + 0.5 * std::sin(t), 1.0});
    }
    const auto m = s.modelFromWorld(scan, "top", circle, {0.0, 0.0, 1.0});
    ASSERT_TRUE(m.action) << m.why;
    ASSERT_EQ(s.apply(*m.action), "");
    ASSERT_EQ(s.deformModel("top", true, 150), "");
    const double voxel = st.volume->frame.voxelSize;
    double worst = 0.0;
    for (const auto& v : s.models())
        if (v.name == "top")
            for (const glm::dvec3& p : *v.vertices)
                if (p.y > 1.45)  // the wrapped cap, above where the model was drawn through the ball
                    worst = std::max(worst, std::fabs(glm::length(p - glm::dvec3(1.0, 1.0, 1.0)) - 0.6));
    EXPECT_LT(worst, 2.0 * voxel) << "the model lies on the scanned surface";
    ASSERT_TRUE(s.selectionOf(scan));
    // A carve along the ball's equator: only the part inside the selection changes.
    const voxel::Volume before = st.volume->clone();
    ASSERT_EQ(s.applyStroke(scan, StrokeTool::Carve, {{3.3, 1.0, 1.0}, {4.7, 1.0, 1.0}}, 0.12), "");
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    const int low = st.volume->frame.indexOf(1, 1.0 - 0.05);
    int changedBelow = 0;
    const voxel::IndexBox box = st.volume->frame.indexBox;
    for (int i = box.lo[0]; i <= box.hi[0]; ++i)
        for (int j = box.lo[1]; j <= low - 8; ++j)
            for (int k = box.lo[2]; k <= box.hi[2]; ++k)
                if (st.volume->value(i, j, k) != before.value(i, j, k)) ++changedBelow;
    EXPECT_EQ(changedBelow, 0) << "nothing changes well below the selection";
    EXPECT_GT(test::differingVoxels(*st.volume, before), 20);
    EXPECT_NE(extractPart(s, "scan", "top", "").find("scanned volume"), std::string::npos);
}

// A volume rewritten on disk is read again like a changed .hf: with a box
// given its grid is replaced in place and its edits applied again; a file
// that no longer fits its entry keeps the last good grid and says why.
TEST_F(ScannedSculpture, AVolumeChangedOnDiskIsReadAgain) {
    const std::string garden = writeGarden();
    nlohmann::json g = nlohmann::json::parse(std::ifstream(garden));
    g["sculptures"][1]["box"] = {{"min", {0.3, 0.3, 0.3}}, {"max", {1.7, 1.7, 1.7}}};
    std::ofstream(garden) << g.dump();
    GardenSession s(loadGarden(garden), settings());
    const int scan = s.findSculpture("scan");
    ASSERT_EQ(s.applyStroke(scan, StrokeTool::Carve, {{3.8, 1.6, 1.0}, {4.2, 1.6, 1.0}}, 0.1), "");
    const Sculpture& st = s.sculptures()[static_cast<std::size_t>(scan)];
    const voxel::Volume before = st.volume->clone();
    const auto touch = [&] {
        const auto p = dir / "ball.raw";
        std::filesystem::last_write_time(p, std::filesystem::last_write_time(p) + std::chrono::seconds(5));
    };
    ::hg::test::ScanBall smaller = ball;
    smaller.radius = 0.5;
    smaller.write((dir / "ball.raw").string(), false);
    touch();
    std::vector<GardenSession::SourceReload> r = s.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].sculpture, "scan");
    EXPECT_EQ(r[0].problem, "");
    EXPECT_GT(test::differingVoxels(*st.volume, before), 1000);
    EXPECT_EQ(s.editCount(scan), 1u) << "the stroke is applied again on the new grid";
    EXPECT_EQ(test::differingVoxels(*st.volume, *st.edits->rebuild()), 0);
    // Cut short: the last good grid stays, with the entry's message.
    const voxel::Volume good = st.volume->clone();
    std::ofstream(dir / "ball.raw", std::ios::binary) << std::string(100, '\0');
    touch();
    r = s.reloadChangedSources();
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NE(r[0].problem.find("$.sculptures[1].volume: "), std::string::npos) << r[0].problem;
    EXPECT_NE(r[0].problem.find("100 bytes, but dims 40 x 40 x 40 of u8 need 64000 bytes"), std::string::npos)
        << r[0].problem;
    EXPECT_EQ(test::differingVoxels(*st.volume, good), 0);
}

TEST_F(ScannedSculpture, ASessionReopensWithTheSameGridAndItsVolumeCopiedIn) {
    const std::string garden = writeGarden();
    const std::string folder = (dir / "session").string();
    std::unique_ptr<voxel::Volume> saved;
    {
        OpenedSession o = openSession({folder, garden}, settings());
        ASSERT_EQ(o.error, "");
        GardenSession& s = *o.session;
        const int scan = s.findSculpture("scan");
        ASSERT_EQ(s.applyStroke(scan, StrokeTool::Carve, {{3.8, 1.6, 1.0}, {4.2, 1.6, 1.0}}, 0.1), "");
        ASSERT_EQ(s.applyPerturbation(scan, QuadricShape::Ellipsoid, {3.0, 1.0, 1.6}, {0.15, 0.15, 0.15}, 2.0), "");
        ASSERT_EQ(s.applyStroke(scan, StrokeTool::Add, {{3.4, 1.0, 1.5}, {3.6, 1.2, 1.5}}, 0.08), "");
        ASSERT_TRUE(s.undo());
        saved = std::make_unique<voxel::Volume>(s.sculptures()[static_cast<std::size_t>(scan)].volume->clone());
    }
    // The session keeps the volume as it was: changing the original later
    // does not change the session.
    EXPECT_TRUE(std::filesystem::exists(dir / "session" / "sources" / "ball.raw"));
    ::hg::test::ScanBall other = ball;
    other.radius = 0.4;
    other.write((dir / "ball.raw").string(), false);
    OpenedSession o = openSession({folder, garden}, settings());
    ASSERT_EQ(o.error, "");
    const int scan = o.session->findSculpture("scan");
    ASSERT_FALSE(o.session->sculptures()[static_cast<std::size_t>(scan)].missing());
    EXPECT_EQ(o.session->editCount(scan), 2u);
    EXPECT_EQ(test::differingVoxels(*o.session->sculptures()[static_cast<std::size_t>(scan)].volume, *saved), 0);
}

TEST_F(ScannedSculpture, ItIsMeshedFromItsGridAndRefusedAsHyperFun) {
    GardenSession s(loadGarden(writeGarden()), settings());
    const int scan = s.findSculpture("scan");
    ASSERT_EQ(s.applyStroke(scan, StrokeTool::Carve, {{3.8, 1.6, 1.0}, {4.2, 1.6, 1.0}}, 0.1), "");
    ExportFileReport report;
    const std::string stl = (dir / "scan.stl").string();
    ASSERT_EQ(exportSculptureFile(s, scan, stl, {}, report), "");
    EXPECT_NE(report.summary.find("1 edits (meshed from its grid)"), std::string::npos) << report.summary;
    const poly::StlReadResult r = poly::readStl(stl);
    ASSERT_EQ(r.error, "");
    const poly::MeshReport m = poly::validateMesh(poly::weldByPosition(r.mesh));
    EXPECT_TRUE(m.ok()) << poly::describe(m);
    // Millimetres at its true size (1 m per model unit): a ball 1.2 m across.
    EXPECT_NEAR(m.boxMax[0] - m.boxMin[0], 1200.0, 40.0);
    for (const char* ext : {"obj", "glb", "vdb"}) {
        const std::string path = (dir / (std::string("scan.") + ext)).string();
        EXPECT_EQ(exportSculptureFile(s, scan, path, {}, report), "") << ext;
        EXPECT_TRUE(std::filesystem::exists(path)) << ext;
    }
    // HyperFun cannot read a volume: refused, saying why and what instead.
    const std::string hf = (dir / "scan.hf").string();
    const std::string why = exportSculptureFile(s, scan, hf, {}, report);
    EXPECT_NE(why.find("sculpture 'scan' is made from a scanned volume (ball.raw), and HyperFun has no way to read a "
                       "volume"),
              std::string::npos) << why;
    EXPECT_NE(why.find("export it as a mesh or a level set instead (.stl, .obj, .glb or .vdb)"), std::string::npos) << why;
    EXPECT_FALSE(std::filesystem::exists(hf));
    EXPECT_EQ(exportHyperFun(s, scan).error, why);
    // A resolution other than the grid's cannot be had from a grid.
    ExportFileOptions finer;
    finer.resolution = 96;
    const std::string res = exportSculptureFile(s, scan, (dir / "fine.stl").string(), finer, report);
    EXPECT_NE(res.find("it is meshed from its grid, at the grid's 48 voxels"), std::string::npos) << res;
    // The HyperFun sculpture beside it still exports as HyperFun.
    EXPECT_EQ(exportSculptureFile(s, 0, (dir / "hf.hf").string(), {}, report), "");
}

TEST_F(ScannedSculpture, ABallCutByTheDataFacesIsClosed) {
    ball.centre = {1.0, 0.3, 1.0};  // reaches below the first sample row
    GardenSession s(loadGarden(writeGarden()), settings());
    const int scan = s.findSculpture("scan");
    ASSERT_FALSE(s.sculptures()[static_cast<std::size_t>(scan)].missing());
    ExportFileReport report;
    const std::string stl = (dir / "cut.stl").string();
    ASSERT_EQ(exportSculptureFile(s, scan, stl, {}, report), "");
    const poly::StlReadResult r = poly::readStl(stl);
    ASSERT_EQ(r.error, "");
    const poly::MeshReport m = poly::validateMesh(poly::weldByPosition(r.mesh));
    EXPECT_TRUE(m.ok()) << poly::describe(m);
    // Flat where the data ends (y = 0, within a sample): the ball's lower cap is cut.
    EXPECT_NEAR(m.boxMin[1], 0.0, 1000.0 * ball.spacing);
}

TEST_F(ScannedSculpture, AScanIsNoMorphSource) {
    writeGarden();
    nlohmann::json g = nlohmann::json::parse(std::ifstream(dir / "garden.json"));
    g["sculptures"].push_back({{"name", "hf2"}, {"file", "ball.hf"}, {"a", {0.2}}, {"resolution", 32},
                               {"placement", {{"position", {0, 0, 3}}}}});
    g["morph"] = {{"sources", {"hf", "scan", "hf2"}}, {"result", {{"resolution", 32}}}};
    std::ofstream(dir / "morph.json") << g.dump();
    const GardenLoad load = loadGarden((dir / "morph.json").string());
    ASSERT_TRUE(load.ok()) << load.error;
    EXPECT_EQ(load.morphErrors.at(0),
              "morph source 'scan' is a scanned volume; the metamorphosis blends HyperFun sculptures, so there is none");
    GardenSession s(load, settings());
    EXPECT_FALSE(s.hasMorph());
    EXPECT_FALSE(s.sculptures()[1].missing());
}

// The committed phantom is what its generator makes, and the garden that
// shows it opens with both of its sculptures (bone and skin) on show.
TEST(ScanContent, ThePhantomIsItsGeneratorsAndItsGardenOpens) {
    const std::string root = HG_SOURCE_DIR;
    std::ifstream in(root + "/content/volumes/phantom.raw", std::ios::binary);
    const std::vector<char> committed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<std::uint8_t> made = tools::makePhantom();
    ASSERT_EQ(committed.size(), made.size()) << "rebuild it: hg_scan_phantom content/volumes/phantom.raw";
    EXPECT_TRUE(std::equal(made.begin(), made.end(), committed.begin(),
                           [](std::uint8_t a, char b) { return a == static_cast<std::uint8_t>(b); }))
        << "rebuild it: hg_scan_phantom content/volumes/phantom.raw";
    GardenLoad load = loadGarden(root + "/content/gardens/scan.json");
    ASSERT_TRUE(load.ok()) << load.error;
    SessionSettings settings;
    settings.maxLevel = 0;
    settings.sculptureResolution = 64;
    GardenSession s(load, settings);
    for (const char* name : {"skull", "head"}) {
        const int i = s.findSculpture(name);
        ASSERT_GE(i, 0) << name;
        const Sculpture& st = s.sculptures()[static_cast<std::size_t>(i)];
        ASSERT_FALSE(st.missing()) << name << ": " << st.error;
        EXPECT_TRUE(st.scanned());
        EXPECT_GT(st.volume->activeVoxelCount(), 5000u) << name;
    }
    // The skin encloses the skull: its box is the larger.
    const auto size = [&](const char* name) {
        const frep::Box3& b = s.sculptures()[static_cast<std::size_t>(s.findSculpture(name))].volume->frame.modelBox;
        return (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
    };
    EXPECT_GT(size("head"), size("skull"));
}

// content/replays/scan_session.json plays: its stroke carves the skin.
TEST(ScanContent, TheReplayCarvesTheHead) {
    const ReplayScript script = loadReplayScript(std::string(HG_SOURCE_DIR) + "/content/replays/scan_session.json");
    SessionSettings settings = test::smallSessionSettings();
    settings.sculptureResolution = 64;
    settings.remeshChunksPerFrame = 0;
    GardenSession s(loadGarden(script.garden), settings);
    const int head = s.findSculpture("head");
    ASSERT_GE(head, 0);
    const voxel::Volume before = s.sculptures()[static_cast<std::size_t>(head)].volume->clone();
    const ReplayResult r = runReplay(script, s, nullptr, {});
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(s.editCount(head), 1u);
    EXPECT_GT(test::differingVoxels(*s.sculptures()[static_cast<std::size_t>(head)].volume, before), 100);
}

#ifdef HG_HYPERGARDEN_EXE
TEST_F(ScannedSculpture, TheCommandLineRefusesHyperFunAndWritesMeshes) {
    const std::string garden = writeGarden();
    const ::hg::test::CommandRun hf =
        ::hg::test::runHypergarden("export '" + garden + "' --sculpture scan -o '" + (dir / "x.hf").string() + "'");
    EXPECT_EQ(hf.status, 1) << hf.output;
    EXPECT_NE(hf.output.find("error: sculpture 'scan' is made from a scanned volume (ball.raw)"), std::string::npos)
        << hf.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.hf"));
    const ::hg::test::CommandRun stl =
        ::hg::test::runHypergarden("export '" + garden + "' --sculpture scan -o '" + (dir / "x.stl").string() + "'");
    EXPECT_EQ(stl.status, 0) << stl.output;
    EXPECT_NE(stl.output.find("(meshed from its grid)"), std::string::npos) << stl.output;
}
#endif

}  // namespace
}  // namespace hg::garden
