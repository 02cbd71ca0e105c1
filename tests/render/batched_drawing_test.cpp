// Batched drawing: every chunk in one arena, a view's chunks in one
// multi-draw. The multi-draw and the one-call-a-chunk fallback give the
// same pixels; the arena keeps every chunk's bytes, where it was placed,
// through growth into new pages and reuse (read back from the GPU).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <set>
#include <vector>

#include "garden/render/chunk_arena.h"
#include "garden/render/chunk_batch.h"
#include "garden/render/shapes.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

class BatchedDrawing : public GlTest {
protected:
    // A few dozen spheres of several sizes, materials and transforms (one
    // squashed, one without normals), on the ground, lit by the sun.
    std::vector<std::uint8_t> renderScene(bool multiDraw, const RenderQuality& quality) {
        EXPECT_EQ(renderer_->setMultiDraw(multiDraw), multiDraw);
        // Each path draws its own shadow map (not the one the other path left).
        renderer_->setShadowReuse(false);
        renderer_->setQuality(quality);
        target_->bind();
        renderer_->beginFrame(makeView({0.0f, 4.0f, 9.0f}, {0.0f, 0.5f, 0.0f}));
        renderer_->drawGround(GroundStyle{});
        int k = 0;
        for (int z = -3; z <= 1; ++z)
            for (int x = -4; x <= 4; ++x, ++k) {
                const ChunkId id = static_cast<ChunkId>(1 + k % 4);
                glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(x * 0.9f, 0.4f, z * 1.1f));
                if (k % 5 == 0) m = glm::scale(m, glm::vec3(1.0f, 0.5f, 1.3f));
                const RenderMaterial material{{0.2f + 0.07f * float(k % 10), 0.5f, 0.9f - 0.08f * float(k % 9)},
                                              0.1f * float(k % 4), 8.0f + 4.0f * float(k % 6)};
                EXPECT_TRUE(renderer_->drawChunk(id, m, material));
                // A sculpture of several chunks: the same placement and
                // material again (one record for them all).
                if (k % 3 == 0) {
                    EXPECT_TRUE(renderer_->drawChunk(1 + (id % 4), m, material));
                    EXPECT_TRUE(renderer_->drawChunk(1 + ((id + 1) % 4), m, material));
                }
            }
        lastStats_ = renderer_->endFrame();
        read();
        return color_;
    }

    void uploadShapes() {
        renderer_->upload(1, 1, uvSphereMesh(0.35f, 48, 24));
        renderer_->upload(2, 1, uvSphereMesh(0.25f, 12, 6));
        renderer_->upload(3, 1, uvSphereMesh(0.4f, 32, 16));
        poly::Mesh bare = uvSphereMesh(0.3f, 24, 12);
        bare.normals.clear();
        renderer_->upload(4, 1, bare);
    }

    RenderStats lastStats_;
};

const RenderMaterial kRedMaterial{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f};

RenderQuality everything() {
    RenderQuality q;  // MSAA, shadows, occlusion: every pass that draws chunks
    return q;
}

// Reads chunk `id` back through its page's vertex array's bindings: the
// bytes must be `m`'s.
void expectHeld(const ChunkArena& arena, ChunkId id, const poly::Mesh& m) {
    const ArenaSlot* s = arena.slot(id);
    ASSERT_NE(s, nullptr) << id;
    ASSERT_EQ(s->vertexCount, m.vertexCount());
    ASSERT_EQ(s->indexCount, m.indices.size());
    glBindVertexArray(arena.vertexArray(s->page));
    GLint vertexBuffer = 0, indexBuffer = 0;
    glGetVertexAttribiv(ChunkArena::kPositionAttribute, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &vertexBuffer);
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &indexBuffer);
    glBindVertexArray(0);
    std::vector<float> v(6 * s->vertexCount);
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(vertexBuffer));
    glGetBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(s->firstVertex * 6 * sizeof(float)),
                       static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data());
    std::vector<std::uint32_t> i(s->indexCount);
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(indexBuffer));
    glGetBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(s->firstIndex * sizeof(std::uint32_t)),
                       static_cast<GLsizeiptr>(i.size() * sizeof(std::uint32_t)), i.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    for (std::size_t n = 0; n < s->vertexCount; ++n)
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(v[6 * n + c], m.positions[3 * n + c]) << "chunk " << id << " vertex " << n;
            ASSERT_EQ(v[6 * n + 3 + c], m.normals[3 * n + c]) << "chunk " << id << " vertex " << n;
        }
    EXPECT_EQ(i, m.indices) << "chunk " << id;
}

