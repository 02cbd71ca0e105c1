// Mesh export: the tiled mesher gives the untiled export mesher's mesh
// triangle for triangle, closed and outward, at a volume matching the
// analytic one; a 1024^3 export runs within its memory limit; STL, OBJ and
// glTF files of one export read back (with tinygltf and a small OBJ reader)
// as the same solid; the VDB is a level set; simplification halves a
// block's triangles and stays closed; bad requests leave no file.
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_export.h"
#include "polygonizer/export/mesh_simplify.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"
#include "polygonizer/export/tiled_mesher.h"
#include "tests/progress_recorder.h"
#include "tests/test_models.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

frep::Box3 cube(double h) {
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = -h;
        b.hi[a] = h;
    }
    return b;
}

frep::Box3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
    frep::Box3 b;
    b.lo[0] = x0, b.lo[1] = y0, b.lo[2] = z0;
    b.hi[0] = x1, b.hi[1] = y1, b.hi[2] = z1;
    return b;
}

// A fresh folder per test, removed afterwards.
struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() /
               ("hg_mesh_export_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

// Triangles as position triples, each turned to start at its smallest
// corner (keeping its orientation), sorted: equal for two meshes when they
// are the same surface, however vertices and triangles are numbered.
using Corner = std::array<float, 3>;
using Triangle = std::array<Corner, 3>;
std::vector<Triangle> triangleSet(const Mesh& m) {
    std::vector<Triangle> out;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        Triangle tri;
        for (std::size_t k = 0; k < 3; ++k)
            for (std::size_t a = 0; a < 3; ++a) tri[k][a] = m.positions[3 * m.indices[3 * t + k] + a];
        const auto first = static_cast<std::size_t>(std::min_element(tri.begin(), tri.end()) - tri.begin());
        std::rotate(tri.begin(), tri.begin() + static_cast<std::ptrdiff_t>(first), tri.end());
        out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::map<Corner, Corner> normalsByPosition(const Mesh& m) {
    std::map<Corner, Corner> out;
    for (std::size_t v = 0; v < m.vertexCount(); ++v)
        out[{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]}] = {m.normals[3 * v], m.normals[3 * v + 1],
                                                                                     m.normals[3 * v + 2]};
    return out;
}

Mesh untiled(const frep::Model& model, const frep::Box3& b, int res) {
    voxel::VolumeRequest req;
    req.box = b;
    req.resolution = res;
    voxel::VoxelizeResult v = voxel::voxelize(model, req);
    EXPECT_TRUE(v.volume) << v.error;
    return meshVolume(*v.volume);
}

void expectSameMesh(const frep::Model& model, const frep::Box3& b, int res, int tile) {
    TiledMeshOptions o;
    o.resolution = res;
    o.tileSize = tile;
    TiledMeshResult tiled = meshModelTiled(model, b, o);
    ASSERT_EQ(tiled.error, "");
    EXPECT_GT(tiled.stats.tilesWithSurface, 1u) << "tiles are used";
    EXPECT_GT(tiled.stats.sharedVertices, 0u) << "vertices are welded across tiles";
    const Mesh whole = untiled(model, b, res);
    ASSERT_FALSE(whole.empty());
    const MeshReport r = validateMesh(tiled.mesh);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(tiled.mesh.triangleCount(), whole.triangleCount());
    EXPECT_EQ(tiled.mesh.vertexCount(), validateMesh(whole).vertices) << "welded: one vertex per crossing";
    EXPECT_TRUE(triangleSet(tiled.mesh) == triangleSet(whole)) << "the same triangles at the same positions";
    EXPECT_TRUE(normalsByPosition(tiled.mesh) == normalsByPosition(whole)) << "the same normals";
    // The same triangles summed in another order: equal to rounding.
    EXPECT_NEAR(r.volume, validateMesh(whole).volume, 1e-12 * r.volume);
}

TEST(TiledMesher, SphereIsClosedOutwardAndHasTheAnalyticVolume) {
    const frep::Model sphere = test::modelFromSource("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }");
    TiledMeshOptions o;
    o.resolution = 128;
    o.tileSize = 32;
    TiledMeshResult tiled = meshModelTiled(sphere, cube(1), o);
    ASSERT_EQ(tiled.error, "");
    // Cells -16 .. 135 (the index box -4 .. 132 and a block below), tiles
    // from -32: 6 of 32.
    EXPECT_EQ(tiled.plan.tileCounts[0], 6);
    EXPECT_GT(tiled.stats.tilesWithSurface, 8u);
    const MeshReport r = validateMesh(tiled.mesh);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.components, 1u);
    EXPECT_NEAR(r.volume, 4.0 / 3.0 * kPi * 0.512, 0.01 * 4.0 / 3.0 * kPi * 0.512);
}

