// The morph triangle's geometry as plain functions, the ImGui widgets driven
// headless with a synthetic mouse, and the overlay drawn by the ImGui GL
// backend into an offscreen target with no GL error.
#include <gtest/gtest.h>

#include <imgui.h>

#include <glm/geometric.hpp>

#include <random>

#include "garden/render/morph_triangle.h"
#include "garden/render/overlay.h"
#include "garden/render/shapes.h"
#include "gl_fixture.h"
#include "headless_imgui.h"

namespace hg::garden::test {
namespace {

const char* const kLabels[3] = {"dryad", "orant", "knot"};

void expectNear(const glm::vec2& a, const glm::vec2& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
}

TEST(MorphTriangle, CornersHaveUnitWeightsAndPointsRoundTrip) {
    const auto& c = morphTriangleCorners();
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 w = triangleWeights(c[static_cast<std::size_t>(i)]);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], i == k ? 1.0f : 0.0f, 1e-6f);
    }
    EXPECT_NEAR(glm::distance(c[0], c[2]), 1.0f, 1e-6f) << "equilateral";
    const glm::vec3 centre = triangleWeights(trianglePoint(glm::vec3(1.0f)));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre[k], 1.0f / 3.0f, 1e-6f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 2.0f);
    for (int n = 0; n < 200; ++n) {
        const glm::vec2 p(u(rng), u(rng));
        const glm::vec3 w = triangleWeights(p);
        EXPECT_NEAR(w.x + w.y + w.z, 1.0f, 1e-5f);
        expectNear(trianglePoint(w), p, 1e-5f);
    }
}

TEST(MorphTriangle, ClampKeepsInsidePointsAndTakesTheNearestBoundaryPoint) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.5f, 2.5f);
    const auto& c = morphTriangleCorners();
    int outside = 0;
    for (int n = 0; n < 500; ++n) {
        const glm::vec2 p(u(rng), u(rng));
        const glm::vec2 q = clampToTriangle(p);
        const glm::vec3 wp = triangleWeights(p);
        const glm::vec3 wq = triangleWeights(q);
        EXPECT_GE(std::min({wq.x, wq.y, wq.z}), -1e-5f) << "clamped point inside";
        if (std::min({wp.x, wp.y, wp.z}) >= 0.0f) {
            expectNear(q, p, 0.0f);
            continue;
        }
        ++outside;
        // No point of the boundary, sampled finely, is nearer.
        float best = 1e9f;
        for (int e = 0; e < 3; ++e)
            for (int s = 0; s <= 1000; ++s) {
                const glm::vec2 b = glm::mix(c[static_cast<std::size_t>(e)], c[static_cast<std::size_t>((e + 1) % 3)], s / 1000.0f);
                best = std::min(best, glm::distance(p, b));
            }
        EXPECT_LE(glm::distance(p, q), best + 1e-5f);
        EXPECT_GE(glm::distance(p, q), best - 1e-3f);
    }
    EXPECT_GT(outside, 200);
    // Beyond a corner the corner itself; beyond the base its foot.
    expectNear(clampToTriangle({-1.0f, -1.0f}), c[0]);
    expectNear(clampToTriangle({0.5f, 3.0f}), c[2]);
    expectNear(clampToTriangle({0.3f, -2.0f}), {0.3f, 0.0f});
}

TEST(MorphTriangle, ScreenMappingPutsTheApexOnTopAndRoundTrips) {
    const MorphTriangleLayout layout = morphTriangleLayout({10.0f, 20.0f}, 100.0f, 13.0f);
    const auto& c = morphTriangleCorners();
    const glm::vec2 apex = triangleToScreen(layout, c[2]);
    const glm::vec2 left = triangleToScreen(layout, c[0]);
    const glm::vec2 right = triangleToScreen(layout, c[1]);
    EXPECT_LT(apex.y, left.y) << "ImGui's y grows downwards";
    EXPECT_FLOAT_EQ(left.y, right.y);
    EXPECT_FLOAT_EQ(right.x - left.x, 100.0f);
    expectNear(screenToTriangle(layout, triangleToScreen(layout, {0.3f, 0.2f})), {0.3f, 0.2f}, 1e-4f);
    // Everything drawn lies inside the widget's box, labels' lines included.
    EXPECT_GE(apex.y - 13.0f, 20.0f);
    EXPECT_LE(left.y + 13.0f, 20.0f + layout.size.y);
    EXPECT_GE(left.x, 10.0f);
    EXPECT_LE(right.x, 10.0f + layout.size.x);
}

