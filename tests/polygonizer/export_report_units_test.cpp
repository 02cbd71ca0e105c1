// Every export report states sizes in the units of the file it writes
// (issue 20: a refused mesh was reported as 1.49 x 1.99 x 0.53 mm, one
// millimetre per model unit, when its STL would have been 1,492 mm across):
// STL in millimetres (mmPerUnit), OBJ, glTF and VDB in metres
// (metresPerUnit), whether the export is written or refused.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "polygonizer/export/mesh_export.h"
#include "polygonizer/export/mesh_validation.h"
#include "tests/test_models.h"

namespace hg::poly {
namespace {

// The three numbers after `key` in `text` ("size: A x B x C"), or none.
std::vector<double> sizeAfter(const std::string& text, const std::string& key) {
    const std::size_t at = text.find(key);
    if (at == std::string::npos) return {};
    double s[3];
    if (std::sscanf(text.c_str() + at + key.size(), "%lf x %lf x %lf", &s[0], &s[1], &s[2]) != 3) return {};
    return {s[0], s[1], s[2]};
}

// An open box 1.492 x 1.99 x 0.53 model units: its six faces but one triangle.
Mesh openBox() {
    const float d[3] = {1.492f, 1.99f, 0.53f};
    Mesh m;
    for (int c = 0; c < 8; ++c)
        for (int a = 0; a < 3; ++a) m.positions.push_back((c >> a) & 1 ? d[a] : 0.0f);
    m.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7};
    return m;
}

TEST(ExportReportUnits, ARefusedMeshIsDescribedInTheUnitsOfTheFileItWouldHaveBeen) {
    const MeshReport r = validateMesh(openBox());
    ASSERT_FALSE(r.closed());
    MeshExportOptions o;
    o.mmPerUnit = 1000.0;  // a sculpture placed at one metre per model unit
    o.metresPerUnit = 1.0;
    const std::string stl = describeUnfitMesh(r, MeshFormat::Stl, o);
    EXPECT_NE(stl.find("not closed"), std::string::npos) << stl;
    const std::vector<double> mm = sizeAfter(stl, "size: ");
    ASSERT_EQ(mm.size(), 3u) << stl;
    EXPECT_NEAR(mm[0], 1492.0, 0.01) << stl;
    EXPECT_NEAR(mm[1], 1990.0, 0.01) << stl;
    EXPECT_NEAR(mm[2], 530.0, 0.01) << stl;
    EXPECT_NE(stl.find(" mm, from"), std::string::npos) << stl;

    o.metresPerUnit = 2.0;
    for (MeshFormat f : {MeshFormat::Obj, MeshFormat::Glb}) {
        const std::string text = describeUnfitMesh(r, f, o);
        const std::vector<double> m = sizeAfter(text, "size: ");
        ASSERT_EQ(m.size(), 3u) << text;
        EXPECT_NEAR(m[0], 2.984, 1e-5) << text;
        EXPECT_NEAR(m[2], 1.06, 1e-5) << text;
        EXPECT_NE(text.find(" m, from"), std::string::npos) << text;
        EXPECT_NE(text.find(" m^3"), std::string::npos) << text;
        EXPECT_EQ(text.find("mm"), std::string::npos) << text;
    }
}

TEST(ExportReportUnits, AWrittenExportIsDescribedInTheUnitsOfItsFile) {
    // A block 1.492 x 1.99 x 0.53 model units at 0.5 m a unit: 746 mm long
    // in the STL (mmPerUnit 500), 0.746 m in the OBJ, glTF and VDB.
    const frep::Model block = ::hg::test::modelFromSource(
        "q(x[3], a[1]) { array c[3]; c = [0, 0, 0]; q = hfBlock(x, c, 1.492, 1.99, 0.53); }");
    frep::Box3 box;
    const double hi[3] = {1.492, 1.99, 0.53};
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = -0.1;
        box.hi[a] = hi[a] + 0.1;
    }
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "hg_export_report_units";
    std::filesystem::create_directories(dir);
    MeshExportOptions o;
    o.resolution = 48;
    o.mmPerUnit = 500.0;
    o.metresPerUnit = 0.5;
    for (const char* name : {"block.stl", "block.obj", "block.glb", "block.vdb"}) {
        MeshExportReport report;
        ASSERT_EQ(exportMesh(block, box, o, (dir / name).string(), report), "") << name;
        const std::string text = describe(report, o);
        const bool stl = std::string(name) == "block.stl";
        const std::vector<double> s = sizeAfter(text, "size ");
        ASSERT_EQ(s.size(), 3u) << text;
        const double unit = stl ? 500.0 : 0.5;
        EXPECT_NEAR(s[0], 1.492 * unit, 0.02 * 1.492 * unit) << name << "\n" << text;
        EXPECT_NEAR(s[1], 1.99 * unit, 0.02 * 1.99 * unit) << name << "\n" << text;
        EXPECT_NE(text.find(stl ? " mm\n" : " m\n"), std::string::npos) << name << "\n" << text;
        EXPECT_EQ(text.find("model units"), std::string::npos) << name << "\n" << text;
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hg::poly
