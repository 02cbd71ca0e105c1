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

void ChunkArena::remove(ChunkId id) {
    auto found = slots_.find(id);
    if (found == slots_.end()) return;
    const ArenaSlot& s = found->second;
    Page& page = *pages_[s.page];
    page.vertexSpace.release(s.firstVertex, s.vertexCount);
    page.indexSpace.release(s.firstIndex, s.indexCount);
    // A page other than the first goes when its last chunk does.
    if (--page.chunks == 0 && s.page > 0) pages_[s.page].reset();
    slots_.erase(found);
}

std::size_t ChunkArena::place(ChunkId id, const poly::Mesh& mesh) {
    remove(id);
    const std::size_t vertexCount = mesh.vertexCount();
    const std::size_t indexCount = mesh.indices.size();
    if (vertexCount == 0 || indexCount == 0) return 0;

    // The first page that holds both ranges, else a new one.
    ArenaSlot slot{0, 0, vertexCount, 0, indexCount};
    auto fits = [&](std::size_t p) {
        if (!hasPage(p)) return false;
        Page& page = *pages_[p];
        const std::optional<std::size_t> v = page.vertexSpace.allocate(vertexCount);
        if (!v) return false;
        const std::optional<std::size_t> i = page.indexSpace.allocate(indexCount);
        if (!i) {
            page.vertexSpace.release(*v, vertexCount);
            return false;
        }
        slot.page = p;
        slot.firstVertex = *v;
        slot.firstIndex = *i;
        return true;
    };
    bool placed = false;
    for (std::size_t p = 0; p < pages_.size() && !placed; ++p) placed = fits(p);
    if (!placed) {
        std::size_t largest = firstVertices_;
        for (const auto& page : pages_)
            if (page) largest = std::max(largest, page->vertexSpace.capacity());
        const std::size_t vertices = std::max(vertexCount, std::min(2 * largest, kMaxPageVertices));
        // Indices in the first page's proportion to its vertices.
        const std::size_t indices = std::max(indexCount, vertices * firstIndices_ / std::max<std::size_t>(firstVertices_, 1));
        if (!fits(makePage(vertices, indices))) throw std::logic_error("chunk arena: a new page too small for its mesh");
    }
    Page& page = *pages_[slot.page];
    ++page.chunks;

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
    return vertexCount * kVertexBytes + indexCount * kIndexBytes;
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
