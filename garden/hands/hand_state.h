// The hands every tool reads (docs/design.md §6): one type for the desktop (mouse
// and keys mapped onto two hands), OpenXR (two controllers) and scripts
// (recorded hands). Tools never see a device.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "garden/hands/tool_intents.h"

namespace hg::garden {

struct Pose {
    glm::vec3 position{0.0f};                     // world, metres
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // -z forward, +y up (OpenXR's convention)

    glm::vec3 forward() const { return orientation * glm::vec3(0.0f, 0.0f, -1.0f); }
    // Where the pointing ray (from position along forward) meets the ground
    // plane y = height; none when it points level or up.
    std::optional<glm::dvec3> groundHit(double height) const {
        const glm::dvec3 o(position), d(forward());
        if (d.y > -1e-4) return std::nullopt;
        return o + d * ((height - o.y) / d.y);
    }
    glm::vec3 up() const { return orientation * glm::vec3(0.0f, 1.0f, 0.0f); }
    glm::vec3 right() const { return orientation * glm::vec3(1.0f, 0.0f, 0.0f); }
};

// Buttons, as bits of HandState::buttons.
enum HandButton : std::uint32_t {
    kButtonPrimary = 1u << 0,    // A / X, or the desktop's orbit toggle
    kButtonSecondary = 1u << 1,  // B / Y; held, the move tool turns (desktop: Shift)
    kButtonMenu = 1u << 2,
    kButtonThumbstick = 1u << 3,  // stick click: fly / walk toggle
    kButtonUndo = 1u << 4,
    kButtonRedo = 1u << 5,
    // Held, the tool hand's aim draws a gesture (issue 22, garden/app/session_gestures.cpp)
    // instead of working the tool: the desktop's middle button, the headset's
    // navigation-hand trigger.
    kButtonGesture = 1u << 6,
};

struct HandState {
    bool tracked = false;
    Pose grip;                 // where the hand holds
    Pose aim;                  // the pointing ray: the desktop's mouse ray
    float trigger = 0.0f;      // 0..1: the tool acts
    // 0..1: how hard, where the device says (the headset's trigger depth
    // past its press threshold, read once the pull settles: session_sculpting.cpp;
    // a mouse is always 1). Scales smooth, inflate and perturb strengths.
    float pressure = 1.0f;
    float squeeze = 0.0f;      // 0..1: grabs the world
    glm::vec2 thumbstick{0.0f};  // -1..1 each: x right, y forward
    std::uint32_t buttons = 0;

    bool pressed(HandButton b) const { return (buttons & b) != 0; }
};

struct Hands {
    HandState tool;        // the dominant hand: tools
    HandState navigation;  // the other hand: moving about, grabbing the world
    glm::vec2 look{0.0f};  // radians to turn this frame (yaw right, pitch up): desktop mouse look, XR snap turn
    float speedScale = 1.0f;  // multiplies walking speed (desktop: the wheel)
    ToolIntents intents;      // what the user asked of the tool this frame (garden/hands/tool_intents.h)
};

}  // namespace hg::garden
