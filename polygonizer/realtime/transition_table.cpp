#include "polygonizer/realtime/transition_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "polygonizer/loop_fan.h"

namespace hg::poly {

namespace {

// The back vertices take the values of the fine corners they stand behind.
constexpr int kBackOf[4] = {0, 2, 6, 8};

TransitionGeometry makeGeometry() {
    TransitionGeometry g;
    for (int v = 0; v < 3; ++v)
        for (int u = 0; u < 3; ++u) g.position[static_cast<size_t>(u + 3 * v)] = {u / 2.0, v / 2.0, 0.0};
    for (int i = 0; i < 4; ++i) {
        auto p = g.position[static_cast<size_t>(kBackOf[i])];
        g.position[static_cast<size_t>(9 + i)] = {p[0], p[1], 1.0};
    }
    g.faces = {
        {0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7},  // fine side (w = 0)
        {9, 10, 12, 11},                                         // back (w = 1)
        {0, 1, 2, 10, 9}, {2, 5, 8, 12, 10}, {8, 7, 6, 11, 12}, {6, 3, 0, 9, 11},  // sides
    };
    // Orient every face counter-clockwise seen from outside: its Newell
    // normal must point away from the cell's centre.
    const double centre[3] = {0.5, 0.5, 0.5};
    for (auto& f : g.faces) {
        double n[3] = {0, 0, 0}, c[3] = {0, 0, 0};
        for (size_t i = 0; i < f.size(); ++i) {
            const auto& p = g.position[static_cast<size_t>(f[i])];
            const auto& q = g.position[static_cast<size_t>(f[(i + 1) % f.size()])];
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
            for (int a = 0; a < 3; ++a) c[a] += p[static_cast<size_t>(a)] / static_cast<double>(f.size());
        }
        double dot = 0;
        for (int a = 0; a < 3; ++a) dot += n[a] * (c[a] - centre[a]);
        if (dot < 0) std::reverse(f.begin(), f.end());
    }
    for (const auto& f : g.faces)
        for (size_t i = 0; i < f.size(); ++i) {
            int a = std::min(f[i], f[(i + 1) % f.size()]), b = std::max(f[i], f[(i + 1) % f.size()]);
            if (g.edgeIndex(a, b) < 0) g.edges.push_back({a, b});
        }
    return g;
}

// Bit f set when edge e (into g.edges) lies on face f of the cell.
std::vector<unsigned> facesOfEdges(const TransitionGeometry& g) {
    std::vector<unsigned> faces(g.edges.size(), 0u);
    for (std::size_t f = 0; f < g.faces.size(); ++f) {
        const auto& face = g.faces[f];
        for (std::size_t i = 0; i < face.size(); ++i)
            faces[static_cast<std::size_t>(g.edgeIndex(face[i], face[(i + 1) % face.size()]))] |= 1u << f;
    }
    return faces;
}

TransitionCase triangulate(int c) {
    const TransitionGeometry& g = transitionGeometry();
    static const std::vector<unsigned> faceBits = facesOfEdges(g);
    std::vector<int> next(g.edges.size(), -1), prevCount(g.edges.size(), 0);
    for (const auto& f : g.faces) {
        const int n = static_cast<int>(f.size());
        for (int k = 0; k < n; ++k) {
            int prev = f[static_cast<size_t>((k + n - 1) % n)], cur = f[static_cast<size_t>(k)];
            if (!transitionInside(c, cur) || transitionInside(c, prev)) continue;  // a run starts at cur
            int end = k;
            while (transitionInside(c, f[static_cast<size_t>((end + 1) % n)])) end = (end + 1) % n;
            int enter = g.edgeIndex(prev, cur);
            int leave = g.edgeIndex(f[static_cast<size_t>(end)], f[static_cast<size_t>((end + 1) % n)]);
            if (next[static_cast<size_t>(leave)] >= 0) throw std::logic_error("transition table: a crossing leads twice");
            next[static_cast<size_t>(leave)] = enter;
            ++prevCount[static_cast<size_t>(enter)];
        }
    }
    TransitionCase tc;
    std::vector<bool> used(g.edges.size(), false);
    for (size_t start = 0; start < g.edges.size(); ++start) {
        if (next[start] < 0 || used[start]) continue;
        std::vector<int> loop;
        for (int e = static_cast<int>(start); !used[static_cast<size_t>(e)]; e = next[static_cast<size_t>(e)]) {
            if (next[static_cast<size_t>(e)] < 0 || prevCount[static_cast<size_t>(e)] != 1)
                throw std::logic_error("transition table: an open loop");
            used[static_cast<size_t>(e)] = true;
            loop.push_back(e);
        }
        // Reversed fan (outward-facing), from a crossing whose chords lie on
        // none of the cell's faces, as in the cell table (loop_fan.h). Across
        // the fine quads and the back quad lie regular cells, which draw no
        // chord on a face, so one here would still be used only twice; the
        // shared rule keeps that from resting on the neighbour's table.
        auto shareFace = [](int a, int b) {
            return (faceBits[static_cast<size_t>(a)] & faceBits[static_cast<size_t>(b)]) != 0;
        };
        const size_t s = fanStartOffFaces(loop, shareFace), n = loop.size();
        for (size_t i = 1; i + 1 < n; ++i) {
            size_t t = tc.triangleCount++;
            tc.edges[3 * t] = static_cast<std::uint8_t>(loop[s]);
            tc.edges[3 * t + 1] = static_cast<std::uint8_t>(loop[(s + i + 1) % n]);
            tc.edges[3 * t + 2] = static_cast<std::uint8_t>(loop[(s + i) % n]);
        }
    }
    return tc;
}

}  // namespace

int TransitionGeometry::edgeIndex(int a, int b) const {
    if (a > b) std::swap(a, b);
    for (size_t i = 0; i < edges.size(); ++i)
        if (edges[i][0] == a && edges[i][1] == b) return static_cast<int>(i);
    return -1;
}

bool transitionInside(int c, int v) { return (c >> (v < 9 ? v : kBackOf[v - 9])) & 1; }

const TransitionGeometry& transitionGeometry() {
    static const TransitionGeometry g = makeGeometry();
    return g;
}

const std::array<TransitionCase, 512>& transitionTable() {
    static const std::array<TransitionCase, 512> table = [] {
        std::array<TransitionCase, 512> t{};
        for (int c = 0; c < 512; ++c) t[static_cast<size_t>(c)] = triangulate(c);
        return t;
    }();
    return table;
}

}  // namespace hg::poly
