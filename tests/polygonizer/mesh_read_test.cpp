// Meshes brought in (polygonizer/export/mesh_read.h): STL, OBJ and PLY files
// written here are read back as the same triangles, polygons as fans, and
// broken files are refused with the file and the line (or byte) at fault.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "polygonizer/export/mesh_read.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"

namespace hg::poly {
namespace {

class MeshRead : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("hg_mesh_read_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string p = (dir / name).string();
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
    std::filesystem::path dir;
};

// A unit cube as 8 corners and 6 quads, counter-clockwise from outside.
const char* kCubeCorners = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const int kCubeQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};

void expectClosedCube(const MeshReadResult& r) {
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.mesh.vertexCount(), 8u);
    EXPECT_EQ(r.mesh.triangleCount(), 12u);
    const MeshReport m = validateMesh(r.mesh);
    EXPECT_TRUE(m.ok()) << describe(m);
    EXPECT_NEAR(m.volume, 1.0, 1e-6);
}

TEST_F(MeshRead, ObjQuadsBecomeFansAndNegativeIndicesCountBack) {
    std::string obj = "# a cube\no cube\n";
    std::string corners = kCubeCorners;
    std::size_t at = 0;
    while (at < corners.size()) {
        const std::size_t end = corners.find('\n', at);
        obj += "v " + corners.substr(at, end - at) + "\n";
        at = end + 1;
    }
    obj += "vn 0 0 1\nvt 0 0\ns off\n";
    for (int f = 0; f < 6; ++f) {
        obj += "f";
        // Half the faces with negative indices (-8 is the first corner), some with a/t/n forms.
        for (int k = 0; k < 4; ++k)
            obj += f % 2 ? " " + std::to_string(kCubeQuads[f][k] - 8) : " " + std::to_string(kCubeQuads[f][k] + 1) + "/1/1";
        obj += "\r\n";
    }
    expectClosedCube(readMeshFile(write("cube.OBJ", obj)));
}

TEST_F(MeshRead, PlyAsciiAndBinaryLittleEndian) {
    std::string head = "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 8\nproperty float x\nproperty float y\n"
                       "property float z\nproperty uchar red\nelement face 6\nproperty list uchar int vertex_indices\n"
                       "end_header\n";
    std::string ascii = head;
    std::string corners = kCubeCorners;
    std::size_t at = 0;
    while (at < corners.size()) {
        const std::size_t end = corners.find('\n', at);
        ascii += corners.substr(at, end - at) + " 200\n";
        at = end + 1;
    }
    for (const auto& q : kCubeQuads)
        ascii += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
                 std::to_string(q[3]) + "\n";
    expectClosedCube(readMeshFile(write("cube.ply", ascii)));

    // The same as binary_little_endian, with an extra element between.
    std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                      "property float z\nelement note 1\nproperty list uchar short values\nelement face 6\n"
                      "property list uchar uint vertex_indices\nend_header\n";
    const auto put = [&bin](const void* p, std::size_t n) { bin.append(static_cast<const char*>(p), n); };
    const float xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (const auto& v : xyz) put(v, 12);
    const unsigned char two = 2;
    const std::int16_t note[2] = {-3, 7};
    put(&two, 1);
    put(note, 4);
    const unsigned char four = 4;
    for (const auto& q : kCubeQuads) {
        put(&four, 1);
        for (int k : q) {
            const std::uint32_t u = static_cast<std::uint32_t>(k);
            put(&u, 4);
        }
    }
    expectClosedCube(readMeshFile(write("cube-bin.ply", bin)));
    // Cut short: refused with the byte where it ends.
    const MeshReadResult cut = readMeshFile(write("cut.ply", bin.substr(0, bin.size() - 3)));
    EXPECT_NE(cut.error.find("cut.ply: byte "), std::string::npos) << cut.error;
    EXPECT_NE(cut.error.find("expected face 5's vertex_indices, but the file ends"), std::string::npos) << cut.error;
}

TEST_F(MeshRead, StlBinaryAndAsciiAreWelded) {
    Mesh cube;
    const float xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (const auto& v : xyz) cube.positions.insert(cube.positions.end(), v, v + 3);
    for (const auto& q : kCubeQuads)
        for (int t : {0, 2}) {
            cube.indices.push_back(static_cast<std::uint32_t>(q[0]));
            cube.indices.push_back(static_cast<std::uint32_t>(q[t == 0 ? 1 : 2]));
            cube.indices.push_back(static_cast<std::uint32_t>(q[t == 0 ? 2 : 3]));
        }
    for (bool ascii : {false, true}) {
        const std::string p = (dir / (ascii ? "a.stl" : "b.stl")).string();
        ASSERT_EQ(writeStl(cube, p, ascii), "");
        expectClosedCube(readMeshFile(p));
    }
}

TEST_F(MeshRead, BrokenFilesSayWhereAndEmptyMeshesAreRefused) {
    struct Case {
        std::string name, text, message;
    };
    const std::vector<Case> cases = {
        {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nv 2 2 2\nv 3 3 3\n# faces\n\n\n\nf 1 2 9\n",
         "range.obj:12: face index 9 out of range (7 vertices)"},
        {"back.obj", "v 0 0 0\nv 1 0 0\nf 1 2 -3\n", "back.obj:3: face index -3 out of range (2 vertices)"},
        {"word.obj", "v 0 0 zero\n", "word.obj:1: expected a number, found 'zero'"},
        {"two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", "two.obj:3: a face needs at least 3 corners, found 2"},
        {"empty.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "empty.obj: the mesh has no triangles"},
        {"notply.ply", "PLY\n", "notply.ply:1: not a PLY file"},
        {"big.ply", "ply\nformat binary_big_endian 1.0\nend_header\n", "big.ply:2: binary_big_endian PLY is not read"},
        {"face.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
         "face.ply:13: face index 3 out of range (3 vertices)"},
        {"noface.ply",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
         "noface.ply:7: the header declares no 'face' element"},
        {"short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n",
         "short.stl: line 6: expected 'vertex', but the file ends"},
        {"nothing.stl", "solid x\nendsolid x\n", "nothing.stl: the mesh has no triangles"},
    };
    for (const Case& c : cases) {
        const MeshReadResult r = readMeshFile(write(c.name, c.text));
        EXPECT_EQ(r.error.rfind((dir / c.name).string(), 0), 0u) << r.error;
        EXPECT_NE(r.error.find(c.message), std::string::npos) << c.name << ": " << r.error;
        EXPECT_TRUE(r.mesh.empty()) << c.name;
    }
    // A binary STL whose count lies: the sizes are named.
    std::string bin(84, '\0');
    bin[80] = 3;
    EXPECT_NE(readMeshFile(write("lie.stl", bin)).error.find("truncated binary STL"), std::string::npos);
    EXPECT_NE(readMeshFile((dir / "gone.obj").string()).error.find("gone.obj"), std::string::npos);
    EXPECT_TRUE(isMeshFileName("a/b.Stl"));
    EXPECT_FALSE(isMeshFileName("a/b.hf"));
}

}  // namespace
}  // namespace hg::poly
