// Every chunk mesh of the garden in two large GPU buffers: one of vertices
// (position and normal, interleaved) and one of indices, each sub-allocated
// by a RangeAllocator, under one vertex array. Drawing many chunks then
// needs no buffer or vertex-array switch between them, which is what lets
// a whole view go out as one multi-draw (chunk_batch.h; docs/rendering.md,
// "Batched drawing").
//
// When a mesh does not fit, the arena moves every live range into new
// buffers, packed in order and as large as needed (twice the old size when
// full): a copy from buffer to buffer on the GPU, no round trip through
// memory, which also undoes fragmentation. Indices stay relative to their
// chunk's first vertex (drawn with a base vertex), so a move rewrites no
// index. Needs its GL context current in every call, the destructor too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>

#include "garden/render/gl_objects.h"
#include "garden/render/range_allocator.h"
#include "polygonizer/mesh.h"

namespace hg::garden {

using ChunkId = std::uint64_t;

// Where a chunk's mesh lies in the arena, in vertices and indices.
struct ArenaSlot {
    std::size_t firstVertex = 0;
    std::size_t vertexCount = 0;
    std::size_t firstIndex = 0;
    std::size_t indexCount = 0;
};

class ChunkArena {
public:
    // Attribute locations of the vertex array: position, normal, draw id.
    static constexpr GLuint kPositionAttribute = 0;
    static constexpr GLuint kNormalAttribute = 1;
    static constexpr GLuint kDrawIdAttribute = 2;

    explicit ChunkArena(std::size_t vertices = std::size_t{1} << 16, std::size_t indices = std::size_t{3} << 16);
    ~ChunkArena();
    ChunkArena(const ChunkArena&) = delete;
    ChunkArena& operator=(const ChunkArena&) = delete;

    // Writes `mesh` as `id`'s, in place of what it held; the bytes written.
    // A mesh without normals gets zero normals (the shader is told apart).
    // An empty mesh holds no space.
    std::size_t place(ChunkId id, const poly::Mesh& mesh);
    void remove(ChunkId id);
    // Nothing for an id the arena does not hold (or holds empty).
    const ArenaSlot* slot(ChunkId id) const;

    // The vertex array over both buffers; attribute kDrawIdAttribute reads
    // a buffer holding 0, 1, 2, ... one per instance (see ensureDrawIds).
    GLuint vertexArray() const { return vao_.get(); }
    // At least `count` entries in the draw-id buffer.
    void ensureDrawIds(std::size_t count);

    std::size_t capacityBytes() const;
    std::size_t usedBytes() const;
    std::size_t moves() const { return moves_; }  // relocations so far (growth or compaction)

private:
    void relocate(std::size_t vertexCapacity, std::size_t indexCapacity);
    void bindAttributes();

    gl::VertexArray vao_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer drawIds_;
    std::size_t drawIdCount_ = 0;
    RangeAllocator vertexSpace_;
    RangeAllocator indexSpace_;
    std::unordered_map<ChunkId, ArenaSlot> slots_;
    std::size_t moves_ = 0;
};

}  // namespace hg::garden
