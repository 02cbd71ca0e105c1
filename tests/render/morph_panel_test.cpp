// One state, one truth (issue 23): the Garden panel's morph triangle and
// weights line are drawn from the session's weights every frame, so a
// blend picked on the ground triangle shows in the panel at once (the
// panel used to keep its own point until a restart), and drawing the panel
// never pushes an old point back into the session.
#include <gtest/gtest.h>

#include <imgui.h>

#include "../garden/session_garden.h"
#include "garden/app/garden_session.h"
#include "garden/render/morph_triangle.h"
#include "garden/render/panels.h"
#include "headless_imgui.h"

namespace hg::garden {
namespace {

class MorphPanel : public test::SmallGardenSession {
protected:
    void SetUp() override {
        test::SmallGardenSession::SetUp();
        createHeadlessImGui(ImVec2(800, 600));
    }
    void TearDown() override {
        ImGui::DestroyContext();
        test::SmallGardenSession::TearDown();
    }
    // Draws the section in a fixed window twice (an auto-sized window shows
    // from its second frame); the centre of the selector's marker on screen:
    // the white vertices of its filled disc.
    glm::vec2 drawnMarker() {
        glm::vec2 centre(0.0f);
        for (int f = 0; f < 2; ++f) {
            ImGui::NewFrame();
            ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
            ImGui::Begin("Garden", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoDecoration);  // no title arrow: white too
            drawMorphSection(*session);
            ImGui::End();
            ImGui::Render();
            const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
            glm::vec2 sum(0.0f);
            int n = 0;
            const ImDrawData* d = ImGui::GetDrawData();
            for (int l = 0; l < d->CmdListsCount; ++l)
                for (const ImDrawVert& v : d->CmdLists[l]->VtxBuffer)
                    if (v.col == IM_COL32(255, 255, 255, 255) && v.uv.x == white.x && v.uv.y == white.y) {
                        sum += glm::vec2(v.pos.x, v.pos.y);
                        ++n;
                    }
            if (f == 1) {
                EXPECT_GT(n, 6);
            }
            centre = sum / static_cast<float>(std::max(n, 1));
        }
        return centre;
    }
};

TEST_F(MorphPanel, APickOnTheGroundShowsInThePanelAtOnce) {
    ASSERT_TRUE(session->hasMorph());
    const glm::vec2 before = drawnMarker();
    const std::array<double, 3> b0 = session->morphWeights()->barycentric;
    // The tool hand picks ball b's corner on the ground (-2, 1.1547).
    session->setMorphPoint(-2.0, 1.1547);
    const MorphWeights picked = *session->morphWeights();
    EXPECT_GT(picked.barycentric[1], 0.99);
    const glm::vec2 after = drawnMarker();
    // The marker moved on screen as the widget's layout puts the new point.
    const MorphTriangleLayout layout = morphTriangleLayout(glm::vec2(0.0f), 180.0f, ImGui::GetTextLineHeight());
    const glm::vec2 moved =
        triangleToScreen(layout, trianglePoint(glm::vec3(picked.barycentric[0], picked.barycentric[1], picked.barycentric[2]))) -
        triangleToScreen(layout, trianglePoint(glm::vec3(b0[0], b0[1], b0[2])));
    EXPECT_GT(glm::length(moved), 20.0f);
    EXPECT_NEAR(after.x - before.x, moved.x, 1.0f);
    EXPECT_NEAR(after.y - before.y, moved.y, 1.0f);
    EXPECT_NEAR(morphSelectorPoint(*session).x, trianglePoint(glm::vec3(0, 1, 0)).x, 0.01f);
    // Drawing it changed nothing in the session.
    EXPECT_EQ(session->morphWeights()->barycentric, picked.barycentric);
    EXPECT_EQ(session->morphWeights()->w, picked.w);
}

}  // namespace
}  // namespace hg::garden
