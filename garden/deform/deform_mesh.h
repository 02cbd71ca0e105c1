// The deformable model's mesh (issue 22, docs/sketching.md "Deformable
// model"): a closed, outward-oriented, manifold triangle mesh in the
// sculpture's model frame, and what the snake and the remesher need to know
// about it (edges with their two triangles, one-rings, normals, volume).
// Every list here is built in a fixed order from the triangle list alone,
// so whatever runs over it is deterministic.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace hg::garden::deform {

struct DeformMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// An icosphere: the icosahedron's faces split `subdivisions` times into
// four, vertices pushed onto the sphere (10 * 4^s + 2 vertices).
DeformMesh sphereMesh(glm::dvec3 centre, double radius, int subdivisions);

// An undirected edge a < b with the triangles on its two sides (t1 ==
// kNoTriangle where only one triangle has it: a hole).
constexpr std::uint32_t kNoTriangle = 0xffffffffu;
struct MeshEdge {
    std::uint32_t a = 0, b = 0;
    std::uint32_t t0 = kNoTriangle, t1 = kNoTriangle;
    int uses = 0;  // triangles that have the edge: 2 on a closed manifold
};

// Every edge, sorted by (a, b).
std::vector<MeshEdge> meshEdges(const DeformMesh& mesh);

// Compressed lists per vertex: items of vertex v are
// items[offsets[v] .. offsets[v + 1]).
struct VertexLists {
    std::vector<std::uint32_t> offsets, items;
    std::size_t count(std::size_t v) const { return offsets[v + 1] - offsets[v]; }
};

// The vertices joined to each vertex by an edge, ascending.
VertexLists vertexNeighbours(const std::vector<MeshEdge>& edges, std::size_t vertexCount);
// The triangles around each vertex, ascending.
VertexLists vertexTriangles(const DeformMesh& mesh);

// Unit area-weighted vertex normals (sum of the triangles' cross products).
std::vector<glm::dvec3> vertexNormals(const DeformMesh& mesh, const VertexLists& triangles);

// The enclosed volume (divergence theorem; > 0 when oriented outward).
double meshVolume(const DeformMesh& mesh);

// "" when every edge has exactly two triangles that use it in opposite
// directions, no triangle repeats a vertex, and every vertex is used; else
// the first thing wrong, with its vertex or triangle.
std::string checkClosedManifold(const DeformMesh& mesh);

// Shortest and longest edge.
struct EdgeLengthRange {
    double min = 0.0, max = 0.0, mean = 0.0;
};
EdgeLengthRange edgeLengthRange(const DeformMesh& mesh);

}  // namespace hg::garden::deform
