#include "garden/deform/remesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hg::garden::deform {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The corner of `tri` where the edge {a, b} starts (tri[k], tri[k + 1] is
// the edge in the triangle's own direction), or -1.
int edgeCorner(const Triangle& tri, std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t p = tri[k], q = tri[(k + 1) % 3];
        if ((p == a && q == b) || (p == b && q == a)) return k;
    }
    return -1;
}

std::uint32_t opposite(const Triangle& tri, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t v : tri)
        if (v != a && v != b) return v;
    return a;
}

glm::dvec3 triangleNormal(const DeformMesh& mesh, const Triangle& tri) {
    return glm::cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]], mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
}

double edgeLength(const DeformMesh& mesh, const MeshEdge& e) {
    return glm::length(mesh.vertices[e.a] - mesh.vertices[e.b]);
}

// Manifold edges (two triangles) whose length passes `keep`, in a fixed
// order: longest first when `longestFirst`, else shortest first; equal
// lengths by vertex.
template <class Keep>
std::vector<std::pair<double, MeshEdge>> edgesBy(const DeformMesh& mesh, const std::vector<MeshEdge>& edges,
                                                 bool longestFirst, Keep keep) {
    std::vector<std::pair<double, MeshEdge>> out;
    for (const MeshEdge& e : edges) {
        if (e.uses != 2) continue;
        const double l = edgeLength(mesh, e);
        if (keep(l)) out.emplace_back(l, e);
    }
    std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
        if (x.first != y.first) return longestFirst ? x.first > y.first : x.first < y.first;
        return x.second.a != y.second.a ? x.second.a < y.second.a : x.second.b < y.second.b;
    });
    return out;
}

// Drops triangles marked dead and vertices no triangle uses, keeping the
// order of the rest.
void compact(DeformMesh& mesh, const std::vector<bool>& deadTriangle) {
    std::vector<Triangle> kept;
    kept.reserve(mesh.triangles.size());
    std::vector<bool> used(mesh.vertices.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (deadTriangle[t]) continue;
        kept.push_back(mesh.triangles[t]);
        for (std::uint32_t v : mesh.triangles[t]) used[v] = true;
    }
    std::vector<std::uint32_t> index(mesh.vertices.size(), kNoTriangle);
    std::vector<glm::dvec3> vertices;
    vertices.reserve(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!used[v]) continue;
        index[v] = static_cast<std::uint32_t>(vertices.size());
        vertices.push_back(mesh.vertices[v]);
    }
    for (Triangle& tri : kept)
        for (std::uint32_t& v : tri) v = index[v];
    mesh.vertices = std::move(vertices);
    mesh.triangles = std::move(kept);
}

bool contains(const VertexLists& lists, std::uint32_t v, std::uint32_t item) {
    const auto begin = lists.items.begin() + lists.offsets[v], end = lists.items.begin() + lists.offsets[v + 1];
    return std::binary_search(begin, end, item);
}

}  // namespace

int splitLongEdges(DeformMesh& mesh, double maxLength) {
    const std::vector<MeshEdge> edges = meshEdges(mesh);
    std::vector<bool> touched(mesh.triangles.size(), false);
    int splits = 0;
    for (const auto& [length, e] : edgesBy(mesh, edges, true, [&](double l) { return l > maxLength; })) {
        if (touched[e.t0] || touched[e.t1]) continue;
        touched[e.t0] = touched[e.t1] = true;
        const auto m = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(0.5 * (mesh.vertices[e.a] + mesh.vertices[e.b]));
        for (std::uint32_t t : {e.t0, e.t1}) {
            const Triangle tri = mesh.triangles[t];
            const int k = edgeCorner(tri, e.a, e.b);
            const std::uint32_t p = tri[k], q = tri[(k + 1) % 3], r = tri[(k + 2) % 3];
            mesh.triangles[t] = {p, m, r};
            mesh.triangles.push_back({m, q, r});
        }
        ++splits;
    }
    return splits;
}

