// Moving about the garden from the hands (docs/design.md §6): walk on the ground at
// eye height, fly freely, or orbit a selected sculpture. The navigation
// hand's thumbstick moves, Hands::look turns, the stick click toggles walk
// and fly, the primary button toggles orbiting (when a target is set).
#pragma once

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/hands/hand_state.h"

namespace hg::garden {

enum class NavigationMode { Walk, Fly, Orbit };

struct NavigationSettings {
    float walkSpeed = 1.4f;     // m/s, a stroll
    float flySpeed = 3.0f;      // m/s
    float eyeHeight = 1.7f;     // m above the ground while walking
    float minPitch = -1.45f, maxPitch = 1.45f;  // radians: never straight up or down
    float orbitMinDistance = 0.3f;
};

class Navigator {
public:
    explicit Navigator(NavigationSettings s = {}) : settings_(s) {}

    // Eye position (metres) and heading: yaw 0 looks along -z, positive
    // yaw turns right; pitch positive looks up.
    void setPose(const glm::vec3& eye, float yaw, float pitch);
    void setMode(NavigationMode m);
    // What orbiting circles (a sculpture's centre); none: orbit is refused.
    void setOrbitTarget(std::optional<glm::vec3> target) { orbitTarget_ = target; }

    void update(const Hands& hands, double dt);

    NavigationMode mode() const { return mode_; }
    const glm::vec3& eye() const { return eye_; }
    float yaw() const { return yaw_; }
    float pitch() const { return pitch_; }
    glm::vec3 forward() const;
    glm::mat4 view() const;

private:
    NavigationSettings settings_;
    NavigationMode mode_ = NavigationMode::Walk;
    NavigationMode beforeOrbit_ = NavigationMode::Walk;
    glm::vec3 eye_{0.0f, 1.7f, 0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f;
    std::optional<glm::vec3> orbitTarget_;
    std::uint32_t previousButtons_ = 0;
};

}  // namespace hg::garden
