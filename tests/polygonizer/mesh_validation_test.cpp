// Mesh checks before printing: closed solids pass with exact volume and
// area; each defect a slicer trips on (holes, flipped triangles, edges
// shared by four triangles, inside-out solids, collapsed triangles) is
// counted and named; welding a triangle soup restores the topology.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh_validation_reference.h"
#include "polygonizer/export/mesh_validation.h"

namespace hg::poly {
namespace {

using test::concatenate;
using test::soup;

constexpr double kPi = 3.14159265358979323846;

void addVertex(Mesh& m, double x, double y, double z) {
    m.positions.push_back(static_cast<float>(x));
    m.positions.push_back(static_cast<float>(y));
    m.positions.push_back(static_cast<float>(z));
}

void addTriangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

// Axis-aligned cube, 8 shared vertices, 12 triangles counter-clockwise
// seen from outside.
Mesh cube(float x = 0, float y = 0, float z = 0, float size = 1) {
    Mesh m;
    for (int k = 0; k < 8; ++k)
        addVertex(m, x + size * static_cast<float>(k & 1), y + size * static_cast<float>((k >> 1) & 1),
                  z + size * static_cast<float>((k >> 2) & 1));
    // Vertex k has x = bit 0, y = bit 1, z = bit 2.
    const std::uint32_t faces[6][4] = {
        {0, 2, 3, 1},  // z = 0, facing -z
        {4, 5, 7, 6},  // z = 1
        {0, 1, 5, 4},  // y = 0
        {2, 6, 7, 3},  // y = 1
        {0, 4, 6, 2},  // x = 0
        {1, 3, 7, 5},  // x = 1
    };
    for (const auto& f : faces) {
        addTriangle(m, f[0], f[1], f[2]);
        addTriangle(m, f[0], f[2], f[3]);
    }
    return m;
}

Mesh tetrahedron() {
    Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 0);
    addVertex(m, 0, 0, 1);
    addTriangle(m, 0, 2, 1);
    addTriangle(m, 0, 1, 3);
    addTriangle(m, 0, 3, 2);
    addTriangle(m, 1, 2, 3);
    return m;
}

Mesh octahedron() {
    Mesh m;
    addVertex(m, 1, 0, 0);   // 0
    addVertex(m, -1, 0, 0);  // 1
    addVertex(m, 0, 1, 0);   // 2
    addVertex(m, 0, -1, 0);  // 3
    addVertex(m, 0, 0, 1);   // 4
    addVertex(m, 0, 0, -1);  // 5
    const std::uint32_t ring[4] = {0, 2, 1, 3};  // counter-clockwise seen from +z
    for (int i = 0; i < 4; ++i) {
        addTriangle(m, ring[i], ring[(i + 1) % 4], 4);
        addTriangle(m, ring[(i + 1) % 4], ring[i], 5);
    }
    return m;
}

// Latitude-longitude sphere with single-vertex poles.
Mesh uvSphere(int rings, int segments, double radius) {
    Mesh m;
    addVertex(m, 0, 0, radius);
    for (int i = 1; i < rings; ++i) {
        const double theta = kPi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * kPi * j / segments;
            addVertex(m, radius * std::sin(theta) * std::cos(phi), radius * std::sin(theta) * std::sin(phi),
                      radius * std::cos(theta));
        }
    }
    addVertex(m, 0, 0, -radius);
    const auto south = static_cast<std::uint32_t>(m.vertexCount() - 1);
    auto at = [&](int ring, int j) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + j % segments); };
    for (int j = 0; j < segments; ++j) {
        addTriangle(m, 0, at(1, j), at(1, j + 1));
        for (int i = 1; i + 1 < rings; ++i) {
            addTriangle(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
            addTriangle(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
        addTriangle(m, south, at(rings - 1, j + 1), at(rings - 1, j));
    }
    return m;
}



void flipTriangle(Mesh& m, std::size_t t) { std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]); }

