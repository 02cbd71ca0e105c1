#include "garden/render/chunk_batch.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

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
    recordOf_.clear();
    pageOf_.clear();
    records_.clear();
}

std::size_t ChunkBatch::addRecord(const DrawRecord& record) {
    const std::size_t index = records();
    for (const glm::vec4& texel : record) records_.insert(records_.end(), {texel.x, texel.y, texel.z, texel.w});
    return index;
}

void ChunkBatch::add(const ArenaSlot& slot, std::size_t record) {
    if (record >= records() || (!recordOf_.empty() && record < recordOf_.back()))
        throw std::logic_error("chunk batch: records must be used in the order they were added");
    Command c{};
    c.count = static_cast<GLuint>(slot.indexCount);
    c.instanceCount = 1;
    c.firstIndex = static_cast<GLuint>(slot.firstIndex);
    c.baseVertex = static_cast<GLint>(slot.firstVertex);
    c.baseInstance = 0;  // set as its page of its group is drawn
    commands_.push_back(c);
    recordOf_.push_back(record);
    pageOf_.push_back(slot.page);
}

bool ChunkBatch::drawsTheSameAs(const ChunkBatch& other) const {
    if (commands_.size() != other.commands_.size() || records_.size() != other.records_.size() ||
        recordOf_ != other.recordOf_ || pageOf_ != other.pageOf_)
        return false;
    for (std::size_t i = 0; i < commands_.size(); ++i) {
        const Command& a = commands_[i];
        const Command& b = other.commands_[i];
        if (a.count != b.count || a.firstIndex != b.firstIndex || a.baseVertex != b.baseVertex) return false;
    }
    // Bit for bit: a record is what the shaders read.
    return records_.empty() || std::memcmp(records_.data(), other.records_.data(), records_.size() * sizeof(float)) == 0;
}

void ChunkBatch::copyDrawsOf(const ChunkBatch& other) {
    commands_ = other.commands_;
    recordOf_ = other.recordOf_;
    pageOf_ = other.pageOf_;
    records_ = other.records_;
}

void ChunkBatch::sendRecords(std::size_t recordFirst, std::size_t recordCount) {
    constexpr std::size_t kFloats = 4 * kDrawRecordTexels;
    // Orphan and refill: the previous view's draws may still be reading.
    glBindBuffer(GL_TEXTURE_BUFFER, recordBuffer_.get());
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(recordCount * kFloats * sizeof(float)),
                 records_.data() + recordFirst * kFloats, GL_STREAM_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

void ChunkBatch::bindPage(const ChunkArena& arena, std::size_t page, bool multiDraw) {
    glBindVertexArray(arena.vertexArray(page));
    if (multiDraw)
        glEnableVertexAttribArray(ChunkArena::kDrawIdAttribute);
    else
        glDisableVertexAttribArray(ChunkArena::kDrawIdAttribute);
}

std::size_t ChunkBatch::draw(ChunkArena& arena, bool multiDraw) {
    if (commands_.empty()) return 0;
    std::size_t calls = 0;
    arena.ensureDrawIds(std::min(maxRecords_, records()));
    glActiveTexture(GL_TEXTURE0 + kDrawRecordUnit);
    glBindTexture(GL_TEXTURE_BUFFER, recordTexture_.get());
    glActiveTexture(GL_TEXTURE0);
    // Groups of commands whose records fit one texture buffer (all of them
    // in one group unless there are tens of thousands of placements).
    for (std::size_t first = 0; first < commands_.size();) {
        const std::size_t recordFirst = recordOf_[first];
        std::size_t end = first;
        while (end < commands_.size() && recordOf_[end] - recordFirst < maxRecords_) ++end;
        sendRecords(recordFirst, recordOf_[end - 1] - recordFirst + 1);
        if (multiDraw) {
            // One call a page: a command's base instance is its record's
            // index within the group, which the identity draw-id buffer
            // hands to the shaders.
            for (std::size_t page = 0; page < arena.pages(); ++page) {
                pageCommands_.clear();
                for (std::size_t k = first; k < end; ++k) {
                    if (pageOf_[k] != page) continue;
                    Command c = commands_[k];
                    c.baseInstance = static_cast<GLuint>(recordOf_[k] - recordFirst);
                    pageCommands_.push_back(c);
                }
                if (pageCommands_.empty()) continue;
                bindPage(arena, page, true);
                glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commandBuffer_.get());
                glBufferData(GL_DRAW_INDIRECT_BUFFER, static_cast<GLsizeiptr>(pageCommands_.size() * sizeof(Command)),
                             pageCommands_.data(), GL_STREAM_DRAW);
                glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr,
                                            static_cast<GLsizei>(pageCommands_.size()), 0);
                glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
                ++calls;
            }
        } else {
            std::size_t bound = arena.pages();  // none yet
            for (std::size_t k = first; k < end; ++k) {
                if (pageOf_[k] != bound) bindPage(arena, bound = pageOf_[k], false);
                const Command& c = commands_[k];
                // The array is disabled: every vertex reads this constant.
                glVertexAttribI1ui(ChunkArena::kDrawIdAttribute, static_cast<GLuint>(recordOf_[k] - recordFirst));
                glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(c.count), GL_UNSIGNED_INT,
                                         reinterpret_cast<const void*>(static_cast<std::size_t>(c.firstIndex) * 4),
                                         c.baseVertex);
                ++calls;
            }
        }
        first = end;
    }
    glActiveTexture(GL_TEXTURE0 + kDrawRecordUnit);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
    return calls;
}

}  // namespace hg::garden
