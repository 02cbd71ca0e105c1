// The history panel (garden/render/history_panel.cpp) lists every action of
// the session's undo history, so it grows with them; closed, it draws
// nothing.
#include <gtest/gtest.h>

#include <imgui.h>

#include "../garden/session_garden.h"
#include "garden/app/garden_session.h"
#include "garden/render/panels.h"
#include "headless_imgui.h"

namespace hg::garden {
namespace {

class HistoryPanel : public test::SmallGardenSession {};

TEST_F(HistoryPanel, ListsEveryActionAndDrawsNothingClosed) {
    createHeadlessImGui(ImVec2(1280, 720));
    const auto vertices = [&](bool open) {
        int n = 0;
        for (int f = 0; f < 2; ++f) {
            ImGui::NewFrame();
            drawHistoryPanel(*session, open);
            ImGui::Render();
            n = ImGui::GetDrawData()->TotalVtxCount;
        }
        return n;
    };
    const int empty = vertices(true);
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{2.45, 0.9, 1.3}, {2.5, 0.6, 1.4}}, 0.1), "");
    const int one = vertices(true);
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Add, {{1.6, 0.5, 1.3}, {1.5, 0.4, 1.2}}, 0.1), "");
    const int two = vertices(true);
    EXPECT_GT(one, empty - 200) << "a line replaces 'nothing done yet'";
    EXPECT_GE(two, one + 4 * 8) << "a second line: its eight glyphs (\"2 stroke c\")";
    EXPECT_EQ(vertices(false), 0);
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace hg::garden
