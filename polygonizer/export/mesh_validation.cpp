#include "polygonizer/export/mesh_validation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "polygonizer/export/mesh_validation_edges.h"

namespace hg::poly {

namespace {

using Vec = std::array<double, 3>;

Vec position(const Mesh& m, std::size_t v) {
    return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool finite(const Mesh& m, std::size_t v) {
    return std::isfinite(m.positions[3 * v]) && std::isfinite(m.positions[3 * v + 1]) &&
           std::isfinite(m.positions[3 * v + 2]);
}

struct Key {
    std::int64_t c[3];
    bool operator==(const Key& o) const { return c[0] == o.c[0] && c[1] == o.c[1] && c[2] == o.c[2]; }
};

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (std::int64_t x : k.c) {
            h ^= static_cast<std::uint64_t>(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        }
        return static_cast<std::size_t>(h);
    }
};

// Bit patterns, so that only identical values meet; -0 and +0 are the same
// point.
Key exactKey(const Mesh& m, std::size_t v) {
    Key k{};
    for (int a = 0; a < 3; ++a) {
        float f = m.positions[3 * v + a];
        if (f == 0.0f) f = 0.0f;
        std::uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        k.c[a] = bits;
    }
    return k;
}

// Cells as wide as the tolerance: any point within reach lies in one of the
// 27 cells around a vertex's own. Clamped so that huge coordinates over a
// tiny tolerance stay defined (they then merge less, never wrongly).
Key cellKey(const Vec& p, double cell) {
    Key k{};
    for (int a = 0; a < 3; ++a) {
        double c = std::floor(p[a] / cell);
        c = std::clamp(c, -4.0e18, 4.0e18);
        k.c[a] = static_cast<std::int64_t>(c);
    }
    return k;
}

// For each vertex, the group it joins; groups are numbered in order of
// their first vertex.
std::vector<std::uint32_t> groupVertices(const Mesh& mesh, float tolerance, std::uint32_t& groups) {
    const std::size_t n = mesh.vertexCount();
    std::vector<std::uint32_t> group(n);
    groups = 0;
    if (!(tolerance > 0) || !std::isfinite(tolerance)) {
        std::unordered_map<Key, std::uint32_t, KeyHash> seen;
        seen.reserve(n);
        for (std::size_t v = 0; v < n; ++v) {
            if (!finite(mesh, v)) {
                group[v] = groups++;
                continue;
            }
            auto [it, inserted] = seen.try_emplace(exactKey(mesh, v), groups);
            if (inserted) ++groups;
            group[v] = it->second;
        }
        return group;
    }
    const double cell = tolerance;
    const double reach2 = cell * cell;
    std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> grid;  // cell -> kept vertices
    std::vector<std::uint32_t> keptVertex;                             // group -> its vertex
    for (std::size_t v = 0; v < n; ++v) {
        if (!finite(mesh, v)) {
            group[v] = groups++;
            keptVertex.push_back(static_cast<std::uint32_t>(v));
            continue;
        }
        const Vec p = position(mesh, v);
        const Key home = cellKey(p, cell);
        std::uint32_t found = UINT32_MAX;
        for (int dz = -1; dz <= 1 && found == UINT32_MAX; ++dz)
            for (int dy = -1; dy <= 1 && found == UINT32_MAX; ++dy)
                for (int dx = -1; dx <= 1 && found == UINT32_MAX; ++dx) {
                    auto it = grid.find(Key{{home.c[0] + dx, home.c[1] + dy, home.c[2] + dz}});
                    if (it == grid.end()) continue;
                    for (std::uint32_t g : it->second) {
                        const Vec d = sub(position(mesh, keptVertex[g]), p);
                        if (dot(d, d) <= reach2) {
                            found = g;
                            break;
                        }
                    }
                }
        if (found == UINT32_MAX) {
            found = groups++;
            keptVertex.push_back(static_cast<std::uint32_t>(v));
            grid[home].push_back(found);
        }
        group[v] = found;
    }
    return group;
}

bool inRange(const Mesh& m, std::size_t t) {
    const std::size_t n = m.vertexCount();
    return m.indices[3 * t] < n && m.indices[3 * t + 1] < n && m.indices[3 * t + 2] < n;
}

bool degenerate(const std::uint32_t* i) { return i[0] == i[1] || i[1] == i[2] || i[0] == i[2]; }

// validateMesh's unit of parallel work: large enough that a task's
// overhead does not show, small enough for a mesh of 100k triangles to
// keep two threads busy. Fixed, so sums come out the same on any number of
// threads.
constexpr std::size_t kChunkTriangles = std::size_t{1} << 15;
constexpr std::size_t kChunkVertices = std::size_t{1} << 16;

// The count and box of the used vertices, as a serial loop keeping
// std::min(lo, x) and std::max(hi, x) from the first used vertex on would
// find them: a value replaces a bound only when strictly beyond it, so a
// NaN never does (but a NaN first value stays the bound), and of equal
// values (-0 and +0) the first stays. Spans of consecutive vertices combine
// in order to the same box.
struct VertexSpan {
    std::size_t used = 0;
    float first[3] = {0, 0, 0};                  // the first used vertex
    bool numeric[3] = {false, false, false};     // lo and hi hold a value that is not NaN
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // over values that are not NaN