TEST_F(BatchedDrawing, MultiDrawAndOneCallPerChunkGiveTheSamePixels) {
    if (!multiDrawAvailable()) GTEST_FAIL() << "llvmpipe offers GL 4.5: multi-draw must be there";
    uploadShapes();
    const std::vector<std::uint8_t> batched = renderScene(true, everything());
    const RenderStats batchedStats = lastStats_;
    const std::vector<std::uint8_t> single = renderScene(false, everything());
    const RenderStats singleStats = lastStats_;

    EXPECT_EQ(batchedStats.chunksDrawn, 75u);
    EXPECT_EQ(singleStats.chunksDrawn, 75u);
    EXPECT_EQ(batchedStats.drawCalls, 2u) << "one multi-draw and the ground";
    EXPECT_EQ(singleStats.drawCalls, 76u) << "a call per chunk and the ground";
    EXPECT_EQ(batchedStats.shadowDrawCalls, 1u);
    EXPECT_EQ(singleStats.shadowDrawCalls, 75u);
    EXPECT_EQ(batchedStats.trianglesDrawn, singleStats.trianglesDrawn);

    ASSERT_EQ(batched.size(), single.size());
    int differing = 0;
    for (std::size_t i = 0; i < batched.size(); ++i) differing += batched[i] != single[i] ? 1 : 0;
    EXPECT_EQ(differing, 0) << "the two paths read the same records with the same programs";
    // And the picture is not empty: many sculpture pixels of varied colour.
    int coloured = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) coloured += pixel(x, y).b > pixel(x, y).g + 30 ? 1 : 0;
    EXPECT_GT(coloured, 2000);
}

TEST_F(BatchedDrawing, OnlyChunksWithinTheShadowDistanceCastAndTheRestStillDraw) {
    renderer_->upload(1, 1, uvSphereMesh(0.5f, 32, 16));
    // The sun low from +x: each sphere's shadow lies beside it towards -x.
    const View view = makeView({0.0f, 2.0f, -30.0f}, {0.0f, 0.3f, -40.0f}, {1.0f, 0.8f, 0.0f});
    const glm::vec3 far(0.0f, 0.6f, -40.0f);
    auto frame = [&](float shadowDistance) {
        RenderQuality q = everything();
        q.ambientOcclusion = false;
        q.shadowDistance = shadowDistance;
        renderer_->setQuality(q);
        target_->bind();
        renderer_->beginFrame(view);
        renderer_->drawGround(GroundStyle{});
        renderer_->drawChunk(1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.6f, -26.0f)), kRedMaterial);
        renderer_->drawChunk(1, glm::translate(glm::mat4(1.0f), far), kRedMaterial);
        const RenderStats stats = renderer_->endFrame();
        read();
        return stats;
    };
    // Where the far sphere's shadow falls: from its centre along the sun's
    // ray down to the ground.
    const glm::vec3 toSun = glm::normalize(glm::vec3(1.0f, 0.8f, 0.0f));
    const glm::vec3 shadowAt = far - toSun * (far.y / toSun.y);
    const glm::ivec2 p = worldToPixel(view, shadowAt);
    ASSERT_TRUE(p.x > 3 && p.y > 3 && p.x < kWidth - 3 && p.y < kHeight - 3);
    auto darkness = [&] {
        int sum = 0;
        for (int y = p.y - 2; y <= p.y + 2; ++y)
            for (int x = p.x - 2; x <= p.x + 2; ++x) sum += pixel(x, y).sum();
        return sum / 25;
    };
    const RenderStats near = frame(6.0f);  // the far sphere is 10 m from the eye, the other 4 m
    EXPECT_EQ(near.chunksDrawn, 2u) << "both drawn";
    const int lawn = darkness();
    EXPECT_GT(count(reddish), 200) << "the far sphere itself is there";
    frame(0.0f);  // no limit
    const int shaded = darkness();
    EXPECT_LT(shaded, lawn - 30) << "its shadow shows only when it may cast";
}

