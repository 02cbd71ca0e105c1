// Every chunk mesh of the garden in a few large GPU buffers: pages, each
// one buffer of vertices (position and normal, interleaved) and one of
// indices, sub-allocated by RangeAllocators, under its own vertex array.
// Drawing many chunks then needs a buffer switch only between pages, which
// is what lets a whole view go out as one multi-draw a page (chunk_batch.h;
// docs/rendering.md, "Batched drawing").
//
// When a mesh fits no page, a new page is made (twice the largest live
// one, up to kMaxPageVertices, and never short of the mesh): nothing
// already placed moves. An arena that moved every live range into larger
// buffers instead held the frame that outgrew it for tens of milliseconds
// (a copy call per chunk, and a stall on buffers the GPU still read); a
// page left empty is let go. Indices stay relative to their chunk's first
// vertex (drawn with a base vertex). Needs its GL context current in every
// call, the destructor too.
//
// Pages made while a garden arrives stay, part empty, as the visitor's
// walk moves chunks between levels. compact(), called a little each frame,
// empties the sparsest such page into the others, GPU to GPU, within a
// byte budget (docs/rendering.md, "The arena": defragmented in the
// background).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "garden/render/gl_objects.h"
#include "garden/render/range_allocator.h"
#include "polygonizer/mesh.h"

namespace hg::garden {

using ChunkId = std::uint64_t;

// Where a chunk's mesh lies in the arena, in vertices and indices.
struct ArenaSlot {
    std::size_t page = 0;  // whose buffers (ChunkArena::vertexArray(page))
    std::size_t firstVertex = 0;
    std::size_t vertexCount = 0;
    std::size_t firstIndex = 0;
    std::size_t indexCount = 0;
};

class ChunkArena {
public:
    // Attribute locations of the vertex arrays: position, normal, draw id.
    static constexpr GLuint kPositionAttribute = 0;
    static constexpr GLuint kNormalAttribute = 1;
    static constexpr GLuint kDrawIdAttribute = 2;
    // The largest page made for meshes that fit it: 48 MiB of vertices.
    static constexpr std::size_t kMaxPageVertices = std::size_t{1} << 21;

    // The first page's size, in vertices and indices; later pages keep its
    // proportion. Six indices a vertex: a closed triangle mesh has about two
    // triangles a vertex, and the garden's chunk meshes measured 5.4 (at
    // three, the index buffers filled with the vertex buffers under half
    // used, and a sparse page had nowhere to go).
    explicit ChunkArena(std::size_t vertices = std::size_t{1} << 16, std::size_t indices = std::size_t{6} << 16);
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

    // Page slots (a page let go leaves its slot empty, for the next one).
    std::size_t pages() const { return pages_.size(); }
    bool hasPage(std::size_t page) const { return page < pages_.size() && pages_[page] != nullptr; }
    // The vertex array over a page's buffers; attribute kDrawIdAttribute
    // reads a buffer holding 0, 1, 2, ... one per instance (ensureDrawIds).
    GLuint vertexArray(std::size_t page) const;
    // At least `count` entries in the draw-id buffer.
    void ensureDrawIds(std::size_t count);

    // Background defragmentation. Moves chunks out of the sparsest page
    // other than the first that is less than kCompactBelow full and whose
    // chunks fit half the other pages' free space, into the fullest pages that
    // hold them (glCopyBufferSubData: the bytes never leave the GPU), until
    // `byteBudget` bytes are moved (at least one chunk when the budget is
    // not 0). The page goes when emptied; new meshes go elsewhere while it
    // empties. Returns the bytes moved: 0 at once, without a look at the
    // pages, while nothing was placed or removed since the last call found
    // nothing to do. Call between views, not while a batch is built: slots
    // change.
    std::size_t compact(std::size_t byteBudget);
    static constexpr double kCompactBelow = 0.5;

    std::size_t capacityBytes() const;
    std::size_t usedBytes() const;
    std::size_t livePages() const;
    std::size_t pagesMade() const { return pagesMade_; }  // pages made so far, the first included
    std::size_t bytesMoved() const { return bytesMoved_; }  // by compact(), so far
    std::size_t chunksMoved() const { return chunksMoved_; }
    // Changes with every place, remove and move: equal generations hold
    // the same bytes in the same places (a pass drawn from the arena can
    // be kept while it stays).
    std::size_t generation() const { return changes_ + chunksMoved_; }

private:
    struct Page;
    static constexpr std::size_t kNoPage = static_cast<std::size_t>(-1);
    std::size_t makePage(std::size_t vertices, std::size_t indices);
    void bindAttributes(const Page& page);
    // Takes `vertices` vertices and `indices` indices from page `p` into
    // `slot`; false (and nothing taken) when the page lacks either.
    bool allocateIn(std::size_t p, std::size_t vertices, std::size_t indices, ArenaSlot& slot);
    // Gives a slot's ranges back; a page other than the first goes with its last chunk.
    void release(const ArenaSlot& slot);
    // How full page `p` is: the fuller of its two buffers.
    double fullness(std::size_t p) const;
    // The page compact() should empty, and its chunks, largest first; false when none.
    bool chooseEvacuee();
    // Moves chunk `id` out of its page into another; false when none holds it.
    bool move(ChunkId id, const std::vector<std::size_t>& into);

    std::vector<std::unique_ptr<Page>> pages_;  // null: let go
    gl::Buffer drawIds_;
    std::size_t drawIdCount_ = 0;
    std::size_t firstVertices_, firstIndices_;  // the first page's size
    std::unordered_map<ChunkId, ArenaSlot> slots_;
    std::size_t pagesMade_ = 0;
    // Background defragmentation: the page being emptied and what is left
    // to move out of it; place()/remove() calls so far, and their count
    // when compact() last found nothing to do.
    std::size_t evacuating_ = kNoPage;
    std::vector<ChunkId> evacuees_;
    std::size_t changes_ = 0, settledAt_ = kNoPage;
    std::size_t bytesMoved_ = 0, chunksMoved_ = 0;
};

}  // namespace hg::garden
