#include "polygonizer/mesh_simplify.h"

#include <meshoptimizer.h>

namespace hg::poly {

Mesh simplifyMesh(const Mesh& mesh, double maxError, SimplifyStats* stats) {
    const std::size_t nv = mesh.vertexCount();
    // meshoptimizer's errors are relative to the mesh's extent.
    const float extent = meshopt_simplifyScale(mesh.positions.data(), nv, 3 * sizeof(float));
    const float target = extent > 0.0f ? static_cast<float>(maxError / static_cast<double>(extent)) : 0.0f;
    std::vector<std::uint32_t> indices(mesh.indices.size());
    float achieved = 0.0f;
    indices.resize(meshopt_simplify(indices.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.data(), nv,
                                    3 * sizeof(float), 0, target, 0, &achieved));

    // Keep the vertices still used, in order of first use.
    std::vector<std::uint32_t> remap(nv);
    const std::size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), nv);
    Mesh out;
    out.positions.resize(3 * used);
    meshopt_remapVertexBuffer(out.positions.data(), mesh.positions.data(), nv, 3 * sizeof(float), remap.data());
    if (mesh.normals.size() == mesh.positions.size()) {
        out.normals.resize(3 * used);
        meshopt_remapVertexBuffer(out.normals.data(), mesh.normals.data(), nv, 3 * sizeof(float), remap.data());
    }
    out.indices.resize(indices.size());
    meshopt_remapIndexBuffer(out.indices.data(), indices.data(), indices.size(), remap.data());
    if (stats) {
        stats->trianglesBefore = mesh.triangleCount();
        stats->trianglesAfter = out.triangleCount();
        stats->error = static_cast<double>(achieved) * static_cast<double>(extent);
    }
    return out;
}

}  // namespace hg::poly
