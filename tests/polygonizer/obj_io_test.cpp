// OBJ files (polygonizer/export/obj_io.h): one object, a `v` line per vertex (the
// position times the scale, metres), a `vn` line per vertex normal and an
// `f a//a b//b c//c` line per triangle, counter-clockwise from outside;
// numbers are the shortest text that reads back as the same float; written
// to a temporary name and renamed, so a failure leaves no partial file.
// What is tested, reading the files back line by line:
//  * the layout (comment, `o NAME`, every v, every vn, every f, nothing
//    else), each number the exact float of the mesh (times the scale, in
//    float) and the shortest that reads back as it, faces the mesh's
//    indices plus one: on a sampled, meshed torus block, and on a mesh
//    whose file is several times the writer's 4 MiB buffer;
//  * read back, the solid is closed and outward with the mesh's volume
//    times the scale cubed;
//  * a bad scale or missing normals are refused with the path and no file;
//    a failing write (ENOSPC through the fault seam, a missing folder)
//    says so with the path and leaves no file, nor a temporary, and an
//    older file of that name as it was.
#include <gtest/gtest.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_files.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/obj_io.h"

namespace hg::poly {
namespace {

using test::ScratchFolder;
using test::slurp;
namespace fs = std::filesystem;

// The significant digits of a number's text ("0.0125" and "1.25e-02": 3).
int significantDigits(std::string_view s) {
    if (!s.empty() && s[0] == '-') s.remove_prefix(1);
    s = s.substr(0, s.find_first_of("eE"));
    std::string digits;
    for (char c : s)
        if (c != '.') digits.push_back(c);
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return 1;
    const std::size_t last = digits.find_last_not_of('0');
    return static_cast<int>(last - first + 1);
}

struct ObjFile {
    std::string comment, object;
    Mesh mesh;
    std::size_t badLines = 0, longNumbers = 0;
};

// A strict reader for what writeObj writes: every line checked.
ObjFile readObjStrictly(const std::string& path) {
    ObjFile o;
    const std::string text = slurp(path);
    EXPECT_TRUE(!text.empty() && text.back() == '\n') << "the last line ends";
    std::size_t pos = 0;
    int section = 0;  // 0 header, 1 v, 2 vn, 3 f
    int lineNo = 0;
    const auto bad = [&](const std::string& line, const char* why) {
        if (o.badLines++ < 5) ADD_FAILURE() << path << ":" << lineNo << ": " << why << ": " << line;
    };
    while (pos < text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string_view line(text.data() + pos, (end == std::string::npos ? text.size() : end) - pos);
        pos = end == std::string::npos ? text.size() : end + 1;
        ++lineNo;
        if (lineNo == 1) {
            if (line.rfind("# ", 0) != 0) bad(std::string(line), "the first line is a comment");
            o.comment = line;
            continue;
        }
        if (lineNo == 2) {
            if (line.rfind("o ", 0) != 0) bad(std::string(line), "the second line names the object");
            o.object = line.substr(2);
            continue;
        }
        const std::size_t space = line.find(' ');
        const std::string_view tag = line.substr(0, space);
        const int want = tag == "v" ? 1 : tag == "vn" ? 2 : tag == "f" ? 3 : -1;
        if (want < 0 || want < section) {
            bad(std::string(line), "a v, vn or f line, in that order");
            continue;
        }
        section = want;
        std::string_view rest = line.substr(space + 1);
        for (int k = 0; k < 3; ++k) {
            const std::size_t next = rest.find(' ');
            const std::string_view token = rest.substr(0, next);
            if ((k < 2) != (next != std::string_view::npos)) bad(std::string(line), "three items");
            if (want == 3) {
                std::uint32_t a = 0, b = 0;
                const std::size_t slashes = token.find("//");
                const auto ra = std::from_chars(token.data(), token.data() + slashes, a);
                const auto rb = std::from_chars(token.data() + slashes + 2, token.data() + token.size(), b);
                if (slashes == std::string_view::npos || ra.ec != std::errc() || rb.ec != std::errc() ||
                    rb.ptr != token.data() + token.size() || a != b || a == 0)
                    bad(std::string(line), "a//a with a from 1");
                o.mesh.indices.push_back(a - 1);
            } else {
                float v = 0;
                const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
                if (r.ec != std::errc() || r.ptr != token.data() + token.size()) bad(std::string(line), "a number");
                (want == 1 ? o.mesh.positions : o.mesh.normals).push_back(v);
                // The shortest text: one significant digit fewer reads back
                // as another float.
                const int n = significantDigits(token);
                if (n > 9) ++o.longNumbers;
                if (n > 1) {
                    char shorter[400];
                    std::snprintf(shorter, sizeof shorter, "%.*g", n - 1, static_cast<double>(v));
                    float back = 0;
                    std::from_chars(shorter, shorter + std::strlen(shorter), back);
                    if (back == v) ++o.longNumbers;
                }
            }
            rest = next == std::string_view::npos ? std::string_view() : rest.substr(next + 1);
        }
    }
    return o;
}

// `file` holds `mesh` exactly, positions times `scale` (in float).
void expectSameMesh(const ObjFile& file, const Mesh& mesh, float scale) {
    EXPECT_EQ(file.badLines, 0u);
    EXPECT_EQ(file.longNumbers, 0u) << "numbers longer than the shortest that reads back";
    ASSERT_EQ(file.mesh.positions.size(), mesh.positions.size());
    ASSERT_EQ(file.mesh.normals.size(), mesh.normals.size());
    ASSERT_EQ(file.mesh.indices, mesh.indices);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        differ += file.mesh.positions[i] != mesh.positions[i] * scale;
        differ += file.mesh.normals[i] != mesh.normals[i];
    }
    EXPECT_EQ(differ, 0u) << "numbers that do not read back as the mesh's floats";
}

TEST(ObjIo, EveryVertexNormalAndTriangleReadsBackExactly) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    ASSERT_EQ(writeObj(mesh, dir.file("torus.obj"), 0.3, "torus_block"), "");
    const ObjFile file = readObjStrictly(dir.file("torus.obj"));
    EXPECT_EQ(file.object, "torus_block");
    EXPECT_NE(file.comment.find("metres"), std::string::npos) << file.comment;
    expectSameMesh(file, mesh, 0.3f);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"torus.obj"}) << "no temporary left";

    // The default: scale 1, object "hypergarden".
    ASSERT_EQ(writeObj(mesh, dir.file("plain.obj")), "");
    const ObjFile plain = readObjStrictly(dir.file("plain.obj"));
    EXPECT_EQ(plain.object, "hypergarden");
    expectSameMesh(plain, mesh, 1.0f);
}

