// glTF binary files (polygonizer/export/gltf_io.h): one scene, one node, one mesh
// with one indexed triangle primitive, POSITION and NORMAL as float vec3
// and indices as uint32, positions times the scale (metres); written whole
// or not at all. What is tested, reading the files back with tinygltf and
// byte by byte:
//  * the GLB container: magic, version 2, the length of the file, a JSON
//    chunk then a BIN chunk, 4-byte aligned;
//  * the scene, node, mesh and primitive, named; accessor types and counts
//    (vertices, vertices, 3 x triangles); buffer views on one buffer with
//    their targets; POSITION's min and max exactly the scaled positions'
//    bounds; every position (times the scale, in float), normal and index
//    as the mesh has it; doubling the scale doubles positions and bounds;
//  * read back, the solid is closed and outward with the mesh's volume
//    times the scale cubed;
//  * a bad scale or missing normals are refused with the path and no file;
//    a failing write leaves no file and an older file as it was.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "mesh_files.h"
#include "polygonizer/export/gltf_io.h"
#include "polygonizer/export/mesh_validation.h"

namespace hg::poly {
namespace {

using test::ScratchFolder;
using test::slurp;

std::uint32_t u32(const std::string& bytes, std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

tinygltf::Model load(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
    EXPECT_EQ(err, "");
    EXPECT_EQ(warn, "");
    return model;
}

// An accessor's elements, read through its buffer view.
template <class T>
std::vector<T> elements(const tinygltf::Model& m, int accessor, std::size_t perElement) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::vector<unsigned char>& data = m.buffers.at(static_cast<std::size_t>(v.buffer)).data;
    const std::size_t bytes = a.count * perElement * sizeof(T);
    EXPECT_LE(a.byteOffset + bytes, v.byteLength);
    EXPECT_LE(v.byteOffset + v.byteLength, data.size());
    std::vector<T> out(a.count * perElement);
    if (v.byteOffset + a.byteOffset + bytes <= data.size())
        std::memcpy(out.data(), data.data() + v.byteOffset + a.byteOffset, bytes);
    return out;
}

// The mesh as the file holds it, every structural promise checked.
Mesh meshOf(const tinygltf::Model& m, const std::string& name) {
    Mesh out;
    EXPECT_EQ(m.asset.version, "2.0");
    EXPECT_EQ(m.asset.generator, "Hypergarden");
    EXPECT_EQ(m.defaultScene, 0);
    if (m.scenes.size() != 1 || m.nodes.size() != 1 || m.meshes.size() != 1 || m.buffers.size() != 1) {
        ADD_FAILURE() << "one scene, node, mesh and buffer: " << m.scenes.size() << " " << m.nodes.size() << " "
                      << m.meshes.size() << " " << m.buffers.size();
        return out;
    }
    EXPECT_EQ(m.scenes[0].nodes, std::vector<int>{0});
    EXPECT_EQ(m.nodes[0].mesh, 0);
    EXPECT_EQ(m.nodes[0].name, name);
    EXPECT_TRUE(m.nodes[0].matrix.empty() && m.nodes[0].scale.empty()) << "the scale is in the positions";
    EXPECT_EQ(m.meshes[0].name, name);
    if (m.meshes[0].primitives.size() != 1) {
        ADD_FAILURE() << "one primitive";
        return out;
    }
    const tinygltf::Primitive& p = m.meshes[0].primitives[0];
    EXPECT_EQ(p.mode, TINYGLTF_MODE_TRIANGLES);
    EXPECT_EQ(p.attributes.size(), 2u);
    const int pos = p.attributes.at("POSITION"), nor = p.attributes.at("NORMAL");
    for (int a : {pos, nor}) {
        const tinygltf::Accessor& acc = m.accessors.at(static_cast<std::size_t>(a));
        EXPECT_EQ(acc.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
        EXPECT_EQ(acc.type, TINYGLTF_TYPE_VEC3);
        EXPECT_EQ(m.bufferViews.at(static_cast<std::size_t>(acc.bufferView)).target, TINYGLTF_TARGET_ARRAY_BUFFER);
    }
    const tinygltf::Accessor& ia = m.accessors.at(static_cast<std::size_t>(p.indices));
    EXPECT_EQ(ia.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    EXPECT_EQ(ia.type, TINYGLTF_TYPE_SCALAR);
    EXPECT_EQ(m.bufferViews.at(static_cast<std::size_t>(ia.bufferView)).target, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    out.positions = elements<float>(m, pos, 3);
    out.normals = elements<float>(m, nor, 3);
    out.indices = elements<std::uint32_t>(m, p.indices, 1);
    return out;
}

// Every position of `file` is the mesh's times `scale` in float, every
// normal and index the mesh's; POSITION's bounds are theirs exactly.
void expectSameMesh(const tinygltf::Model& m, const Mesh& file, const Mesh& mesh, float scale) {
    ASSERT_EQ(file.positions.size(), mesh.positions.size());
    ASSERT_EQ(file.normals.size(), mesh.normals.size());
    EXPECT_EQ(file.indices, mesh.indices);
    std::size_t differ = 0;
    std::vector<double> lo(3, 1e300), hi(3, -1e300);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const float p = mesh.positions[i] * scale;
        differ += file.positions[i] != p || file.normals[i] != mesh.normals[i];
        lo[i % 3] = std::min(lo[i % 3], static_cast<double>(p));
        hi[i % 3] = std::max(hi[i % 3], static_cast<double>(p));
    }
    EXPECT_EQ(differ, 0u);
    const tinygltf::Accessor& pa =
        m.accessors.at(static_cast<std::size_t>(m.meshes.at(0).primitives.at(0).attributes.at("POSITION")));
    EXPECT_EQ(pa.count, mesh.vertexCount());
    EXPECT_EQ(pa.minValues, lo);
    EXPECT_EQ(pa.maxValues, hi);
}

TEST(GltfIo, TheGlbContainerIsWellFormed) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    ASSERT_EQ(writeGlb(mesh, dir.file("t.glb"), 0.5), "");
    const std::string bytes = slurp(dir.file("t.glb"));
    ASSERT_GE(bytes.size(), 28u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    EXPECT_EQ(u32(bytes, 4), 2u) << "version";
    EXPECT_EQ(u32(bytes, 8), bytes.size()) << "the header's length is the file's";
    const std::uint32_t jsonLength = u32(bytes, 12);
    EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au) << "JSON first";
    EXPECT_EQ(jsonLength % 4, 0u);
    ASSERT_LE(20u + jsonLength + 8u, bytes.size());
    const std::size_t bin = 20 + jsonLength;
    const std::uint32_t binLength = u32(bytes, bin);
    EXPECT_EQ(u32(bytes, bin + 4), 0x004E4942u) << "then BIN";
    EXPECT_EQ(binLength % 4, 0u);
    EXPECT_EQ(bin + 8 + binLength, bytes.size()) << "two chunks, nothing after";
    // The buffer is positions, normals and indices.
    EXPECT_GE(binLength, 2 * mesh.positions.size() * sizeof(float) + mesh.indices.size() * sizeof(std::uint32_t));
    EXPECT_LT(binLength, 2 * mesh.positions.size() * sizeof(float) + mesh.indices.size() * sizeof(std::uint32_t) + 4);
    EXPECT_NE(bytes.find("\"POSITION\"", 20), std::string::npos);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"t.glb"}) << "no temporary left";
}

TEST(GltfIo, TinygltfReadsBackEveryAccessorExactly) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    ASSERT_EQ(writeGlb(mesh, dir.file("t.glb"), 0.3, "torus_block"), "");
    const tinygltf::Model m = load(dir.file("t.glb"));
    const Mesh back = meshOf(m, "torus_block");
    expectSameMesh(m, back, mesh, 0.3f);
    const auto& p = m.meshes.at(0).primitives.at(0);
    EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(p.attributes.at("NORMAL"))).count, mesh.vertexCount());
    EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(p.indices)).count, 3 * mesh.triangleCount());

    // The default name, and twice the scale: positions and bounds doubled.
    ASSERT_EQ(writeGlb(mesh, dir.file("a.glb"), 0.75), "");
    ASSERT_EQ(writeGlb(mesh, dir.file("b.glb"), 1.5), "");
    const tinygltf::Model a = load(dir.file("a.glb")), b = load(dir.file("b.glb"));
    const Mesh ma = meshOf(a, "hypergarden"), mb = meshOf(b, "hypergarden");
    ASSERT_EQ(ma.positions.size(), mb.positions.size());
    for (std::size_t i = 0; i < ma.positions.size(); ++i) ASSERT_EQ(mb.positions[i], 2.0f * ma.positions[i]) << i;
    const auto& pa = a.accessors.at(static_cast<std::size_t>(a.meshes[0].primitives[0].attributes.at("POSITION")));
    const auto& pb = b.accessors.at(static_cast<std::size_t>(b.meshes[0].primitives[0].attributes.at("POSITION")));
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(pb.minValues.at(k), 2.0 * pa.minValues.at(k));
        EXPECT_EQ(pb.maxValues.at(k), 2.0 * pa.maxValues.at(k));
    }
    // A large mesh the same way.
    const Mesh big = test::uvSphere(120, 200);
    ASSERT_EQ(writeGlb(big, dir.file("big.glb"), 2.0), "");
    const tinygltf::Model mbig = load(dir.file("big.glb"));
    expectSameMesh(mbig, meshOf(mbig, "hypergarden"), big, 2.0f);
}