    void add(const float* p) {
        for (int a = 0; a < 3; ++a) {
            if (used == 0) first[a] = p[a];
            if (std::isnan(p[a])) continue;
            lo[a] = numeric[a] ? std::min(lo[a], p[a]) : p[a];
            hi[a] = numeric[a] ? std::max(hi[a], p[a]) : p[a];
            numeric[a] = true;
        }
        ++used;
    }
    void append(const VertexSpan& o) {
        if (o.used == 0) return;
        for (int a = 0; a < 3; ++a) {
            if (used == 0) first[a] = o.first[a];
            if (!o.numeric[a]) continue;
            lo[a] = numeric[a] ? std::min(lo[a], o.lo[a]) : o.lo[a];
            hi[a] = numeric[a] ? std::max(hi[a], o.hi[a]) : o.hi[a];
            numeric[a] = true;
        }
        used += o.used;
    }
    float boxMin(int a) const { return used == 0 ? 0.0f : std::isnan(first[a]) ? first[a] : lo[a]; }
    float boxMax(int a) const { return used == 0 ? 0.0f : std::isnan(first[a]) ? first[a] : hi[a]; }
};

VertexSpan spanOfUsed(const Mesh& mesh, const std::atomic<std::uint8_t>* used) {
    const std::size_t n = mesh.vertexCount();
    const std::size_t chunks = (n + kChunkVertices - 1) / kChunkVertices;
    std::vector<VertexSpan> spans(chunks);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c)
            for (std::size_t v = c * kChunkVertices; v < std::min(n, (c + 1) * kChunkVertices); ++v)
                if (used[v].load(std::memory_order_relaxed)) spans[c].add(&mesh.positions[3 * v]);
    });
    VertexSpan all;
    for (const VertexSpan& s : spans) all.append(s);
    return all;
}

}  // namespace

Mesh weldByPosition(const Mesh& mesh, float tolerance) {
    std::uint32_t groups = 0;
    const std::vector<std::uint32_t> group = groupVertices(mesh, tolerance, groups);

    Mesh out;
    std::vector<std::uint32_t> tris;
    tris.reserve(mesh.indices.size());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (!inRange(mesh, t)) continue;
        const std::uint32_t g[3] = {group[mesh.indices[3 * t]], group[mesh.indices[3 * t + 1]],
                                    group[mesh.indices[3 * t + 2]]};
        if (degenerate(g)) continue;
        tris.insert(tris.end(), g, g + 3);
    }

    // Groups no triangle uses are dropped; the rest keep their order.
    std::vector<std::uint32_t> final(groups, UINT32_MAX);
    for (std::uint32_t g : tris) final[g] = 0;
    std::uint32_t used = 0;
    for (std::uint32_t& f : final)
        if (f == 0) f = used++;

    out.positions.resize(3 * std::size_t{used});
    std::vector<bool> placed(used, false);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const std::uint32_t f = final[group[v]];
        if (f == UINT32_MAX || placed[f]) continue;
        placed[f] = true;
        std::copy_n(&mesh.positions[3 * v], 3, &out.positions[3 * std::size_t{f}]);
    }

    if (mesh.normals.size() == mesh.positions.size() && used > 0) {
        std::vector<double> sum(3 * std::size_t{used}, 0.0);
        std::vector<std::size_t> first(used, SIZE_MAX);
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const std::uint32_t f = final[group[v]];
            if (f == UINT32_MAX) continue;
            if (first[f] == SIZE_MAX) first[f] = v;
            for (int a = 0; a < 3; ++a) sum[3 * f + a] += static_cast<double>(mesh.normals[3 * v + a]);
        }
        out.normals.resize(sum.size());
        for (std::size_t f = 0; f < used; ++f) {
            const Vec s{sum[3 * f], sum[3 * f + 1], sum[3 * f + 2]};
            const double len = std::sqrt(dot(s, s));
            for (int a = 0; a < 3; ++a) {
                // Opposite normals cancel (a knife edge); the first one is
                // still a better guess than no direction at all.
                out.normals[3 * f + a] = len > 0 && std::isfinite(len) ? static_cast<float>(s[a] / len)
                                                                        : mesh.normals[3 * first[f] + a];
            }
        }
    }

    out.indices = std::move(tris);
    for (std::uint32_t& i : out.indices) i = final[i];
    return out;
}

