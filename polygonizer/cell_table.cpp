#include "polygonizer/cell_table.h"

#include <cstddef>
#include <vector>

#include "polygonizer/loop_fan.h"

namespace hg::poly {

namespace {

// Edges along x, then y, then z; each from its corner with the bit clear.
std::array<std::array<int, 2>, 12> makeEdges() {
    std::array<std::array<int, 2>, 12> edges{};
    std::size_t e = 0;
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 8; ++c)
            if (!(c & (1 << a))) edges[e++] = {c, c | (1 << a)};
    return edges;
}

int edgeBetween(int c0, int c1) {
    for (int e = 0; e < 12; ++e) {
        const auto& ec = kEdgeCorners[static_cast<std::size_t>(e)];
        if ((ec[0] == c0 && ec[1] == c1) || (ec[0] == c1 && ec[1] == c0)) return e;
    }
    return -1;
}

// Whether edges e0 and e1 lie on one face of the cube: all their corners
// agree on some axis.
bool shareFace(int e0, int e1) {
    const auto& a = kEdgeCorners[static_cast<std::size_t>(e0)];
    const auto& b = kEdgeCorners[static_cast<std::size_t>(e1)];
    const int same = ~(a[0] ^ a[1]) & ~(a[0] ^ b[0]) & ~(a[0] ^ b[1]) & 7;
    return same != 0;
}

// The six faces, corners in counter-clockwise order seen from outside the
// cube: the cross product of the first two edges points out of the cube.
std::vector<std::array<int, 4>> faces() {
    std::vector<std::array<int, 4>> out;
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            int u = (a + 1) % 3, v = (a + 2) % 3;
            int base = side << a;
            std::array<int, 4> f = {base, base | (1 << u), base | (1 << u) | (1 << v), base | (1 << v)};
            // (u, v, a) is right-handed, so this order faces +a; flip for the low side.
            if (side == 0) std::swap(f[1], f[3]);
            out.push_back(f);
        }
    return out;
}

CellCase triangulate(int mask) {
    auto inside = [mask](int c) { return (mask >> c) & 1; };
    // next[e]: the crossing the loop goes to after crossing e.
    int next[12];
    for (int& n : next) n = -1;
    for (const auto& f : faces()) {
        for (int k = 0; k < 4; ++k) {
            int prev = f[static_cast<std::size_t>((k + 3) % 4)], cur = f[static_cast<std::size_t>(k)];
            if (!inside(cur) || inside(prev)) continue;  // cur starts a run of inside corners
            int end = k;
            while (inside(f[static_cast<std::size_t>((end + 1) % 4)])) end = (end + 1) % 4;
            int enter = edgeBetween(prev, cur);
            int leave = edgeBetween(f[static_cast<std::size_t>(end)], f[static_cast<std::size_t>((end + 1) % 4)]);
            next[leave] = enter;  // inside on the left, seen from outside the cube
        }
    }
    CellCase cc;
    bool used[12] = {};
    for (int start = 0; start < 12; ++start) {
        if (next[start] < 0 || used[start]) continue;
        std::vector<int> loop;
        for (int e = start; !used[e]; e = next[e]) {
            used[e] = true;
            loop.push_back(e);
        }
        // The loop runs counter-clockwise around the inside region seen from
        // outside the cube, so its right-hand normal points into the solid:
        // fan it in reverse for outward-facing triangles. The fan starts
        // where none of its chords lies on a face of the cube: a chord there
        // can be the neighbour's chord too, an edge of four triangles
        // (loop_fan.h says when).
        const std::size_t s = fanStartOffFaces(loop, shareFace), n = loop.size();
        for (std::size_t i = 1; i + 1 < n; ++i) {
            std::size_t t = cc.triangleCount++;
            cc.edges[3 * t] = static_cast<std::uint8_t>(loop[s]);
            cc.edges[3 * t + 1] = static_cast<std::uint8_t>(loop[(s + i + 1) % n]);
            cc.edges[3 * t + 2] = static_cast<std::uint8_t>(loop[(s + i) % n]);
        }
    }
    return cc;
}

}  // namespace

const std::array<std::array<int, 2>, 12> kEdgeCorners = makeEdges();
const std::array<int, 12> kEdgeAxis = [] {
    std::array<int, 12> axis{};
    for (std::size_t e = 0; e < 12; ++e) {
        const int bit = kEdgeCorners[e][0] ^ kEdgeCorners[e][1];
        axis[e] = bit == 1 ? 0 : bit == 2 ? 1 : 2;
    }
    return axis;
}();

const std::array<CellCase, 256>& cellTable() {
    static const std::array<CellCase, 256> table = [] {
        std::array<CellCase, 256> t{};
        for (int m = 0; m < 256; ++m) t[static_cast<std::size_t>(m)] = triangulate(m);
        return t;
    }();
    return table;
}

}  // namespace hg::poly
