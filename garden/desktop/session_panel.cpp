#include "garden/desktop/session_panel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <utility>

#include "garden/app/garden_session.h"
#include "garden/window/desktop_keys.h"
#include "garden/desktop/panel_layout.h"
#include "garden/desktop/recent_sessions.h"
#include "garden/session/session_copy.h"
#include "garden/session/session_folder.h"
#include "garden/session/session_view.h"

namespace hg::garden {

SessionPanel::SessionPanel(std::string recentPath) : recentPath_(std::move(recentPath)) {
    std::string warning;
    recent_ = loadRecentSessions(recentPath_, warning);
    if (!warning.empty()) setStatus(warning, true);
}

void SessionPanel::setStatus(std::string text, bool error) {
    status_ = std::move(text);
    error_ = error;
}

void SessionPanel::setFolder(const std::string& folder) {
    const std::size_t n = std::min(folder.size(), sizeof folder_ - 1);
    folder.copy(folder_, n);
    folder_[n] = '\0';
}

void SessionPanel::opened(const std::string& dir) {
    if (recentPath_.empty() || dir.empty()) return;
    if (std::string why = rememberSession(recentPath_, dir); !why.empty()) setStatus("recent sessions not kept: " + why, true);
    std::string warning;
    recent_ = loadRecentSessions(recentPath_, warning);
}

std::string SessionPanel::duplicate(const GardenSession& session, const SessionRecorder& recorder, const std::string& to) {
    std::string why = copySession(recorder, to);
    // The copy opens where the user is looking now.
    const std::string panels = panelLayout();
    if (why.empty()) why = writeSessionView(to, session.navigator(), &session.tool(), &panels);
    if (why.empty()) setStatus("copied the session to " + to, false);
    else setStatus("no copy: " + why, true);
    return why;
}

std::string SessionPanel::saveAs(const GardenSession& session, const SessionRecorder& recorder, const std::string& to) {
    if (!duplicate(session, recorder, to).empty()) return "";
    setStatus("saved as " + to + "; going on there", false);
    return to;
}

std::string SessionPanel::draw(GardenSession& session, const SessionRecorder* recorder) {
    std::string goTo;
    if (!ImGui::CollapsingHeader("Session")) return goTo;
    if (!recorder) {
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "no session folder: nothing is saved");
        ImGui::TextDisabled("start with --session FOLDER to keep your work");
    } else {
        ImGui::Text("saving into %s", recorder->paths().dir.c_str());
        ImGui::SetNextItemWidth(300.0f);
        ImGui::InputTextWithHint("##copy folder", "a new or empty folder", folder_, sizeof folder_);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("where Duplicate or Save As copies the session");
        if (ImGui::Button("Duplicate")) duplicate(session, *recorder, folder_);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("copy the session, with this view, and go on here");
        ImGui::SameLine();
        if (ImGui::Button("Save As")) goTo = saveAs(session, *recorder, folder_);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("copy the session, with this view, and go on in the copy");
    }
    const std::string current = recorder ? std::filesystem::absolute(recorder->paths().dir).lexically_normal().string() : "";
    // Leaving loses nothing only when every action is on disk.
    const bool canLeave = !unsavedWork(session);
    bool any = false;
    for (const std::string& dir : recent_) {
        if (dir == current) continue;
        if (!any) ImGui::TextDisabled("recent sessions:");
        any = true;
        ImGui::PushID(dir.c_str());
        ImGui::BeginDisabled(!canLeave);
        if (ImGui::SmallButton("open")) goTo = dir;
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip(canLeave ? "this session is closed (everything in it is saved) and that one opened"
                                       : "not everything here is saved: save it first (a session folder, Retry)");
        ImGui::SameLine();
        ImGui::TextUnformatted(dir.c_str());
        ImGui::PopID();
    }
    if (!status_.empty()) {
        if (error_) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.35f, 1.0f), "%s", status_.c_str());
        else ImGui::TextWrapped("%s", status_.c_str());
    }
    return goTo;
}

}  // namespace hg::garden
