#include "garden/hands/desktop_hands.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

namespace hg::garden {

Pose rayThroughPixel(glm::vec2 pixel, glm::vec2 viewport, const glm::mat4& view, const glm::mat4& projection) {
    const glm::vec2 ndc(2.0f * pixel.x / viewport.x - 1.0f, 1.0f - 2.0f * pixel.y / viewport.y);
    const glm::mat4 inv = glm::inverse(projection * view);
    glm::vec4 nearPoint = inv * glm::vec4(ndc, -1.0f, 1.0f), farPoint = inv * glm::vec4(ndc, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    const glm::vec3 eye = glm::vec3(glm::inverse(view)[3]);
    const glm::vec3 dir = glm::normalize(glm::vec3(farPoint) - glm::vec3(nearPoint));
    Pose p;
    p.position = eye;
    // The rotation taking -z to `dir`, keeping +y as up as far as it goes.
    const glm::vec3 up = std::fabs(dir.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    p.orientation = glm::quatLookAt(dir, up);
    return p;
}

void applyPointer(DesktopInput& in, const PointerFrame& p, glm::vec2 windowToFramebuffer, bool free) {
    in.toolButton = free && p.toolButton;
    in.lookButton = free && p.lookButton;
    in.gestureButton = free && p.gestureButton;
    in.mouse = p.toolPosition * windowToFramebuffer;
    in.mouseDelta = p.lookDelta;
}

Hands mapDesktop(const DesktopInput& in, const glm::mat4& view, const glm::mat4& projection, const DesktopMapping& m,
                 float previousSpeedScale) {
    Hands h;
    h.navigation.tracked = true;
    h.navigation.thumbstick = glm::vec2(static_cast<float>(in.right) - static_cast<float>(in.left),
                                        static_cast<float>(in.forward) - static_cast<float>(in.back));
    if (in.flyToggle) h.navigation.buttons |= kButtonThumbstick;
    if (in.orbitToggle) h.navigation.buttons |= kButtonPrimary;
    h.navigation.grip = Pose{glm::vec3(glm::inverse(view)[3]), glm::quat_cast(glm::mat3(glm::inverse(view)))};
    h.navigation.aim = h.navigation.grip;

    h.tool.tracked = true;
    h.tool.aim = rayThroughPixel(in.mouse, in.viewport, view, projection);
    h.tool.grip = h.tool.aim;
    h.tool.trigger = in.toolButton ? 1.0f : 0.0f;
    h.tool.thumbstick = glm::vec2(0.0f, static_cast<float>(in.up) - static_cast<float>(in.down));
    if (in.undo) h.tool.buttons |= kButtonUndo;
    if (in.redo) h.tool.buttons |= kButtonRedo;
    if (in.turn) h.tool.buttons |= kButtonSecondary;
    if (in.gestureButton) h.tool.buttons |= kButtonGesture;

    if (in.lookButton) h.look = glm::vec2(in.mouseDelta.x, -in.mouseDelta.y) * m.lookRadiansPerPixel;
    h.speedScale = previousSpeedScale * std::pow(m.speedStep, in.wheel);
    return h;
}

}  // namespace hg::garden
