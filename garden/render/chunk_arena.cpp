#include "garden/render/chunk_arena.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <vector>

namespace hg::garden {
namespace {

constexpr std::size_t kVertexBytes = 6 * sizeof(float);  // position, normal
constexpr std::size_t kIndexBytes = sizeof(std::uint32_t);

const void* byteOffset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

GLsizeiptr bytes(std::size_t n) { return static_cast<GLsizeiptr>(n); }

std::size_t slotBytes(const ArenaSlot& s) { return s.vertexCount * kVertexBytes + s.indexCount * kIndexBytes; }

gl::Buffer makeBuffer(GLenum target, std::size_t size) {
    gl::Buffer b = gl::Buffer::create();
    glBindBuffer(target, b.get());
    glBufferData(target, bytes(std::max<std::size_t>(size, 1)), nullptr, GL_STATIC_DRAW);
    return b;
}

}  // namespace

struct ChunkArena::Page {
    gl::VertexArray vao;
    gl::Buffer vertices, indices;
    RangeAllocator vertexSpace, indexSpace;
    std::size_t chunks = 0;
};

ChunkArena::ChunkArena(std::size_t vertices, std::size_t indices)
    : drawIds_(gl::Buffer::create()), firstVertices_(vertices), firstIndices_(indices) {
    ensureDrawIds(1024);
    makePage(vertices, indices);
}

ChunkArena::~ChunkArena() = default;

std::size_t ChunkArena::makePage(std::size_t vertices, std::size_t indices) {
    auto page = std::make_unique<Page>();
    page->vao = gl::VertexArray::create();
    page->vertexSpace = RangeAllocator(vertices);
    page->indexSpace = RangeAllocator(indices);
    glBindVertexArray(page->vao.get());
    page->vertices = makeBuffer(GL_ARRAY_BUFFER, vertices * kVertexBytes);
    page->indices = makeBuffer(GL_ELEMENT_ARRAY_BUFFER, indices * kIndexBytes);
    bindAttributes(*page);
    glBindVertexArray(0);
    ++pagesMade_;
    const auto empty = std::find(pages_.begin(), pages_.end(), nullptr);
    if (empty != pages_.end()) {
        *empty = std::move(page);
        return static_cast<std::size_t>(empty - pages_.begin());
    }
    pages_.push_back(std::move(page));
    return pages_.size() - 1;
}

void ChunkArena::bindAttributes(const Page& page) {
    // The page's vertex array is bound by the caller.
    glBindBuffer(GL_ARRAY_BUFFER, page.vertices.get());
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, kVertexBytes, byteOffset(0));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, kVertexBytes, byteOffset(3 * sizeof(float)));
    glBindBuffer(GL_ARRAY_BUFFER, drawIds_.get());
    glVertexAttribIPointer(kDrawIdAttribute, 1, GL_UNSIGNED_INT, sizeof(std::uint32_t), byteOffset(0));
    glVertexAttribDivisor(kDrawIdAttribute, 1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, page.indices.get());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GLuint ChunkArena::vertexArray(std::size_t page) const { return hasPage(page) ? pages_[page]->vao.get() : 0; }

