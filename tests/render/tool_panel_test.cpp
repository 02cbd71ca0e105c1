// The tool panel (garden/render/tool_panel.cpp) driven headless with a
// synthetic mouse on a real session: its radio buttons pick the tool, its
// buttons undo and redo a real stroke, its checkbox sets the selected
// sculpture's mirror plane and "discard edits" takes the edits out (undo
// puts them back).
#include <gtest/gtest.h>

#include <imgui.h>
#include <imgui_internal.h>

#include <optional>

#include "../garden/session_garden.h"
#include "headless_imgui.h"
#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/render/panels.h"

namespace hg::garden {
namespace {

class ToolPanelTest : public test::SmallGardenSession {
protected:
    void SetUp() override {
        test::SmallGardenSession::SetUp();
        createHeadlessImGui(ImVec2(1280, 720));
        frame({0, 0}, false);
        frame({0, 0}, false);  // an auto-sized window shows from its second frame
    }
    void TearDown() override {
        ImGui::DestroyContext();
        test::SmallGardenSession::TearDown();
    }
    // One frame of the panel; the item hovered in it.
    ImGuiID frame(ImVec2 mouse, bool down) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = mouse;
        io.MouseDown[0] = down;
        ImGui::NewFrame();
        drawToolPanel(*session);
        const ImGuiID hovered = ImGui::GetCurrentContext()->HoveredId;
        ImGui::Render();
        return hovered;
    }
    // A control's id: inside the panel's window and its table.
    static ImGuiID idOf(const char* label) {
        const ImGuiWindow* w = ImGui::FindWindowByName("Tool");
        return ImHashStr(label, 0, ImHashStr("##tool", 0, w->ID));
    }
    // Where the mouse hovers the control `label`, found by moving it over
    // the panel; none when the panel does not show it.
    std::optional<ImVec2> find(const char* label) {
        const ImGuiWindow* w = ImGui::FindWindowByName("Tool");
        const ImGuiID id = idOf(label);
        for (float y = w->Pos.y; y < w->Pos.y + w->Size.y; y += 3.0f)
            for (float x = w->Pos.x; x < w->Pos.x + w->Size.x; x += 6.0f)
                if (frame({x, y}, false) == id) return ImVec2(x, y);
        return std::nullopt;
    }
    // Clicks the control `label`; false when it is not there.
    bool click(const char* label) {
        const auto at = find(label);
        if (!at) return false;
        frame(*at, true);
        frame(*at, false);
        frame({0, 0}, false);
        frame({0, 0}, false);  // the panel's layout follows what the click changed
        return true;
    }
};

TEST_F(ToolPanelTest, TheRadioButtonsPickTheTool) {
    using K = ToolSettings::Kind;
    const std::pair<const char*, K> tools[] = {{"carve (1)", K::Carve},     {"add (2)", K::Add},
                                               {"soft carve (3)", K::Melt}, {"perturb (4)", K::Perturb},
                                               {"impacts (5)", K::Impacts}, {"move (6)", K::Move},
                                               {"smooth (8)", K::Smooth},   {"inflate (9)", K::Inflate},
                                               {"morph (0)", K::None}};
    for (const auto& [label, kind] : tools) {
        ASSERT_TRUE(click(label)) << label;
        EXPECT_EQ(session->tool().kind, kind) << label;
    }
    // The reverse shows for the tools that have one.
    EXPECT_FALSE(find("reverse (R)"));
    ASSERT_TRUE(click("carve (1)"));
    ASSERT_TRUE(click("reverse (R)"));
    EXPECT_TRUE(session->tool().reverse);
    ASSERT_TRUE(click("soft carve (3)"));
    EXPECT_FALSE(find("reverse (R)")) << "the soft carve has no reverse";
    ASSERT_TRUE(click("smooth (8)"));
    EXPECT_FALSE(find("reverse (R)")) << "smooth has no reverse";
    EXPECT_TRUE(find("strength")) << "smooth's strength";
    EXPECT_TRUE(find("falloff"));
    ASSERT_TRUE(click("inflate (9)"));
    ASSERT_TRUE(click("reverse (R)"));
    EXPECT_TRUE(session->tool().reverse) << "inflate's reverse deflates";
    EXPECT_TRUE(find("strength (voxels)"));
}

TEST_F(ToolPanelTest, UndoRedoMirrorAndDiscardActOnTheSession) {
    const int c = session->findSculpture("c");
    ASSERT_EQ(session->applyStroke(c, StrokeTool::Carve, {{1.8, 0.5, 1.75}, {2.2, 0.5, 1.75}}, 0.1), "");
    ASSERT_EQ(session->editCount(c), 1u);
    ASSERT_TRUE(click("undo (Ctrl+Z)"));
    EXPECT_EQ(session->editCount(c), 0u);
    ASSERT_TRUE(click("redo (Ctrl+Shift+Z)"));
    EXPECT_EQ(session->editCount(c), 1u);

    EXPECT_FALSE(find("mirror plane (M)")) << "nothing selected";
    session->select(c);
    frame({0, 0}, false);
    ASSERT_TRUE(click("mirror plane (M)"));
    const Sculpture& ball = session->sculptures()[static_cast<std::size_t>(c)];
    ASSERT_TRUE(ball.mirror);
    EXPECT_EQ(ball.mirror->point, centralMirror(ball).point);
    ASSERT_TRUE(click("mirror plane (M)"));
    EXPECT_FALSE(ball.mirror);

    ASSERT_TRUE(click("discard edits"));
    EXPECT_EQ(session->editCount(c), 0u);
    ASSERT_TRUE(click("undo (Ctrl+Z)")) << "a discard is undone like any action";
    EXPECT_EQ(session->editCount(c), 1u);
    ASSERT_TRUE(click("redo (Ctrl+Shift+Z)"));
    EXPECT_EQ(session->editCount(c), 0u);
}

TEST_F(ToolPanelTest, TheMaterialListGivesTheSelectionAnotherMaterialUndoably) {
    const int a = session->findSculpture("a");
    EXPECT_FALSE(find("material")) << "nothing selected";
    session->select(a);
    frame({0, 0}, false);
    frame({0, 0}, false);
    ASSERT_TRUE(click("material"));
    // The open list: the garden's "red", then the built-ins.
    const ImGuiWindow* list = ImGui::FindWindowByName("##Combo_00");
    ASSERT_TRUE(list && list->Active) << "the list opened";
    std::optional<ImVec2> marble;
    for (float y = list->Pos.y; y < list->Pos.y + list->Size.y && !marble; y += 2.0f)
        if (frame({list->Pos.x + 20.0f, y}, false) == ImHashStr("marble", 0, list->ID)) marble = ImVec2(list->Pos.x + 20.0f, y);
    ASSERT_TRUE(marble) << "marble is in the list";
    frame(*marble, true);
    frame(*marble, false);
    const Sculpture& s = session->sculptures()[static_cast<std::size_t>(a)];
    EXPECT_EQ(s.material.name, "marble");
    EXPECT_EQ(s.material.kind, MaterialKind::Marble);
    EXPECT_EQ(session->history().back().action, "material");
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(s.material.name, "red");
}

}  // namespace
}  // namespace hg::garden
