// The key list a new user needs on screen: the key table the window binds
// (garden/render/key_table.h, the README's table is checked against it),
// toggled by F1, and a one-line hint at the bottom of the window while it
// is closed.
#include <imgui.h>

#include <algorithm>
#include <functional>

#include "garden/render/key_table.h"
#include "garden/render/panels.h"

namespace hg::garden {

void drawKeyRows(const char* id, float keyWidth, const std::function<bool(const KeyRow&)>& pick) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, keyWidth);
    ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
    for (const KeyRow& r : keyTable()) {
        if (pick && !pick(r)) continue;
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextWrapped("%s", r.keys.c_str());
        ImGui::TableSetColumnIndex(1);
        ImGui::TextWrapped("%s", r.does.c_str());
    }
    ImGui::EndTable();
}

void drawHelpPanel(bool& open, glm::vec2 bottomCentre) {
    if (!open) {
        ImGui::SetNextWindowPos(ImVec2(bottomCentre.x, bottomCentre.y - 6.0f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
        ImGui::SetNextWindowBgAlpha(0.45f);
        ImGui::Begin("##help hint", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                         ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoInputs);
        ImGui::TextUnformatted("F1: keys and help");
        ImGui::End();
        return;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(760.0f, display.x - 20.0f), 0.0f), ImGuiCond_Appearing);
    if (ImGui::Begin("Keys and mouse (F1)", &open, ImGuiWindowFlags_NoSavedSettings)) {
        drawKeyRows("##keys", 200.0f, nullptr);
        ImGui::TextDisabled("Panels take the keys and clicks over them. Esc or F1 closes this list.");
    }
    ImGui::End();
}

}  // namespace hg::garden
