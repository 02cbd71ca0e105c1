// The export mesher: closed, manifold, outward-facing meshes whose volume
// matches the analytic volume of a sphere, a box and a torus at 128^3, on
// our own sculptures too; and the generated cell table's invariants.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "frep/language/parser.h"
#include "polygonizer/cell_table.h"
#include "polygonizer/export/export_mesher.h"
#include "polygonizer/export/mesh_validation.h"
#include "sample_program.h"
#include "voxel/sampler.h"

namespace hg::poly {
namespace {

constexpr double kPi = 3.14159265358979323846;

using test::sampleProgram;

TEST(CellTable, EveryCaseUsesExactlyItsCrossingEdges) {
    const auto& table = cellTable();
    EXPECT_EQ(table[0].triangleCount, 0);
    EXPECT_EQ(table[255].triangleCount, 0);
    for (int m = 1; m < 255; ++m) {
        const CellCase& c = table[static_cast<size_t>(m)];
        ASSERT_GT(c.triangleCount, 0) << m;
        // Within a cell, every edge between two crossings is used by an even
        // number of triangles, or is on the cube's surface (used once):
        // crossings on cube faces chain into closed loops.
        int crossings = 0;
        for (int e = 0; e < 12; ++e) {
            const auto& ec = kEdgeCorners[static_cast<size_t>(e)];
            crossings += ((m >> ec[0]) & 1) != ((m >> ec[1]) & 1);
        }
        std::set<int> used;
        for (int t = 0; t < 3 * c.triangleCount; ++t) used.insert(c.edges[static_cast<size_t>(t)]);
        EXPECT_EQ(static_cast<int>(used.size()), crossings) << "case " << m << " uses exactly its crossing edges";
    }
}

void expectWatertight(const Mesh& mesh, double expectedVolume, double tolerance) {
    MeshReport r = validateMesh(mesh);
    EXPECT_EQ(r.boundaryEdges, 0u);
    EXPECT_EQ(r.nonManifoldEdges, 0u);
    EXPECT_EQ(r.inconsistentEdges, 0u);
    EXPECT_TRUE(r.closed());
    EXPECT_TRUE(r.manifold());
    EXPECT_TRUE(r.outwardFacing());
    EXPECT_NEAR(r.volume, expectedVolume, tolerance * expectedVolume);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST(ExportMesher, SphereBoxAndTorusAreWatertightWithinOnePercentOfTheirVolume) {
    Mesh sphere = meshVolume(sampleProgram("q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }", 128));
    expectWatertight(sphere, 4.0 / 3.0 * kPi * 0.512, 0.01);
    Mesh box = meshVolume(sampleProgram("q(x[3], a[1]) { array c[3]; c = [-0.5, -0.3, -0.2]; q = hfBlock(x, c, 1.0, 0.6, 0.4); }", 128));
    expectWatertight(box, 1.0 * 0.6 * 0.4, 0.01);
    Mesh torus = meshVolume(sampleProgram("q(x[3], a[1]) { array c[3]; c = [0, 0, 0]; q = hfTorusY(x, c, 0.6, 0.2); }", 128));
    expectWatertight(torus, 2 * kPi * kPi * 0.6 * 0.04, 0.01);
    MeshReport t = validateMesh(torus);
    // Euler characteristic V - E + F = 0 for a torus, 2 for a sphere.
    EXPECT_EQ(static_cast<long>(t.vertices) - static_cast<long>(3 * t.triangles / 2) + static_cast<long>(t.triangles), 0);
    MeshReport s = validateMesh(sphere);
    EXPECT_EQ(static_cast<long>(s.vertices) - static_cast<long>(3 * s.triangles / 2) + static_cast<long>(s.triangles), 2);
}

TEST(ExportMesher, OurSculpturesAreWatertight) {
    for (const char* name : {"key_orant.hf", "key_knot.hf", "path_column.hf"}) {
        SCOPED_TRACE(name);
        frep::ParseResult r = frep::parseFile((std::filesystem::path(HG_SOURCE_DIR) / "content" / "hyperfun" / name).string());
        ASSERT_TRUE(r.ok());
        auto program = std::make_shared<const frep::Program>(std::move(*r.program));
        frep::Model model(program, program->defaultBody());
        voxel::VolumeRequest req;
        req.resolution = 96;
        voxel::VoxelizeResult v = voxel::voxelize(model, req);
        ASSERT_TRUE(v.volume) << v.error;
        MeshReport rep = validateMesh(meshVolume(*v.volume));
        EXPECT_TRUE(rep.ok()) << describe(rep);
        EXPECT_GT(rep.volume, 0.0);
    }
}

TEST(ExportMesher, ASolidCutByTheBoxIsCappedThere) {
    // A half-space sampled in a given box: the mesh closes on the box's faces.
    frep::ParseResult r = frep::parseProgram("q(x[3], a[1]) { q = -x[2]; }", "half.hf");
    auto program = std::make_shared<const frep::Program>(std::move(*r.program));
    frep::Model model(program, 0);
    voxel::VolumeRequest req;
    req.resolution = 32;
    frep::Box3 box;
    for (int a = 0; a < 3; ++a) { box.lo[a] = -1; box.hi[a] = 1; }
    req.box = box;
    voxel::VoxelizeResult v = voxel::voxelize(model, req);
    ASSERT_TRUE(v.volume) << v.error;
    MeshReport rep = validateMesh(meshVolume(*v.volume));
    EXPECT_TRUE(rep.closed());
    EXPECT_TRUE(rep.manifold());
    EXPECT_GT(rep.volume, 0.0);
}

}  // namespace
}  // namespace hg::poly