TEST(TiledMesher, TorusWithABlockEqualsTheUntiledMesh) {
    expectSameMesh(test::modelFromSource(test::kTorusBlock), cube(1), 96, 32);
}

TEST(TiledMesher, ASolidCutByItsBoxIsCappedAcrossTilesAsUntiled) {
    // The totem reaches z = +-2.05: the box cuts it, so the caps on the
    // index box's faces run through several tiles.
    const frep::Model totem = test::modelFromFile(std::string(HG_TEST_DATA_DIR) + "/bounded/totem.hf");
    expectSameMesh(totem, box(-1, -1, -1.2, 1, 1, 1.2), 80, 32);
    expectSameMesh(totem, box(-1, -1, -1.2, 1, 1, 1.2), 80, 16);
}

TEST(TiledMesher, TheGuardRefusesWhatDoesNotFitAndSaysWhatWould) {
    const frep::Model sphere = test::modelFromSource("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }");
    TiledMeshOptions o;
    o.resolution = 4096;
    o.memoryLimit = std::uint64_t{64} << 20;
    TiledMeshPlan plan;
    const std::string why = planTiledMesh(sphere, cube(1), o, plan);
    EXPECT_NE(why.find("resolution 4096"), std::string::npos) << why;
    EXPECT_NE(why.find("or less would fit"), std::string::npos) << why;
    EXPECT_GT(plan.estimatedBytes, plan.limit);
    // The resolution it names does fit.
    const std::size_t at = why.find("; resolution ") + 13;
    o.resolution = std::stoi(why.substr(at));
    EXPECT_EQ(planTiledMesh(sphere, cube(1), o, plan), "");
    EXPECT_LE(plan.estimatedBytes, plan.limit);
    o.resolution = 0;
    EXPECT_NE(planTiledMesh(sphere, cube(1), o, plan), "");
    o.resolution = 64;
    o.tileSize = 12;
    EXPECT_NE(planTiledMesh(sphere, cube(1), o, plan).find("multiple of 8"), std::string::npos);
}

// The process's peak resident memory since the last reset, in bytes.
void resetPeakMemory() {
    std::ofstream("/proc/self/clear_refs") << "5";
}
std::uint64_t peakMemory() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        std::uint64_t kb = 0;
        if (key == "VmHWM:" && status >> kb) return kb * 1024;
    }
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<std::uint64_t>(u.ru_maxrss) * 1024;
}

Mesh readWelded(const std::string& stl) {
    StlReadResult r = readStl(stl);
    EXPECT_EQ(r.error, "");
    return weldByPosition(r.mesh);
}

TEST(MeshExport, A1024CubedStlStaysWithinItsMemoryLimitAndIsClean) {
    // A rod along x, 1024 voxels long and 51 across: small to write, but
    // every tile along its length is sampled at full resolution.
    const frep::Model rod = test::modelFromSource(
        "rod(x[3], a[1]) { rod = (0.0025 - x[2]^2 - x[3]^2) & (0.9025 - x[1]^2); }");
    TempDir dir;
    MeshExportOptions o;
    o.resolution = 1024;
    o.memoryLimitMiB = 256;
    o.mmPerUnit = 10;
    MeshExportReport report;
    ::hg::test::RecordingProgress progress;
    resetPeakMemory();
    const std::string why =
        exportMesh(rod, box(-1, -0.1, -0.1, 1, 0.1, 0.1), o, dir.file("rod.stl"), report, &progress);
    const std::uint64_t peak = peakMemory();
    ASSERT_EQ(why, "");
    EXPECT_TRUE(progress.risesTo(1.0));
    EXPECT_GT(progress.fractions().size(), report.tiles) << "each tile, and inside its sampling";
    EXPECT_GT(report.tiles, 4u);
    EXPECT_LE(report.estimatedBytes, report.limitBytes);
    EXPECT_LE(report.peakTileBytes, report.estimatedBytes);
    EXPECT_LT(peak, std::uint64_t{256} << 20) << "peak resident memory of the whole process";
    // The rod: pi r^2 l (l = 1.9), its size, and a clean file.
    EXPECT_NEAR(report.volume, kPi * 0.0025 * 1.9, 0.005 * kPi * 0.0025 * 1.9);
    EXPECT_NEAR(report.size[0], 1.9, 0.005);
    EXPECT_NEAR(report.size[1], 0.1, 0.002);
    const Mesh back = readWelded(dir.file("rod.stl"));
    const MeshReport r = validateMesh(back);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.triangles, report.triangles);
    EXPECT_NEAR(r.volume, report.volume * 1000.0, 1e-4 * r.volume) << "millimetres";
}

