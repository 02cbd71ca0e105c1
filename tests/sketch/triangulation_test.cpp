// The constrained Delaunay triangulation of outlines and Teddy's chordal
// axis on it (issue 22, "Inflation").
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "garden/sketch/chordal_axis.h"
#include "garden/sketch/outline.h"
#include "garden/sketch/triangulation.h"
#include "tests/sketch/sketch_shapes.h"

namespace hg::garden::sketch {
namespace {

using namespace hg::test::sketch;

std::vector<Vec2> outlineOf(const std::vector<Vec2>& raw, int samples) {
    OutlineOptions o;
    o.samples = samples;
    const Outline out = makeOutline(raw, o);
    EXPECT_TRUE(out.ok()) << out.error;
    return out.points;
}

struct Case {
    const char* name;
    std::vector<Vec2> polygon;
};

std::vector<Case> cases() {
    return {{"circle", outlineOf(circlePath(0.3, 400, 0.002), 80)},
            {"oval", outlineOf(ellipsePath(0.5, 0.12, 600, 0.001), 120)},
            {"L", outlineOf(polygonPath(lCorners(), 400.0, 0.0005), 100)},
            {"star", outlineOf(polygonPath(starCorners(), 400.0, 0.0005), 150)},
            {"blob", outlineOf(drawn([](double s) {
                                         const double a = 2 * kPi * s;
                                         return (0.3 + 0.1 * std::sin(3 * a) + 0.05 * std::cos(5 * a)) *
                                                Vec2(std::cos(a), std::sin(a));
                                     },
                                     500, 0.001),
                               200)}};
}

double triangleArea(const std::vector<Vec2>& p, const std::array<int, 3>& t) {
    return 0.5 * orient(p[static_cast<size_t>(t[0])], p[static_cast<size_t>(t[1])], p[static_cast<size_t>(t[2])]);
}

TEST(SketchTriangulation, IsAValidConstrainedDelaunayTriangulation) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const auto& p = c.polygon;
        const size_t n = p.size();
        ASSERT_GE(n, 8u);
        const Triangulation t = triangulatePolygon(p);
        ASSERT_TRUE(t.ok()) << t.error;
        ASSERT_EQ(t.triangles.size(), n - 2);
        // The triangles tile the polygon: all positive, areas sum to its area,
        // each outline edge in exactly one triangle, each diagonal in two
        // (with opposite directions) and inside the polygon.
        double area = 0.0;
        std::map<std::pair<int, int>, int> edges;
        for (const auto& tri : t.triangles) {
            const double a = triangleArea(p, tri);
            EXPECT_GT(a, 0.0);
            area += a;
            for (int k = 0; k < 3; ++k) edges[{tri[static_cast<size_t>(k)], tri[static_cast<size_t>((k + 1) % 3)]}]++;
        }
        EXPECT_NEAR(area, signedArea(p), 1e-12 * signedArea(p) * static_cast<double>(n));
        for (size_t i = 0; i < n; ++i) EXPECT_EQ((edges[{static_cast<int>(i), static_cast<int>((i + 1) % n)}]), 1);
        for (const auto& [e, count] : edges) {
            EXPECT_EQ(count, 1);
            const bool outline = (e.second == (e.first + 1) % static_cast<int>(n));
            if (!outline) {
                EXPECT_EQ(edges.count({e.second, e.first}), 1u) << e.first << "-" << e.second;
                EXPECT_TRUE(insidePolygon(0.5 * (p[static_cast<size_t>(e.first)] + p[static_cast<size_t>(e.second)]), p));
            }
        }
        // Locally Delaunay across every interior edge; the neighbour table
        // agrees with the shared edges.
        for (size_t ti = 0; ti < t.triangles.size(); ++ti)
            for (int k = 0; k < 3; ++k) {
                const auto& tri = t.triangles[ti];
                const int a = tri[static_cast<size_t>(k)], b = tri[static_cast<size_t>((k + 1) % 3)],
                          c2 = tri[static_cast<size_t>((k + 2) % 3)];
                const int nb = t.neighbours[ti][static_cast<size_t>(k)];
                const bool outline = (c2 == (b + 1) % static_cast<int>(n));
                EXPECT_EQ(nb < 0, outline);
                if (nb < 0) continue;
                int d = -1;
                for (int v : t.triangles[static_cast<size_t>(nb)])
                    if (v != b && v != c2) d = v;
                EXPECT_LE(inCircle(p[static_cast<size_t>(a)], p[static_cast<size_t>(b)], p[static_cast<size_t>(c2)],
                                   p[static_cast<size_t>(d)]),
                          kDelaunayTolerance);
            }
    }
}

