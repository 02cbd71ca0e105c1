#include "garden/sketch/chordal_axis.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hg::garden::sketch {

namespace {

constexpr int kNone = -1;
constexpr int kSuppressed = -2;  // an edge a pruned region's fan took over at a junction

// From `start` (inside), a pattern search up the distance to the outline
// to the centre of the largest inscribed circle: where a shape folds into
// one node, a circle's sphere is then centred, not off by wherever the
// triangulation's chords happen to lie.
Vec2 inscribedCentre(Vec2 best, const std::vector<Vec2>& poly) {
    double bestD = boundaryDistance(best, poly);
    double step = 0.25 * bestD;
    while (step > 1e-4 * bestD) {
        bool moved = false;
        for (int k = 0; k < 8; ++k) {
            const double a = k * 0.7853981633974483;
            const Vec2 c = best + step * Vec2(std::cos(a), std::sin(a));
            const double d = boundaryDistance(c, poly);
            if (d > bestD && insidePolygon(c, poly)) {
                bestD = d;
                best = c;
                moved = true;
            }
        }
        if (!moved) step *= 0.5;
    }
    return best;
}

struct Builder {
    const std::vector<Vec2>& poly;
    const Triangulation& t;
    const AxisOptions& options;
    ChordalAxis axis;
    std::vector<std::array<int, 3>> edgeNode;  // per triangle corner: the node at the opposite edge's midpoint

    Builder(const std::vector<Vec2>& p, const Triangulation& tri, const AxisOptions& o)
        : poly(p), t(tri), options(o), edgeNode(tri.triangles.size(), {kNone, kNone, kNone}) {}

    const Vec2& P(int v) const { return poly[static_cast<size_t>(v)]; }
    const std::array<int, 3>& tri(int ti) const { return t.triangles[static_cast<size_t>(ti)]; }
    int nb(int ti, int k) const { return t.neighbours[static_cast<size_t>(ti)][static_cast<size_t>(k)]; }
    TriangleKind kind(int ti) const { return axis.kinds[static_cast<size_t>(ti)]; }

    int addNode(const Vec2& p) {
        axis.nodes.push_back({p, 0.0});
        return static_cast<int>(axis.nodes.size()) - 1;
    }
    // The corner of t2 opposite the edge it shares with ti.
    int mirrorCorner(int t2, int ti) const {
        for (int k = 0; k < 3; ++k)
            if (nb(t2, k) == ti) return k;
        return kNone;
    }
    void setEdgeNode(int ti, int k, int node) {
        edgeNode[static_cast<size_t>(ti)][static_cast<size_t>(k)] = node;
        const int t2 = nb(ti, k);
        if (t2 >= 0) edgeNode[static_cast<size_t>(t2)][static_cast<size_t>(mirrorCorner(t2, ti))] = node;
    }
    Vec2 edgeMidpoint(int ti, int k) const {
        return 0.5 * (P(tri(ti)[static_cast<size_t>((k + 1) % 3)]) + P(tri(ti)[static_cast<size_t>((k + 2) % 3)]));
    }
    Vec2 centroid(int ti) const { return (P(tri(ti)[0]) + P(tri(ti)[1]) + P(tri(ti)[2])) / 3.0; }

    void classify() {
        for (size_t ti = 0; ti < t.triangles.size(); ++ti) {
            int outline = 0;
            for (int k = 0; k < 3; ++k) outline += t.neighbours[ti][static_cast<size_t>(k)] < 0;
            axis.kinds.push_back(outline == 0 ? TriangleKind::Junction
                                 : outline == 1 ? TriangleKind::Sleeve
                                 : outline == 2 ? TriangleKind::Terminal
                                                : TriangleKind::Whole);
        }
        axis.pruned.assign(t.triangles.size(), 0);
        axis.triangleNodes.assign(t.triangles.size(), {kNone, kNone});
    }

    // Whether every vertex of the region lies in the circle on the chord.
    bool semicircleHolds(const std::vector<int>& region, const Vec2& m, double radius) const {
        const double limit = radius * (1.0 + options.pruneSlack);
        for (int ti : region)
            for (int v : tri(ti))
                if (distance2(P(v), m) > limit) return false;
        return true;
    }