// A small OBJ reader: v, vn and f lines of the form a//a.
struct Obj {
    Mesh mesh;
    std::size_t normals = 0;
};
Obj readObj(const std::string& path) {
    Obj o;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            float x, y, z;
            s >> x >> y >> z;
            o.mesh.positions.insert(o.mesh.positions.end(), {x, y, z});
        } else if (tag == "vn") {
            float x, y, z;
            s >> x >> y >> z;
            EXPECT_NEAR(x * x + y * y + z * z, 1.0f, 1e-4f);
            o.mesh.normals.insert(o.mesh.normals.end(), {x, y, z});
            ++o.normals;
        } else if (tag == "f") {
            for (int k = 0; k < 3; ++k) {
                std::string corner;
                s >> corner;
                const std::size_t slash = corner.find("//");
                EXPECT_NE(slash, std::string::npos) << corner;
                EXPECT_EQ(corner.substr(0, slash), corner.substr(slash + 2)) << "a normal per vertex";
                o.mesh.indices.push_back(static_cast<std::uint32_t>(std::stoul(corner) - 1));
            }
        }
    }
    return o;
}

Mesh readGlb(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
    Mesh m;
    if (model.meshes.size() != 1) {
        ADD_FAILURE() << "one mesh";
        return m;
    }
    const tinygltf::Primitive& p = model.meshes[0].primitives.at(0);
    EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
    auto floats = [&](int accessor) {
        const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(accessor));
        const tinygltf::BufferView& v = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
        EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
        EXPECT_EQ(a.type, TINYGLTF_TYPE_VEC3);
        const auto* d = reinterpret_cast<const float*>(model.buffers.at(static_cast<std::size_t>(v.buffer)).data.data() +
                                                       v.byteOffset + a.byteOffset);
        return std::vector<float>(d, d + 3 * a.count);
    };
    m.positions = floats(p.attributes.at("POSITION"));
    m.normals = floats(p.attributes.at("NORMAL"));
    const tinygltf::Accessor& ia = model.accessors.at(static_cast<std::size_t>(p.indices));
    EXPECT_EQ(ia.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    const tinygltf::BufferView& iv = model.bufferViews.at(static_cast<std::size_t>(ia.bufferView));
    const auto* idx = reinterpret_cast<const std::uint32_t*>(
        model.buffers.at(static_cast<std::size_t>(iv.buffer)).data.data() + iv.byteOffset + ia.byteOffset);
    m.indices.assign(idx, idx + ia.count);
    // The accessor's bounds are the positions' (glTF requires them).
    const tinygltf::Accessor& pa = model.accessors.at(static_cast<std::size_t>(p.attributes.at("POSITION")));
    EXPECT_EQ(pa.minValues.size(), 3u);
    return m;
}

// Same solid in two files: triangle count, bounding box (to float
// precision, after undoing each file's unit) and volume.
void expectSameSolid(const MeshReport& a, double unitA, const MeshReport& b, double unitB) {
    EXPECT_TRUE(a.ok()) << describe(a);
    EXPECT_TRUE(b.ok()) << describe(b);
    EXPECT_EQ(a.triangles, b.triangles);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(a.boxMin[k] / unitA, b.boxMin[k] / unitB, 2e-7 * 2);
        EXPECT_NEAR(a.boxMax[k] / unitA, b.boxMax[k] / unitB, 2e-7 * 2);
    }
    EXPECT_NEAR(a.volume / (unitA * unitA * unitA), b.volume / (unitB * unitB * unitB), 1e-5 * a.volume / (unitA * unitA * unitA));
}

