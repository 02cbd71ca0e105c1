// The union of every chunk's mesh at given levels (or of those a remesh
// queue shows), and how its welded edges are used: what the chunk mesher
// and remesh queue tests check for closed seams.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/chunk_mesher.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/realtime/remesh_queue.h"
#include "polygonizer/mesh.h"

namespace hg::poly::test {

inline Mesh unionOf(const LodPyramid& pyramid, const ChunkLayout& layout, const std::vector<int>& levels) {
    const std::vector<ChunkLod> lods = chunkLods(layout, levels);
    Mesh all;
    for (std::size_t i = 0; i < layout.count(); ++i) {
        Mesh m = meshChunk(pyramid, layout, i, lods[i]);
        EXPECT_EQ(m.normals.size(), m.positions.size());
        const auto base = static_cast<std::uint32_t>(all.vertexCount());
        all.positions.insert(all.positions.end(), m.positions.begin(), m.positions.end());
        all.normals.insert(all.normals.end(), m.normals.begin(), m.normals.end());
        for (std::uint32_t idx : m.indices) all.indices.push_back(base + idx);
    }
    return all;
}

// The union of the meshes a remesh queue has on show (chunks with none left out).
inline Mesh shownUnion(const RemeshQueue& q) {
    Mesh all;
    for (std::size_t i = 0; i < q.count(); ++i) {
        auto m = q.mesh(i);
        if (!m) continue;
        const auto base = static_cast<std::uint32_t>(all.vertexCount());
        all.positions.insert(all.positions.end(), m->positions.begin(), m->positions.end());
        for (std::uint32_t idx : m->indices) all.indices.push_back(base + idx);
    }
    return all;
}

// Edges of the welded mesh used other than twice by its triangles, as
// counts: [boundary (once), pinches (four times, on a chunk edge line),
// other].
struct EdgeUse {
    std::size_t boundary = 0, pinches = 0, other = 0;
};

// A pinch is where a feature thinner than a coarse cell passes between two
// fine chunks diagonal to each other across a chunk edge: the two coarse
// chunks around that edge see no volume there, so the surface closes but
// touches itself along the edge line. Anywhere else an edge must be used
// exactly twice.
inline EdgeUse edgeUse(const Mesh& welded, const ChunkLayout& layout) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t t = 0; t < welded.triangleCount(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            std::uint32_t a = welded.indices[3 * t + k], b = welded.indices[3 * t + (k + 1) % 3];
            if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
        }
    const voxel::VolumeFrame& f = layout.frame();
    auto onChunkEdgeLine = [&](std::uint32_t v) {
        int planes = 0;
        for (std::size_t a = 0; a < 3; ++a) {
            double i = (static_cast<double>(welded.positions[3 * v + a]) - f.modelBox.lo[a]) / f.voxelSize;
            double r = i / layout.chunkSize();
            planes += std::fabs(r - std::round(r)) * layout.chunkSize() < 1e-3;
        }
        return planes >= 2;
    };
    EdgeUse e;
    for (const auto& [edge, n] : uses) {
        if (n == 1) ++e.boundary;
        else if (n == 4 && onChunkEdgeLine(edge.first) && onChunkEdgeLine(edge.second)) ++e.pinches;
        else if (n != 2) ++e.other;
    }
    return e;
}

}  // namespace hg::poly::test