TEST_F(BatchedDrawing, ChunksSurviveTheArenaGrowing) {
    // Enough chunks to outgrow the first buffers several times, with drops
    // and new versions between: the picture must equal that of a renderer
    // that only ever held the final meshes, which span pages.
    const std::size_t startCapacity = renderer_->arena().capacityBytes();
    uploadShapes();
    for (int round = 0; round < 3; ++round)
        for (ChunkId id = 10; id < 110; ++id) {
            renderer_->upload(id, static_cast<std::uint64_t>(round + 1),
                              uvSphereMesh(0.2f + 0.01f * float(id % 7), 40 + round * 8, 20 + round * 4));
            if (id % 3 == 0) renderer_->drop(id - 1);
        }
    EXPECT_GT(renderer_->arena().pagesMade(), 1u) << "the arena had to grow";
    EXPECT_GT(renderer_->arena().capacityBytes(), startCapacity);
    // Meshes of shape 3's size until one no longer fits the shapes' page:
    // shape 3 placed again then goes to another page.
    const poly::Mesh three = uvSphereMesh(0.4f, 32, 16);
    const std::size_t first = renderer_->arena().slot(1)->page;
    renderer_->drop(3);  // its own range goes to the fillers
    ChunkId filler = 1000;
    while (renderer_->arena().slot(filler - 1) == nullptr || renderer_->arena().slot(filler - 1)->page == first)
        renderer_->upload(filler++, 1, three);
    renderer_->upload(3, 2, three);
    for (ChunkId id = 1000; id < filler; ++id) renderer_->drop(id);
    std::set<std::size_t> pages;
    for (ChunkId id = 1; id <= 4; ++id) pages.insert(renderer_->arena().slot(id)->page);
    const std::vector<std::uint8_t> churned = renderScene(true, everything());
    EXPECT_EQ(lastStats_.drawCalls, pages.size() + 1) << "one multi-draw a page, and the ground";
    EXPECT_EQ(renderScene(false, everything()), churned) << "a call a chunk, page by page";
    EXPECT_GT(pages.size(), 1u) << "the scene spans pages";

    // The churn's chunks gone (the scene never drew them), the first page
    // has room: compacted in the background between frames, the scene's
    // chunks move back to it, and the pixels do not change.
    for (ChunkId id = 10; id < 110; ++id) renderer_->drop(id);
    EXPECT_EQ(renderScene(true, everything()), churned);
    const std::size_t livePages = renderer_->arena().livePages();
    while (renderer_->compactArena(64 << 10) > 0) {
        EXPECT_EQ(renderScene(true, everything()), churned) << "mid-way through compaction";
    }
    EXPECT_GT(renderer_->arena().chunksMoved(), 0u);
    EXPECT_LT(renderer_->arena().livePages(), livePages);
    EXPECT_EQ(renderScene(true, everything()), churned);
    EXPECT_EQ(lastStats_.drawCalls, 2u) << "the scene on one page again";
    EXPECT_EQ(renderScene(false, everything()), churned);

    renderer_ = std::make_unique<Renderer>();
    uploadShapes();
    const std::vector<std::uint8_t> fresh = renderScene(true, everything());
    EXPECT_EQ(churned, fresh);
}

// A small arena outgrows its first page at once: later meshes go to new
// pages, and no chunk placed ever moves (an arena that moved them all held
// the frame that outgrew it); a page whose chunks are all gone is let go.
TEST_F(BatchedDrawing, TheArenaKeepsEveryChunkWhereItWasPlacedAcrossPages) {
    ChunkArena arena(256, 512);
    std::vector<poly::Mesh> meshes;
    for (int k = 0; k < 12; ++k) meshes.push_back(uvSphereMesh(0.1f * float(k + 1), 8 + k, 4 + k / 2));
    std::vector<ArenaSlot> placed;
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        arena.place(k, meshes[k]);
        placed.push_back(*arena.slot(k));
        for (std::size_t j = 0; j < k; ++j) {
            const ArenaSlot* s = arena.slot(j);
            ASSERT_EQ(s->page, placed[j].page) << "chunk " << j << " moved as chunk " << k << " came";
            ASSERT_EQ(s->firstVertex, placed[j].firstVertex) << "chunk " << j;
            ASSERT_EQ(s->firstIndex, placed[j].firstIndex) << "chunk " << j;
        }
    }
    EXPECT_GT(arena.pagesMade(), 2u);
    arena.remove(3);
    arena.remove(7);
    meshes[5] = uvSphereMesh(2.0f, 30, 15);
    arena.place(5, meshes[5]);
    EXPECT_EQ(arena.slot(3), nullptr);
    EXPECT_EQ(arena.slot(7), nullptr);
    EXPECT_GE(arena.capacityBytes(), arena.usedBytes());

    for (std::size_t k = 0; k < meshes.size(); ++k)
        if (k != 3 && k != 7) expectHeld(arena, k, meshes[k]);

    // Every chunk of a later page gone: the page goes with them.
    const std::size_t page = arena.slot(11)->page;
    ASSERT_GT(page, 0u);
    const std::size_t before = arena.capacityBytes();
    for (std::size_t k = 0; k < meshes.size(); ++k)
        if (arena.slot(k) && arena.slot(k)->page == page) arena.remove(k);
    EXPECT_FALSE(arena.hasPage(page));
    EXPECT_LT(arena.capacityBytes(), before);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Pages made while the garden arrived, left part empty as chunks went:
