// The generated transition cell table: every case uses exactly its crossing
// edges and closes into loops on the cell's faces, and on each face it
// shares with a regular cell (the four fine quads, the back quad) it makes
// the same segments as the regular cell table, so seams between levels
// cannot crack.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "polygonizer/cell_table.h"
#include "polygonizer/realtime/transition_table.h"

namespace hg::poly {
namespace {

using Pair = std::pair<int, int>;

Pair sorted(int a, int b) { return a < b ? Pair{a, b} : Pair{b, a}; }

// Pairs of crossings used by exactly one triangle: the loops on the faces.
template <class Case>
std::set<Pair> loopSegments(const Case& c) {
    std::map<Pair, int> uses;
    for (int t = 0; t < c.triangleCount; ++t)
        for (int k = 0; k < 3; ++k)
            ++uses[sorted(c.edges[static_cast<size_t>(3 * t + k)], c.edges[static_cast<size_t>(3 * t + (k + 1) % 3)])];
    std::set<Pair> out;
    for (const auto& [p, n] : uses) {
        EXPECT_LE(n, 2);
        if (n == 1) out.insert(p);
    }
    return out;
}

TEST(TransitionTable, EveryCaseClosesOnTheCellFacesWithExactlyItsCrossings) {
    const auto& g = transitionGeometry();
    const auto& table = transitionTable();
    EXPECT_EQ(table[0].triangleCount, 0);
    EXPECT_EQ(table[511].triangleCount, 0);
    for (int c = 1; c < 511; ++c) {
        SCOPED_TRACE(c);
        const TransitionCase& tc = table[static_cast<size_t>(c)];
        std::set<int> used, crossing;
        for (int t = 0; t < 3 * tc.triangleCount; ++t) used.insert(tc.edges[static_cast<size_t>(t)]);
        for (size_t e = 0; e < g.edges.size(); ++e)
            if (transitionInside(c, g.edges[e][0]) != transitionInside(c, g.edges[e][1])) crossing.insert(static_cast<int>(e));
        ASSERT_EQ(used, crossing);
        for (const Pair& s : loopSegments(tc)) {
            bool onOneFace = false;
            for (const auto& f : g.faces) {
                auto onFace = [&](int e) {
                    int a = g.edges[static_cast<size_t>(e)][0], b = g.edges[static_cast<size_t>(e)][1];
                    for (size_t i = 0; i < f.size(); ++i)
                        if (sorted(f[i], f[(i + 1) % f.size()]) == Pair{a, b}) return true;
                    return false;
                };
                onOneFace = onOneFace || (onFace(s.first) && onFace(s.second));
            }
            ASSERT_TRUE(onOneFace) << "segment " << s.first << "-" << s.second << " is not on a face";
        }
    }
}

// A quad face's vertices at local (0|1, 0|1) corners.
std::array<std::array<int, 2>, 4> localCorners(const std::vector<int>& face) {
    const auto& g = transitionGeometry();
    double lo[2] = {1e9, 1e9};
    for (int v : face)
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], g.position[static_cast<size_t>(v)][static_cast<size_t>(a)]);
    std::array<std::array<int, 2>, 4> out{};
    for (size_t i = 0; i < 4; ++i)
        for (int a = 0; a < 2; ++a)
            out[i][static_cast<size_t>(a)] = g.position[static_cast<size_t>(face[i])][static_cast<size_t>(a)] > lo[a] + 1e-9;
    return out;
}

TEST(TransitionTable, SharedQuadFacesCutLikeRegularCells) {
    const auto& g = transitionGeometry();
    const auto& regular = cellTable();
    int checked = 0;
    std::size_t segments = 0;
    for (size_t fi = 0; fi < g.faces.size(); ++fi) {
        const auto& face = g.faces[fi];
        if (face.size() != 4) continue;  // the pentagons are shared with transition cells only
        const auto local = localCorners(face);
        // The regular cube face x = 0 with corner (0, y, z) at local (y, z).
        auto cubeCorner = [](const std::array<int, 2>& l) { return 2 * l[0] + 4 * l[1]; };
        for (int c = 0; c < 512; ++c) {
            int cube = 0;
            for (size_t i = 0; i < 4; ++i)
                if (transitionInside(c, face[i])) cube |= 1 << cubeCorner(local[i]);
            // Segments on this face, as pairs of local corner pairs.
            auto asLocal = [&](int a, int b) {
                std::array<int, 2> la{}, lb{};
                for (size_t i = 0; i < 4; ++i) {
                    if (face[i] == a) la = local[i];
                    if (face[i] == b) lb = local[i];
                }
                return sorted(cubeCorner(la), cubeCorner(lb));
            };
            std::set<std::pair<Pair, Pair>> ours, theirs;
            auto onThisFace = [&](int e) {
                int a = g.edges[static_cast<size_t>(e)][0], b = g.edges[static_cast<size_t>(e)][1];
                for (size_t i = 0; i < 4; ++i)
                    if (sorted(face[i], face[(i + 1) % 4]) == Pair{a, b}) return true;
                return false;
            };
            for (const Pair& s : loopSegments(transitionTable()[static_cast<size_t>(c)]))
                if (onThisFace(s.first) && onThisFace(s.second)) {
                    Pair p = asLocal(g.edges[static_cast<size_t>(s.first)][0], g.edges[static_cast<size_t>(s.first)][1]);
                    Pair q = asLocal(g.edges[static_cast<size_t>(s.second)][0], g.edges[static_cast<size_t>(s.second)][1]);
                    ours.insert(p < q ? std::pair{p, q} : std::pair{q, p});
                }
            for (const Pair& s : loopSegments(regular[static_cast<size_t>(cube)])) {
                auto ends = [](int e) {
                    const auto& ec = kEdgeCorners[static_cast<size_t>(e)];
                    return sorted(ec[0], ec[1]);
                };
                Pair p = ends(s.first), q = ends(s.second);
                bool xZero = !(p.first & 1) && !(p.second & 1) && !(q.first & 1) && !(q.second & 1);
                if (xZero) theirs.insert(p < q ? std::pair{p, q} : std::pair{q, p});
            }
            ASSERT_EQ(ours, theirs) << "face " << fi << ", case " << c;
            segments += ours.size();
            ++checked;
        }
    }
    EXPECT_EQ(checked, 5 * 512);
    EXPECT_GT(segments, 2000u) << "the comparison is not vacuous";
}

}  // namespace
}  // namespace hg::poly