TEST(GltfIo, ReadBackTheSolidIsClosedOutwardAndScaled) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const MeshReport original = validateMesh(mesh);
    ASSERT_TRUE(original.ok()) << describe(original);
    for (double scale : {1.0, 0.25, 0.0254}) {
        ASSERT_EQ(writeGlb(mesh, dir.file("t.glb"), scale), "");
        const MeshReport back = validateMesh(meshOf(load(dir.file("t.glb")), "hypergarden"));
        EXPECT_TRUE(back.ok()) << describe(back);
        EXPECT_EQ(back.triangles, original.triangles);
        EXPECT_NEAR(back.volume, original.volume * scale * scale * scale, 1e-5 * back.volume) << scale;
    }
}

TEST(GltfIo, BadScalesAndMissingNormalsAreRefusedWithoutAFile) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const std::string path = dir.file("bad.glb");
    for (double scale : {0.0, -2.0, std::nan(""), -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()}) {
        EXPECT_EQ(writeGlb(mesh, path, scale), "cannot write " + path + ": the scale must be finite and positive") << scale;
    }
    Mesh noNormals = mesh;
    noNormals.normals.clear();
    EXPECT_EQ(writeGlb(noNormals, path), "cannot write " + path + ": the mesh has no normal for every vertex");
    // Readers refuse a glTF with an empty binary chunk: no triangles, no file.
    EXPECT_EQ(writeGlb(Mesh{}, path), "cannot write " + path + ": the mesh has no triangles");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(GltfIo, AFailedWriteLeavesNothingAndKeepsTheOlderFile) {
    ScratchFolder dir;
    const Mesh mesh = test::torusMesh();
    const std::string path = dir.file("t.glb");
    {
        test::FailingExportWrites full(ENOSPC);
        const std::string why = writeGlb(mesh, path);
        EXPECT_NE(why.find(path), std::string::npos) << why;
        EXPECT_NE(why.find(std::strerror(ENOSPC)), std::string::npos) << why;
    }
    EXPECT_TRUE(dir.entries().empty()) << "no partial file, no temporary";
    ASSERT_EQ(writeGlb(test::uvSphere(8, 12), path), "");
    const std::string older = slurp(path);
    {
        test::FailingExportWrites failing(EIO);
        EXPECT_NE(writeGlb(mesh, path), "");
    }
    EXPECT_EQ(slurp(path), older);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"t.glb"});
    ASSERT_EQ(writeGlb(mesh, path), "");
    const tinygltf::Model m = load(path);
    expectSameMesh(m, meshOf(m, "hypergarden"), mesh, 1.0f);
}

}  // namespace
}  // namespace hg::poly
