// One chunk's mesh at its level of detail, from the LOD pyramid: regular
// cells (cell_table.h) inside, and Transvoxel transition cells
// (transition_table.h) on every face whose neighbour is one level finer, so
// the union of all chunk meshes is closed at level seams.
//
// How the seams close. A transition face's regular cells are shrunk: the
// chunk's samples on that face move inward by half a cell, and the slab
// they leave is filled by transition cells, whose fine side carries the
// finer neighbour's samples (the same points and values its own cells use)
// and whose back side meets the shrunk cells. A sample that also lies on a
// face WITHOUT transitions stays where it is ("pinned"): that face then keeps
// exactly the geometry of the neighbour behind it, whatever that neighbour
// does elsewhere. The transition cells along a pinned edge are flattened
// onto the edge; the segments they leave on it are the same ones the
// chunk diagonally across makes, so the two meet there. This is what makes
// every configuration with face neighbours at most one level apart closed,
// including the corner of a fine region, where plain Transvoxel leaves a
// crack (its coarse chunk diagonal to the fine one samples the shared edge
// coarsely while its two neighbours sample it finely).
//
// Crossing positions are computed from the edge's two sample points and
// values in one canonical order, so the chunks on either side of a face
// produce bit-identical vertices there; a union welded by position is one
// closed surface.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "polygonizer/realtime/chunk_layout.h"
#include "polygonizer/realtime/lod_pyramid.h"
#include "polygonizer/mesh.h"

namespace hg::poly {

// A chunk's faces, in the order -x, +x, -y, +y, -z, +z (bit f of a mask).
constexpr int kChunkFaces = 6;

struct ChunkLod {
    int level = 0;
    std::uint8_t transitionFaces = 0;  // faces whose neighbour is one level finer

    bool operator==(const ChunkLod& o) const { return level == o.level && transitionFaces == o.transitionFaces; }
    bool operator!=(const ChunkLod& o) const { return !(*this == o); }
};

// Each chunk's level and transition faces from the levels of all chunks (in
// the layout's order). Throws std::invalid_argument when face neighbours
// differ by more than one level, which transition cells cannot stitch.
std::vector<ChunkLod> chunkLods(const ChunkLayout& layout, const std::vector<int>& levels);

struct ChunkMeshStats {
    std::size_t regularCells = 0;
    std::size_t transitionCells = 0;
    std::size_t surfaceCells = 0;  // cells of either kind with triangles
};

// Samples of one level in a box (level indices), x fastest.
struct SampleBlock {
    voxel::IndexBox box;
    std::vector<float> values;

    float at(const int p[3]) const {
        return values[static_cast<std::size_t>((p[2] - box.lo[2]) * box.extent(1) + (p[1] - box.lo[1])) *
                          static_cast<std::size_t>(box.extent(0)) +
                      static_cast<std::size_t>(p[0] - box.lo[0])];
    }
};

// Everything one chunk's mesh is made from, copied out of the pyramid by
// gatherChunk: its level's samples (with one more on each side, for
// gradients) and the finer level's samples on each transition face. Meshing
// it reads nothing else, so it can run on another thread while the grid and
// the pyramid change (the remesh queue's background meshing,
// docs/design.md §5).
struct ChunkSamples {
    voxel::VolumeFrame frame;
    ChunkLod lod;
    int chunkSize = 0;
    int origin[3] = {0, 0, 0};  // level-0 index of the chunk's low corner
    SampleBlock coarse;
    SampleBlock fine[kChunkFaces];  // empty where the face has no transition
};

// The chunk's samples at `lod`. The pyramid must have more than `lod.level`
// levels; throws std::invalid_argument otherwise, or for a level-0 chunk
// with transition faces.
ChunkSamples gatherChunk(const LodPyramid& pyramid, const ChunkLayout& layout, std::size_t chunk, const ChunkLod& lod);

// The chunk's mesh in model units, with unit normals from the field's
// gradient (central differences on the level's samples) and vertices shared
// inside the chunk.
Mesh meshChunk(const ChunkSamples& samples, ChunkMeshStats* stats = nullptr);
// The same, gathered first.
Mesh meshChunk(const LodPyramid& pyramid, const ChunkLayout& layout, std::size_t chunk, const ChunkLod& lod,
               ChunkMeshStats* stats = nullptr);

}  // namespace hg::poly
