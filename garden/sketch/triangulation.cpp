#include "garden/sketch/triangulation.h"

#include <cmath>
#include <unordered_map>
#include <utility>

namespace hg::garden::sketch {

double inCircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const Vec2 p = a - d, q = b - d, r = c - d;
    const double pp = dot2(p, p), qq = dot2(q, q), rr = dot2(r, r);
    const double t1 = pp * cross(q, r), t2 = qq * cross(r, p), t3 = rr * cross(p, q);
    const double scale = std::fabs(t1) + std::fabs(t2) + std::fabs(t3);
    return scale > 0.0 ? (t1 + t2 + t3) / scale : 0.0;
}

namespace {

// Ear clipping over a ring of vertex indices. An ear is a convex corner
// whose triangle holds no reflex vertex; only the two neighbours of a
// clipped corner change, so each clip re-tests two corners and the whole
// runs in O(n r) for r reflex vertices.
class EarClipper {
public:
    explicit EarClipper(const std::vector<Vec2>& p) : p_(p), n_(static_cast<int>(p.size())), prev_(p.size()), next_(p.size()), ear_(p.size()) {
        for (int i = 0; i < n_; ++i) {
            prev_[static_cast<size_t>(i)] = (i + n_ - 1) % n_;
            next_[static_cast<size_t>(i)] = (i + 1) % n_;
        }
        for (int i = 0; i < n_; ++i) ear_[static_cast<size_t>(i)] = isEar(i);
    }

    std::vector<std::array<int, 3>> run() {
        std::vector<std::array<int, 3>> out;
        int left = n_, i = 0, sinceClip = 0;
        while (left > 3) {
            if (ear_[static_cast<size_t>(i)] || sinceClip > left) {
                // After a full turn without an ear (rounding on a nearly
                // degenerate outline) the most convex corner is clipped.
                if (!ear_[static_cast<size_t>(i)]) i = mostConvex(i);
                const int a = prev(i), c = next(i);
                out.push_back({a, i, c});
                next_[static_cast<size_t>(a)] = c;
                prev_[static_cast<size_t>(c)] = a;
                --left;
                ear_[static_cast<size_t>(a)] = isEar(a);
                ear_[static_cast<size_t>(c)] = isEar(c);
                i = c;
                sinceClip = 0;
            } else {
                i = next(i);
                ++sinceClip;
            }
        }
        out.push_back({prev(i), i, next(i)});
        return out;
    }

private:
    int prev(int i) const { return prev_[static_cast<size_t>(i)]; }
    int next(int i) const { return next_[static_cast<size_t>(i)]; }
    const Vec2& at(int i) const { return p_[static_cast<size_t>(i)]; }

    bool isEar(int i) const {
        const int a = prev(i), c = next(i);
        if (orient(at(a), at(i), at(c)) <= 0.0) return false;
        for (int v = next(c); v != a; v = next(v)) {
            if (orient(at(prev(v)), at(v), at(next(v))) > 0.0) continue;  // convex corners cannot be inside
            if (orient(at(a), at(i), at(v)) >= 0.0 && orient(at(i), at(c), at(v)) >= 0.0 &&
                orient(at(c), at(a), at(v)) >= 0.0)
                return false;
        }
        return true;
    }

    int mostConvex(int start) const {
        int best = start;
        double bestTurn = -1e300;
        int i = start;
        do {
            const Vec2 u = at(i) - at(prev(i)), w = at(next(i)) - at(i);
            const double turn = cross(u, w) / (length2(u) * length2(w) + 1e-300);
            if (turn > bestTurn) { bestTurn = turn; best = i; }
            i = next(i);
        } while (i != start);
        return best;
    }

