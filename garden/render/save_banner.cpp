// The banner that tells the user their work is not safe on disk
// (docs/session-format.md, "What the user sees"): drawn by the desktop
// overlay and the headset's hand panel alike, from the session's
// JournalSink status. Red while finished actions wait in memory (with the
// folder, the reason and a Retry button), amber when the session opened
// read-only on a record it cannot play (with what to do).
#include <imgui.h>

#include <string>

#include "garden/app/garden_session.h"
#include "garden/render/panels.h"

namespace hg::garden {

bool drawSaveBanner(GardenSession& session, glm::vec2 topLeft, float width) {
    JournalSink* journal = session.journal();
    if (!journal) return false;
    const SaveStatus status = journal->saveStatus();
    if (status.saved()) return false;
    const bool notSaved = status.state == SaveStatus::State::NotSaved;
    ImGui::SetNextWindowPos(ImVec2(topLeft.x, topLeft.y));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, notSaved ? ImVec4(0.62f, 0.05f, 0.05f, 0.96f) : ImVec4(0.62f, 0.36f, 0.02f, 0.96f));
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 1.0f, 1.0f, 1.0f));
    ImGui::Begin("##save banner", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushTextWrapPos(0.0f);
    const std::string actions = std::to_string(status.unsaved) + (status.unsaved == 1 ? " action" : " actions");
    const std::string title =
        notSaved ? "NOT SAVED: " + actions + " only in memory, retried with each new action"
                 : "READ-ONLY: the journal holds a record that cannot be played" +
                       (status.unsaved ? "; " + actions + " made here not saved" : std::string());
    ImGui::TextUnformatted(title.c_str());
    ImGui::TextUnformatted(status.reason.c_str());
    if (!status.remedy.empty()) ImGui::TextUnformatted(status.remedy.c_str());
    ImGui::PopTextWrapPos();
    if (notSaved) {
        ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.85f, 0.25f, 0.2f, 1.0f));
        if (ImGui::Button("Retry saving")) journal->retrySave();
        ImGui::PopStyleColor();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("write the actions kept in memory to the journal now (each new action retries too)");
    }
    ImGui::End();
    ImGui::PopStyleColor(2);
    return true;
}

}  // namespace hg::garden
