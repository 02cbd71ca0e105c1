#include "garden/desktop/desktop_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"

namespace hg::garden {

namespace {

std::optional<ToolSettings::Kind> toolOfDigit(int digit) {
    using K = ToolSettings::Kind;
    constexpr K kinds[] = {K::None, K::Carve, K::Add, K::Melt, K::Perturb, K::Impacts, K::Move};
    if (digit < 0 || digit > 6) return std::nullopt;
    return kinds[digit];
}

}  // namespace

bool addKeyPress(DesktopKeys& keys, int key, int mods) {
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0, shift = (mods & GLFW_MOD_SHIFT) != 0;
    if (ctrl) {
        if (key == GLFW_KEY_Z) (shift ? keys.redo : keys.undo) = true;
        else if (key == GLFW_KEY_Y) keys.redo = true;
        else return false;
        return true;
    }
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) {
        keys.tool = toolOfDigit(key - GLFW_KEY_0);
        return keys.tool.has_value();
    }
    if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) {
        keys.tool = toolOfDigit(key - GLFW_KEY_KP_0);
        return keys.tool.has_value();
    }
    switch (key) {
        case GLFW_KEY_LEFT_BRACKET: --keys.sizeSteps; return true;
        case GLFW_KEY_RIGHT_BRACKET: ++keys.sizeSteps; return true;
        case GLFW_KEY_R: keys.reverse = !keys.reverse; return true;
        case GLFW_KEY_M: keys.mirror = !keys.mirror; return true;
        case GLFW_KEY_SPACE: keys.fly = true; return true;
        case GLFW_KEY_O: keys.orbit = true; return true;
        case GLFW_KEY_G: keys.detail = true; return true;
        case GLFW_KEY_F9: keys.headset = true; return true;
        case GLFW_KEY_F12: keys.screenshot = true; return true;
        case GLFW_KEY_ESCAPE: keys.quit = true; return true;
        case GLFW_KEY_HOME: keys.resetView = true; return true;
        case GLFW_KEY_F1: keys.help = true; return true;
        default: return false;
    }
}

bool quitRequested(const DesktopKeys& keys) {
    return keys.quit && !(ImGui::GetCurrentContext() && ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId));
}

void applyToolKeys(const DesktopKeys& keys, float& wheel, GardenSession& session) {
    ToolSettings& tool = session.tool();
    if (keys.tool) tool.kind = *keys.tool;
    if (keys.reverse) tool.reverse = !tool.reverse;
    const int selected = session.selected();
    if (keys.mirror && selected >= 0) {
        const Sculpture& s = session.sculptures()[static_cast<std::size_t>(selected)];
        if (!s.missing()) session.setMirror(selected, s.mirror ? std::nullopt : std::optional<MirrorPlane>(centralMirror(s)));
    }
    if (tool.kind == ToolSettings::Kind::Move) {
        const float steps = static_cast<float>(keys.sizeSteps) + (selected >= 0 ? wheel : 0.0f);
        if (selected >= 0) wheel = 0.0f;
        if (steps != 0.0f && selected >= 0) {
            const Placement before = session.sculptures()[static_cast<std::size_t>(selected)].placement;
            Placement p = before;
            p.scale = std::clamp(p.scale * std::pow(kToolSizeStep, static_cast<double>(steps)), kMinSculptureScale,
                                 kMaxSculptureScale);
            if (p.scale != before.scale) session.moveSculpture(selected, p);
        }
        return;
    }
    if (keys.sizeSteps != 0) scaleToolSize(tool, std::pow(kToolSizeStep, keys.sizeSteps));
}

Hands desktopHands(DesktopInput in, const DesktopKeys& keys, GardenSession& session, const glm::mat4& projection,
                   float& speed) {
    applyToolKeys(keys, in.wheel, session);
    in.undo = keys.undo;
    in.redo = keys.redo;
    in.flyToggle = keys.fly;
    in.orbitToggle = keys.orbit;
    const Hands hands = mapDesktop(in, session.view(), projection, DesktopMapping{}, speed);
    speed = hands.speedScale;
    return hands;
}

}  // namespace hg::garden
