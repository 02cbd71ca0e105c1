#include "garden/sketch/inflation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace hg::garden::sketch {

namespace {

struct Node {
    Vec2 p;
    double r;
};

Node lerp(const Node& a, const Node& b, double t) { return {a.p + t * (b.p - a.p), a.r + t * (b.r - a.r)}; }

// The piece's value at a plane point: r(t) - distance to q(t).
double pieceValue(const ConePiece& c, const Vec2& p) {
    const Vec2 d = c.b - c.a;
    const double l2 = dot2(d, d);
    const double t = l2 > 0.0 ? std::clamp(dot2(p - c.a, d) / l2, 0.0, 1.0) : 0.0;
    return c.ra + t * (c.rb - c.ra) - distance2(p, c.a + t * d);
}

// The axis as chains of nodes between branch points and ends (the chordal
// axis of a simple polygon is a tree).
std::vector<std::vector<int>> axisChains(const ChordalAxis& axis) {
    const size_t n = axis.nodes.size();
    std::vector<std::vector<int>> adj(n);
    for (const auto& e : axis.edges) {
        adj[static_cast<size_t>(e[0])].push_back(e[1]);
        adj[static_cast<size_t>(e[1])].push_back(e[0]);
    }
    std::vector<std::vector<int>> chains;
    std::vector<std::vector<char>> walked(n);
    for (size_t i = 0; i < n; ++i) walked[i].assign(adj[i].size(), 0);
    auto markWalked = [&](int from, int to) {
        auto& a = adj[static_cast<size_t>(from)];
        for (size_t k = 0; k < a.size(); ++k)
            if (a[k] == to) walked[static_cast<size_t>(from)][k] = 1;
    };
    for (size_t s = 0; s < n; ++s) {
        if (adj[s].size() == 2) continue;
        for (size_t k = 0; k < adj[s].size(); ++k) {
            if (walked[s][k]) continue;
            std::vector<int> chain{static_cast<int>(s)};
            int prev = static_cast<int>(s), cur = adj[s][k];
            markWalked(prev, cur);
            markWalked(cur, prev);
            chain.push_back(cur);
            while (adj[static_cast<size_t>(cur)].size() == 2) {
                const auto& a = adj[static_cast<size_t>(cur)];
                const int next = a[0] == prev ? a[1] : a[0];
                markWalked(cur, next);
                markWalked(next, cur);
                prev = cur;
                cur = next;
                chain.push_back(cur);
            }
            chains.push_back(std::move(chain));
        }
    }
    return chains;
}

// Douglas-Peucker on the chain's balls, interpolated by arc length: node k
// is kept when its ball sticks out of the interpolated ball by more than
// `shortTol` (the silhouette would lose it; a ball the interpolation
// swallows costs nothing) or the interpolated ball there pokes out of the
// outline by more than `overTol`.
void simplifyChain(const std::vector<Vec2>& poly, const std::vector<Node>& c, size_t lo, size_t hi,
                   const std::vector<double>& arc, double shortTol, double overTol, std::vector<char>& keep) {
    if (hi <= lo + 1) return;
    size_t worst = lo;
    double worstExcess = 0.0;
    const double span = arc[hi] - arc[lo];
    for (size_t k = lo + 1; k < hi; ++k) {
        const double t = span > 0.0 ? (arc[k] - arc[lo]) / span : 0.5;
        const Node m = lerp(c[lo], c[hi], t);
        double excess = distance2(m.p, c[k].p) + c[k].r - m.r - shortTol;
        if (excess <= worstExcess) excess = std::max(excess, m.r - boundaryDistance(m.p, poly) - overTol);
        if (excess > worstExcess) { worstExcess = excess; worst = k; }
    }
    if (worst == lo) return;
    keep[worst] = 1;
    simplifyChain(poly, c, lo, worst, arc, shortTol, overTol, keep);
    simplifyChain(poly, c, worst, hi, arc, shortTol, overTol, keep);
}

// A segment whose interpolated radius strays from the true distance to the
// outline inside it by more than `tol` is split there: too large (a
// concave bend between two nodes) would poke out of the outline; too small
// (the distance is not linear along the axis, near junctions above all)
// would leave a dent in the silhouette.
void addSegment(const std::vector<Vec2>& poly, const Node& a, const Node& b, double tol, int depth,
                std::vector<ConePiece>& out) {
    if (depth < 8 && distance2(a.p, b.p) > tol) {
        double worst = 0.0, worstT = 0.5;
        for (double t : {0.25, 0.5, 0.75}) {
            const Node m = lerp(a, b, t);
            const double off = std::fabs(m.r - boundaryDistance(m.p, poly));
            if (off > worst) { worst = off; worstT = t; }
        }
        if (worst > tol) {
            Node m = lerp(a, b, worstT);
            m.r = boundaryDistance(m.p, poly);
            addSegment(poly, a, m, tol, depth + 1, out);
            addSegment(poly, m, b, tol, depth + 1, out);
            return;
        }
    }
    out.push_back({a.p, b.p, a.r, b.r, false});
}

// Whether the segment from p to outline vertex v stays inside the outline
// (crosses no outline edge other than those at v).
bool reachesVertex(const std::vector<Vec2>& poly, const Vec2& p, size_t v) {
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        if (i == v || j == v) continue;
        double s, t;
        if (segmentsCross(p, poly[v], poly[i], poly[j], s, t)) return false;
    }
    return true;
}

