#include "polygonizer/export/gltf_io.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "io/checked_write.h"

namespace hg::poly {

namespace {

// One buffer: positions, then normals, then indices, each a buffer view
// with one accessor.
int addView(tinygltf::Model& m, std::size_t offset, std::size_t bytes, int target) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    view.target = target;
    m.bufferViews.push_back(view);
    return static_cast<int>(m.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& m, int view, int componentType, int type, std::size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    m.accessors.push_back(a);
    return static_cast<int>(m.accessors.size() - 1);
}

tinygltf::Model buildModel(const Mesh& mesh, float scale, const std::string& name) {
    tinygltf::Model m;
    const std::size_t nv = mesh.vertexCount();
    const std::size_t vertexBytes = 3 * nv * sizeof(float), indexBytes = mesh.indices.size() * sizeof(std::uint32_t);
    tinygltf::Buffer buffer;
    buffer.data.resize(2 * vertexBytes + indexBytes);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    auto* positions = reinterpret_cast<float*>(buffer.data.data());
    for (std::size_t i = 0; i < 3 * nv; ++i) {
        positions[i] = mesh.positions[i] * scale;
        lo[i % 3] = std::min(lo[i % 3], static_cast<double>(positions[i]));
        hi[i % 3] = std::max(hi[i % 3], static_cast<double>(positions[i]));
    }
    std::memcpy(buffer.data.data() + vertexBytes, mesh.normals.data(), vertexBytes);
    std::memcpy(buffer.data.data() + 2 * vertexBytes, mesh.indices.data(), indexBytes);
    m.buffers.push_back(std::move(buffer));

    const int p = addAccessor(m, addView(m, 0, vertexBytes, TINYGLTF_TARGET_ARRAY_BUFFER), TINYGLTF_COMPONENT_TYPE_FLOAT,
                              TINYGLTF_TYPE_VEC3, nv);
    m.accessors[static_cast<std::size_t>(p)].minValues = lo;  // required for POSITION
    m.accessors[static_cast<std::size_t>(p)].maxValues = hi;
    const int n = addAccessor(m, addView(m, vertexBytes, vertexBytes, TINYGLTF_TARGET_ARRAY_BUFFER),
                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, nv);
    const int ix = addAccessor(m, addView(m, 2 * vertexBytes, indexBytes, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());

    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = p;
    prim.attributes["NORMAL"] = n;
    prim.indices = ix;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gm;
    gm.name = name;
    gm.primitives.push_back(prim);
    m.meshes.push_back(gm);
    tinygltf::Node node;
    node.mesh = 0;
    node.name = name;
    m.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    m.scenes.push_back(scene);
    m.defaultScene = 0;
    m.asset.version = "2.0";
    m.asset.generator = "Hypergarden";
    return m;
}

}  // namespace

std::string writeGlb(const Mesh& mesh, const std::string& path, double scale, const std::string& meshName) {
    if (!(scale > 0.0) || !std::isfinite(scale)) return "cannot write " + path + ": the scale must be finite and positive";
    if (mesh.normals.size() != mesh.positions.size())
        return "cannot write " + path + ": the mesh has no normal for every vertex";
    // glTF readers refuse a binary chunk of no bytes: an empty mesh is no file.
    if (mesh.triangleCount() == 0) return "cannot write " + path + ": the mesh has no triangles";
    const tinygltf::Model model = buildModel(mesh, static_cast<float>(scale), meshName);
    // Encoded in memory (binary, not pretty printed), then written with
    // every step checked: tinygltf's own file writer does not report a full
    // disk.
    tinygltf::TinyGLTF gltf;
    std::ostringstream out(std::ios::binary);
    if (!gltf.WriteGltfSceneToStream(&model, out, false, true)) return "cannot write " + path + ": glTF encoding failed";
    return io::writeFileAtomically(path, out.str(), io::WriteSite::Export);
}

}  // namespace hg::poly
