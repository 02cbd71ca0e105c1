// Sculptures shaded once a pixel (docs/rendering.md, "Shaded once a
// pixel"): their surfaces drawn first, then lit by a screen pass a
// material over the tiles that hold it. Read back as real pixels, the
// picture is the one the mesh program draws lighting each triangle.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "garden/render/material_look.h"
#include "garden/render/screenshot.h"
#include "garden/render/surface_buffer.h"
#include "garden/render/shapes.h"
#include "garden/scene/materials.h"
#include "gl_fixture.h"

namespace hg::garden::test {
namespace {

class ShadeOncePerPixelTest : public GlTest {
protected:
    struct Placed {
        ChunkId id;
        glm::mat4 model;
        RenderMaterial material;
    };
    // The scene drawn at `quality`; the colours read back.
    std::vector<std::uint8_t> render(const View& view, const std::vector<Placed>& placed, const RenderQuality& quality,
                                     bool ground) {
        renderer_->setQuality(quality);
        target_->bind();
        renderer_->beginFrame(view);
        for (const Placed& p : placed) renderer_->drawChunk(p.id, p.model, p.material);
        if (ground) renderer_->drawGround(GroundStyle{});
        stats_ = renderer_->endFrame();
        read();
        if (const char* dump = std::getenv("HG_LOOK_DUMP"))
            writePng(std::string(dump) + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                         std::to_string(dumps_++) + ".png", kWidth, kHeight, color_);
        return color_;
    }
    static RenderQuality perTriangle() {
        RenderQuality q = qualityOf(QualityPreset::Low);
        q.shadeOncePerPixel = false;
        return q;
    }
    // The largest difference of a channel, and the pixels that differ by more than 2.
    static std::pair<int, int> difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
        int most = 0, over = 0;
        for (std::size_t i = 0; i < a.size(); i += 4) {
            int d = 0;
            for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[i + c]) - int(b[i + c])));
            most = std::max(most, d);
            over += d > 2 ? 1 : 0;
        }
        return {most, over};
    }
    RenderStats stats_;
    int dumps_ = 0;
};

// Every built-in material and a plain one, overlapping in depth, one of
// them without normals (its face normals from derivatives) and one in the
// clay view, over the ground: the same picture both ways, to rounding, and
// by a multi-draw or a call a chunk.
TEST_F(ShadeOncePerPixelTest, GivesThePictureOfLightingEachTriangle) {
    ASSERT_TRUE(shadesOncePerPixel(qualityOf(QualityPreset::Low)));
    renderer_->upload(1, 1, uvSphereMesh(0.5f, 48, 24));
    poly::Mesh faceted = uvSphereMesh(0.5f, 12, 6);
    faceted.normals.clear();
    renderer_->upload(2, 1, faceted);
    std::vector<Placed> placed;
    const std::vector<Material> materials = builtinMaterials();
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const float x = -1.6f + 0.55f * float(i), z = -0.4f * float(i % 2);
        placed.push_back({1, glm::translate(glm::mat4(1.0f), {x, 0.6f, z}), renderMaterial(materials[i], 0.1f)});
    }
    placed.push_back({2, glm::translate(glm::mat4(1.0f), {0.2f, 1.4f, -0.6f}), RenderMaterial{}});
    // The clay view's cavity shading, from the triangles' derivatives.
    placed.push_back({2, glm::translate(glm::mat4(1.0f), {-1.0f, 1.4f, -0.6f}), clayViewMaterial()});
    const View view = makeView({0.0f, 1.6f, 4.0f}, {0.0f, 0.6f, 0.0f});
    const std::vector<std::uint8_t> lit = render(view, placed, perTriangle(), true);
    const RenderStats perTriangleStats = stats_;
    const std::vector<std::uint8_t> once = render(view, placed, qualityOf(QualityPreset::Low), true);
    const auto [most, over] = difference(lit, once);
    EXPECT_LE(most, 2) << over << " pixels differ by more than 2";
    // It drew what it says: the sculptures and a screen pass a kind.
    EXPECT_EQ(stats_.trianglesDrawn, perTriangleStats.trianglesDrawn);
    EXPECT_GT(stats_.drawCalls, perTriangleStats.drawCalls);
    // On GL 3.3 (a call a chunk, the record's index a constant attribute):
    // the same picture.
    if (renderer_->multiDraw()) {
        renderer_->setMultiDraw(false);
        EXPECT_EQ(render(view, placed, qualityOf(QualityPreset::Low), true), once);
        renderer_->setMultiDraw(true);
    }
    // And not an empty scene: the sculptures cover a good part of it.
    const View empty = view;
    const std::vector<std::uint8_t> bare = render(empty, {}, qualityOf(QualityPreset::Low), true);
    EXPECT_GT(difference(bare, once).second, kWidth * kHeight / 10);
}

// Drawn at a render scale whose pixels are no whole number of tiles
// (197 x 197 at 0.77), the light reaches the last row and column, and the
// sculptures cut by the view's edges.
TEST_F(ShadeOncePerPixelTest, LightsThePartTilesAtTheViewsEdges) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    const std::vector<Placed> placed = {
        {1, glm::translate(glm::mat4(1.0f), {-1.3f, 0.0f, 0.0f}), renderMaterial(*builtinMaterial("marble"), 0.1f)},
        {1, glm::translate(glm::mat4(1.0f), {1.3f, 0.2f, 0.0f}), renderMaterial(*builtinMaterial("bronze"), 0.1f)},
        {1, glm::translate(glm::mat4(1.0f), {0.0f, -1.4f, 0.3f}), renderMaterial(*builtinMaterial("wood"), 0.1f)}};
    const View view = makeView({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f});
    RenderQuality triangles = perTriangle(), once = qualityOf(QualityPreset::Low);
    triangles.renderScale = once.renderScale = 0.77f;
    ASSERT_NE(scenePixels(kWidth, once) % SurfaceBuffer::kTilePixels, 0);
    const std::vector<std::uint8_t> lit = render(view, placed, triangles, false);
    const std::vector<std::uint8_t> shaded = render(view, placed, once, false);
    const auto [most, over] = difference(lit, shaded);
    EXPECT_LE(most, 2) << over << " pixels differ by more than 2";
    // The sculptures reach every edge of the view.
    const Rgba sky = pixel(kWidth / 2, 2);
    for (const glm::ivec2 edge : {glm::ivec2(0, kHeight / 2), glm::ivec2(kWidth - 1, kHeight / 2 - 10),
                                  glm::ivec2(kWidth / 2, kHeight - 1)}) {
        const Rgba p = pixel(edge.x, edge.y);
        EXPECT_GT(std::abs(p.r - sky.r) + std::abs(p.g - sky.g) + std::abs(p.b - sky.b), 30)
            << "a sculpture at " << edge.x << ", " << edge.y;
    }
}

}  // namespace
}  // namespace hg::garden::test
