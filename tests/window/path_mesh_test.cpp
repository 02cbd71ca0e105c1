// Garden paths as ribbons: the default garden's circuit (a twelve-sided
// ring) covers its width all round and reaches no further out than its
// mitred corners (the ribbon of square-capped quads stuck out at every
// corner); open paths end flush; sharp bends are cut at the mitre limit.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "garden/window/path_mesh.h"

namespace hg::garden {
namespace {

glm::vec2 at(const poly::Mesh& m, std::uint32_t v) { return {m.positions[3 * v], m.positions[3 * v + 2]}; }

// Distance from q to the path's centre line.
float toCentre(const PathSpec& path, glm::vec2 q) {
    float best = 1e30f;
    const std::size_t n = path.points.size(), segments = path.closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const glm::vec2 a(path.points[i][0], path.points[i][1]), b(path.points[(i + 1) % n][0], path.points[(i + 1) % n][1]);
        const float t = std::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
        best = std::min(best, glm::length(q - (a + t * (b - a))));
    }
    return best;
}

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// Triangles (seen from above) holding q.
int cover(const poly::Mesh& m, glm::vec2 q) {
    int n = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec2 a = at(m, m.indices[t]), b = at(m, m.indices[t + 1]), c = at(m, m.indices[t + 2]);
        const float d1 = cross(b - a, q - a), d2 = cross(c - b, q - b), d3 = cross(a - c, q - c);
        n += ((d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0)) ? 1 : 0;
    }
    return n;
}

PathSpec circuit() {  // content/gardens/default.json's
    PathSpec p;
    p.width = 1.4;
    p.closed = true;
    p.points = {{0, 6.5},   {3.25, 5.63},   {5.63, 3.25},   {6.5, 0},  {5.63, -3.25}, {3.25, -5.63},
                {0, -6.5},  {-3.25, -5.63}, {-5.63, -3.25}, {-6.5, 0}, {-5.63, 3.25}, {-3.25, 5.63}};
    return p;
}

TEST(PathMesh, TheRingCoversItsWidthAllRoundAndStopsAtItsMitres) {
    const PathSpec path = circuit();
    const poly::Mesh m = pathMesh(path, 0.0);
    EXPECT_EQ(m.vertexCount(), 24u);
    EXPECT_EQ(m.indices.size(), 12u * 6u);
    const float h = 0.7f;
    // Each bend turns by 30 degrees: its mitred corner is h / cos(15) out.
    const float mitre = h / std::cos(glm::radians(15.0f));
    for (std::uint32_t v = 0; v < m.vertexCount(); ++v) {
        EXPECT_NEAR(toCentre(path, at(m, v)), 0.0f, mitre * 1.001f) << v;
        EXPECT_NEAR(m.positions[3 * v + 1], 0.01f, 1e-6f);
        EXPECT_EQ(m.normals[3 * v + 1], 1.0f);
    }
    // On a grid: within 0.97 h of the centre line, covered; beyond the
    // mitres, not; once, except on the triangles' shared edges.
    int inside = 0, outside = 0, twice = 0;
    for (float x = -8.0f; x <= 8.0f; x += 0.05f)
        for (float z = -8.0f; z <= 8.0f; z += 0.05f) {
            const glm::vec2 q(x + 0.0123f, z + 0.0071f);  // off the grid of edges
            const float d = toCentre(path, q);
            const int c = cover(m, q);
            if (d < 0.97f * h) {
                ++inside;
                EXPECT_GE(c, 1) << "a gap at (" << q.x << ", " << q.y << ")";
            } else if (d > mitre * 1.001f) {
                ++outside;
                EXPECT_EQ(c, 0) << "the ribbon reaches (" << q.x << ", " << q.y << "), " << d << " m from the centre";
            }
            twice += c > 1 ? 1 : 0;
        }
    EXPECT_GT(inside, 5000);
    EXPECT_GT(outside, 50000);
    EXPECT_LT(twice, inside / 100) << "quads overlapping at the bends";
    // Faces up: counter-clockwise seen from above, with +y up and z towards the viewer.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec2 a = at(m, m.indices[t]), b = at(m, m.indices[t + 1]), c = at(m, m.indices[t + 2]);
        EXPECT_LT(cross(b - a, c - a), 0.0f) << "triangle " << t / 3 << ": (x, z) clockwise is counter-clockwise from +y";
    }
}

TEST(PathMesh, AnOpenPathEndsFlushAndASharpBendIsCutAtTheMitreLimit) {
    PathSpec path;
    path.width = 2.0;
    path.points = {{0, 0}, {0, 0}, {10, 0}, {0, 0.5}};  // a repeat, then a hairpin
    const poly::Mesh m = pathMesh(path, 1.0);
    ASSERT_EQ(m.vertexCount(), 6u) << "the repeated point dropped";
    EXPECT_EQ(m.indices.size(), 12u);
    // Flush ends: the end pairs straddle their points at right angles.
    EXPECT_NEAR(glm::length(at(m, 0) - glm::vec2(0, 0)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(at(m, 1) - glm::vec2(0, 0)), 1.0f, 1e-5f);
    EXPECT_NEAR(at(m, 0).x, 0.0f, 1e-5f);
    EXPECT_NEAR(m.positions[1], 1.01f, 1e-6f);
    // The hairpin's corner: cut at the limit, not a spike metres long.
    EXPECT_NEAR(glm::length(at(m, 2) - glm::vec2(10, 0)), kPathMitreLimit * 1.0f, 1e-4f);
    EXPECT_NEAR(glm::length(at(m, 3) - glm::vec2(10, 0)), kPathMitreLimit * 1.0f, 1e-4f);

    PathSpec dot;
    dot.points = {{1, 1}, {1, 1}};
    EXPECT_TRUE(pathMesh(dot, 0.0).empty());
    PathSpec repeated = circuit();
    repeated.points.push_back(repeated.points.front());  // closed, with its first point written again last
    EXPECT_EQ(pathMesh(repeated, 0.0).vertexCount(), 24u);
}

}  // namespace
}  // namespace hg::garden
