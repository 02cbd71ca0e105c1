// Esc or the window's close button with work that is not saved: a question
// instead of a silent loss (issue 23). Saved work closes at once.
#include <imgui.h>

#include "garden/render/panels.h"

namespace hg::garden {

bool drawQuitQuestion(bool ask, const std::string& what) {
    constexpr const char* kTitle = "Quit without saving?";
    if (ask) ImGui::OpenPopup(kTitle);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    bool quit = false;
    if (ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(what.c_str());
        ImGui::Spacing();
        if (ImGui::Button("Quit")) {
            quit = true;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    return quit;
}

}  // namespace hg::garden