MeshReport validateMesh(const Mesh& mesh) {
    MeshReport r;
    const std::size_t triCount = mesh.triangleCount();
    const std::size_t vertexCount = mesh.vertexCount();
    r.triangles = triCount;
    const std::size_t chunks = (triCount + kChunkTriangles - 1) / kChunkTriangles;
    auto forChunks = [&](auto body) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& c) {
            for (std::size_t k = c.begin(); k != c.end(); ++k)
                body(k, k * kChunkTriangles, std::min(triCount, (k + 1) * kChunkTriangles));
        });
    };

    // Flags written by many threads at once, all with the same value.
    std::unique_ptr<std::atomic<std::uint8_t>[]> usedVertex(new std::atomic<std::uint8_t>[vertexCount]());
    std::vector<std::uint8_t> live(triCount, 0);  // in range and not degenerate
    std::vector<std::array<std::size_t, 2>> bad(chunks, {0, 0});  // invalid, degenerate per chunk
    forChunks([&](std::size_t c, std::size_t begin, std::size_t end) {
        const std::uint32_t* indices = mesh.indices.data();
        std::size_t invalid = 0, collapsed = 0;
        for (std::size_t t = begin; t < end; ++t) {
            const std::uint32_t* i = indices + 3 * t;
            if (i[0] >= vertexCount || i[1] >= vertexCount || i[2] >= vertexCount) {
                ++invalid;
                continue;
            }
            for (int k = 0; k < 3; ++k) usedVertex[i[k]].store(1, std::memory_order_relaxed);
            const bool d = degenerate(i);
            collapsed += d ? 1 : 0;
            live[t] = d ? 0 : 1;
        }
        bad[c] = {invalid, collapsed};
    });
    for (const auto& b : bad) {
        r.invalidTriangles += b[0];
        r.degenerateTriangles += b[1];
    }

    const VertexSpan span = spanOfUsed(mesh, usedVertex.get());
    r.vertices = span.used;
    for (int a = 0; a < 3; ++a) {
        r.boxMin[a] = span.boxMin(a);
        r.boxMax[a] = span.boxMax(a);
    }

    // Measured from the box centre: the terms stay small for a model far
    // from the origin, so less cancels. Summed per chunk, then the chunks
    // in order: the same total on any number of threads.
    const Vec centre{0.5 * (static_cast<double>(r.boxMin[0]) + static_cast<double>(r.boxMax[0])),
                     0.5 * (static_cast<double>(r.boxMin[1]) + static_cast<double>(r.boxMax[1])),
                     0.5 * (static_cast<double>(r.boxMin[2]) + static_cast<double>(r.boxMax[2]))};
    std::vector<std::array<double, 2>> sums(chunks, {0.0, 0.0});  // six times the volume, twice the area
    forChunks([&](std::size_t c, std::size_t begin, std::size_t end) {
        const std::uint32_t* indices = mesh.indices.data();
        const std::uint8_t* counted = live.data();
        double sixVolume = 0, twiceArea = 0;
        for (std::size_t t = begin; t < end; ++t) {
            if (!counted[t]) continue;
            const Vec a = sub(position(mesh, indices[3 * t]), centre);
            const Vec b = sub(position(mesh, indices[3 * t + 1]), centre);
            const Vec d = sub(position(mesh, indices[3 * t + 2]), centre);
            sixVolume += dot(a, cross(b, d));
            const Vec n = cross(sub(b, a), sub(d, a));
            twiceArea += std::sqrt(dot(n, n));
        }
        sums[c] = {sixVolume, twiceArea};
    });
    double sixVolume = 0, twiceArea = 0;
    for (const auto& s : sums) {
        sixVolume += s[0];
        twiceArea += s[1];
    }
    r.volume = sixVolume / 6;
    r.area = twiceArea / 2;

    const EdgeCensus edges = censusEdges(mesh, live, defaultEdgeLayout(triCount, vertexCount));
    r.boundaryEdges = edges.boundaryEdges;
    r.nonManifoldEdges = edges.nonManifoldEdges;
    r.inconsistentEdges = edges.inconsistentEdges;
    r.components = edges.components;
    return r;
}