void ChunkArena::ensureDrawIds(std::size_t count) {
    if (count <= drawIdCount_) return;
    const std::size_t n = std::max(count, 2 * drawIdCount_);
    std::vector<std::uint32_t> ids(n);
    std::iota(ids.begin(), ids.end(), 0u);
    // Refilled in place: the pages' vertex arrays name this buffer.
    glBindBuffer(GL_ARRAY_BUFFER, drawIds_.get());
    glBufferData(GL_ARRAY_BUFFER, bytes(n * sizeof(std::uint32_t)), ids.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    drawIdCount_ = n;
}

const ArenaSlot* ChunkArena::slot(ChunkId id) const {
    auto found = slots_.find(id);
    return found == slots_.end() ? nullptr : &found->second;
}

void ChunkArena::release(const ArenaSlot& s) {
    Page& page = *pages_[s.page];
    page.vertexSpace.release(s.firstVertex, s.vertexCount);
    page.indexSpace.release(s.firstIndex, s.indexCount);
    // A page other than the first goes when its last chunk does.
    if (--page.chunks == 0 && s.page > 0) {
        pages_[s.page].reset();
        if (s.page == evacuating_) {
            evacuating_ = kNoPage;
            evacuees_.clear();
        }
    }
}

void ChunkArena::remove(ChunkId id) {
    auto found = slots_.find(id);
    if (found == slots_.end()) return;
    ++changes_;
    release(found->second);
    slots_.erase(found);
}

bool ChunkArena::allocateIn(std::size_t p, std::size_t vertices, std::size_t indices, ArenaSlot& slot) {
    if (!hasPage(p)) return false;
    Page& page = *pages_[p];
    const std::optional<std::size_t> v = page.vertexSpace.allocate(vertices);
    if (!v) return false;
    const std::optional<std::size_t> i = page.indexSpace.allocate(indices);
    if (!i) {
        page.vertexSpace.release(*v, vertices);
        return false;
    }
    slot = ArenaSlot{p, *v, vertices, *i, indices};
    ++page.chunks;
    return true;
}

std::size_t ChunkArena::place(ChunkId id, const poly::Mesh& mesh) {
    remove(id);
    const std::size_t vertexCount = mesh.vertexCount();
    const std::size_t indexCount = mesh.indices.size();
    if (vertexCount == 0 || indexCount == 0) return 0;

    ++changes_;

    // The first page that holds both ranges (the one being emptied last),
    // else a new one.
    ArenaSlot slot;
    bool placed = false;
    for (std::size_t p = 0; p < pages_.size() && !placed; ++p)
        placed = p != evacuating_ && allocateIn(p, vertexCount, indexCount, slot);
    if (!placed && evacuating_ != kNoPage) placed = allocateIn(evacuating_, vertexCount, indexCount, slot);
    if (!placed) {
        std::size_t largest = firstVertices_;
        for (const auto& page : pages_)
            if (page) largest = std::max(largest, page->vertexSpace.capacity());
        const std::size_t vertices = std::max(vertexCount, std::min(2 * largest, kMaxPageVertices));
        // Indices in the first page's proportion to its vertices.
        const std::size_t indices = std::max(indexCount, vertices * firstIndices_ / std::max<std::size_t>(firstVertices_, 1));
        if (!allocateIn(makePage(vertices, indices), vertexCount, indexCount, slot))
            throw std::logic_error("chunk arena: a new page too small for its mesh");
    }
    Page& page = *pages_[slot.page];

    std::vector<float> interleaved(vertexCount * 6, 0.0f);
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (std::size_t k = 0; k < vertexCount; ++k) {
        std::copy_n(&mesh.positions[3 * k], 3, &interleaved[6 * k]);
        if (normals) std::copy_n(&mesh.normals[3 * k], 3, &interleaved[6 * k + 3]);
    }
    glBindBuffer(GL_ARRAY_BUFFER, page.vertices.get());
    glBufferSubData(GL_ARRAY_BUFFER, bytes(slot.firstVertex * kVertexBytes), bytes(vertexCount * kVertexBytes),
                    interleaved.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    // The element buffer is the vertex array's: bind that, not the buffer alone.
    glBindVertexArray(page.vao.get());
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, bytes(slot.firstIndex * kIndexBytes), bytes(indexCount * kIndexBytes),
                    mesh.indices.data());
    glBindVertexArray(0);
    slots_[id] = slot;
    return slotBytes(slot);
}

// --- background defragmentation ---------------------------------------------------

namespace {

double fill(const RangeAllocator& space) {
    return space.capacity() == 0 ? 1.0 : static_cast<double>(space.used()) / static_cast<double>(space.capacity());
}

void copyBytes(GLuint from, std::size_t fromByte, GLuint to, std::size_t toByte, std::size_t count) {
    glBindBuffer(GL_COPY_READ_BUFFER, from);
    glBindBuffer(GL_COPY_WRITE_BUFFER, to);
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(fromByte),
                        static_cast<GLintptr>(toByte), bytes(count));
}

}  // namespace

double ChunkArena::fullness(std::size_t p) const {
    return std::max(fill(pages_[p]->vertexSpace), fill(pages_[p]->indexSpace));
}