int collapseShortEdges(DeformMesh& mesh, double minLength, double maxLength) {
    if (mesh.vertices.size() <= 6) return 0;
    const std::vector<MeshEdge> edges = meshEdges(mesh);
    const VertexLists ring = vertexNeighbours(edges, mesh.vertices.size());
    const VertexLists fan = vertexTriangles(mesh);
    // A vertex is dirty once a collapse changed a triangle around it: the
    // lists above are then stale for it, so no later collapse of this round
    // may look at it.
    std::vector<bool> dirty(mesh.vertices.size(), false), deadTriangle(mesh.triangles.size(), false);
    const auto ringClean = [&](std::uint32_t v) {
        if (dirty[v]) return false;
        for (std::uint32_t i = ring.offsets[v]; i < ring.offsets[v + 1]; ++i)
            if (dirty[ring.items[i]]) return false;
        return true;
    };
    int collapses = 0;
    for (const auto& [length, e] : edgesBy(mesh, edges, false, [&](double l) { return l < minLength; })) {
        const std::uint32_t a = e.a, b = e.b;
        if (!ringClean(a) || !ringClean(b)) continue;
        const std::uint32_t c = opposite(mesh.triangles[e.t0], a, b), d = opposite(mesh.triangles[e.t1], a, b);
        // The link condition: a and b share exactly the neighbours c and d,
        // and c and d keep at least three edges, so the mesh stays manifold.
        int common = 0;
        for (std::uint32_t i = ring.offsets[a]; i < ring.offsets[a + 1]; ++i)
            if (contains(ring, b, ring.items[i])) ++common;
        if (common != 2 || c == d || ring.count(c) <= 3 || ring.count(d) <= 3) continue;
        const glm::dvec3 m = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
        // No new edge too long, no triangle turned over or made a sliver.
        bool ok = true;
        for (std::uint32_t v : {a, b}) {
            for (std::uint32_t i = ring.offsets[v]; ok && i < ring.offsets[v + 1]; ++i)
                if (glm::length(mesh.vertices[ring.items[i]] - m) > maxLength) ok = false;
            for (std::uint32_t i = fan.offsets[v]; ok && i < fan.offsets[v + 1]; ++i) {
                const std::uint32_t t = fan.items[i];
                if (t == e.t0 || t == e.t1) continue;
                const glm::dvec3 before = triangleNormal(mesh, mesh.triangles[t]);
                const glm::dvec3 keep = mesh.vertices[v];
                mesh.vertices[v] = m;
                const glm::dvec3 after = triangleNormal(mesh, mesh.triangles[t]);
                mesh.vertices[v] = keep;
                const double lb = glm::length(before), la = glm::length(after);
                if (!(la > 0.0) || glm::dot(before, after) < 0.5 * lb * la) ok = false;
            }
        }
        if (!ok) continue;
        mesh.vertices[a] = m;
        for (std::uint32_t i = fan.offsets[b]; i < fan.offsets[b + 1]; ++i) {
            const std::uint32_t t = fan.items[i];
            if (t == e.t0 || t == e.t1) {
                deadTriangle[t] = true;
                continue;
            }
            for (std::uint32_t& v : mesh.triangles[t])
                if (v == b) v = a;
        }
        for (std::uint32_t v : {a, b}) {
            dirty[v] = true;
            for (std::uint32_t i = ring.offsets[v]; i < ring.offsets[v + 1]; ++i) dirty[ring.items[i]] = true;
        }
        ++collapses;
    }
    if (collapses > 0) compact(mesh, deadTriangle);
    return collapses;
}