// Spokes to the outline vertices the pieces leave farther out than `tol`,
// worst first; each spoke updates the coverage of the rest.
int addSpokes(const std::vector<Vec2>& poly, const ChordalAxis& axis, double tol,
              double simplifyTol, double overshootTol, std::vector<ConePiece>& pieces) {
    const size_t n = poly.size();
    std::vector<double> cover(n, -1e300);
    for (size_t i = 0; i < n; ++i)
        for (const ConePiece& c : pieces) cover[i] = std::max(cover[i], pieceValue(c, poly[i]));
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cover[a] < cover[b]; });
    int spokes = 0;
    std::vector<int> byGap(axis.nodes.size());
    for (size_t v : order) {
        if (cover[v] >= -tol) continue;
        // From the axis node that leaves the vertex least uncovered (for a
        // corner, the node whose ball touches both its sides: the spoke is
        // then the medial axis into the corner) and that sees the vertex.
        int best = -1;
        for (size_t k = 0; k < byGap.size(); ++k) byGap[k] = static_cast<int>(k);
        std::sort(byGap.begin(), byGap.end(), [&](int x, int y) {
            const AxisNode& p = axis.nodes[static_cast<size_t>(x)];
            const AxisNode& q = axis.nodes[static_cast<size_t>(y)];
            return distance2(p.p, poly[v]) - p.radius < distance2(q.p, poly[v]) - q.radius;
        });
        for (size_t k = 0; k < byGap.size() && k < 8 && best < 0; ++k)
            if (reachesVertex(poly, axis.nodes[static_cast<size_t>(byGap[k])].p, v)) best = byGap[k];
        if (best < 0) continue;
        // The spoke's balls follow the distance to the outline along it
        // (as the medial axis does into a corner, linearly to 0 at its tip),
        // simplified and checked as the axis' chains are.
        const AxisNode& a = axis.nodes[static_cast<size_t>(best)];
        const int steps = 8;
        std::vector<Node> chain;
        std::vector<double> arc;
        for (int k = 0; k <= steps; ++k) {
            const Vec2 p = a.p + (poly[v] - a.p) * (static_cast<double>(k) / steps);
            chain.push_back({p, k == 0 ? a.radius : k == steps ? 0.0 : boundaryDistance(p, poly)});
            arc.push_back(distance2(a.p, p));
        }
        std::vector<char> keep(chain.size(), 0);
        keep.front() = keep.back() = 1;
        simplifyChain(poly, chain, 0, chain.size() - 1, arc, simplifyTol, overshootTol, keep);
        const size_t first = pieces.size();
        size_t last = 0;
        for (size_t k = 1; k < chain.size(); ++k) {
            if (!keep[k]) continue;
            addSegment(poly, chain[last], chain[k], overshootTol, 0, pieces);
            last = k;
        }
        ++spokes;
        for (size_t c = first; c < pieces.size(); ++c) {
            pieces[c].spoke = true;
            for (size_t i = 0; i < n; ++i) cover[i] = std::max(cover[i], pieceValue(pieces[c], poly[i]));
        }
    }
    return spokes;
}

void computeBounds(InflatedSolid& s) {
    s.lo = Vec3(1e300);
    s.hi = Vec3(-1e300);
    const SketchPlane& pl = s.plane;
    // An end ball of radius r, squashed to r * thickness along the normal,
    // is an ellipsoid; its box half-extent along axis i is
    // r sqrt(u_i^2 + v_i^2 + (k n_i)^2).
    Vec3 extent;
    for (int i = 0; i < 3; ++i) {
        const double kn = s.thickness * pl.normal[i];
        extent[i] = std::sqrt(pl.u[i] * pl.u[i] + pl.v[i] * pl.v[i] + kn * kn);
    }
    for (const ConePiece& c : s.pieces)
        for (int e = 0; e < 2; ++e) {
            const Vec3 centre = pl.toWorld(e == 0 ? c.a : c.b);
            const double r = e == 0 ? c.ra : c.rb;
            s.lo = glm::min(s.lo, centre - r * extent);
            s.hi = glm::max(s.hi, centre + r * extent);
        }
}

}  // namespace