TEST(MeshExport, StlObjAndGlbReadBackAsTheSameSolid) {
    const frep::Model torus = test::modelFromSource(test::kTorusBlock);
    TempDir dir;
    MeshExportOptions o;
    o.resolution = 64;
    o.mmPerUnit = 25.0;
    o.metresPerUnit = 0.5;
    MeshExportReport stl, obj, glb;
    ASSERT_EQ(exportMesh(torus, cube(1), o, dir.file("t.stl"), stl), "");
    ASSERT_EQ(exportMesh(torus, cube(1), o, dir.file("t.obj"), obj), "");
    ASSERT_EQ(exportMesh(torus, cube(1), o, dir.file("t.GLB"), glb), "");
    EXPECT_EQ(glb.format, MeshFormat::Glb);
    EXPECT_EQ(stl.triangles, obj.triangles);
    EXPECT_EQ(stl.triangles, glb.triangles);

    const MeshReport fromStl = validateMesh(readWelded(dir.file("t.stl")));
    const Obj o2 = readObj(dir.file("t.obj"));
    EXPECT_EQ(o2.normals, o2.mesh.vertexCount());
    const MeshReport fromObj = validateMesh(o2.mesh);
    const Mesh g = readGlb(dir.file("t.GLB"));
    EXPECT_EQ(g.normals.size(), g.positions.size());
    const MeshReport fromGlb = validateMesh(g);
    EXPECT_EQ(fromStl.triangles, stl.triangles);
    expectSameSolid(fromStl, 25.0, fromObj, 0.5);
    expectSameSolid(fromStl, 25.0, fromGlb, 0.5);
    EXPECT_NEAR(fromGlb.volume, stl.volume * 0.125, 1e-5 * fromGlb.volume) << "metres";
    // The OBJ and glTF carry the same vertices and normals.
    EXPECT_EQ(o2.mesh.indices, g.indices);
    ASSERT_EQ(o2.mesh.positions.size(), g.positions.size());
    for (std::size_t i = 0; i < g.positions.size(); ++i) {
        ASSERT_EQ(o2.mesh.positions[i], g.positions[i]) << i;
        ASSERT_EQ(o2.mesh.normals[i], g.normals[i]) << i;
    }
}

TEST(MeshExport, VdbIsALevelSetNegativeInsideWithOurMetadata) {
    const frep::Model sphere = test::modelFromSource("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }");
    TempDir dir;
    MeshExportOptions o;
    o.resolution = 48;
    MeshExportReport report;
    ASSERT_EQ(exportMesh(sphere, cube(1), o, dir.file("s.vdb"), report), "");
    EXPECT_NEAR(report.volume, 4.0 / 3.0 * kPi * 0.512, 0.03 * 4.0 / 3.0 * kPi * 0.512);
    openvdb::io::File file(dir.file("s.vdb"));
    file.open();
    openvdb::GridPtrVecPtr grids = file.getGrids();
    file.close();
    ASSERT_EQ(grids->size(), 1u);
    auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>((*grids)[0]);
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_TRUE(grid->metaValue<std::string>("hypergarden.sign").find("negative inside") != std::string::npos);
    // A signed distance: -0.8 + |p| near the surface, in model units.
    const openvdb::Coord centreOffSurface = grid->transform().worldToIndexNodeCentered(openvdb::Vec3d(0.75, 0, 0));
    EXPECT_NEAR(grid->tree().getValue(centreOffSurface), -0.05, 0.02);
    const openvdb::Coord outside = grid->transform().worldToIndexNodeCentered(openvdb::Vec3d(0.85, 0, 0));
    EXPECT_NEAR(grid->tree().getValue(outside), 0.05, 0.02);

    // In metres: a sculpture placed at 2 m per model unit is twice as large
    // in the file, its distances too.
    o.metresPerUnit = 2.0;
    ASSERT_EQ(exportMesh(sphere, cube(1), o, dir.file("m.vdb"), report), "");
    openvdb::io::File metres(dir.file("m.vdb"));
    metres.open();
    auto big = openvdb::gridPtrCast<openvdb::FloatGrid>((*metres.getGrids())[0]);
    metres.close();
    ASSERT_TRUE(big);
    EXPECT_NE(big->metaValue<std::string>("hypergarden.sign").find("metres"), std::string::npos);
    EXPECT_NEAR(big->tree().getValue(big->transform().worldToIndexNodeCentered(openvdb::Vec3d(1.5, 0, 0))), -0.1, 0.04);
    EXPECT_NEAR(big->tree().getValue(big->transform().worldToIndexNodeCentered(openvdb::Vec3d(1.7, 0, 0))), 0.1, 0.04);
}

