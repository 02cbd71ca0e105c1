#include "garden/render/chunk_batch.h"

#include <algorithm>

namespace hg::garden {

bool multiDrawAvailable() {
    if (epoxy_gl_version() >= 43) return true;
    return epoxy_has_gl_extension("GL_ARB_multi_draw_indirect") && epoxy_has_gl_extension("GL_ARB_base_instance");
}

ChunkBatch::ChunkBatch()
    : recordBuffer_(gl::Buffer::create()), recordTexture_(gl::Texture::create()), commandBuffer_(gl::Buffer::create()) {
    GLint texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
    // GL 3.3 promises 65,536 texels: 7,281 draws a group at the least.
    maxRecords_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::max(texels, 65536)) / kDrawRecordTexels);
    glBindBuffer(GL_TEXTURE_BUFFER, recordBuffer_.get());
    glBufferData(GL_TEXTURE_BUFFER, sizeof(DrawRecord), nullptr, GL_STREAM_DRAW);
    glBindTexture(GL_TEXTURE_BUFFER, recordTexture_.get());
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, recordBuffer_.get());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

ChunkBatch::~ChunkBatch() = default;

void ChunkBatch::clear() {
    commands_.clear();
    records_.clear();
    sent_ = false;
}

void ChunkBatch::add(const ArenaSlot& slot, const DrawRecord& record) {
    Command c{};
    c.count = static_cast<GLuint>(slot.indexCount);
    c.instanceCount = 1;
    c.firstIndex = static_cast<GLuint>(slot.firstIndex);
    c.baseVertex = static_cast<GLint>(slot.firstVertex);
    c.baseInstance = 0;  // set per group in send()
    commands_.push_back(c);
    for (const glm::vec4& texel : record) records_.insert(records_.end(), {texel.x, texel.y, texel.z, texel.w});
    sent_ = false;
}

void ChunkBatch::send(std::size_t first, std::size_t count, bool commands) {
    if (sent_ && sentFirst_ == first && sentCount_ == count && (sentCommands_ || !commands)) return;
    constexpr std::size_t kFloats = 4 * kDrawRecordTexels;
    // Orphan and refill: the previous view's draws may still be reading.
    glBindBuffer(GL_TEXTURE_BUFFER, recordBuffer_.get());
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(count * kFloats * sizeof(float)),
                 records_.data() + first * kFloats, GL_STREAM_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    // Within a group, draw k's base instance is k: the identity draw-id
    // buffer turns it into its record's index.
    for (std::size_t k = 0; k < count; ++k) commands_[first + k].baseInstance = static_cast<GLuint>(k);
    // GL 3.3 has no indirect buffer binding at all.
    if (commands) {
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commandBuffer_.get());
        glBufferData(GL_DRAW_INDIRECT_BUFFER, static_cast<GLsizeiptr>(count * sizeof(Command)),
                     commands_.data() + first, GL_STREAM_DRAW);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    }
    sentCommands_ = commands;
    sent_ = true;
    sentFirst_ = first;
    sentCount_ = count;
}

std::size_t ChunkBatch::draw(ChunkArena& arena, bool multiDraw) {
    if (commands_.empty()) return 0;
    std::size_t calls = 0;
    const std::size_t group = std::min(maxRecords_, commands_.size());
    arena.ensureDrawIds(group);
    glBindVertexArray(arena.vertexArray());
    if (multiDraw)
        glEnableVertexAttribArray(ChunkArena::kDrawIdAttribute);
    else
        glDisableVertexAttribArray(ChunkArena::kDrawIdAttribute);
    glActiveTexture(GL_TEXTURE0 + kDrawRecordUnit);
    glBindTexture(GL_TEXTURE_BUFFER, recordTexture_.get());
    glActiveTexture(GL_TEXTURE0);
    for (std::size_t first = 0; first < commands_.size(); first += group) {
        const std::size_t count = std::min(group, commands_.size() - first);
        send(first, count, multiDraw);
        if (multiDraw) {
            glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commandBuffer_.get());
            glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, static_cast<GLsizei>(count), 0);
            glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
            ++calls;
            continue;
        }
        for (std::size_t k = 0; k < count; ++k) {
            const Command& c = commands_[first + k];
            // The array is disabled: every vertex reads this constant.
            glVertexAttribI1ui(ChunkArena::kDrawIdAttribute, static_cast<GLuint>(k));
            glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(c.count), GL_UNSIGNED_INT,
                                     reinterpret_cast<const void*>(static_cast<std::size_t>(c.firstIndex) * 4),
                                     c.baseVertex);
            ++calls;
        }
    }
    glActiveTexture(GL_TEXTURE0 + kDrawRecordUnit);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
    return calls;
}

}  // namespace hg::garden
