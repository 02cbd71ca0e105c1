// An ImGui context with no backend: enough for widgets, which only build
// draw lists (the font atlas built, no imgui.ini).
#pragma once

#include <imgui.h>

namespace hg::garden {

inline void createHeadlessImGui(ImVec2 displaySize) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = displaySize;
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
}

}  // namespace hg::garden
