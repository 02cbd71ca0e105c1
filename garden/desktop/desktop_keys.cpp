#include "garden/desktop/desktop_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui.h>

#include <cmath>

#include "garden/app/garden_session.h"
#include "garden/app/tool_intents.h"

namespace hg::garden {

namespace {

std::optional<ToolSettings::Kind> toolOfDigit(int digit) {
    using K = ToolSettings::Kind;
    constexpr K kinds[] = {K::None, K::Carve, K::Add, K::Melt, K::Perturb, K::Impacts, K::Move, K::Sketch};
    if (digit < 0 || digit > 7) return std::nullopt;
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

ToolIntents desktopIntents(const DesktopKeys& keys, float& wheel, const GardenSession& session, double dt,
                           DesktopCarry& carry) {
    ToolIntents intents;
    if (keys.tool) intents.tool = toolChoiceOf(*keys.tool);
    intents.reverse = keys.reverse;
    if (keys.mirror) intents.mirror = MirrorIntent::Toggle;
    if (keys.sizeSteps != 0) intents.size = std::pow(kToolSizeStep, keys.sizeSteps);
    carry.sinceScaleStep += dt;
    const ToolSettings::Kind kind = keys.tool ? *keys.tool : session.tool().kind;
    if (kind == ToolSettings::Kind::Move && session.selected() >= 0) {
        if (wheel != 0.0f) intents.selectionScale = std::pow(kToolSizeStep, static_cast<double>(wheel));
        if (wheel != 0.0f || keys.sizeSteps != 0) carry.sinceScaleStep = 0.0;
        wheel = 0.0f;
        intents.held = carry.sinceScaleStep < kScaleBurstSeconds;
    }
    return intents;
}

Hands desktopHands(DesktopInput in, const DesktopKeys& keys, const GardenSession& session, const glm::mat4& projection,
                   double dt, DesktopCarry& carry) {
    const ToolIntents intents = desktopIntents(keys, in.wheel, session, dt, carry);
    in.undo = keys.undo;
    in.redo = keys.redo;
    in.flyToggle = keys.fly;
    in.orbitToggle = keys.orbit;
    Hands hands = mapDesktop(in, session.view(), projection, DesktopMapping{}, carry.speed);
    hands.intents = intents;
    carry.speed = hands.speedScale;
    return hands;
}

}  // namespace hg::garden