    void markRegion(const std::vector<int>& region, int apex) {
        for (int ti : region) {
            axis.pruned[static_cast<size_t>(ti)] = 1;
            axis.triangleNodes[static_cast<size_t>(ti)] = {apex, kNone};
        }
        ++axis.prunedRegions;
    }

    // The point of the region farthest from the outline among its chords'
    // midpoints and triangles' centroids: the centre of a shape pruned whole.
    int wholeShapeNode(const std::vector<int>& region) {
        Vec2 best = centroid(region.front());
        double bestD = -1.0;
        for (int ti : region)
            for (int k = 0; k < 4; ++k) {
                const Vec2 c = k == 3 ? centroid(ti) : edgeMidpoint(ti, k);
                const double d = boundaryDistance(c, poly);
                if (d > bestD) { bestD = d; best = c; }
            }
        return addNode(inscribedCentre(best, poly));
    }

    // A pruned region growing across its chord, the edge opposite corner
    // `ck` of triangle `cur`.
    struct Front {
        std::vector<int> region;
        int cur;
        int ck;
    };
    // Per junction: the regions that reached it, with the junction's corner
    // opposite the edge each came across.
    std::vector<std::vector<std::pair<std::vector<int>, int>>> arrivals;
    std::vector<int> pendingJunctions;

    int nodeAtChord(int cur, int ck) {
        const int node = addNode(edgeMidpoint(cur, ck));
        setEdgeNode(cur, ck, node);
        return node;
    }

    void claim(const std::vector<int>& region) {
        for (int ti : region) axis.pruned[static_cast<size_t>(ti)] = 1;
    }

    void grow(Front f) {
        claim(f.region);
        for (;;) {
            const Vec2 m = edgeMidpoint(f.cur, f.ck);
            const double radius = 0.5 * distance2(P(tri(f.cur)[static_cast<size_t>((f.ck + 1) % 3)]),
                                                  P(tri(f.cur)[static_cast<size_t>((f.ck + 2) % 3)]));
            const int next = nb(f.cur, f.ck);
            if (!semicircleHolds(f.region, m, radius)) {
                markRegion(f.region, nodeAtChord(f.cur, f.ck));
                return;
            }
            if (axis.pruned[static_cast<size_t>(next)]) {
                // Another region ended at this chord: both fan from its midpoint.
                const int e = edgeNode[static_cast<size_t>(f.cur)][static_cast<size_t>(f.ck)];
                markRegion(f.region, e >= 0 ? e : nodeAtChord(f.cur, f.ck));
                return;
            }
            if (kind(next) == TriangleKind::Junction) {
                auto& at = arrivals[static_cast<size_t>(next)];
                at.push_back({std::move(f.region), mirrorCorner(next, f.cur)});
                if (at.size() >= 2) pendingJunctions.push_back(next);
                return;
            }
            f.region.push_back(next);
            axis.pruned[static_cast<size_t>(next)] = 1;
            if (kind(next) != TriangleKind::Sleeve) {
                // The other terminal: the whole outline folds into one node.
                markRegion(f.region, wholeShapeNode(f.region));
                return;
            }
            const int back = mirrorCorner(next, f.cur);
            int forward = kNone;
            for (int k = 0; k < 3; ++k)
                if (k != back && nb(next, k) >= 0) forward = k;
            f.cur = next;
            f.ck = forward;
        }
    }

    // A junction two pruned regions reached becomes part of one region
    // with them, which goes on growing across the junction's third edge
    // (Teddy stops at every junction; going on is what folds a round blob,
    // whose Delaunay triangulation has junctions anywhere, into one centre).
    // Three regions: the whole outline, one node.
    void mergeAt(int j) {
        if (axis.pruned[static_cast<size_t>(j)]) return;
        auto& at = arrivals[static_cast<size_t>(j)];
        std::vector<int> region{j};
        bool came[3] = {false, false, false};
        for (auto& [r, corner] : at) {
            region.insert(region.end(), r.begin(), r.end());
            came[corner] = true;
        }
        at.clear();
        if (came[0] && came[1] && came[2]) {
            claim(region);
            markRegion(region, wholeShapeNode(region));
            return;
        }
        int third = 0;
        while (came[third]) ++third;
        grow(Front{std::move(region), j, third});
    }