Mesh insideOut(Mesh m) {
    for (std::size_t t = 0; t < m.triangleCount(); ++t) flipTriangle(m, t);
    return m;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MeshValidation, UnitCubeIsWatertightWithExactVolumeAndArea) {
    const MeshReport r = validateMesh(cube());
    EXPECT_EQ(r.triangles, 12u);
    EXPECT_EQ(r.vertices, 8u);
    EXPECT_EQ(r.boundaryEdges, 0u);
    EXPECT_EQ(r.nonManifoldEdges, 0u);
    EXPECT_EQ(r.inconsistentEdges, 0u);
    EXPECT_EQ(r.degenerateTriangles, 0u);
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.volume, 1.0);
    EXPECT_EQ(r.area, 6.0);
    for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(r.boxMin[a], 0.0f);
        EXPECT_EQ(r.boxMax[a], 1.0f);
    }
    EXPECT_TRUE(r.closed());
    EXPECT_TRUE(r.manifold());
    EXPECT_TRUE(r.outwardFacing());
    EXPECT_TRUE(r.ok());
}

TEST(MeshValidation, VolumeStaysExactFarFromTheOrigin) {
    const MeshReport r = validateMesh(cube(1000, -2000, 3000, 2));
    EXPECT_EQ(r.volume, 8.0);
    EXPECT_EQ(r.area, 24.0);
    EXPECT_EQ(r.boxMin[1], -2000.0f);
    EXPECT_EQ(r.boxMax[2], 3002.0f);
}

TEST(MeshValidation, TetrahedronAndOctahedron) {
    const MeshReport t = validateMesh(tetrahedron());
    EXPECT_TRUE(t.ok()) << describe(t);
    EXPECT_DOUBLE_EQ(t.volume, 1.0 / 6);
    EXPECT_DOUBLE_EQ(t.area, 1.5 + std::sqrt(3.0) / 2);

    const MeshReport o = validateMesh(octahedron());
    EXPECT_TRUE(o.ok()) << describe(o);
    EXPECT_EQ(o.triangles, 8u);
    EXPECT_EQ(o.vertices, 6u);
    EXPECT_DOUBLE_EQ(o.volume, 4.0 / 3);
    EXPECT_DOUBLE_EQ(o.area, 8 * std::sqrt(3.0) / 2);
}

TEST(MeshValidation, SphereIsClosedWithGenusZeroAndNearlyTheBallsVolume) {
    const Mesh m = uvSphere(32, 64, 2.0);
    const MeshReport r = validateMesh(m);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.components, 1u);
    // Euler characteristic of a sphere: V - E + F = 2, with E = 3F/2.
    const auto v = static_cast<long>(r.vertices), f = static_cast<long>(r.triangles);
    EXPECT_EQ(v - 3 * f / 2 + f, 2);
    const double ball = 4.0 / 3 * kPi * 8;
    EXPECT_LT(r.volume, ball);  // inscribed
    EXPECT_GT(r.volume, 0.98 * ball);
    EXPECT_LT(r.area, 4 * kPi * 4);
    EXPECT_GT(r.area, 0.98 * 4 * kPi * 4);
}

TEST(MeshValidation, MissingTriangleLeavesThreeBoundaryEdges) {
    Mesh m = cube();
    m.indices.resize(m.indices.size() - 3);
    const MeshReport r = validateMesh(m);
    EXPECT_EQ(r.boundaryEdges, 3u);
    EXPECT_FALSE(r.closed());
    EXPECT_TRUE(r.manifold());
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "boundary edges: 3")) << describe(r);
    EXPECT_TRUE(contains(describe(r), "open (3 boundary edges)")) << describe(r);
    EXPECT_FALSE(contains(describe(r), "watertight and manifold"));
}

TEST(MeshValidation, FlippedTriangleMakesItsEdgesInconsistent) {
    Mesh m = cube();
    flipTriangle(m, 4);
    const MeshReport r = validateMesh(m);
    EXPECT_EQ(r.inconsistentEdges, 3u);
    EXPECT_TRUE(r.closed());
    EXPECT_TRUE(r.manifold());
    EXPECT_FALSE(r.outwardFacing());
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "orientation: inconsistent (3 edges")) << describe(r);
}