std::string SketchPlane::check() const {
    const double tol = 1e-6;
    if (std::fabs(glm::length(u) - 1.0) > tol || std::fabs(glm::length(v) - 1.0) > tol ||
        std::fabs(glm::length(normal) - 1.0) > tol)
        return "the sketch plane's axes must be unit vectors";
    if (std::fabs(glm::dot(u, v)) > tol || std::fabs(glm::dot(u, normal)) > tol || std::fabs(glm::dot(v, normal)) > tol)
        return "the sketch plane's axes must be orthogonal";
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(origin[i])) return "the sketch plane's origin is not finite";
    return "";
}

SketchPlane planeFacing(const Vec3& origin, const Vec3& normal) {
    SketchPlane p;
    p.origin = origin;
    p.normal = glm::normalize(normal);
    // The world axis least aligned with the normal seeds u.
    const Vec3 a = std::fabs(p.normal.x) < 0.6 ? Vec3(1, 0, 0) : std::fabs(p.normal.y) < 0.6 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    p.u = glm::normalize(a - glm::dot(a, p.normal) * p.normal);
    p.v = glm::cross(p.normal, p.u);
    return p;
}

double silhouetteValue(const std::vector<ConePiece>& pieces, const Vec2& p) {
    double best = -1e300;
    for (const ConePiece& c : pieces) best = std::max(best, pieceValue(c, p));
    return best;
}

Inflation inflate(const std::vector<Vec2>& polygon, double spacing, const SketchPlane& plane,
                  const InflationOptions& options) {
    Inflation out;
    out.error = plane.check();
    if (!out.error.empty()) return out;
    if (!(options.thickness > 0.0)) {
        out.error = "the thickness must be positive";
        return out;
    }
    if (!(spacing > 0.0)) spacing = perimeter(polygon) / static_cast<double>(std::max<size_t>(polygon.size(), 1));
    out.triangulation = triangulatePolygon(polygon);
    if (!out.triangulation.ok()) {
        out.error = out.triangulation.error;
        return out;
    }
    out.axis = chordalAxis(polygon, out.triangulation, options.axis);
    if (!out.axis.ok()) {
        out.error = out.axis.error;
        return out;
    }
    InflatedSolid& s = out.solid;
    s.plane = plane;
    s.thickness = options.thickness;
    const double overshoot = options.overshootTolerance * spacing;
    if (out.axis.edges.empty()) {
        // One node: a circle's sphere (or a shape pruned whole).
        const AxisNode& a = out.axis.nodes.front();
        s.pieces.push_back({a.p, a.p, a.radius, a.radius, false});
    }
    for (const std::vector<int>& chain : axisChains(out.axis)) {
        std::vector<Node> c;
        std::vector<double> arc;
        for (int i : chain) {
            const AxisNode& a = out.axis.nodes[static_cast<size_t>(i)];
            arc.push_back(c.empty() ? 0.0 : arc.back() + distance2(c.back().p, a.p));
            c.push_back({a.p, a.radius});
        }
        // Consecutive chords of a sleeve lean alternately left and right, so
        // their midpoints zigzag about the true axis; two (1 2 1)/4 passes
        // straighten it (ends fixed), and each moved node takes its own
        // distance to the outline again.
        for (int pass = 0; pass < 2 && c.size() > 2; ++pass) {
            std::vector<Node> smooth = c;
            for (size_t k = 1; k + 1 < c.size(); ++k) {
                smooth[k].p = 0.25 * c[k - 1].p + 0.5 * c[k].p + 0.25 * c[k + 1].p;
                smooth[k].r = boundaryDistance(smooth[k].p, polygon);
            }
            c.swap(smooth);
        }
        for (size_t k = 1; k < c.size(); ++k) arc[k] = arc[k - 1] + distance2(c[k - 1].p, c[k].p);
        std::vector<char> keep(c.size(), 0);
        keep.front() = keep.back() = 1;
        simplifyChain(polygon, c, 0, c.size() - 1, arc, options.simplifyTolerance * spacing, overshoot, keep);
        size_t last = 0;
        for (size_t k = 1; k < c.size(); ++k) {
            if (!keep[k]) continue;
            if (distance2(c[last].p, c[k].p) > 0.0) addSegment(polygon, c[last], c[k], overshoot, 0, s.pieces);
            last = k;
        }
    }
    if (s.pieces.empty()) {
        out.error = "the chordal axis has no extent";
        return out;
    }
    out.spokes = addSpokes(polygon, out.axis, options.coverTolerance * spacing,
                           options.simplifyTolerance * spacing, overshoot, s.pieces);
    computeBounds(s);
    return out;
}

}  // namespace hg::garden::sketch
