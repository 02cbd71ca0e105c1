#include "garden/deform/deform_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

namespace hg::garden::deform {

DeformMesh sphereMesh(glm::dvec3 centre, double radius, int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (glm::dvec3& p : v) p = glm::normalize(p);
    std::vector<std::array<std::uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        const auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto it = middle.find(key);
            if (it != middle.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            const auto index = static_cast<std::uint32_t>(v.size() - 1);
            middle.emplace(key, index);
            return index;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        next.reserve(f.size() * 4);
        for (const auto& tri : f) {
            const std::uint32_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
            next.push_back({tri[0], ab, ca});
            next.push_back({tri[1], bc, ab});
            next.push_back({tri[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        f = std::move(next);
    }
    DeformMesh mesh;
    mesh.vertices.reserve(v.size());
    for (const glm::dvec3& p : v) mesh.vertices.push_back(centre + radius * p);
    mesh.triangles = std::move(f);
    return mesh;
}

std::vector<MeshEdge> meshEdges(const DeformMesh& mesh) {
    // Each triangle side filed under its lower vertex (a counting sort, in
    // triangle order), each vertex's short list sorted by the upper vertex
    // (a stable insertion sort keeps the triangles ascending), then runs of
    // equal (a, b) merged: sorted by (a, b) without a full sort, which the
    // snake would pay after every remeshing round.
    const std::size_t n = mesh.vertices.size();
    std::vector<std::uint32_t> offsets(n + 2, 0);
    for (const auto& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++offsets[std::min(tri[k], tri[(k + 1) % 3]) + 2];
    for (std::size_t v = 2; v < offsets.size(); ++v) offsets[v] += offsets[v - 1];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> sides(mesh.triangles.size() * 3);  // (b, triangle)
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t p = tri[k], q = tri[(k + 1) % 3];
            sides[offsets[std::min(p, q) + 1]++] = {std::max(p, q), t};
        }
    }
    std::vector<MeshEdge> edges;
    edges.reserve(sides.size() / 2 + 1);
    for (std::uint32_t a = 0; a < n; ++a) {
        const auto begin = sides.begin() + offsets[a], end = sides.begin() + offsets[a + 1];
        for (auto i = begin + (begin != end ? 1 : 0); i < end; ++i)
            for (auto j = i; j > begin && (j - 1)->first > j->first; --j) std::iter_swap(j - 1, j);
        for (auto i = begin; i < end;) {
            MeshEdge e;
            e.a = a;
            e.b = i->first;
            auto j = i;
            for (; j < end && j->first == e.b; ++j) {
                if (e.uses == 0) e.t0 = j->second;
                else if (e.uses == 1) e.t1 = j->second;
                ++e.uses;
            }
            edges.push_back(e);
            i = j;
        }
    }
    return edges;
}

namespace {

// Counting sort of (key, item) pairs into per-key lists; items keep the
// order they are given in.
VertexLists listsFrom(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs, std::size_t keys) {
    VertexLists l;
    l.offsets.assign(keys + 1, 0);
    for (const auto& p : pairs) ++l.offsets[p.first + 1];
    for (std::size_t k = 0; k < keys; ++k) l.offsets[k + 1] += l.offsets[k];
    l.items.resize(pairs.size());
    std::vector<std::uint32_t> fill(l.offsets.begin(), l.offsets.end() - 1);
    for (const auto& p : pairs) l.items[fill[p.first]++] = p.second;
    return l;
}

}  // namespace

VertexLists vertexNeighbours(const std::vector<MeshEdge>& edges, std::size_t vertexCount) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    pairs.reserve(edges.size() * 2);
    for (const MeshEdge& e : edges) {
        pairs.emplace_back(e.a, e.b);
        pairs.emplace_back(e.b, e.a);
    }
    // Edges are sorted by (a, b), so each vertex's b-side neighbours come
    // in ascending order but its a-side ones interleave: sort each list.
    VertexLists l = listsFrom(pairs, vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v)
        std::sort(l.items.begin() + l.offsets[v], l.items.begin() + l.offsets[v + 1]);
    return l;
}

VertexLists vertexTriangles(const DeformMesh& mesh) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    pairs.reserve(mesh.triangles.size() * 3);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t]) pairs.emplace_back(v, t);
    return listsFrom(pairs, mesh.vertices.size());
}

