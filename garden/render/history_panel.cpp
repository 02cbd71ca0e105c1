// The history panel (issue 23, "undo you can see"): every action of the
// undo history with the sculpture it was on, newest at the bottom, what
// redo would bring back greyed below it; undo and redo over every
// sculpture, and undo on the selected sculpture alone
// (GardenSession::undoSculpture, journalled so sessions replay it).
#include <imgui.h>

#include <string>

#include "garden/app/garden_session.h"
#include "garden/render/panels.h"

namespace hg::garden {

void drawHistoryPanel(GardenSession& session, bool& open) {
    if (!open) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, 0.5f * display.y), ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(300.0f, 260.0f), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("History (H)", &open)) {
        ImGui::End();
        return;
    }
    if (ImGui::Button("undo")) session.undo();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the last action, whichever sculpture it was on (Ctrl+Z)");
    ImGui::SameLine();
    if (ImGui::Button("redo")) session.redo();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ctrl+Shift+Z");
    const int selected = session.selected();
    const std::string own =
        selected >= 0 ? "undo on " + session.sculptures()[static_cast<std::size_t>(selected)].name : "undo on the selection";
    ImGui::SameLine();
    ImGui::BeginDisabled(selected < 0);
    if (ImGui::Button(own.c_str())) session.undoSculpture(selected);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("the selected sculpture's last action only; the others' stay (Ctrl+Alt+Z)");
    ImGui::Separator();
    historyList(session);
    ImGui::End();
}

void historyList(GardenSession& session) {
    const int selected = session.selected();
    const std::vector<HistoryItem> items = session.history();
    if (items.empty()) ImGui::TextDisabled("nothing done yet");
    if (ImGui::BeginChild("##actions")) {
        int n = 0;
        for (const HistoryItem& item : items) {
            ++n;
            const bool mine = item.sculpture == selected;
            if (item.undone)
                ImGui::TextDisabled("%3d  %s  %s (undone)", n, item.action.c_str(), item.name.c_str());
            else if (mine)
                ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%3d  %s  %s", n, item.action.c_str(), item.name.c_str());
            else
                ImGui::Text("%3d  %s  %s", n, item.action.c_str(), item.name.c_str());
        }
        if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);  // follow the newest
    }
    ImGui::EndChild();
}

}  // namespace hg::garden