TEST(SketchTriangulation, FlipsAFanIntoDelaunay) {
    // A long thin rectangle with many points: ear clipping alone gives
    // slivers; the flips must have run.
    const auto p = outlineOf(polygonPath({{0, 0}, {1, 0}, {1, 0.1}, {0, 0.1}}, 500.0), 60);
    const Triangulation t = triangulatePolygon(p);
    ASSERT_TRUE(t.ok());
    EXPECT_GT(t.flips, 0);
}

TEST(SketchTriangulation, RefusesClockwise) {
    EXPECT_FALSE(triangulatePolygon({{0, 0}, {0, 1}, {1, 1}, {1, 0}}).ok());
    EXPECT_FALSE(triangulatePolygon({{0, 0}, {1, 0}}).ok());
}

TEST(SketchChordalAxis, ClassifiesAndPrunes) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Triangulation t = triangulatePolygon(c.polygon);
        const ChordalAxis axis = chordalAxis(c.polygon, t);
        ASSERT_TRUE(axis.ok()) << axis.error;
        int terminal = 0, junction = 0;
        for (TriangleKind k : axis.kinds) {
            terminal += k == TriangleKind::Terminal;
            junction += k == TriangleKind::Junction;
        }
        // The dual of a polygon's triangulation is a tree of degree <= 3:
        // leaves = branch points + 2.
        EXPECT_EQ(terminal, junction + 2);
        // The axis is a tree inside the outline, each node at its distance.
        EXPECT_EQ(axis.edges.size() + 1, axis.nodes.size());
        for (const AxisNode& a : axis.nodes) {
            EXPECT_TRUE(insidePolygon(a.p, c.polygon));
            EXPECT_GT(a.radius, 0.0);
            EXPECT_DOUBLE_EQ(a.radius, boundaryDistance(a.p, c.polygon));
        }
        for (size_t ti = 0; ti < t.triangles.size(); ++ti) EXPECT_GE(axis.triangleNodes[ti][0], 0);
    }
}

TEST(SketchChordalAxis, CircleFoldsIntoItsCentre) {
    const auto p = outlineOf(circlePath(0.3, 400), 64);
    const ChordalAxis axis = chordalAxis(p, triangulatePolygon(p));
    ASSERT_TRUE(axis.ok());
    // Every branch is pruned: what is left is a short spine at the centre.
    for (const AxisNode& a : axis.nodes) {
        EXPECT_LT(length2(a.p), 0.05 * 0.3);
        EXPECT_NEAR(a.radius, 0.3, 0.06 * 0.3);
    }
}

TEST(SketchChordalAxis, OvalIsOneSpineAlongItsLength) {
    const auto p = outlineOf(ellipsePath(0.5, 0.1, 600), 160);
    const ChordalAxis axis = chordalAxis(p, triangulatePolygon(p));
    ASSERT_TRUE(axis.ok());
    double minX = 1e9, maxX = -1e9;
    for (const AxisNode& a : axis.nodes) {
        EXPECT_LT(std::fabs(a.p.y), 0.02);
        minX = std::min(minX, a.p.x);
        maxX = std::max(maxX, a.p.x);
    }
    // Pruned round ends: the spine stops about a half-width from the tips.
    EXPECT_LT(maxX, 0.5);
    EXPECT_GT(maxX, 0.3);
    EXPECT_GT(minX, -0.5);
    EXPECT_LT(minX, -0.3);
    EXPECT_EQ(axis.prunedRegions, 2);
}

}  // namespace
}  // namespace hg::garden::sketch
