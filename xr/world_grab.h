// Two-handed manipulation of the world (docs/design.md §6, §8): squeezing the
// navigation hand grabs the world, which then follows the hand; squeezing
// both scales it about the midpoint of the hands (the scale clamped, never
// zero or negative) and turns it about the vertical through that midpoint
// as the hands turn. The world point under the grabbing hand (one hand) or
// under the midpoint (two) stays under it. Works on the StageRig only.
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "xr/stage_rig.h"

namespace hg::xr {

// The rig's scale range: the world from ten times bigger to ten times smaller.
constexpr float kMinRigScale = 0.1f;
constexpr float kMaxRigScale = 10.0f;

class WorldGrab {
public:
    // The hands' grip positions in the stage, each present while its hand
    // squeezes. Returns the rig for this frame; a change in which hands
    // squeeze starts a new grab from `rig`.
    StageRig update(const StageRig& rig, const std::optional<glm::vec3>& navigationHand,
                    const std::optional<glm::vec3>& toolHand);
    bool grabbing() const { return hands_ > 0; }
    bool scaling() const { return hands_ == 2; }

private:
    int hands_ = 0;  // 0 none, 1 navigation hand, 2 both
    StageRig start_;
    glm::vec3 a0_{0.0f}, b0_{0.0f};  // navigation and tool hand at the grab's start (stage)
};

}  // namespace hg::xr
