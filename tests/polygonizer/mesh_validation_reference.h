// The serial validateMesh as it was before it went parallel (a sort of all
// edge uses, one union-find, one loop for the box, volume and area): the
// reference the parallel validation and edge census must agree with.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <random>
#include <vector>

#include "polygonizer/export/mesh_validation.h"

namespace hg::poly::test {

inline MeshReport referenceValidate(const Mesh& mesh) {
    using Vec = std::array<double, 3>;
    auto position = [&](std::size_t v) -> Vec {
        return {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
    };
    auto sub = [](const Vec& a, const Vec& b) -> Vec { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto cross = [](const Vec& a, const Vec& b) -> Vec {
        return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const std::size_t n = mesh.vertexCount();
    auto inRange = [&](std::size_t t) {
        return mesh.indices[3 * t] < n && mesh.indices[3 * t + 1] < n && mesh.indices[3 * t + 2] < n;
    };
    auto degenerate = [](const std::uint32_t* i) { return i[0] == i[1] || i[1] == i[2] || i[0] == i[2]; };

    MeshReport r;
    const std::size_t triCount = mesh.triangleCount();
    r.triangles = triCount;
    std::vector<bool> usedVertex(n, false);
    std::vector<bool> live(triCount, false);
    for (std::size_t t = 0; t < triCount; ++t) {
        if (!inRange(t)) {
            ++r.invalidTriangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) usedVertex[mesh.indices[3 * t + k]] = true;
        if (degenerate(&mesh.indices[3 * t]))
            ++r.degenerateTriangles;
        else
            live[t] = true;
    }
    bool anyVertex = false;
    for (std::size_t v = 0; v < n; ++v) {
        if (!usedVertex[v]) continue;
        ++r.vertices;
        for (int a = 0; a < 3; ++a) {
            const float x = mesh.positions[3 * v + a];
            r.boxMin[a] = anyVertex ? std::min(r.boxMin[a], x) : x;
            r.boxMax[a] = anyVertex ? std::max(r.boxMax[a], x) : x;
        }
        anyVertex = true;
    }
    const Vec centre{0.5 * (static_cast<double>(r.boxMin[0]) + static_cast<double>(r.boxMax[0])),
                     0.5 * (static_cast<double>(r.boxMin[1]) + static_cast<double>(r.boxMax[1])),
                     0.5 * (static_cast<double>(r.boxMin[2]) + static_cast<double>(r.boxMax[2]))};
    double sixVolume = 0, twiceArea = 0;
    for (std::size_t t = 0; t < triCount; ++t) {
        if (!live[t]) continue;
        const Vec a = sub(position(mesh.indices[3 * t]), centre);
        const Vec b = sub(position(mesh.indices[3 * t + 1]), centre);
        const Vec c = sub(position(mesh.indices[3 * t + 2]), centre);
        sixVolume += dot(a, cross(b, c));
        const Vec nn = cross(sub(b, a), sub(c, a));
        twiceArea += std::sqrt(dot(nn, nn));
    }
    r.volume = sixVolume / 6;
    r.area = twiceArea / 2;

    struct EdgeUse {
        std::uint64_t key;
        std::size_t tri;
        bool forward;
    };
    std::vector<EdgeUse> uses;
    for (std::size_t t = 0; t < triCount; ++t) {
        if (!live[t]) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[3 * t + k], b = mesh.indices[3 * t + (k + 1) % 3];
            const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
            uses.push_back({(lo << 32) | hi, t, a < b});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
    std::vector<std::size_t> parent(triCount);
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto find = [&](std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i, forward = 0;
        for (; j < uses.size() && uses[j].key == uses[i].key; ++j) {
            forward += uses[j].forward ? 1 : 0;
            parent[find(uses[j].tri)] = find(uses[i].tri);
        }
        const std::size_t count = j - i;
        if (count == 1)
            ++r.boundaryEdges;
        else if (count > 2)
            ++r.nonManifoldEdges;
        else if (forward != 1)
            ++r.inconsistentEdges;
        i = j;
    }
    for (std::size_t t = 0; t < triCount; ++t)
        if (live[t] && find(t) == t) ++r.components;
    return r;
}

// A closed latitude-longitude sphere (single-vertex poles), counter-
// clockwise from outside; with many segments its poles are wide fans.
// Every triangle with its own three vertices, as an STL file stores it:
// only boundary edges.
inline Mesh soup(const Mesh& m) {
    Mesh s;
    for (std::uint32_t i : m.indices) {
        s.positions.insert(s.positions.end(), &m.positions[3 * i], &m.positions[3 * i] + 3);
        s.indices.push_back(static_cast<std::uint32_t>(s.indices.size()));
    }
    return s;
}

// b's triangles after a's, on vertices of their own.
inline Mesh concatenate(Mesh a, const Mesh& b) {
    const auto offset = static_cast<std::uint32_t>(a.vertexCount());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (std::uint32_t i : b.indices) a.indices.push_back(i + offset);
    return a;
}

inline Mesh latLongSphere(int rings, int segments, double radius, double cx = 0) {
    Mesh m;
    auto add = [&m](double x, double y, double z) {
        for (double c : {x, y, z}) m.positions.push_back(static_cast<float>(c));
    };
    const double pi = 3.14159265358979323846;
    add(cx, 0, radius);
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double theta = pi * i / rings, phi = 2 * pi * j / segments;
            add(cx + radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                radius * std::cos(theta));
        }
    add(cx, 0, -radius);
    const auto south = static_cast<std::uint32_t>(m.vertexCount() - 1);
    auto at = [&](int ring, int j) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + j % segments); };
    auto tri = [&m](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        m.indices.insert(m.indices.end(), {a, b, c});
    };
    for (int j = 0; j < segments; ++j) {
        tri(0, at(1, j), at(1, j + 1));
        for (int i = 1; i + 1 < rings; ++i) {
            tri(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            tri(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
        tri(south, at(rings - 1, j + 1), at(rings - 1, j));
    }
    return m;
}

// Every kind of defect validation counts, at random places (seeded): holes,
// flipped triangles, duplicated triangles (edges used three and four times),
// triangles with two equal corners or an index out of range, stray
// triangles between random vertices, and unused vertices; then the vertex
// numbers shuffled, so that nothing is where a welded mesh would put it.
inline Mesh withDefects(Mesh m, unsigned seed, bool shuffle = true) {
    std::mt19937 rng(seed);
    const std::size_t n = m.vertexCount();
    auto pick = [&rng](std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(rng); };
    std::vector<std::uint32_t> tris(m.indices);
    std::vector<std::uint32_t> out;
    const std::size_t triangles = tris.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        std::uint32_t a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
        const std::size_t roll = pick(1000);
        if (roll < 10) continue;  // hole
        if (roll < 20) std::swap(b, c);  // flipped
        out.insert(out.end(), {a, b, c});
        if (roll >= 20 && roll < 25) out.insert(out.end(), {a, b, c});  // duplicate: three uses an edge
        if (roll >= 25 && roll < 28) out.insert(out.end(), {a, c, b});  // back to back: edges used both ways twice
        if (roll >= 28 && roll < 31) out.insert(out.end(), {a, a, b});  // degenerate
        if (roll >= 31 && roll < 33)  // invalid
            out.insert(out.end(), {a, b, static_cast<std::uint32_t>(n + 4 + pick(5))});
        if (roll >= 33 && roll < 36)
            out.insert(out.end(), {static_cast<std::uint32_t>(pick(n)), static_cast<std::uint32_t>(pick(n)),
                                   static_cast<std::uint32_t>(pick(n))});  // stray
    }
    // Unused vertices at the end, one of them far away.
    for (int k = 0; k < 4; ++k) m.positions.insert(m.positions.end(), {1e6f, 0.0f, static_cast<float>(k)});
    m.indices = out;
    if (shuffle) {
        std::vector<std::uint32_t> perm(m.vertexCount());
        std::iota(perm.begin(), perm.end(), 0u);
        std::shuffle(perm.begin(), perm.end(), rng);
        std::vector<float> positions(m.positions.size());
        for (std::size_t v = 0; v < perm.size(); ++v)
            for (int a = 0; a < 3; ++a) positions[3 * perm[v] + a] = m.positions[3 * v + a];
        m.positions = positions;
        for (std::uint32_t& i : m.indices)
            if (i < perm.size()) i = perm[i];
    }
    return m;
}

}  // namespace hg::poly::test