bool ChunkArena::chooseEvacuee() {
    std::size_t freeVertices = 0, freeIndices = 0;
    for (const auto& page : pages_)
        if (page) {
            freeVertices += page->vertexSpace.unused();
            freeIndices += page->indexSpace.unused();
        }
    std::size_t best = kNoPage;
    for (std::size_t p = 1; p < pages_.size(); ++p) {
        if (!hasPage(p) || fullness(p) >= kCompactBelow) continue;
        const Page& page = *pages_[p];
        // Its chunks must fit half the others' free space: the others keep
        // room for what comes next, or a page would be made again at once
        // (and half is a need, not a promise: free space can be in pieces
        // too small; move() finds out).
        const std::size_t otherVertices = freeVertices - page.vertexSpace.unused();
        const std::size_t otherIndices = freeIndices - page.indexSpace.unused();
        if (2 * page.vertexSpace.used() > otherVertices || 2 * page.indexSpace.used() > otherIndices) continue;
        if (best == kNoPage || fullness(p) < fullness(best)) best = p;
    }
    if (best == kNoPage) return false;
    evacuating_ = best;
    evacuees_.clear();
    for (const auto& [id, s] : slots_)
        if (s.page == best) evacuees_.push_back(id);
    // Taken from the back: the smallest last, where free pieces are likeliest.
    std::sort(evacuees_.begin(), evacuees_.end(), [&](ChunkId a, ChunkId b) {
        const std::size_t sa = slotBytes(slots_.at(a)), sb = slotBytes(slots_.at(b));
        return sa != sb ? sa < sb : a < b;
    });
    return true;
}

bool ChunkArena::move(ChunkId id, const std::vector<std::size_t>& into) {
    ArenaSlot& from = slots_.at(id);
    ArenaSlot to;
    bool found = false;
    for (std::size_t p : into)
        if ((found = allocateIn(p, from.vertexCount, from.indexCount, to))) break;
    if (!found) return false;
    const Page& source = *pages_[from.page];
    const Page& target = *pages_[to.page];
    copyBytes(source.vertices.get(), from.firstVertex * kVertexBytes, target.vertices.get(), to.firstVertex * kVertexBytes,
              from.vertexCount * kVertexBytes);
    copyBytes(source.indices.get(), from.firstIndex * kIndexBytes, target.indices.get(), to.firstIndex * kIndexBytes,
              from.indexCount * kIndexBytes);
    const ArenaSlot old = from;
    from = to;
    release(old);
    bytesMoved_ += slotBytes(to);
    ++chunksMoved_;
    return true;
}

std::size_t ChunkArena::compact(std::size_t byteBudget) {
    if (byteBudget == 0 || changes_ == settledAt_) return 0;
    if (evacuating_ == kNoPage && !chooseEvacuee()) {
        settledAt_ = changes_;  // nothing to do until a chunk comes or goes
        return 0;
    }
    // Into the fullest pages first: the sparse ones are emptied in their turn.
    std::vector<std::size_t> into;
    for (std::size_t p = 0; p < pages_.size(); ++p)
        if (hasPage(p) && p != evacuating_) into.push_back(p);
    std::stable_sort(into.begin(), into.end(), [&](std::size_t a, std::size_t b) { return fullness(a) > fullness(b); });
    std::size_t moved = 0;
    while (evacuating_ != kNoPage && !evacuees_.empty() && moved < byteBudget) {
        const ChunkId id = evacuees_.back();
        auto s = slots_.find(id);
        // Gone or placed again since the page was chosen: not this page's now.
        if (s == slots_.end() || s->second.page != evacuating_) {
            evacuees_.pop_back();
            continue;
        }
        const std::size_t size = slotBytes(s->second);
        if (!move(id, into)) {
            // The free space is in pieces too small: try again when a chunk comes or goes.
            evacuating_ = kNoPage;
            evacuees_.clear();
            settledAt_ = changes_;
            break;
        }
        moved += size;
        if (evacuating_ != kNoPage) evacuees_.pop_back();  // the last one's move let the page go
    }
    if (evacuating_ != kNoPage && evacuees_.empty()) evacuating_ = kNoPage;
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    return moved;
}

std::size_t ChunkArena::livePages() const {
    return static_cast<std::size_t>(std::count_if(pages_.begin(), pages_.end(), [](const auto& p) { return p != nullptr; }));
}

std::size_t ChunkArena::capacityBytes() const {
    std::size_t n = 0;
    for (const auto& page : pages_)
        if (page) n += page->vertexSpace.capacity() * kVertexBytes + page->indexSpace.capacity() * kIndexBytes;
    return n;
}

std::size_t ChunkArena::usedBytes() const {
    std::size_t n = 0;
    for (const auto& page : pages_)
        if (page) n += page->vertexSpace.used() * kVertexBytes + page->indexSpace.used() * kIndexBytes;
    return n;
}

}  // namespace hg::garden