TEST(MeshValidation, CubesSharingAnEdgeAreNonManifold) {
    // The second cube touches the first along the edge x = y = 1.
    const Mesh m = weldByPosition(concatenate(cube(), cube(1, 1, 0)));
    EXPECT_EQ(m.vertexCount(), 14u);
    const MeshReport r = validateMesh(m);
    EXPECT_EQ(r.nonManifoldEdges, 1u);
    EXPECT_EQ(r.boundaryEdges, 0u);
    EXPECT_EQ(r.components, 1u);  // joined through the shared edge
    EXPECT_FALSE(r.manifold());
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "non-manifold edges: 1")) << describe(r);
}

TEST(MeshValidation, InsideOutCubeHasNegativeVolume) {
    const MeshReport r = validateMesh(insideOut(cube()));
    EXPECT_EQ(r.volume, -1.0);
    EXPECT_EQ(r.inconsistentEdges, 0u);
    EXPECT_TRUE(r.closed());
    EXPECT_FALSE(r.outwardFacing());
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "inside out")) << describe(r);
}

TEST(MeshValidation, DisjointCubesAreTwoComponents) {
    const MeshReport r = validateMesh(concatenate(cube(), cube(3, 0, 0)));
    EXPECT_EQ(r.components, 2u);
    EXPECT_EQ(r.volume, 2.0);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_TRUE(contains(describe(r), "2 parts")) << describe(r);
}

TEST(MeshValidation, DegenerateAndInvalidTrianglesAreCountedAndSkipped) {
    Mesh m = cube();
    addTriangle(m, 0, 0, 1);
    addTriangle(m, 0, 1, 99);
    const MeshReport r = validateMesh(m);
    EXPECT_EQ(r.triangles, 14u);
    EXPECT_EQ(r.degenerateTriangles, 1u);
    EXPECT_EQ(r.invalidTriangles, 1u);
    EXPECT_EQ(r.boundaryEdges, 0u) << "neither adds edges";
    EXPECT_EQ(r.volume, 1.0);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "1 degenerate triangle")) << describe(r);
    EXPECT_TRUE(contains(describe(r), "invalid indices")) << describe(r);
}

TEST(MeshValidation, EmptyMeshIsNotOk) {
    const MeshReport r = validateMesh(Mesh{});
    EXPECT_EQ(r.triangles, 0u);
    EXPECT_EQ(r.components, 0u);
    EXPECT_FALSE(r.closed());
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(contains(describe(r), "no triangles")) << describe(r);
}

TEST(MeshValidation, DescribeReportsMillimetres) {
    const std::string text = describe(validateMesh(cube()), 10.0);
    EXPECT_TRUE(contains(text, "triangles: 12")) << text;
    EXPECT_TRUE(contains(text, "volume: 1000 mm^3 (1 cm^3)")) << text;
    EXPECT_TRUE(contains(text, "surface area: 600 mm^2")) << text;
    EXPECT_TRUE(contains(text, "size: 10 x 10 x 10 mm")) << text;
    EXPECT_TRUE(contains(text, "boundary edges: 0")) << text;
    EXPECT_TRUE(contains(text, "non-manifold edges: 0")) << text;
    EXPECT_TRUE(contains(text, "orientation: consistent, facing outward")) << text;
    EXPECT_TRUE(contains(text, "verdict: watertight and manifold")) << text;
}

TEST(Weld, CubeSoupWeldsToEightVerticesAndValidates) {
    const Mesh s = soup(cube());
    ASSERT_EQ(s.vertexCount(), 36u);
    EXPECT_FALSE(validateMesh(s).closed()) << "a soup has only boundary edges";
    const Mesh w = weldByPosition(s);
    EXPECT_EQ(w.vertexCount(), 8u);
    EXPECT_EQ(w.triangleCount(), 12u);
    const MeshReport r = validateMesh(w);
    EXPECT_TRUE(r.closed());
    EXPECT_TRUE(r.manifold());
    EXPECT_TRUE(r.outwardFacing());
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_EQ(r.volume, 1.0);
}