// An ImGui context with no backend: enough for widgets, which only build
// draw lists.
class HeadlessImGui : public ::testing::Test {
protected:
    void SetUp() override { createHeadlessImGui(ImVec2(800, 600)); }
    void TearDown() override { ImGui::DestroyContext(); }

    // One frame with the mouse at `mouse`, button down or up; returns what
    // the widget returned and where its layout was.
    bool frame(const glm::vec2& mouse, bool down, glm::vec2& point, MorphTriangleLayout& layout) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(mouse.x, mouse.y);
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(20, 20));
        ImGui::SetNextWindowSize(ImVec2(400, 400));
        ImGui::Begin("Morph");
        const ImVec2 cursor = ImGui::GetCursorScreenPos();
        layout = morphTriangleLayout({cursor.x, cursor.y}, 180.0f, ImGui::GetTextLineHeight());
        const bool changed = morphTriangleWidget(kLabels, point);
        ImGui::End();
        ImGui::Render();
        return changed;
    }
};

TEST_F(HeadlessImGui, DraggingInTheTrianglePicksTheClampedPoint) {
    glm::vec2 point = trianglePoint(glm::vec3(1.0f));
    MorphTriangleLayout layout{};
    EXPECT_FALSE(frame({0, 0}, false, point, layout));
    EXPECT_FALSE(frame({0, 0}, false, point, layout));
    // Hover, then press inside the triangle near the left corner.
    const glm::vec2 press = triangleToScreen(layout, {0.2f, 0.1f});
    EXPECT_FALSE(frame(press, false, point, layout));
    EXPECT_TRUE(frame(press, true, point, layout));
    // ImGui floors the mouse position to whole pixels.
    expectNear(point, {0.2f, 0.1f}, 1.5f / layout.side);
    // Drag out past the right corner: the point stops on the triangle.
    const glm::vec2 beyond = triangleToScreen(layout, {1.3f, -0.2f});
    EXPECT_TRUE(frame(beyond, true, point, layout));
    expectNear(point, morphTriangleCorners()[1], 1e-4f);
    EXPECT_FALSE(frame(beyond, true, point, layout)) << "held still: no change";
    // Released, the mouse moves without picking.
    EXPECT_FALSE(frame(press, false, point, layout));
    expectNear(point, morphTriangleCorners()[1], 1e-4f);
    // A press outside the widget does not pick either.
    EXPECT_FALSE(frame({700, 550}, false, point, layout));
    EXPECT_FALSE(frame({700, 550}, true, point, layout));
    const glm::vec3 w = triangleWeights(point);
    EXPECT_NEAR(w.y, 1.0f, 1e-4f);
}

FrameHistory sampleHistory(int frames) {
    FrameHistory history(120);
    for (int i = 0; i < frames; ++i) {
        FrameStats s;
        s.frame = static_cast<std::uint64_t>(i);
        for (int k = 0; k < kStageCount; ++k) s.stageMs[static_cast<std::size_t>(k)] = 0.5 + 0.1 * k + (i % 7) * 0.2;
        for (double ms : s.stageMs) s.totalMs += ms;
        s.morphSamples = 1000u * static_cast<std::size_t>(i);
        s.chunksMeshed = 3;
        s.trianglesDrawn = 120000;
        history.push(s);
    }
    return history;
}