    std::vector<int> junctionNodes;
    int junctionNode(int ti) {
        int& node = junctionNodes[static_cast<size_t>(ti)];
        if (node == kNone) node = addNode(centroid(ti));
        return node;
    }

    void build() {
        classify();
        const int count = static_cast<int>(t.triangles.size());
        junctionNodes.assign(t.triangles.size(), kNone);
        if (count == 1) {
            const int node = addNode(centroid(0));
            axis.triangleNodes[0] = {node, kNone};
            axis.pruned[0] = 1;
        }
        arrivals.resize(t.triangles.size());
        for (int ti = 0; ti < count; ++ti) {
            if (kind(ti) != TriangleKind::Terminal || axis.pruned[static_cast<size_t>(ti)]) continue;
            int ck = kNone;
            for (int k = 0; k < 3; ++k)
                if (nb(ti, k) >= 0) ck = k;
            grow(Front{{ti}, ti, ck});
        }
        while (!pendingJunctions.empty()) {
            const int j = pendingJunctions.back();
            pendingJunctions.pop_back();
            mergeAt(j);
        }
        // A junction one region reached: the region fans from its centroid,
        // which stays on the axis between the other two branches.
        for (int ti = 0; ti < count; ++ti)
            for (auto& [r, corner] : arrivals[static_cast<size_t>(ti)]) {
                setEdgeNode(ti, corner, kSuppressed);
                markRegion(r, junctionNode(ti));
            }
        // Midpoints of the interior edges between triangles left standing.
        for (int ti = 0; ti < count; ++ti) {
            if (axis.pruned[static_cast<size_t>(ti)]) continue;
            for (int k = 0; k < 3; ++k) {
                const int t2 = nb(ti, k);
                if (t2 < 0 || edgeNode[static_cast<size_t>(ti)][static_cast<size_t>(k)] != kNone) continue;
                setEdgeNode(ti, k, addNode(edgeMidpoint(ti, k)));
            }
        }
        for (int ti = 0; ti < count; ++ti) {
            if (axis.pruned[static_cast<size_t>(ti)]) continue;
            std::vector<int> ends;
            for (int k = 0; k < 3; ++k) {
                const int e = edgeNode[static_cast<size_t>(ti)][static_cast<size_t>(k)];
                if (nb(ti, k) >= 0 && e >= 0) ends.push_back(e);
            }
            if (kind(ti) == TriangleKind::Junction) {
                const int c = junctionNode(ti);
                for (int e : ends) axis.edges.push_back({c, e});
                axis.triangleNodes[static_cast<size_t>(ti)] = {c, kNone};
            } else if (ends.size() == 2) {
                axis.edges.push_back({ends[0], ends[1]});
                axis.triangleNodes[static_cast<size_t>(ti)] = {ends[0], ends[1]};
            }
        }
        // Everything pruned into one node (regions that met at a chord):
        // centre it as a whole shape's node is.
        if (axis.edges.empty() && axis.nodes.size() == 1) axis.nodes[0].p = inscribedCentre(axis.nodes[0].p, poly);
        for (AxisNode& n : axis.nodes) n.radius = boundaryDistance(n.p, poly);
        if (axis.nodes.empty()) axis.error = "the triangulation gave no chordal axis";
    }
};

}  // namespace

ChordalAxis chordalAxis(const std::vector<Vec2>& polygon, const Triangulation& t, const AxisOptions& options) {
    if (!t.ok() || t.triangles.empty()) {
        ChordalAxis a;
        a.error = t.ok() ? "no triangles" : t.error;
        return a;
    }
    Builder b(polygon, t, options);
    b.build();
    return std::move(b.axis);
}

}  // namespace hg::garden::sketch
