// Meshes as sculptures (docs/garden-format.md, "mesh"; voxel/mesh_volume.h):
// a closed mesh's level set has its zero within a voxel of the triangles and
// its inside where the mesh's is; an open one becomes a thin shell; a garden
// entry naming an OBJ opens, is sculpted, meshed watertight and refused as
// HyperFun; `hypergarden garden add` writes mesh and volume entries.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "garden/export/export_file.h"
#include "garden/export/hyperfun_export.h"
#include "garden/scene/garden_file.h"
#include "garden/scene/garden_making.h"
#include "polygonizer/export/mesh_read.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "session_garden.h"
#include "voxel/mesh_volume.h"
#include "voxel/vdb_io.h"

namespace hg::garden {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A UV sphere of `radius` about `centre` as OBJ text: poles and rings,
// quads between the rings, counter-clockwise from outside.
std::string sphereObj(double radius, const std::array<double, 3>& centre, int rings = 24, int segments = 48) {
    std::ostringstream o;
    o.precision(9);
    o << "v " << centre[0] << ' ' << centre[1] + radius << ' ' << centre[2] << '\n';
    for (int r = 1; r < rings; ++r) {
        const double phi = kPi * r / rings;
        for (int s = 0; s < segments; ++s) {
            const double theta = 2.0 * kPi * s / segments;
            o << "v " << centre[0] + radius * std::sin(phi) * std::cos(theta) << ' ' << centre[1] + radius * std::cos(phi)
              << ' ' << centre[2] + radius * std::sin(phi) * std::sin(theta) << '\n';
        }
    }
    o << "v " << centre[0] << ' ' << centre[1] - radius << ' ' << centre[2] << '\n';
    const int south = 2 + (rings - 1) * segments;
    const auto at = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) o << "f 1 " << at(1, s + 1) << ' ' << at(1, s) << '\n';
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            o << "f " << at(r, s) << ' ' << at(r, s + 1) << ' ' << at(r + 1, s + 1) << ' ' << at(r + 1, s) << '\n';
    for (int s = 0; s < segments; ++s) o << "f " << south << ' ' << at(rings - 1, s) << ' ' << at(rings - 1, s + 1) << '\n';
    return o.str();
}