TEST_F(HeadlessImGui, StatsPanelDrawsWithAndWithoutFrames) {
    // Vertices ImGui builds for the panel (its second frame: an auto-sized
    // window is hidden on its first).
    auto vertices = [](const FrameHistory& history) {
        int count = 0;
        for (int f = 0; f < 2; ++f) {
            ImGui::NewFrame();
            drawStatsPanel(history);
            ImGui::Render();
            count = ImGui::GetDrawData()->TotalVtxCount;
        }
        return count;
    };
    // It starts folded (a new user's view); folded, it is its title alone.
    const int folded = vertices(sampleHistory(300));
    ImGui::SetWindowCollapsed(kStatsPanelTitle, false);
    const int none = vertices(sampleHistory(0));
    EXPECT_GT(none, folded) << "unfolded, it says there are no frames";
    const int one = vertices(sampleHistory(1));
    const int full = vertices(sampleHistory(300));
    EXPECT_GT(none, 0) << "says there are no frames";
    EXPECT_GT(one, none + 500) << "stage bars, counters, graph";
    // The graph draws a segment per frame kept (4 vertices each).
    EXPECT_GT(full, one + 4 * 100);
    EXPECT_EQ(sampleHistory(300).frames().size(), 120u);
    // Given what the session holds, it adds two lines, and asks only while
    // unfolded.
    MemoryReport held;
    held.grids = 300u << 20;
    held.levels = 40u << 20;
    held.sculptures = 200;
    int asked = 0;
    const std::function<const MemoryReport&()> memory = [&]() -> const MemoryReport& {
        ++asked;
        return held;
    };
    int withMemory = 0;
    for (int f = 0; f < 2; ++f) {
        ImGui::NewFrame();
        drawStatsPanel(sampleHistory(300), false, memory);
        ImGui::Render();
        withMemory = ImGui::GetDrawData()->TotalVtxCount;
    }
    EXPECT_GT(withMemory, full + 200) << "the memory lines";
    EXPECT_GT(asked, 0);
    ImGui::SetWindowCollapsed(kStatsPanelTitle, true);
    asked = 0;
    for (int f = 0; f < 2; ++f) {
        ImGui::NewFrame();
        drawStatsPanel(sampleHistory(300), false, memory);
        ImGui::Render();
    }
    EXPECT_EQ(asked, 0) << "folded, it does not walk the grids";
}

TEST_F(GlTest, OverlayDrawsOverTheSceneWithoutGlErrors) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    Overlay overlay(*window_, false);
    EXPECT_THROW(Overlay(*window_, false), GlError) << "one ImGui context at a time";
    const FrameHistory history = sampleHistory(200);
    glm::vec2 point = trianglePoint(glm::vec3(1.0f));

    target_->bind();
    renderer_->beginFrame(makeView({0, 0, 5}, {0, 0, 0}));
    renderer_->drawChunk(1, glm::mat4(1.0f), RenderMaterial{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f});
    renderer_->endFrame();
    read();
    const std::vector<std::uint8_t> scene = color_;

    for (int f = 0; f < 3; ++f) {  // windows settle their size over a frame or two
        overlay.newFrame();
        drawStatsPanel(history);
        ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
        ImGui::Begin("Morph");
        morphTriangleWidget(kLabels, point, 100.0f);
        ImGui::End();
        target_->bind();
        overlay.render();
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "frame " << f;
    }
    read();
    int changed = 0;
    for (std::size_t i = 0; i < scene.size(); i += 4)
        changed += (scene[i] != color_[i] || scene[i + 1] != color_[i + 1] || scene[i + 2] != color_[i + 2]) ? 1 : 0;
    EXPECT_GT(changed, 3000) << "panels cover part of the image";
    EXPECT_LT(changed, kWidth * kHeight) << "and leave some of the scene";

    // The renderer's next frame is unaffected by the state ImGui used.
    target_->bind();
    renderer_->beginFrame(makeView({0, 0, 5}, {0, 0, 0}));
    renderer_->drawChunk(1, glm::mat4(1.0f), RenderMaterial{{0.9f, 0.1f, 0.1f}, 0.2f, 32.0f});
    renderer_->endFrame();
    read();
    EXPECT_EQ(color_, scene);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The stats panel, given the renderer's chunk arena, adds its line: what the
// GPU's mesh buffers hold and use.
TEST_F(GlTest, StatsPanelShowsTheGpuMeshBuffers) {
    renderer_->upload(1, 1, uvSphereMesh(1.0f, 48, 24));
    Overlay overlay(*window_, false);
    const FrameHistory history = sampleHistory(200);
    auto vertices = [&](const ChunkArena* arena) {
        int count = 0;
        for (int f = 0; f < 3; ++f) {
            overlay.newFrame();
            ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
            drawStatsPanel(history, false, {}, arena);
            ImGui::SetWindowCollapsed(kStatsPanelTitle, false);  // it starts folded
            target_->bind();
            overlay.render();
            count = ImGui::GetDrawData()->TotalVtxCount;
        }
        return count;
    };
    // Small text, so the whole panel fits the 256-pixel window (ImGui draws
    // no line below its edge).
    ImGui::GetIO().FontGlobalScale = 0.25f;
    const int without = vertices(nullptr);
    const int with = vertices(&renderer_->arena());
    ImGui::GetIO().FontGlobalScale = 1.0f;
    EXPECT_GT(with, without + 100) << "a line of text more";
    EXPECT_GT(renderer_->arena().usedBytes(), 0u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace hg::garden::test