// compact() empties the sparsest into the others, a budget at a time, GPU
// to GPU, and lets it go; every chunk keeps its bytes; pages more than half
// full, and the first, are left alone; nothing more to do costs nothing.
// Sixty small meshes over several pages of a small arena.
std::vector<poly::Mesh> fillPages(ChunkArena& arena) {
    std::vector<poly::Mesh> meshes;
    for (int k = 0; k < 60; ++k) meshes.push_back(uvSphereMesh(0.05f * float(k % 9 + 1), 10 + k % 5, 5 + k % 3));
    for (std::size_t k = 0; k < meshes.size(); ++k) arena.place(k, meshes[k]);
    return meshes;
}

// Most chunks of the later pages go, as a visitor's walk takes them to
// other levels; the ids kept.
std::set<ChunkId> thinLaterPages(ChunkArena& arena, std::size_t count) {
    std::set<ChunkId> kept;
    for (std::size_t k = 0; k < count; ++k)
        if (arena.slot(k)->page == 0 || k % 6 == 0) kept.insert(k);
        else arena.remove(k);
    return kept;
}

TEST_F(BatchedDrawing, CompactingEmptiesSparsePagesIntoTheOthersAndKeepsEveryChunk) {
    ChunkArena arena(512, 1024);
    const std::vector<poly::Mesh> meshes = fillPages(arena);
    ASSERT_GE(arena.pagesMade(), 3u) << "meshes enough for several pages";
    EXPECT_EQ(arena.compact(1 << 20), 0u) << "every page is full: nothing to move";

    const std::set<ChunkId> kept = thinLaterPages(arena, meshes.size());
    std::set<std::size_t> pagesBefore;
    for (ChunkId k : kept) pagesBefore.insert(arena.slot(k)->page);
    ASSERT_GT(pagesBefore.size(), 1u);
    const std::size_t livePages = arena.livePages();
    const std::size_t capacity = arena.capacityBytes(), used = arena.usedBytes();

    // A budget smaller than any chunk: one chunk a call.
    std::size_t calls = 0, moved = 0;
    while (std::size_t bytes = arena.compact(1)) {
        EXPECT_EQ(arena.chunksMoved(), ++calls) << "one chunk a call on a budget of a byte";
        moved += bytes;
        ASSERT_LT(calls, 1000u);
    }
    EXPECT_GT(calls, 0u);
    EXPECT_EQ(moved, arena.bytesMoved());
    EXPECT_LT(arena.livePages(), livePages) << "a sparse page emptied and let go";
    EXPECT_LT(arena.capacityBytes(), capacity);
    EXPECT_EQ(arena.usedBytes(), used) << "the same chunks, elsewhere";
    for (ChunkId k : kept) expectHeld(arena, k, meshes[k]);
    EXPECT_TRUE(arena.hasPage(0));
    // What is left is either more than half full or has nowhere to go.
    EXPECT_EQ(arena.compact(1 << 20), 0u);
    EXPECT_EQ(arena.compact(1 << 20), 0u);

    // New meshes still come and go around what was moved.
    for (std::size_t k = 100; k < 130; ++k) arena.place(k, meshes[k % meshes.size()]);
    for (ChunkId k : kept) expectHeld(arena, k, meshes[k]);
    for (std::size_t k = 100; k < 130; ++k) expectHeld(arena, k, meshes[k % meshes.size()]);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A budget of 0 never moves anything; a big budget moves several chunks in one call.
TEST_F(BatchedDrawing, CompactingKeepsToItsBudget) {
    ChunkArena arena(512, 1024);
    const std::vector<poly::Mesh> meshes = fillPages(arena);
    thinLaterPages(arena, meshes.size());
    EXPECT_EQ(arena.compact(0), 0u);
    EXPECT_EQ(arena.chunksMoved(), 0u);
    const std::size_t budget = 3 * (meshes[0].vertexCount() * 24 + meshes[0].indices.size() * 4);
    const std::size_t bytes = arena.compact(budget);
    EXPECT_GT(arena.chunksMoved(), 1u);
    // The budget is passed by the last chunk moved at most.
    std::size_t largest = 0;
    for (const poly::Mesh& m : meshes) largest = std::max(largest, m.vertexCount() * 24 + m.indices.size() * 4);
    EXPECT_LT(bytes, budget + largest);
}

}  // namespace
}  // namespace hg::garden::test