namespace {

std::string num(double x, int digits = 6) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    return buf;
}

std::string count(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string describe(const MeshReport& r, double mmPerUnit) { return describe(r, mmPerUnit, "mm"); }

std::string describe(const MeshReport& r, double perModelUnit, const std::string& unit) {
    const double s = perModelUnit;
    const std::string& u = unit;
    std::string out;
    out += "triangles: " + std::to_string(r.triangles) + " (" + count(r.vertices, "vertex", "vertices") + ", " +
           count(r.components, "part", "parts") + ")\n";
    out += "volume: " + num(r.volume * s * s * s) + " " + u + "^3";
    if (u == "mm") out += " (" + num(r.volume * s * s * s / 1000) + " cm^3)";
    if (!r.closed()) out += ", not meaningful: the surface is open";
    out += "\n";
    out += "surface area: " + num(r.area * s * s) + " " + u + "^2\n";
    double size[3], lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = static_cast<double>(r.boxMin[a]) * s;
        hi[a] = static_cast<double>(r.boxMax[a]) * s;
        size[a] = hi[a] - lo[a];
    }
    out += "size: " + num(size[0]) + " x " + num(size[1]) + " x " + num(size[2]) + " " + u + ", from (" + num(lo[0]) +
           ", " + num(lo[1]) + ", " + num(lo[2]) + ") to (" + num(hi[0]) + ", " + num(hi[1]) + ", " + num(hi[2]) +
           ") " + u + "\n";
    out += "boundary edges: " + std::to_string(r.boundaryEdges) + (r.boundaryEdges ? " (holes)\n" : "\n");
    out += "non-manifold edges: " + std::to_string(r.nonManifoldEdges) +
           (r.nonManifoldEdges ? " (shared by more than two triangles)\n" : "\n");
    out += "degenerate triangles: " + std::to_string(r.degenerateTriangles) + "\n";
    if (r.invalidTriangles) out += "triangles with invalid indices: " + std::to_string(r.invalidTriangles) + "\n";
    out += "orientation: ";
    if (r.inconsistentEdges)
        out += "inconsistent (" + count(r.inconsistentEdges, "edge", "edges") + " between triangles facing opposite ways)";
    else if (r.volume > 0)
        out += "consistent, facing outward";
    else if (r.volume < 0)
        out += "consistent but inside out (negative volume)";
    else
        out += "consistent, no enclosed volume";
    out += "\n";

    std::vector<std::string> problems;
    if (r.triangles == 0) problems.push_back("no triangles");
    if (r.boundaryEdges) problems.push_back("open (" + count(r.boundaryEdges, "boundary edge", "boundary edges") + ")");
    if (r.nonManifoldEdges)
        problems.push_back("non-manifold (" + count(r.nonManifoldEdges, "edge", "edges") + ")");
    if (r.inconsistentEdges) problems.push_back("inconsistently oriented");
    else if (r.triangles > 0 && r.volume < 0) problems.push_back("inside out");
    else if (r.triangles > 0 && !(r.volume > 0)) problems.push_back("encloses no volume");
    if (r.degenerateTriangles)
        problems.push_back(count(r.degenerateTriangles, "degenerate triangle", "degenerate triangles"));
    if (r.invalidTriangles)
        problems.push_back(count(r.invalidTriangles, "triangle", "triangles") + " with invalid indices");
    out += "verdict: ";
    if (r.ok()) {
        out += "watertight and manifold";
    } else {
        out += "not printable as is: ";
        for (std::size_t i = 0; i < problems.size(); ++i) out += (i ? "; " : "") + problems[i];
    }
    out += "\n";
    return out;
}

}  // namespace hg::poly