TEST(ObjIo, ReadBackTheSolidIsClosedOutwardAndScaled) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const MeshReport original = validateMesh(mesh);
    ASSERT_TRUE(original.ok()) << describe(original);
    for (double scale : {1.0, 0.25, 0.0254}) {
        ASSERT_EQ(writeObj(mesh, dir.file("t.obj"), scale), "");
        const MeshReport back = validateMesh(readObjStrictly(dir.file("t.obj")).mesh);
        EXPECT_TRUE(back.ok()) << describe(back);
        EXPECT_EQ(back.triangles, original.triangles);
        EXPECT_NEAR(back.volume, original.volume * scale * scale * scale, 1e-5 * back.volume) << scale;
        for (int a = 0; a < 3; ++a) EXPECT_FLOAT_EQ(back.boxMax[a], original.boxMax[a] * static_cast<float>(scale));
    }
}

TEST(ObjIo, AFileSeveralTimesTheBufferReadsBackExactly) {
    ScratchFolder dir;
    const Mesh mesh = test::uvSphere(240, 400);  // ~96k vertices, ~190k triangles
    ASSERT_TRUE(validateMesh(mesh).ok());
    ASSERT_EQ(writeObj(mesh, dir.file("big.obj"), 1.7), "");
    EXPECT_GT(fs::file_size(dir.file("big.obj")), std::uintmax_t{12} << 20);
    expectSameMesh(readObjStrictly(dir.file("big.obj")), mesh, 1.7f);
}

TEST(ObjIo, BadScalesAndMissingNormalsAreRefusedWithoutAFile) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const std::string path = dir.file("bad.obj");
    for (double scale : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        const std::string why = writeObj(mesh, path, scale);
        EXPECT_EQ(why, "cannot write " + path + ": the scale must be finite and positive") << scale;
    }
    Mesh noNormals = mesh;
    noNormals.normals.clear();
    EXPECT_EQ(writeObj(noNormals, path), "cannot write " + path + ": the mesh has no normal for every vertex");
    Mesh fewNormals = mesh;
    fewNormals.normals.resize(fewNormals.normals.size() - 3);
    EXPECT_EQ(writeObj(fewNormals, path), "cannot write " + path + ": the mesh has no normal for every vertex");
    EXPECT_TRUE(dir.entries().empty());
    // A name with a line break stays on its "o" line: no vertex of its own.
    ASSERT_EQ(writeObj(mesh, path, 1.0, "a\nv 9 9 9"), "");
    std::ifstream in(path);
    std::string line;
    std::size_t vertices = 0, objects = 0;
    while (std::getline(in, line)) {
        vertices += line.rfind("v ", 0) == 0;
        objects += line.rfind("o ", 0) == 0;
    }
    EXPECT_EQ(vertices, mesh.vertexCount());
    EXPECT_EQ(objects, 1u);
}

TEST(ObjIo, AFailedWriteLeavesNothingAndKeepsTheOlderFile) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const std::string path = dir.file("t.obj");
    {
        test::FailingExportWrites full(ENOSPC);
        const std::string why = writeObj(mesh, path);
        EXPECT_NE(why.find(path), std::string::npos) << why;
        EXPECT_NE(why.find(std::strerror(ENOSPC)), std::string::npos) << why;
    }
    EXPECT_TRUE(dir.entries().empty()) << "no partial file, no temporary";

    // An older file of that name stays whole when its replacement fails.
    ASSERT_EQ(writeObj(test::uvSphere(8, 12), path), "");
    const std::string older = slurp(path);
    {
        test::FailingExportWrites full(EIO);
        EXPECT_NE(writeObj(mesh, path), "");
    }
    EXPECT_EQ(slurp(path), older);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"t.obj"});
    // Once writes work again it is replaced.
    ASSERT_EQ(writeObj(mesh, path), "");
    expectSameMesh(readObjStrictly(path), mesh, 1.0f);

    const std::string nowhere = dir.file("no/such/folder/t.obj");
    const std::string why = writeObj(mesh, nowhere);
    EXPECT_NE(why.find(nowhere), std::string::npos) << why;
}

}  // namespace
}  // namespace hg::poly
