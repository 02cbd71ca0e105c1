#include "polygonizer/export/mesh_simplify.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>

#include "polygonizer/export/mesh_validation.h"

namespace hg::poly {

namespace {

// Drops each pair of triangles on the same three vertices in opposite
// orders: a fold meshoptimizer leaves where a collapse flattens a fin, which
// encloses nothing but uses its edges twice more (a non-manifold edge).
void removeFolds(std::vector<std::uint32_t>& indices) {
    const std::size_t n = indices.size() / 3;
    // Each triangle turned to start at its smallest vertex (keeping its
    // order); a fold's two triangles then differ only in the last two.
    struct Key {
        std::array<std::uint32_t, 3> v;
        std::uint32_t triangle;
        std::array<std::uint32_t, 3> set() const {
            return {v[0], std::min(v[1], v[2]), std::max(v[1], v[2])};
        }
    };
    std::vector<Key> keys(n);
    for (std::size_t t = 0; t < n; ++t) {
        std::array<std::uint32_t, 3> v = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
        std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
        keys[t] = {v, static_cast<std::uint32_t>(t)};
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.set() != b.set() ? a.set() < b.set() : a.triangle < b.triangle;
    });
    std::vector<bool> drop(n, false);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const Key& a = keys[i];
        const Key& b = keys[i + 1];
        // Exactly two on this vertex set, in opposite orders.
        if (a.set() != b.set() || a.v[1] != b.v[2] || (i + 2 < n && keys[i + 2].set() == a.set()) ||
            (i > 0 && keys[i - 1].set() == a.set()))
            continue;
        drop[a.triangle] = drop[b.triangle] = true;
        ++i;
    }
    std::size_t to = 0;
    for (std::size_t t = 0; t < n; ++t) {
        if (drop[t]) continue;
        for (std::size_t k = 0; k < 3; ++k) indices[to + k] = indices[3 * t + k];
        to += 3;
    }
    indices.resize(to);
}

}  // namespace

Mesh simplifyMesh(const Mesh& mesh, double maxError, SimplifyStats* stats) {
    const std::size_t nv = mesh.vertexCount();
    SimplifyStats st;
    st.trianglesBefore = mesh.triangleCount();
    // meshoptimizer's errors are relative to the mesh's extent.
    const double extent = meshopt_simplifyScale(mesh.positions.data(), nv, 3 * sizeof(float));

    // The candidate of each pass is checked on a mesh that shares nothing
    // but the positions with the input (validation reads no normals).
    Mesh probe;
    probe.positions = mesh.positions;
    std::vector<std::uint32_t> current = mesh.indices, next;
    std::size_t triangles = current.size() / 3;
    std::size_t target = 0;  // first, all that the error allows
    while (extent > 0.0 && maxError > st.error) {
        const auto relative = static_cast<float>((maxError - st.error) / extent);
        float achieved = 0.0f;
        next.resize(current.size());
        next.resize(meshopt_simplify(next.data(), current.data(), current.size(), mesh.positions.data(), nv,
                                     3 * sizeof(float), 3 * target, relative, 0, &achieved));
        if (next.size() >= current.size()) break;  // the error allows nothing more
        const std::size_t reached = next.size() / 3;
        removeFolds(next);
        probe.indices.swap(next);
        const bool ok = !probe.indices.empty() && validateMesh(probe).ok();
        probe.indices.swap(next);
        if (ok) {
            current.swap(next);
            triangles = current.size() / 3;
            st.error += static_cast<double>(achieved) * extent;
            ++st.passes;
            target = 0;
            continue;
        }
        // Some collapse in this step breaks the surface: smaller steps get
        // up to it.
        const std::size_t step = triangles - std::max(target, reached);
        if (step <= std::max<std::size_t>(1, triangles / 100)) {
            st.stoppedByTopology = true;
            break;
        }
        target = triangles - step / 2;
    }

    // Keep the vertices still used, in order of first use.
    std::vector<std::uint32_t> remap(nv);
    const std::size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), current.data(), current.size(), nv);
    Mesh out;
    out.positions.resize(3 * used);
    meshopt_remapVertexBuffer(out.positions.data(), mesh.positions.data(), nv, 3 * sizeof(float), remap.data());
    if (mesh.normals.size() == mesh.positions.size()) {
        out.normals.resize(3 * used);
        meshopt_remapVertexBuffer(out.normals.data(), mesh.normals.data(), nv, 3 * sizeof(float), remap.data());
    }
    out.indices.resize(current.size());
    meshopt_remapIndexBuffer(out.indices.data(), current.data(), current.size(), remap.data());
    st.trianglesAfter = out.triangleCount();
    if (stats) *stats = st;
    return out;
}

}  // namespace hg::poly