TEST(MeshExport, SimplifyHalvesABlocksTrianglesAndStaysClosed) {
    const frep::Model block = test::modelFromSource(
        "b(x[3], a[1]) { array c[3]; c = [-0.5, -0.3, -0.2]; b = hfBlock(x, c, 1.0, 0.6, 0.4); }");
    TempDir dir;
    MeshExportOptions o;
    o.resolution = 64;
    MeshExportReport plain, simple;
    ASSERT_EQ(exportMesh(block, cube(1), o, dir.file("plain.stl"), plain), "");
    o.simplifyError = 0.002;  // a fifth of a voxel
    ASSERT_EQ(exportMesh(block, cube(1), o, dir.file("simple.stl"), simple), "");
    EXPECT_TRUE(simple.simplified) << simple.simplifyNote;
    EXPECT_EQ(simple.trianglesBeforeSimplify, plain.triangles);
    EXPECT_LT(simple.triangles * 2, plain.triangles) << simple.triangles << " of " << plain.triangles;
    EXPECT_LE(simple.simplifyAchievedError, 0.002);
    const MeshReport r = validateMesh(readWelded(dir.file("simple.stl")));
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.triangles, simple.triangles);
    EXPECT_NEAR(r.volume, plain.volume, 0.01 * plain.volume);
}

TEST(MeshExport, SimplificationRemovesFoldsAndStopsWhereACollapseWouldBreakTheSurface) {
    // A disc 1.3 voxels thick: meshoptimizer alone, at 0.01 units, leaves
    // non-manifold edges, and at 0.3 (10 voxels) collapses it to nothing.
    const frep::Model plate = test::modelFromSource("q(x[3], a[1]) { q = (0.0004 - x[3]^2) & (0.5 - x[1]^2 - x[2]^2); }");
    TempDir dir;
    MeshExportOptions o;
    o.resolution = 64;
    MeshExportReport plain, simple;
    ASSERT_EQ(exportMesh(plate, cube(1), o, dir.file("plain.obj"), plain), "");
    Mesh raw = readObj(dir.file("plain.obj")).mesh;
    const float extent = meshopt_simplifyScale(raw.positions.data(), raw.vertexCount(), 12);
    for (const double error : {0.01, 0.3}) {
        std::vector<std::uint32_t> out(raw.indices.size());
        out.resize(meshopt_simplify(out.data(), raw.indices.data(), raw.indices.size(), raw.positions.data(),
                                    raw.vertexCount(), 12, 0, static_cast<float>(error) / extent, 0, nullptr));
        Mesh m = raw;
        m.indices = out;
        EXPECT_FALSE(validateMesh(m).ok()) << "meshoptimizer alone breaks it at " << error;
    }
    // At 0.01 the breaks are folds (two triangles on the same vertices in
    // opposite orders), which simplifyMesh removes: one pass, all the way.
    SimplifyStats s;
    const Mesh unfolded = simplifyMesh(raw, 0.01, &s);
    EXPECT_TRUE(validateMesh(unfolded).ok()) << describe(validateMesh(unfolded));
    EXPECT_FALSE(s.stoppedByTopology);
    EXPECT_GE(s.passes, 1);
    EXPECT_LT(s.trianglesAfter * 10, s.trianglesBefore) << s.trianglesAfter;
    EXPECT_LE(s.error, 0.01);
    // At 0.3 collapses that empty the disc must be stopped.
    o.simplifyError = 0.3;
    ASSERT_EQ(exportMesh(plate, cube(1), o, dir.file("simple.obj"), simple), "");
    EXPECT_TRUE(simple.simplified);
    EXPECT_LT(simple.triangles * 4, plain.triangles) << simple.triangles << " of " << plain.triangles;
    EXPECT_NE(simple.simplifyNote.find("stopped at"), std::string::npos) << simple.simplifyNote;
    EXPECT_NE(describe(simple, o).find("note: "), std::string::npos);
    const MeshReport r = validateMesh(readObj(dir.file("simple.obj")).mesh);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.triangles, simple.triangles);
}