std::vector<glm::dvec3> vertexNormals(const DeformMesh& mesh, const VertexLists& triangles) {
    std::vector<glm::dvec3> faceNormal(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        faceNormal[t] = glm::cross(mesh.vertices[tri[1]] - mesh.vertices[tri[0]],
                                   mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    }
    std::vector<glm::dvec3> normals(mesh.vertices.size(), glm::dvec3(0.0));
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        glm::dvec3 n(0.0);
        for (std::uint32_t i = triangles.offsets[v]; i < triangles.offsets[v + 1]; ++i) n += faceNormal[triangles.items[i]];
        const double length = glm::length(n);
        normals[v] = length > 0.0 ? n / length : glm::dvec3(0.0);
    }
    return normals;
}

double meshVolume(const DeformMesh& mesh) {
    double six = 0.0;
    for (const auto& tri : mesh.triangles)
        six += glm::dot(mesh.vertices[tri[0]], glm::cross(mesh.vertices[tri[1]], mesh.vertices[tri[2]]));
    return six / 6.0;
}

std::string checkClosedManifold(const DeformMesh& mesh) {
    std::vector<bool> used(mesh.vertices.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (std::uint32_t v : tri) {
            if (v >= mesh.vertices.size()) return "triangle " + std::to_string(t) + " names a missing vertex";
            used[v] = true;
        }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
            return "triangle " + std::to_string(t) + " repeats a vertex";
    }
    for (std::size_t v = 0; v < used.size(); ++v)
        if (!used[v]) return "vertex " + std::to_string(v) + " is in no triangle";
    for (const MeshEdge& e : meshEdges(mesh)) {
        const std::string name = "edge " + std::to_string(e.a) + "-" + std::to_string(e.b);
        if (e.uses != 2) return name + " is in " + std::to_string(e.uses) + " triangles";
        // Outward orientation: the two triangles run the edge both ways.
        const auto forward = [&](std::uint32_t t) {
            const auto& tri = mesh.triangles[t];
            for (int k = 0; k < 3; ++k)
                if (tri[k] == e.a && tri[(k + 1) % 3] == e.b) return true;
            return false;
        };
        if (forward(e.t0) == forward(e.t1)) return name + " is oriented the same way by both its triangles";
    }
    // A vertex whose triangles form two fans (a pinch) passes the edge
    // test: walk its one-ring from one triangle and it must come back
    // having met every triangle around it.
    const VertexLists fan = vertexTriangles(mesh);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> ring;  // (next, previous) of v in each triangle
        for (std::uint32_t i = fan.offsets[v]; i < fan.offsets[v + 1]; ++i) {
            const auto& tri = mesh.triangles[fan.items[i]];
            const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
            ring.emplace_back(tri[(k + 1) % 3], tri[(k + 2) % 3]);
        }
        std::size_t steps = 0;
        std::uint32_t at = ring.front().second;
        do {
            const auto next = std::find_if(ring.begin(), ring.end(), [&](const auto& r) { return r.first == at; });
            if (next == ring.end()) break;
            at = next->second;
            ++steps;
        } while (at != ring.front().second && steps <= ring.size());
        if (steps != ring.size()) return "vertex " + std::to_string(v) + " is a pinch of more than one fan";
    }
    return "";
}

EdgeLengthRange edgeLengthRange(const DeformMesh& mesh) {
    EdgeLengthRange r;
    const std::vector<MeshEdge> edges = meshEdges(mesh);
    if (edges.empty()) return r;
    r.min = 1e300;
    double sum = 0.0;
    for (const MeshEdge& e : edges) {
        const double l = glm::length(mesh.vertices[e.a] - mesh.vertices[e.b]);
        r.min = std::min(r.min, l);
        r.max = std::max(r.max, l);
        sum += l;
    }
    r.mean = sum / static_cast<double>(edges.size());
    return r;
}

}  // namespace hg::garden::deform
