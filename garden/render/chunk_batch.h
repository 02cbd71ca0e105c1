// One view's chunk draws as a batch: records of transform and material in
// a texture buffer (one per placement: every chunk of a sculpture shares
// its sculpture's), and per chunk a command naming its range in the chunk
// arena and its record. Drawn with one glMultiDrawElementsIndirect per
// arena page where GL 4.3 (or ARB_multi_draw_indirect with
// ARB_base_instance) is present, each command's base instance selecting
// its record; else, on GL 3.3, one glDrawElementsBaseVertex per chunk with
// the record's index as a constant attribute. Both paths use the same programs and records, so they give the
// same pixels (docs/rendering.md, "Batched drawing").
//
// Programs that draw a batch declare HG_DRAW_RECORD_GLSL (shaders.h) and
// read the records from texture unit kDrawRecordUnit.
#pragma once

#include <glm/vec4.hpp>

#include <array>

#include <cstddef>
#include <vector>

#include "garden/render/chunk_arena.h"
#include "garden/render/gl_objects.h"

namespace hg::garden {

// The texture unit the batch's records are bound to while it draws.
constexpr GLint kDrawRecordUnit = 4;
// vec4 texels per draw record (shaders.h's HG_DRAW_RECORD_GLSL reads them).
constexpr int kDrawRecordTexels = 10;
// A draw's record as the shaders read it; renderer.cpp fills it.
using DrawRecord = std::array<glm::vec4, kDrawRecordTexels>;

// Whether this context can draw a batch in one call (GL 4.3, or 3.3 with
// ARB_multi_draw_indirect and ARB_base_instance).
bool multiDrawAvailable();

class ChunkBatch {
public:
    ChunkBatch();
    ~ChunkBatch();
    ChunkBatch(const ChunkBatch&) = delete;
    ChunkBatch& operator=(const ChunkBatch&) = delete;

    void clear();
    // A record for the chunks that follow; its index.
    std::size_t addRecord(const DrawRecord& record);
    // A chunk drawn with record `record`: records are used in the order
    // they were added (std::logic_error otherwise), so a group of draws
    // needs one contiguous range of them.
    void add(const ArenaSlot& slot, std::size_t record);
    std::size_t size() const { return commands_.size(); }
    std::size_t records() const { return records_.size() / (4 * kDrawRecordTexels); }
    bool empty() const { return commands_.empty(); }

    // Draws every chunk with the program in use, whose draw records are
    // read from kDrawRecordUnit; `multiDraw` false takes the one-call-a-chunk
    // path. Returns the GL draw calls made.
    std::size_t draw(ChunkArena& arena, bool multiDraw);

    // Whether `other` holds exactly this batch's draws: the same ranges of
    // the same pages with the same records (what a pass drawn from either
    // would show, given the same arena contents).
    bool drawsTheSameAs(const ChunkBatch& other) const;
    // This batch's draws made `other`'s (no GL call: a copy to compare later).
    void copyDrawsOf(const ChunkBatch& other);

private:
    struct Command {  // GL's DrawElementsIndirectCommand
        GLuint count;
        GLuint instanceCount;
        GLuint firstIndex;
        GLint baseVertex;
        GLuint baseInstance;
    };
    // Sends the records [recordFirst, recordFirst + recordCount).
    void sendRecords(std::size_t recordFirst, std::size_t recordCount);
    // Binds `page`'s vertex array, the draw-id attribute an array for a
    // multi-draw and a constant otherwise (vertex-array state).
    static void bindPage(const ChunkArena& arena, std::size_t page, bool multiDraw);

    std::vector<Command> commands_;
    std::vector<std::size_t> recordOf_;  // per command
    std::vector<std::size_t> pageOf_;    // per command: its arena page
    std::vector<Command> pageCommands_;  // one page's commands of a group, as sent
    std::vector<float> records_;         // kDrawRecordTexels * 4 floats per record
    gl::Buffer recordBuffer_;
    gl::Texture recordTexture_;
    gl::Buffer commandBuffer_;
    std::size_t maxRecords_ = 0;  // what one texture buffer can hold
};

}  // namespace hg::garden