TEST(MeshExport, SimplifiedMeshKeepsVerticesAndNormalsOfTheOriginal) {
    const frep::Model sphere = test::modelFromSource("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }");
    TiledMeshOptions o;
    o.resolution = 48;
    TiledMeshResult t = meshModelTiled(sphere, cube(1), o);
    ASSERT_EQ(t.error, "");
    SimplifyStats s;
    const Mesh simple = simplifyMesh(t.mesh, 0.01, &s);
    EXPECT_LT(s.trianglesAfter, s.trianglesBefore);
    EXPECT_EQ(s.trianglesAfter, simple.triangleCount());
    const auto original = normalsByPosition(t.mesh);
    for (const auto& [p, n] : normalsByPosition(simple)) {
        auto it = original.find(p);
        ASSERT_NE(it, original.end());
        EXPECT_EQ(it->second, n);
    }
    EXPECT_TRUE(validateMesh(simple).ok());
}

TEST(MeshExport, BadRequestsGiveClearErrorsAndLeaveNoFile) {
    const frep::Model sphere = test::modelFromSource("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }");
    TempDir dir;
    MeshExportOptions o;
    MeshExportReport report;
    auto expectNoFile = [&](const std::string& path) {
        EXPECT_FALSE(fs::exists(path)) << path;
        for (const auto& e : fs::directory_iterator(dir.path)) ADD_FAILURE() << "left behind: " << e.path();
    };

    o.resolution = 0;
    std::string why = exportMesh(sphere, cube(1), o, dir.file("zero.stl"), report);
    EXPECT_NE(why.find("resolution"), std::string::npos) << why;
    expectNoFile(dir.file("zero.stl"));

    o.resolution = 8192;
    o.memoryLimitMiB = 64;
    why = exportMesh(sphere, cube(1), o, dir.file("huge.stl"), report);
    EXPECT_NE(why.find("or less would fit"), std::string::npos) << why;
    expectNoFile(dir.file("huge.stl"));
    o.memoryLimitMiB = 0;

    o.resolution = 32;
    why = exportMesh(sphere, cube(1), o, dir.file("shape.xyz"), report);
    EXPECT_NE(why.find("unknown extension .xyz"), std::string::npos) << why;
    expectNoFile(dir.file("shape.xyz"));
    why = exportMesh(sphere, cube(1), o, dir.file("noext"), report);
    EXPECT_NE(why.find("unknown extension"), std::string::npos) << why;

    why = exportMesh(sphere, cube(1), o, dir.file("missing/dir/s.stl"), report);
    EXPECT_NE(why.find("cannot write"), std::string::npos) << why;
    EXPECT_NE(why.find("missing/dir/s.stl"), std::string::npos) << why;

    o.mmPerUnit = -1;
    why = exportMesh(sphere, cube(1), o, dir.file("neg.stl"), report);
    EXPECT_NE(why.find("millimetres"), std::string::npos) << why;
    expectNoFile(dir.file("neg.stl"));
    o.mmPerUnit = 1;

    o.simplifyError = 0.01;
    why = exportMesh(sphere, cube(1), o, dir.file("s.vdb"), report);
    EXPECT_NE(why.find("simplification"), std::string::npos) << why;
    expectNoFile(dir.file("s.vdb"));
    o.simplifyError = 0;

    // Nothing inside the box.
    why = exportMesh(sphere, box(2, 2, 2, 3, 3, 3), o, dir.file("empty.obj"), report);
    EXPECT_NE(why.find("no surface"), std::string::npos) << why;
    expectNoFile(dir.file("empty.obj"));
}

}  // namespace
}  // namespace hg::poly
