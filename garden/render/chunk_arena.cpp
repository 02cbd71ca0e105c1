#include "garden/render/chunk_arena.h"

#include <algorithm>
#include <numeric>
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

ChunkArena::ChunkArena(std::size_t vertices, std::size_t indices)
    : vao_(gl::VertexArray::create()), vertexSpace_(vertices), indexSpace_(indices) {
    glBindVertexArray(vao_.get());
    vertices_ = makeBuffer(GL_ARRAY_BUFFER, vertices * kVertexBytes);
    indices_ = makeBuffer(GL_ELEMENT_ARRAY_BUFFER, indices * kIndexBytes);
    drawIds_ = gl::Buffer::create();
    bindAttributes();
    glBindVertexArray(0);
    ensureDrawIds(1024);
}

ChunkArena::~ChunkArena() = default;

void ChunkArena::bindAttributes() {
    // The vertex array is bound by the caller.
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, kVertexBytes, byteOffset(0));
    glEnableVertexAttribArray(kNormalAttribute);
    glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, kVertexBytes, byteOffset(3 * sizeof(float)));
    glBindBuffer(GL_ARRAY_BUFFER, drawIds_.get());
    glVertexAttribIPointer(kDrawIdAttribute, 1, GL_UNSIGNED_INT, sizeof(std::uint32_t), byteOffset(0));
    glVertexAttribDivisor(kDrawIdAttribute, 1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ChunkArena::ensureDrawIds(std::size_t count) {
    if (count <= drawIdCount_) return;
    const std::size_t n = std::max(count, 2 * drawIdCount_);
    std::vector<std::uint32_t> ids(n);
    std::iota(ids.begin(), ids.end(), 0u);
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
    vertexSpace_.release(found->second.firstVertex, found->second.vertexCount);
    indexSpace_.release(found->second.firstIndex, found->second.indexCount);
    slots_.erase(found);
}

std::size_t ChunkArena::place(ChunkId id, const poly::Mesh& mesh) {
    remove(id);
    const std::size_t vertexCount = mesh.vertexCount();
    const std::size_t indexCount = mesh.indices.size();
    if (vertexCount == 0 || indexCount == 0) return 0;

    std::optional<std::size_t> v = vertexSpace_.allocate(vertexCount);
    std::optional<std::size_t> i = v ? indexSpace_.allocate(indexCount) : std::nullopt;
    if (!v || !i) {
        if (v) vertexSpace_.release(*v, vertexCount);
        // Packed, the live ranges leave the free space in one piece at the
        // end; double the buffers when even that is short.
        auto fit = [](const RangeAllocator& space, std::size_t need) {
            std::size_t capacity = std::max<std::size_t>(space.capacity(), 1);
            while (capacity - space.used() < need) capacity *= 2;
            return capacity;
        };
        relocate(fit(vertexSpace_, vertexCount), fit(indexSpace_, indexCount));
        v = vertexSpace_.allocate(vertexCount);
        i = indexSpace_.allocate(indexCount);
    }

    std::vector<float> interleaved(vertexCount * 6, 0.0f);
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (std::size_t k = 0; k < vertexCount; ++k) {
        std::copy_n(&mesh.positions[3 * k], 3, &interleaved[6 * k]);
        if (normals) std::copy_n(&mesh.normals[3 * k], 3, &interleaved[6 * k + 3]);
    }
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glBufferSubData(GL_ARRAY_BUFFER, bytes(*v * kVertexBytes), bytes(vertexCount * kVertexBytes), interleaved.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    // The element buffer is the vertex array's: bind that, not the buffer alone.
    glBindVertexArray(vao_.get());
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, bytes(*i * kIndexBytes), bytes(indexCount * kIndexBytes),
                    mesh.indices.data());
    glBindVertexArray(0);
    slots_[id] = ArenaSlot{*v, vertexCount, *i, indexCount};
    return vertexCount * kVertexBytes + indexCount * kIndexBytes;
}

void ChunkArena::relocate(std::size_t vertexCapacity, std::size_t indexCapacity) {
    gl::Buffer newVertices = makeBuffer(GL_COPY_WRITE_BUFFER, vertexCapacity * kVertexBytes);
    gl::Buffer newIndices = makeBuffer(GL_COPY_WRITE_BUFFER, indexCapacity * kIndexBytes);
    // In the order the ranges lie now, so neighbours stay neighbours.
    std::vector<ArenaSlot*> live;
    live.reserve(slots_.size());
    for (auto& [id, s] : slots_) live.push_back(&s);
    std::sort(live.begin(), live.end(), [](const ArenaSlot* a, const ArenaSlot* b) { return a->firstVertex < b->firstVertex; });

    RangeAllocator vertexSpace(vertexCapacity), indexSpace(indexCapacity);
    auto copy = [](GLuint from, GLuint to, std::size_t src, std::size_t dst, std::size_t size) {
        glBindBuffer(GL_COPY_READ_BUFFER, from);
        glBindBuffer(GL_COPY_WRITE_BUFFER, to);
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, bytes(src), bytes(dst), bytes(size));
    };
    for (ArenaSlot* s : live) {
        const std::size_t v = *vertexSpace.allocate(s->vertexCount);
        const std::size_t i = *indexSpace.allocate(s->indexCount);
        copy(vertices_.get(), newVertices.get(), s->firstVertex * kVertexBytes, v * kVertexBytes,
             s->vertexCount * kVertexBytes);
        copy(indices_.get(), newIndices.get(), s->firstIndex * kIndexBytes, i * kIndexBytes,
             s->indexCount * kIndexBytes);
        s->firstVertex = v;
        s->firstIndex = i;
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    vertices_ = std::move(newVertices);
    indices_ = std::move(newIndices);
    vertexSpace_ = vertexSpace;
    indexSpace_ = indexSpace;
    glBindVertexArray(vao_.get());
    bindAttributes();
    glBindVertexArray(0);
    ++moves_;
}

std::size_t ChunkArena::capacityBytes() const {
    return vertexSpace_.capacity() * kVertexBytes + indexSpace_.capacity() * kIndexBytes;
}

std::size_t ChunkArena::usedBytes() const {
    return vertexSpace_.used() * kVertexBytes + indexSpace_.used() * kIndexBytes;
}

}  // namespace hg::garden
