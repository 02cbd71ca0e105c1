#include "garden/app/navigator.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace hg::garden {

void Navigator::setPose(const glm::vec3& eye, float yaw, float pitch) {
    eye_ = eye;
    yaw_ = yaw;
    pitch_ = std::clamp(pitch, settings_.minPitch, settings_.maxPitch);
    if (mode_ == NavigationMode::Walk) eye_.y = settings_.eyeHeight;
}

void Navigator::setMode(NavigationMode m) {
    if (m == NavigationMode::Orbit && !orbitTarget_) return;
    if (m == NavigationMode::Orbit && mode_ != NavigationMode::Orbit) beforeOrbit_ = mode_;
    mode_ = m;
    if (mode_ == NavigationMode::Walk) eye_.y = settings_.eyeHeight;
}

glm::vec3 Navigator::forward() const {
    return {std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

glm::mat4 Navigator::view() const { return glm::lookAt(eye_, eye_ + forward(), glm::vec3(0.0f, 1.0f, 0.0f)); }

void Navigator::update(const Hands& hands, double dt) {
    const std::uint32_t buttons = hands.navigation.buttons;
    const std::uint32_t pressed = buttons & ~previousButtons_;
    previousButtons_ = buttons;
    if (pressed & kButtonThumbstick)
        setMode(mode_ == NavigationMode::Fly ? NavigationMode::Walk : NavigationMode::Fly);
    if (pressed & kButtonPrimary) setMode(mode_ == NavigationMode::Orbit ? beforeOrbit_ : NavigationMode::Orbit);

    const float t = static_cast<float>(dt);
    const glm::vec2 stick = hands.navigation.thumbstick;
    if (mode_ == NavigationMode::Orbit && orbitTarget_) {
        // Turning circles the target; the stick's y comes closer, x circles.
        const glm::vec3 target = *orbitTarget_;
        float distance = std::max(glm::length(eye_ - target), settings_.orbitMinDistance);
        yaw_ += hands.look.x + stick.x * t * 1.0f;
        pitch_ = std::clamp(pitch_ + hands.look.y, settings_.minPitch, settings_.maxPitch);
        distance = std::max(settings_.orbitMinDistance, distance * (1.0f - stick.y * t));
        eye_ = target - forward() * distance;
        eye_.y = std::max(eye_.y, 0.05f);  // never below the ground
        return;
    }
    yaw_ += hands.look.x;
    pitch_ = std::clamp(pitch_ + hands.look.y, settings_.minPitch, settings_.maxPitch);
    const float speed = (mode_ == NavigationMode::Fly ? settings_.flySpeed : settings_.walkSpeed) * hands.speedScale;
    if (mode_ == NavigationMode::Walk) {
        const glm::vec3 ahead(std::sin(yaw_), 0.0f, -std::cos(yaw_)), right(std::cos(yaw_), 0.0f, std::sin(yaw_));
        eye_ += (ahead * stick.y + right * stick.x) * speed * t;
        eye_.y = settings_.eyeHeight;
    } else {
        const glm::vec3 right(std::cos(yaw_), 0.0f, std::sin(yaw_));
        eye_ += (forward() * stick.y + right * stick.x + glm::vec3(0.0f, 1.0f, 0.0f) * hands.tool.thumbstick.y) * speed * t;
        eye_.y = std::max(eye_.y, 0.05f);
    }
}

}  // namespace hg::garden
