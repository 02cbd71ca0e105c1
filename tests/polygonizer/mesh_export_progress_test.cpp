// Export's progress and cancel (io/progress.h): the export mesher's
// fractions rise to 1, and an export cancelled part way, or just before its
// write, writes nothing: no file, no temporary, and a file that was at the
// path before is left as it was.
#include <gtest/gtest.h>

#include <fstream>

#include "mesh_files.h"
#include "polygonizer/export/mesh_export.h"
#include "polygonizer/export/tiled_mesher.h"
#include "tests/progress_recorder.h"
#include "tests/test_models.h"

namespace hg::poly {
namespace {

using ::hg::test::RecordingProgress;

constexpr const char* kSphere = "q(x[3], a[1]) { q = 0.64 - (x[1]^2 + x[2]^2 + x[3]^2); }";

frep::Box3 cube(double h) { return frep::Box3{{-h, -h, -h}, {h, h, h}}; }

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

TEST(ExportProgress, TheExportMeshersFractionsRiseToOne) {
    const frep::Model sphere = ::hg::test::modelFromSource(kSphere);
    RecordingProgress tiles;
    TiledMeshOptions o;
    o.resolution = 96;
    o.tileSize = 32;
    o.progress = &tiles;
    const TiledMeshResult t = meshModelTiled(sphere, cube(1), o);
    ASSERT_EQ(t.error, "");
    EXPECT_FALSE(t.cancelled);
    EXPECT_FALSE(tiles.overlapped());
    EXPECT_TRUE(tiles.risesTo(1.0));
    EXPECT_GT(tiles.fractions().size(), t.plan.tiles());

    // The whole export: the mesh, then validation and the write, then 1.
    test::ScratchFolder dir;
    RecordingProgress exported;
    MeshExportOptions mo;
    mo.resolution = 96;
    mo.tileSize = 32;
    MeshExportReport report;
    ASSERT_EQ(exportMesh(sphere, cube(1), mo, dir.file("ball.stl"), report, &exported), "");
    EXPECT_FALSE(report.cancelled);
    EXPECT_TRUE(exported.risesTo(1.0));
    EXPECT_GT(exported.fractions().size(), t.plan.tiles());
}

TEST(ExportProgress, CancelledPartWayNothingIsWrittenAndTheOldFileStays) {
    const frep::Model sphere = ::hg::test::modelFromSource(kSphere);
    test::ScratchFolder dir;
    const std::string old = dir.file("ball.stl");
    writeText(old, "the print from last week");
    MeshExportOptions mo;
    mo.resolution = 160;
    mo.tileSize = 32;
    for (const char* name : {"ball.stl", "fresh.obj", "ball.vdb"}) {
        SCOPED_TRACE(name);
        RecordingProgress progress(0.3);  // Cancel pressed a third of the way
        MeshExportReport report;
        EXPECT_EQ(exportMesh(sphere, cube(1), mo, dir.file(name), report, &progress), io::kCancelled);
        EXPECT_TRUE(report.cancelled);
        EXPECT_LT(progress.fraction(), 0.6) << "the export went on after the cancel";
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"ball.stl"});
        EXPECT_EQ(test::slurp(old), "the print from last week");
    }
}

TEST(ExportProgress, CancelledWhenTheMeshIsMadeTheFileIsNotWritten) {
    const frep::Model sphere = ::hg::test::modelFromSource(kSphere);
    test::ScratchFolder dir;
    MeshExportOptions mo;
    mo.resolution = 64;
    // The mesh ends at 0.9 of the export: cancelled there, between the
    // mesh and the write.
    RecordingProgress progress(0.9);
    MeshExportReport report;
    EXPECT_EQ(exportMesh(sphere, cube(1), mo, dir.file("ball.glb"), report, &progress), io::kCancelled);
    EXPECT_TRUE(report.cancelled);
    EXPECT_DOUBLE_EQ(progress.fraction(), 0.9);
    EXPECT_GT(report.triangles, 0u) << "the mesh was made and validated";
    EXPECT_TRUE(dir.entries().empty());

    // From a finished grid (a scanned volume's export) likewise.
    const voxel::Volume grid = test::sampleInUnitCube(::hg::test::modelFromSource(kSphere), 48);
    io::NullProgress cancelled;
    cancelled.cancel();
    EXPECT_EQ(exportVolumeMesh(grid, mo, dir.file("grid.stl"), report, &cancelled), io::kCancelled);
    EXPECT_TRUE(report.cancelled);
    EXPECT_TRUE(dir.entries().empty());
    RecordingProgress watched;
    EXPECT_EQ(exportVolumeMesh(grid, mo, dir.file("grid.stl"), report, &watched), "");
    EXPECT_FALSE(report.cancelled);
    EXPECT_TRUE(watched.risesTo(1.0));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"grid.stl"});
}

}  // namespace
}  // namespace hg::poly
