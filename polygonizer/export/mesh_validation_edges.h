// The edge half of validateMesh: how many triangles use each edge, in
// which directions, and which triangles the edges join into parts. Parallel
// on TBB and linear in the mesh: no global sort of the edges.
//
// Every edge use (corner k of triangle t to the next corner) goes to a
// bucket by its lower vertex number, a range of 2^bucketShift vertices: a
// chunk of triangles counts its uses per bucket, the counts give every
// chunk its place in every bucket, and the uses are written there. All the
// uses of an edge are then in one bucket, and each bucket gathers its edges
// in a small hash table that stays in cache; triangles sharing an edge are
// joined in a union-find as their uses meet. Meshes number their vertices
// roughly in space (the export mesher by block, a weld by first use), so a
// bucket's triangles lie close together in memory too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "polygonizer/mesh.h"

namespace hg::poly {

struct EdgeCensus {
    std::size_t boundaryEdges = 0;      // used once
    std::size_t nonManifoldEdges = 0;   // used three or more times
    std::size_t inconsistentEdges = 0;  // used twice, both times in one direction
    std::size_t components = 0;         // edge-connected groups of the counted triangles
};

// How the work is cut. Every layout gives the same census, whatever the
// number of threads; the tests use small ones to get many chunks and
// buckets out of small meshes.
struct EdgeLayout {
    std::size_t chunkTriangles = 0;  // triangles per chunk, at least 1
    int bucketShift = 0;             // 2^bucketShift vertices per bucket, fewer than 2^32 buckets
    bool wideIds = false;            // 64-bit edge-use and triangle numbers even where 32 bits hold them
};

// Chunks of at least 32768 triangles and at most about 256 of them;
// buckets of at least 256 vertices (about 1500 uses, a table of 100 KiB)
// and at most about 16384 of them: the per-chunk, per-bucket counts stay
// within 16 MiB for any mesh.
EdgeLayout defaultEdgeLayout(std::size_t triangles, std::size_t vertices);

// The census over the triangles with live[t] != 0 (their three indices in
// range and different; live has one entry per triangle).
EdgeCensus censusEdges(const Mesh& mesh, const std::vector<std::uint8_t>& live, const EdgeLayout& layout);

}  // namespace hg::poly
