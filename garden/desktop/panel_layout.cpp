#include "garden/desktop/panel_layout.h"

#include <imgui.h>

namespace hg::garden {

std::string panelLayout() {
    if (!ImGui::GetCurrentContext()) return "";
    return ImGui::SaveIniSettingsToMemory();
}

void restorePanelLayout(const std::string& layout) {
    if (!ImGui::GetCurrentContext() || layout.empty()) return;
    ImGui::LoadIniSettingsFromMemory(layout.data(), layout.size());
}

}  // namespace hg::garden