    const std::vector<Vec2>& p_;
    int n_;
    std::vector<int> prev_, next_;
    std::vector<char> ear_;
};

void linkNeighbours(Triangulation& t) {
    std::unordered_map<long long, std::pair<int, int>> edges;  // (from, to) -> (triangle, opposite corner)
    const long long stride = 1LL << 32;
    t.neighbours.assign(t.triangles.size(), {-1, -1, -1});
    for (int ti = 0; ti < static_cast<int>(t.triangles.size()); ++ti) {
        const auto& tri = t.triangles[static_cast<size_t>(ti)];
        for (int k = 0; k < 3; ++k) {
            const int from = tri[static_cast<size_t>((k + 1) % 3)], to = tri[static_cast<size_t>((k + 2) % 3)];
            auto it = edges.find(static_cast<long long>(to) * stride + from);  // the same edge, other way round
            if (it != edges.end()) {
                t.neighbours[static_cast<size_t>(ti)][static_cast<size_t>(k)] = it->second.first;
                t.neighbours[static_cast<size_t>(it->second.first)][static_cast<size_t>(it->second.second)] = ti;
            } else {
                edges[static_cast<long long>(from) * stride + to] = {ti, k};
            }
        }
    }
}

int cornerOf(const std::array<int, 3>& tri, int v) {
    for (int k = 0; k < 3; ++k)
        if (tri[static_cast<size_t>(k)] == v) return k;
    return -1;
}

void replaceNeighbour(Triangulation& t, int tri, int from, int to) {
    if (tri < 0) return;
    for (int& nb : t.neighbours[static_cast<size_t>(tri)])
        if (nb == from) nb = to;
}

// Lawson's flips: an interior edge whose opposite vertex lies inside the
// other triangle's circumcircle is replaced by the other diagonal of their
// quadrilateral (which is then convex), and the quadrilateral's four outer
// edges are checked again.
void flipToDelaunay(Triangulation& t, const std::vector<Vec2>& p) {
    std::vector<std::pair<int, int>> stack;
    for (int ti = 0; ti < static_cast<int>(t.triangles.size()); ++ti)
        for (int k = 0; k < 3; ++k) stack.push_back({ti, k});
    const long long maxFlips = static_cast<long long>(p.size()) * static_cast<long long>(p.size()) + 100;
    auto P = [&](int v) -> const Vec2& { return p[static_cast<size_t>(v)]; };
    while (!stack.empty() && t.flips < maxFlips) {
        auto [ti, k] = stack.back();
        stack.pop_back();
        const int t2 = t.neighbours[static_cast<size_t>(ti)][static_cast<size_t>(k)];
        if (t2 < 0) continue;
        auto& A = t.triangles[static_cast<size_t>(ti)];
        const int a = A[static_cast<size_t>(k)], b = A[static_cast<size_t>((k + 1) % 3)], c = A[static_cast<size_t>((k + 2) % 3)];
        auto& B = t.triangles[static_cast<size_t>(t2)];
        const int k2 = (cornerOf(B, b) + 1) % 3;  // B = (d, c, b) from d
        const int d = B[static_cast<size_t>(k2)];
        if (inCircle(P(a), P(b), P(c), P(d)) <= kDelaunayTolerance) continue;
        if (orient(P(a), P(b), P(d)) <= 0.0 || orient(P(a), P(d), P(c)) <= 0.0) continue;
        const int nbBD = t.neighbours[static_cast<size_t>(t2)][static_cast<size_t>((k2 + 1) % 3)];  // across b-d
        const int nbDC = t.neighbours[static_cast<size_t>(t2)][static_cast<size_t>((k2 + 2) % 3)];  // across d-c
        const int nbCA = t.neighbours[static_cast<size_t>(ti)][static_cast<size_t>((k + 1) % 3)];   // across c-a
        const int nbAB = t.neighbours[static_cast<size_t>(ti)][static_cast<size_t>((k + 2) % 3)];   // across a-b
        t.triangles[static_cast<size_t>(ti)] = {a, b, d};
        t.neighbours[static_cast<size_t>(ti)] = {nbBD, t2, nbAB};
        t.triangles[static_cast<size_t>(t2)] = {a, d, c};
        t.neighbours[static_cast<size_t>(t2)] = {nbDC, nbCA, ti};
        replaceNeighbour(t, nbBD, t2, ti);
        replaceNeighbour(t, nbCA, ti, t2);
        ++t.flips;
        stack.push_back({ti, 0});
        stack.push_back({ti, 2});
        stack.push_back({t2, 0});
        stack.push_back({t2, 1});
    }
}

}  // namespace

Triangulation triangulatePolygon(const std::vector<Vec2>& polygon) {
    Triangulation t;
    if (polygon.size() < 3) {
        t.error = "a polygon needs at least 3 vertices";
        return t;
    }
    if (signedArea(polygon) <= 0.0) {
        t.error = "the polygon is not counter-clockwise";
        return t;
    }
    t.triangles = EarClipper(polygon).run();
    linkNeighbours(t);
    flipToDelaunay(t, polygon);
    return t;
}

}  // namespace hg::garden::sketch
