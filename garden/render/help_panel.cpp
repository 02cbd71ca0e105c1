// The key list a new user needs on screen (README "Keys and mouse", the
// same table): open at the first look, toggled by F1, and a one-line hint
// at the bottom of the window while it is closed.
#include <imgui.h>

#include "garden/render/panels.h"

namespace hg::garden {

namespace {

struct KeyRow {
    const char* keys;
    const char* does;
};

constexpr KeyRow kRows[] = {
    {"W A S D, Q / E", "walk (or fly) forward, left, back, right; down / up"},
    {"right button drag", "look"},
    {"wheel", "walking speed (move tool: the selection's scale)"},
    {"space", "fly / walk"},
    {"Home", "back to where the garden starts"},
    {"O", "orbit the selected sculpture"},
    {"G", "full detail around where the mouse points, or off"},
    {"left button", "use the tool where the mouse points (no tool: pick the blend on the ground triangle)"},
    {"0 1 2 3 4 5 6 7", "tool: none, carve, add, melt, perturb, impacts, move, sketch"},
    {"[ / ]", "the tool's size smaller / larger"},
    {"R", "reverse (carve <-> add, pull <-> push)"},
    {"M", "the selected sculpture's mirror plane on / off"},
    {"Shift + drag", "move tool: turn the sculpture"},
    {"Ctrl+Z, Ctrl+Shift+Z", "undo, redo"},
    {"F9", "into the OpenXR headset and back"},
    {"F12", "screenshot"},
    {"F1", "this list"},
    {"Esc", "quit (or close an open drop-down)"},
};

}  // namespace

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
    ImGui::SetNextWindowPos(ImVec2(0.5f * ImGui::GetIO().DisplaySize.x, 0.5f * ImGui::GetIO().DisplaySize.y),
                            ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Keys and mouse (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
            for (const KeyRow& r : kRows) {
                ImGui::TableNextRow();
                ImGui::TableSetColumnIndex(0);
                ImGui::TextUnformatted(r.keys);
                ImGui::TableSetColumnIndex(1);
                ImGui::TextUnformatted(r.does);
            }
            ImGui::EndTable();
        }
        ImGui::TextDisabled("Panels take the keys and clicks over them. The README has the rest.");
    }
    ImGui::End();
}

}  // namespace hg::garden
