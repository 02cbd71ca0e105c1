// The first-run overlay (issue 23): a new user sees what the garden is and
// the few keys to begin with before anything else, until they dismiss it;
// the desktop remembers that in its settings (garden/desktop/desktop_settings.h).
#include <imgui.h>

#include <algorithm>

#include "garden/render/key_table.h"
#include "garden/render/panels.h"

namespace hg::garden {

namespace {

// The rows of the key table a first hour needs, in the table's words.
bool firstHourRow(const KeyRow& r) {
    for (const char* keys : {"W A S D, Q / E", "right button drag", "left button", "0 1 2 3 4 5 6 7",
                             "Ctrl+Z, Ctrl+Shift+Z (Ctrl+Y)", "Home", "F1"})
        if (r.keys == keys) return true;
    return false;
}

}  // namespace

bool drawFirstRunPanel(bool& open) {
    if (!open) return false;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x - 20.0f), 0.0f), ImGuiCond_Always);
    ImGui::Begin("Welcome to Hypergarden", nullptr,
                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoResize);
    ImGui::TextWrapped(
        "A garden of HyperFun sculptures you can walk through and sculpt. Pick a tool with the number keys, then "
        "press on a sculpture and drag: the stroke edits that sculpture only. Every action can be undone.");
    ImGui::Spacing();
    drawKeyRows("##first keys", 180.0f, firstHourRow);
    ImGui::Spacing();
    const bool dismissed = ImGui::Button("Start") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
    ImGui::SameLine();
    ImGui::TextDisabled("F1 shows every key at any time; Esc closes this too.");
    ImGui::End();
    if (dismissed) open = false;
    return dismissed;
}

}  // namespace hg::garden
