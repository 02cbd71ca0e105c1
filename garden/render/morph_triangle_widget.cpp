#include <imgui.h>

#include "garden/render/morph_triangle.h"
#include "garden/render/panels.h"

namespace hg::garden {
namespace {

ImVec2 im(const glm::vec2& v) { return ImVec2(v.x, v.y); }

// One colour per key sculpture, blended across the face like the morph.
const ImU32 kCornerColors[3] = {IM_COL32(200, 90, 80, 255), IM_COL32(80, 170, 100, 255), IM_COL32(80, 120, 210, 255)};

}  // namespace

bool morphTriangleWidget(const char* const labels[3], glm::vec2& point, float side) {
    const ImVec2 cursor = ImGui::GetCursorScreenPos();
    const MorphTriangleLayout layout =
        morphTriangleLayout(glm::vec2(cursor.x, cursor.y), side, ImGui::GetTextLineHeight());
    ImGui::InvisibleButton("##morph_triangle", im(layout.size));

    bool changed = false;
    if (ImGui::IsItemActive()) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const glm::vec2 picked = clampToTriangle(screenToTriangle(layout, glm::vec2(mouse.x, mouse.y)));
        if (picked != point) {
            point = picked;
            changed = true;
        }
    }

    ImDrawList* draw = ImGui::GetWindowDrawList();
    const auto& corners = morphTriangleCorners();
    ImVec2 screen[3];
    for (int i = 0; i < 3; ++i) screen[i] = im(triangleToScreen(layout, corners[static_cast<std::size_t>(i)]));
    // Vertex colours need the font atlas's white pixel as texture coordinate.
    const ImVec2 white = ImGui::GetFontTexUvWhitePixel();
    draw->PrimReserve(3, 3);
    const ImDrawIdx base = static_cast<ImDrawIdx>(draw->_VtxCurrentIdx);
    for (int i = 0; i < 3; ++i) draw->PrimWriteVtx(screen[i], white, kCornerColors[i]);
    draw->PrimWriteIdx(base);
    draw->PrimWriteIdx(static_cast<ImDrawIdx>(base + 1));
    draw->PrimWriteIdx(static_cast<ImDrawIdx>(base + 2));
    draw->AddTriangle(screen[0], screen[1], screen[2], IM_COL32(240, 240, 240, 255), 1.5f);

    const float line = ImGui::GetTextLineHeight();
    for (int i = 0; i < 3; ++i) {
        const char* label = labels[i] ? labels[i] : "";
        const ImVec2 textSize = ImGui::CalcTextSize(label);
        // Labels centred under the base corners and above the apex.
        const float y = i == 2 ? screen[i].y - line - 2.0f : screen[i].y + 2.0f;
        draw->AddText(ImVec2(screen[i].x - 0.5f * textSize.x, y), ImGui::GetColorU32(ImGuiCol_Text), label);
    }
    const ImVec2 marker = im(triangleToScreen(layout, clampToTriangle(point)));
    draw->AddCircleFilled(marker, 5.0f, IM_COL32(255, 255, 255, 255));
    draw->AddCircle(marker, 5.0f, IM_COL32(0, 0, 0, 255), 0, 1.5f);

    const glm::vec3 w = triangleWeights(point);
    ImGui::Text("%s %.2f  %s %.2f  %s %.2f", labels[0] ? labels[0] : "", static_cast<double>(w.x),
                labels[1] ? labels[1] : "", static_cast<double>(w.y), labels[2] ? labels[2] : "",
                static_cast<double>(w.z));
    return changed;
}

}  // namespace hg::garden
