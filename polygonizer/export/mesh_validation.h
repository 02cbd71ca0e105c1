// Is a mesh fit for a 3D printer? Slicers need a closed, manifold surface
// with every triangle facing outward; these checks look at the index
// topology, so a triangle soup (an STL as read) must be welded first.
#pragma once

#include <cstddef>
#include <string>

#include "polygonizer/mesh.h"

namespace hg::poly {

// Merges vertices at the same position (tolerance 0: bit-identical after
// folding -0 into +0; otherwise within `tolerance`, each vertex joining the
// first earlier kept vertex in reach) and drops the triangles that collapse
// (two equal indices). Triangles with an index out of range are dropped too,
// and so are vertices no remaining triangle uses. Normals, when present for
// every vertex, are averaged over each merged group and renormalized.
// Vertices with a non-finite coordinate are never merged.
Mesh weldByPosition(const Mesh& mesh, float tolerance = 0);

struct MeshReport {
    std::size_t triangles = 0;
    std::size_t vertices = 0;            // used by at least one valid triangle
    std::size_t boundaryEdges = 0;       // used by one triangle: a hole's rim
    std::size_t nonManifoldEdges = 0;    // used by three or more triangles
    std::size_t inconsistentEdges = 0;   // used twice in the same direction: a flipped neighbour
    std::size_t degenerateTriangles = 0; // two equal indices
    std::size_t invalidTriangles = 0;    // an index past the vertex array
    std::size_t components = 0;          // edge-connected groups of triangles
    double volume = 0;                   // signed; positive when facing outward
    double area = 0;
    float boxMin[3] = {0, 0, 0};
    float boxMax[3] = {0, 0, 0};

    bool closed() const { return triangles > 0 && boundaryEdges == 0; }
    bool manifold() const { return nonManifoldEdges == 0; }
    bool outwardFacing() const { return inconsistentEdges == 0 && volume > 0; }
    bool ok() const {
        return closed() && manifold() && outwardFacing() && degenerateTriangles == 0 && invalidTriangles == 0;
    }
};

// Edges are the sorted index pairs of the non-degenerate, valid triangles;
// volume, area and box are over those triangles too. Runs on TBB (edges:
// mesh_validation_edges.h) and gives the same report on any number of
// threads.
MeshReport validateMesh(const Mesh& mesh);

// A few lines for a person: counts, volume and size in millimetres (model
// units times `mmPerUnit`), the defects found, and a one-line verdict.
std::string describe(const MeshReport& report, double mmPerUnit = 1.0);
// The same in another length unit: `perModelUnit` of `unit` ("m", "model
// units", ...) per model unit. Say sizes in the unit of the file a mesh is
// written to (a sculpture's STL is in millimetres of its true size, its OBJ
// and glTF in metres), never in one a person has to convert from.
std::string describe(const MeshReport& report, double perModelUnit, const std::string& unit);

}  // namespace hg::poly