TEST(Weld, SphereSoupWeldsBackToTheIndexedMesh) {
    const Mesh m = uvSphere(12, 24, 1.0);
    const Mesh w = weldByPosition(soup(m));
    EXPECT_EQ(w.vertexCount(), m.vertexCount());
    EXPECT_EQ(w.triangleCount(), m.triangleCount());
    EXPECT_TRUE(validateMesh(w).ok());
}

TEST(Weld, ToleranceMergesNearbyVertices) {
    Mesh s = soup(cube());
    // Each corner copy moved by a different few millionths.
    for (std::size_t i = 0; i < s.positions.size(); ++i)
        s.positions[i] += 1e-6f * static_cast<float>(i % 5);
    EXPECT_GT(weldByPosition(s).vertexCount(), 8u) << "without tolerance only identical positions merge";
    const Mesh w = weldByPosition(s, 1e-4f);
    EXPECT_EQ(w.vertexCount(), 8u);
    const MeshReport r = validateMesh(w);
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_NEAR(r.volume, 1.0, 1e-4);
}

TEST(Weld, ToleranceDoesNotMergeDistinctVertices) {
    const Mesh w = weldByPosition(soup(cube(0, 0, 0, 0.01f)), 0.001f);
    EXPECT_EQ(w.vertexCount(), 8u);
    EXPECT_TRUE(validateMesh(w).ok());
}

TEST(Weld, CollapsedTrianglesAreDropped) {
    Mesh s = soup(cube());
    // A sliver whose corners lie within the tolerance of one another.
    addVertex(s, 0.5, 0.5, 0.5);
    addVertex(s, 0.5 + 1e-5, 0.5, 0.5);
    addVertex(s, 0.5, 0.5 + 1e-5, 0.5);
    addTriangle(s, 36, 37, 38);
    addTriangle(s, 0, 1, 1000);  // out of range
    const Mesh w = weldByPosition(s, 1e-3f);
    EXPECT_EQ(w.triangleCount(), 12u);
    EXPECT_EQ(w.vertexCount(), 8u) << "vertices only the dropped triangle used go too";
    EXPECT_TRUE(validateMesh(w).ok());
}

TEST(Weld, NegativeZeroIsTheSamePointAsZero) {
    Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 0);
    addVertex(m, -0.0, -0.0, -0.0);
    addTriangle(m, 0, 1, 2);
    addTriangle(m, 3, 2, 1);
    EXPECT_EQ(weldByPosition(m).vertexCount(), 3u);
}

TEST(Weld, NormalsAreAveragedToUnitLength) {
    const Mesh c = cube();
    Mesh s = soup(c);
    // Face normals per corner, as a flat-shaded soup would carry them.
    for (std::size_t t = 0; t < s.triangleCount(); ++t) {
        const float* p = &s.positions[9 * t];
        const float e1[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]};
        const float e2[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
        const float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                            e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; ++k) s.normals.insert(s.normals.end(), n, n + 3);
    }
    const Mesh w = weldByPosition(s);
    ASSERT_EQ(w.normals.size(), w.positions.size());
    for (std::size_t v = 0; v < w.vertexCount(); ++v) {
        const float* n = &w.normals[3 * v];
        const float* p = &w.positions[3 * v];
        const double len = std::sqrt(static_cast<double>(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
        EXPECT_NEAR(len, 1.0, 1e-6);
        // Each corner's normal leans away from the cube's centre on all
        // three axes.
        for (int a = 0; a < 3; ++a) EXPECT_GT((p[a] - 0.5f) * n[a], 0.0f) << "vertex " << v << " axis " << a;
    }
}

}  // namespace
}  // namespace hg::poly