int flipTowardEvenValence(DeformMesh& mesh) {
    const std::vector<MeshEdge> edges = meshEdges(mesh);
    const VertexLists ring = vertexNeighbours(edges, mesh.vertices.size());
    std::vector<int> valence(mesh.vertices.size());
    for (std::size_t v = 0; v < valence.size(); ++v) valence[v] = static_cast<int>(ring.count(v));
    std::vector<bool> dirty(mesh.vertices.size(), false);
    int flips = 0;
    for (const MeshEdge& e : edges) {
        if (e.uses != 2) continue;
        const Triangle t0 = mesh.triangles[e.t0], t1 = mesh.triangles[e.t1];
        const int k = edgeCorner(t0, e.a, e.b);
        // A triangle a flip earlier in this round rewrote no longer has the edge.
        if (k < 0 || edgeCorner(t1, e.a, e.b) < 0) continue;
        // t0 runs p -> q -> r, t1 runs q -> p -> s: the quad p, s, q, r.
        const std::uint32_t p = t0[k], q = t0[(k + 1) % 3], r = t0[(k + 2) % 3], s = opposite(t1, p, q);
        if (dirty[p] || dirty[q] || dirty[r] || dirty[s] || r == s) continue;
        if (valence[p] <= 3 || valence[q] <= 3 || contains(ring, r, s)) continue;
        const auto deviation = [](int vp, int vq, int vr, int vs) {
            return std::abs(vp - 6) + std::abs(vq - 6) + std::abs(vr - 6) + std::abs(vs - 6);
        };
        if (deviation(valence[p] - 1, valence[q] - 1, valence[r] + 1, valence[s] + 1) >=
            deviation(valence[p], valence[q], valence[r], valence[s]))
            continue;
        // Only where the quad is nearly flat and convex enough that both new
        // triangles face the way the old ones did.
        const Triangle n0 = {p, s, r}, n1 = {s, q, r};
        const glm::dvec3 before = triangleNormal(mesh, t0) + triangleNormal(mesh, t1);
        const glm::dvec3 a0 = triangleNormal(mesh, n0), a1 = triangleNormal(mesh, n1);
        const double lb = glm::length(before);
        if (glm::dot(a0, before) < 0.5 * glm::length(a0) * lb || glm::dot(a1, before) < 0.5 * glm::length(a1) * lb)
            continue;
        mesh.triangles[e.t0] = n0;
        mesh.triangles[e.t1] = n1;
        --valence[p];
        --valence[q];
        ++valence[r];
        ++valence[s];
        dirty[p] = dirty[q] = dirty[r] = dirty[s] = true;
        ++flips;
    }
    return flips;
}

void smoothTangentially(DeformMesh& mesh, double factor) {
    const VertexLists ring = vertexNeighbours(meshEdges(mesh), mesh.vertices.size());
    const std::vector<glm::dvec3> normals = vertexNormals(mesh, vertexTriangles(mesh));
    std::vector<glm::dvec3> moved(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        glm::dvec3 centroid(0.0);
        for (std::uint32_t i = ring.offsets[v]; i < ring.offsets[v + 1]; ++i) centroid += mesh.vertices[ring.items[i]];
        centroid /= static_cast<double>(std::max<std::size_t>(1, ring.count(v)));
        const glm::dvec3 toCentroid = centroid - mesh.vertices[v];
        moved[v] = mesh.vertices[v] + factor * (toCentroid - glm::dot(toCentroid, normals[v]) * normals[v]);
    }
    mesh.vertices = std::move(moved);
}

int remeshRound(DeformMesh& mesh, double edgeLength) {
    return splitLongEdges(mesh, 4.0 / 3.0 * edgeLength) +
           collapseShortEdges(mesh, 0.8 * edgeLength, 4.0 / 3.0 * edgeLength) + flipTowardEvenValence(mesh);
}

DeformMesh remeshUniform(DeformMesh mesh, double edgeLength, int passes, const SurfaceProjection& project) {
    constexpr int kMaxRounds = 40;  // each round halves what is left, roughly
    for (int pass = 0; pass < passes; ++pass) {
        for (int round = 0; round < kMaxRounds && splitLongEdges(mesh, 4.0 / 3.0 * edgeLength) > 0; ++round) {
        }
        for (int round = 0;
             round < kMaxRounds && collapseShortEdges(mesh, 0.8 * edgeLength, 4.0 / 3.0 * edgeLength) > 0; ++round) {
        }
        for (int round = 0; round < 4 && flipTowardEvenValence(mesh) > 0; ++round) {
        }
        smoothTangentially(mesh, 0.5);
        if (project)
            for (glm::dvec3& p : mesh.vertices) p = project(p);
    }
    return mesh;
}

DeformMesh remeshUniform(DeformMesh mesh, double edgeLength, int passes) {
    return remeshUniform(std::move(mesh), edgeLength, passes, {});
}

}  // namespace hg::garden::deform