class ImportedMesh : public test::ScratchDir {
protected:
    std::string writeGarden(const nlohmann::json& mesh) {
        write("ball.obj", sphereObj(0.5, {0.0, 0.6, 0.0}));
        nlohmann::json g = {{"version", 1},
                            {"sculptures", {{{"name", "ball"}, {"mesh", mesh}, {"resolution", 48}}}}};
        return write("garden.json", g.dump(2));
    }
    static SessionSettings settings() {
        SessionSettings s = test::smallSessionSettings();
        s.maxLevel = 0;
        return s;
    }
    static std::string read(const std::string& path) {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

// Where the grid crosses zero going +x from `from` (model units), or NaN.
double crossingAlongX(const voxel::Volume& v, const std::array<double, 3>& from) {
    const voxel::VolumeFrame& f = v.frame;
    const int j = f.indexOf(1, from[1]), k = f.indexOf(2, from[2]);
    for (int i = f.indexOf(0, from[0]); i < f.indexBox.hi[0]; ++i) {
        const float a = v.value(i, j, k), b = v.value(i + 1, j, k);
        if (a >= 0.0f && b < 0.0f) return f.coordinate(0, i) + f.voxelSize * static_cast<double>(a / (a - b));
    }
    return std::nan("");
}

TEST_F(ImportedMesh, AClosedMeshsZeroLiesOnItsTrianglesAndItsInsideIsInside) {
    const poly::MeshReadResult sphere = poly::readMeshFile(write("s.obj", sphereObj(0.5, {1.0, 2.0, 3.0})));
    ASSERT_EQ(sphere.error, "");
    EXPECT_TRUE(voxel::meshIsClosed(sphere.mesh.positions, sphere.mesh.indices));
    voxel::MeshLevelSetRequest request;
    request.resolution = 40;
    const voxel::VoxelizeResult r = voxel::levelSetFromMesh(sphere.mesh.positions, sphere.mesh.indices, request);
    ASSERT_TRUE(r.volume) << r.error;
    const voxel::Volume& v = *r.volume;
    const voxel::VolumeFrame& f = v.frame;
    EXPECT_EQ(f.resolution, 40);
    // The box: the mesh's bounds and the margin.
    EXPECT_NEAR(f.modelBox.lo[0], 0.5 - voxel::kMeshBoxMargin, 1e-5);
    EXPECT_NEAR(f.modelBox.hi[1], 2.5 + voxel::kMeshBoxMargin, 1e-5);
    // Deep inside, far outside, and the zero where the triangles are: along
    // +x the mesh's equator vertex is at radius 0.5 exactly.
    EXPECT_EQ(v.value(f.indexOf(0, 1.0), f.indexOf(1, 2.0), f.indexOf(2, 3.0)), f.band);
    EXPECT_EQ(v.value(f.indexBox.lo[0], f.indexBox.lo[1], f.indexBox.lo[2]), -f.band);
    EXPECT_NEAR(crossingAlongX(v, {1.0, 2.0, 3.0}), 1.5, f.voxelSize);
    // A unit of the grid is a voxel: a voxel inside reads about +1.
    EXPECT_NEAR(v.value(f.indexOf(0, 1.5 - f.voxelSize), f.indexOf(1, 2.0), f.indexOf(2, 3.0)), 1.0f, 0.35f);

    // Refusals say why.
    EXPECT_EQ(voxel::levelSetFromMesh({}, {}, request).error, "the mesh has no triangles");
    EXPECT_NE(voxel::levelSetFromMesh({0, 0, 0}, {0, 1, 2}, request).error.find("past its 1 vertices"), std::string::npos);
}

TEST_F(ImportedMesh, AnOpenMeshBecomesAThinShell) {
    // A square sheet in the plane y = 0: no inside of its own.
    const std::vector<float> p = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
    const std::vector<std::uint32_t> t = {0, 2, 1, 0, 3, 2};
    EXPECT_FALSE(voxel::meshIsClosed(p, t));
    voxel::MeshLevelSetRequest request;
    request.resolution = 32;
    const voxel::VoxelizeResult r = voxel::levelSetFromMesh(p, t, request);
    ASSERT_TRUE(r.volume) << r.error;
    const voxel::Volume& v = *r.volume;
    const voxel::VolumeFrame& f = v.frame;
    const int i = f.indexOf(0, 0.5), k = f.indexOf(2, 0.5), j = f.indexOf(1, 0.0);
    // At the voxel nearest the sheet: inside by the shell's half-thickness
    // less its distance to the sheet; two voxels off it: outside.
    const double off = std::fabs(f.coordinate(1, j)) / f.voxelSize;
    EXPECT_NEAR(v.value(i, j, k), static_cast<float>(voxel::kMeshShellVoxels - off), 0.1f);
    EXPECT_GT(v.value(i, j, k), 0.0f);
    EXPECT_LT(v.value(i, j + 2, k), 0.0f);
    EXPECT_LT(v.value(i, j - 2, k), 0.0f);
}

TEST_F(ImportedMesh, TheGardenEntryOpensIsSculptedMeshedAndRefusedAsHyperFun) {
    const GardenLoad load = loadGarden(writeGarden({{"file", "ball.obj"}}));
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_TRUE(load.garden->sculptures[0].mesh);
    ASSERT_TRUE(load.sculptures[0].mesh);
    GardenSession s(load, settings());
    Sculpture& ball = s.sculptures()[0];
    ASSERT_FALSE(ball.missing()) << ball.error;
    EXPECT_TRUE(ball.meshed());
    EXPECT_TRUE(ball.gridOnly());
    EXPECT_NEAR(crossingAlongX(*ball.volume, {0.0, 0.6, 0.0}), 0.5, ball.volume->frame.voxelSize);
    // Sculpted like any other: a carve across its top, undone bit for bit.
    const voxel::Volume original = ball.volume->clone();
    ASSERT_EQ(s.applyStroke(0, StrokeTool::Carve, {{-0.2, 1.1, 0.0}, {0.2, 1.1, 0.0}}, 0.1), "");
    EXPECT_GT(test::differingVoxels(*ball.volume, original), 50);
    // Meshed from its grid: closed, manifold, facing out, about 1 m across.
    ExportFileReport report;
    const std::string stl = (dir / "ball.stl").string();
    ASSERT_EQ(exportSculptureFile(s, 0, stl, {}, report), "");
    const poly::StlReadResult r = poly::readStl(stl);
    ASSERT_EQ(r.error, "");
    const poly::MeshReport m = poly::validateMesh(poly::weldByPosition(r.mesh));
    EXPECT_TRUE(m.ok()) << poly::describe(m);
    EXPECT_NEAR(m.boxMax[0] - m.boxMin[0], 1000.0, 40.0);
    // HyperFun cannot read a mesh: refused, saying what to use instead.
    const HyperFunExport hf = exportHyperFun(s, 0);
    EXPECT_NE(hf.error.find("sculpture 'ball' is made from a mesh (ball.obj), and HyperFun has no way to read a mesh"),
              std::string::npos) << hf.error;
    EXPECT_NE(hf.error.find("(.stl, .obj, .glb or .vdb)"), std::string::npos);
    ASSERT_TRUE(s.undo());
    EXPECT_EQ(test::differingVoxels(*ball.volume, original), 0);
}

TEST_F(ImportedMesh, ABadEntryOrFileSaysWhere) {
    const std::string garden = (dir / "garden.json").string();
    GardenLoad txt = loadGarden(writeGarden({{"file", "ball.txt"}}));
    EXPECT_NE(txt.error.find("$.sculptures[0].mesh.file: expected a mesh file (.stl, .obj or .ply), found 'ball.txt'"),
              std::string::npos) << txt.error;
    GardenLoad extra = loadGarden(writeGarden({{"file", "ball.obj"}, {"iso", 0}}));
    EXPECT_FALSE(extra.ok());
    // A broken file marks the sculpture missing, with the entry and the line.
    write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    const GardenLoad bad = loadGarden(writeGarden({{"file", "bad.obj"}}));
    ASSERT_TRUE(bad.ok()) << bad.error;
    EXPECT_NE(bad.sculptures[0].error.find(garden + ": $.sculptures[0].mesh: " + (dir / "bad.obj").string() +
                                           ":4: face index 4 out of range (3 vertices)"),
              std::string::npos) << bad.sculptures[0].error;
    GardenSession s(bad, settings());
    EXPECT_TRUE(s.sculptures()[0].missing());
    // A body applies to HyperFun only.
    nlohmann::json g = {{"version", 1},
                        {"sculptures", {{{"name", "b"}, {"mesh", {{"file", "ball.obj"}}}, {"body", "x"}}}}};
    write("body.json", g.dump());
    EXPECT_NE(loadGarden((dir / "body.json").string()).error.find("'body' applies to a HyperFun file, not to a mesh"),
              std::string::npos);
}

TEST_F(ImportedMesh, GardenAddWritesMeshAndVolumeEntries) {
    write("ball.obj", sphereObj(0.5, {0.0, 0.6, 0.0}));
    write("ball.hf", "my_model(x[3], a[1]) { my_model = 1 - (x[1]^2 + x[2]^2 + x[3]^2); }\n");
    ModelToPlace first;
    first.file = (dir / "ball.hf").string();
    std::string error;
    const std::string garden = write("garden.json", gardenOfOneModel(first, error));
    ASSERT_EQ(error, "");
    ModelToPlace mesh;
    mesh.file = (dir / "ball.obj").string();
    mesh.name = "imported";
    mesh.size = 2.0;
    const std::string withMesh = gardenWithModel(read(garden), garden, mesh, error);
    ASSERT_EQ(error, "");
    const nlohmann::json j = nlohmann::json::parse(withMesh);
    EXPECT_EQ(j["sculptures"][1]["mesh"]["file"], "ball.obj");
    EXPECT_FALSE(j["sculptures"][1].contains("file"));
    // Sized: 1 model unit across becomes 2 m, standing on the ground.
    EXPECT_NEAR(j["sculptures"][1]["placement"]["scale"].get<double>(), 2.0, 1e-3);
    EXPECT_NEAR(j["sculptures"][1]["placement"]["position"][1].get<double>(), -0.1 * 2.0, 1e-3);
    write("garden.json", withMesh);
    const GardenLoad load = loadGarden(garden);
    ASSERT_TRUE(load.ok()) << load.error;
    ASSERT_TRUE(load.sculptures[1].mesh) << load.sculptures[1].error;

    // A level set written by OpenVDB comes in as a volume: its zero, inside below.
    const poly::MeshReadResult sphere = poly::readMeshFile(mesh.file);
    voxel::MeshLevelSetRequest request;
    request.resolution = 32;
    voxel::VoxelizeResult r = voxel::levelSetFromMesh(sphere.mesh.positions, sphere.mesh.indices, request);
    ASSERT_TRUE(r.volume) << r.error;
    ASSERT_EQ(voxel::writeLevelSet(*r.volume, (dir / "ls.vdb").string()), "");
    ModelToPlace vdb;
    vdb.file = (dir / "ls.vdb").string();
    const std::string withVdb = gardenWithModel(withMesh, garden, vdb, error);
    ASSERT_EQ(error, "");
    const nlohmann::json v = nlohmann::json::parse(withVdb)["sculptures"][2];
    EXPECT_EQ(v["volume"]["file"], "ls.vdb");
    EXPECT_EQ(v["volume"]["iso"], 0.0);
    EXPECT_EQ(v["volume"]["inside"], "below");
    write("garden.json", withVdb);
    GardenSession s(loadGarden(garden), settings());
    ASSERT_FALSE(s.sculptures()[2].missing()) << s.sculptures()[2].error;
    EXPECT_TRUE(s.sculptures()[2].scanned());
    EXPECT_NEAR(crossingAlongX(*s.sculptures()[2].volume, {0.0, 0.6, 0.0}), 0.5,
                1.5 * s.sculptures()[2].volume->frame.voxelSize);

    // A raw volume's layout is not in its file; a body is HyperFun's.
    write("x.raw", std::string(8, '\0'));
    ModelToPlace raw;
    raw.file = (dir / "x.raw").string();
    EXPECT_EQ(gardenWithModel(withVdb, garden, raw, error), "");
    EXPECT_NE(error.find("a raw volume needs its dimensions"), std::string::npos) << error;
    mesh.name = "other";
    mesh.body = "b";
    EXPECT_EQ(gardenWithModel(withVdb, garden, mesh, error), "");
    EXPECT_NE(error.find("a body (--body) applies to a HyperFun file, not to a mesh"), std::string::npos) << error;
}

#ifdef HG_HYPERGARDEN_EXE
TEST_F(ImportedMesh, TheCommandLineAddsAMesh) {
    write("ball.hf", "my_model(x[3], a[1]) { my_model = 1 - (x[1]^2 + x[2]^2 + x[3]^2); }\n");
    ModelToPlace first;
    first.file = (dir / "ball.hf").string();
    std::string error;
    const std::string garden = write("garden.json", gardenOfOneModel(first, error));
    const std::string obj = write("ball.obj", sphereObj(0.5, {0.0, 0.6, 0.0}));
    test::ShellRun r = test::shell("\"$HG\" garden add '" + garden + "' '" + obj + "' --name scanned --resolution 40");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("added 'scanned'"), std::string::npos) << r.output;
    const nlohmann::json j = nlohmann::json::parse(read(garden));
    EXPECT_EQ(j["sculptures"][1]["mesh"]["file"], "ball.obj");
    EXPECT_EQ(j["sculptures"][1]["resolution"], 40);
    // It exports as a mesh from the command line, closed.
    r = test::shell("\"$HG\" export '" + garden + "' --sculpture scanned -o '" + (dir / "x.stl").string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    const poly::StlReadResult stl = poly::readStl((dir / "x.stl").string());
    ASSERT_EQ(stl.error, "");
    EXPECT_TRUE(poly::validateMesh(poly::weldByPosition(stl.mesh)).ok());
    // A broken mesh: the file and line, and the garden file untouched.
    const std::string before = read(garden);
    const std::string bad = write("bad.ply", "ply\nformat ascii 1.0\nelement vertex x\n");
    r = test::shell("\"$HG\" garden add '" + garden + "' '" + bad + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find(bad + ":3: expected 'element NAME COUNT'"), std::string::npos) << r.output;
    EXPECT_EQ(read(garden), before);
}
#endif

}  // namespace
}  // namespace hg::garden
