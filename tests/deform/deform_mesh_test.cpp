// The deformable model's mesh: the icosphere, the checks, uniform
// remeshing, and the sketched model meshed from its inflated solid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "garden/deform/deform_mesh.h"
#include "garden/deform/remesh.h"
#include "garden/deform/sketch_mesh.h"
#include "garden/sketch/outline.h"
#include "tests/sketch/sketch_shapes.h"

namespace hg::garden::deform {
namespace {

constexpr double kPi = 3.141592653589793;

TEST(DeformMesh, IcosphereIsClosedOutwardAndOnItsSphere) {
    const DeformMesh s = sphereMesh(glm::dvec3(1.0, -2.0, 0.5), 0.5, 3);
    EXPECT_EQ(s.vertices.size(), 642u);
    EXPECT_EQ(s.triangles.size(), 1280u);
    EXPECT_EQ(checkClosedManifold(s), "");
    for (const glm::dvec3& p : s.vertices) EXPECT_NEAR(glm::length(p - glm::dvec3(1.0, -2.0, 0.5)), 0.5, 1e-12);
    const double ball = 4.0 / 3.0 * kPi * 0.125;
    EXPECT_GT(meshVolume(s), 0.97 * ball);
    EXPECT_LT(meshVolume(s), ball);
}

TEST(DeformMesh, TheCheckFindsHolesFlipsAndPinches) {
    DeformMesh s = sphereMesh(glm::dvec3(0.0), 1.0, 1);
    DeformMesh hole = s;
    hole.triangles.pop_back();
    EXPECT_NE(checkClosedManifold(hole).find("in 1 triangles"), std::string::npos) << checkClosedManifold(hole);
    DeformMesh flipped = s;
    std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
    EXPECT_NE(checkClosedManifold(flipped).find("oriented"), std::string::npos);
    // Two spheres sharing one vertex: every edge is fine, the vertex is not.
    DeformMesh pinch = s;
    const DeformMesh other = sphereMesh(glm::dvec3(2.0, 0.0, 0.0), 1.0, 1);
    const auto offset = static_cast<std::uint32_t>(pinch.vertices.size());
    pinch.vertices.insert(pinch.vertices.end(), other.vertices.begin() + 1, other.vertices.end());
    for (auto t : other.triangles) {
        for (auto& v : t) v = v == 0 ? 0 : v + offset - 1;  // its vertex 0 is the first sphere's
        pinch.triangles.push_back(t);
    }
    EXPECT_NE(checkClosedManifold(pinch).find("pinch"), std::string::npos) << checkClosedManifold(pinch);
}

TEST(Remesh, UniformEdgesFromACoarseAndAFineSphere) {
    for (int subdivisions : {2, 5}) {
        const double edge = 0.1;
        const DeformMesh r = remeshUniform(sphereMesh(glm::dvec3(0.0), 1.0, subdivisions), edge, 6,
                                           [](const glm::dvec3& p) { return glm::normalize(p); });
        const EdgeLengthRange e = edgeLengthRange(r);
        std::printf("remesh from subdivision %d: %zu vertices, edges %.4f..%.4f (mean %.4f)\n", subdivisions,
                    r.vertices.size(), e.min, e.max, e.mean);
        EXPECT_EQ(checkClosedManifold(r), "");
        EXPECT_GE(e.min, 0.5 * edge);
        EXPECT_LE(e.max, 1.6 * edge);
        // About the number of vertices a uniform triangulation of edge 0.1 has.
        const double expected = 4.0 * kPi / (std::sqrt(3.0) / 2.0 * edge * edge);
        EXPECT_GT(static_cast<double>(r.vertices.size()), 0.6 * expected);
        EXPECT_LT(static_cast<double>(r.vertices.size()), 1.6 * expected);
    }
}

TEST(Remesh, ValenceMovesTowardSix) {
    const DeformMesh r = remeshUniform(sphereMesh(glm::dvec3(0.0), 1.0, 2), 0.12, 6,
                                       [](const glm::dvec3& p) { return glm::normalize(p); });
    const VertexLists ring = vertexNeighbours(meshEdges(r), r.vertices.size());
    int six = 0;
    for (std::size_t v = 0; v < r.vertices.size(); ++v) six += ring.count(v) == 6;
    EXPECT_GT(static_cast<double>(six) / static_cast<double>(r.vertices.size()), 0.6);
}

TEST(SketchMesh, ACircleGivesAClosedSphere) {
    const double R = 0.3;
    sketch::OutlineOptions o;
    o.samples = 96;
    const sketch::Outline outline = sketch::makeOutline(test::sketch::circlePath(R, 500, 0.001), o);
    ASSERT_TRUE(outline.ok()) << outline.error;
    const sketch::SketchPlane plane = sketch::planeFacing(sketch::Vec3(1.0, 2.0, 0.5), sketch::Vec3(0.3, -0.5, 0.8));
    const sketch::Inflation inflation = sketch::inflate(outline.points, outline.spacing, plane);
    ASSERT_TRUE(inflation.ok()) << inflation.error;
    const double edge = 0.03;
    const DeformMesh mesh = meshOfInflatedSketch(inflation.solid, edge);
    ASSERT_FALSE(mesh.vertices.empty());
    EXPECT_EQ(checkClosedManifold(mesh), "");
    // The circle's centre in the world: the mean of the outline on the plane.
    sketch::Vec2 c(0.0);
    for (const sketch::Vec2& p : outline.points) c += p;
    c /= static_cast<double>(outline.points.size());
    const glm::dvec3 centre = plane.toWorld(c);
    double worst = 0.0;
    for (const glm::dvec3& p : mesh.vertices) worst = std::max(worst, std::fabs(glm::length(p - centre) - R));
    const EdgeLengthRange e = edgeLengthRange(mesh);
    const double ball = 4.0 / 3.0 * kPi * R * R * R;
    std::printf("circle R %.2f: %zu vertices, worst off the sphere %.4f, edges %.4f..%.4f, volume %.4f of %.4f\n", R,
                mesh.vertices.size(), worst, e.min, e.max, meshVolume(mesh), ball);
    EXPECT_LT(worst, 0.01 * R);
    EXPECT_GE(e.min, 0.5 * edge);
    EXPECT_LE(e.max, 1.6 * edge);
    EXPECT_NEAR(meshVolume(mesh), ball, 0.03 * ball);
}

TEST(SketchMesh, NoPiecesNoMesh) {
    EXPECT_TRUE(meshOfInflatedSketch(sketch::InflatedSolid{}, 0.05).vertices.empty());
}

}  // namespace
}  // namespace hg::garden::deform
