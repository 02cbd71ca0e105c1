#include "xr/world_grab.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace hg::xr {

namespace {

// Below this the hands are taken to be together: the scale holds.
constexpr float kMinHandSpan = 1e-3f;

// The heading of a horizontal direction in the navigator's convention.
float heading(const glm::vec3& d) { return std::atan2(d.x, -d.z); }

}  // namespace

StageRig WorldGrab::update(const StageRig& rig, const std::optional<glm::vec3>& navigationHand,
                           const std::optional<glm::vec3>& toolHand) {
    const int hands = navigationHand ? (toolHand ? 2 : 1) : 0;
    if (hands != hands_) {
        hands_ = hands;
        start_ = rig;
        if (navigationHand) a0_ = *navigationHand;
        if (toolHand) b0_ = *toolHand;
        return rig;
    }
    if (hands == 0) return rig;
    StageRig r = start_;
    if (hands == 1) {
        r.origin = start_.toWorld(a0_) - r.rotation() * (r.scale * *navigationHand);
        return r;
    }
    const glm::vec3 d0 = b0_ - a0_, d1 = *toolHand - *navigationHand;
    const float span0 = glm::length(d0), span1 = glm::length(d1);
    if (span0 > kMinHandSpan && span1 > kMinHandSpan)
        r.scale = std::clamp(start_.scale * span0 / span1, kMinRigScale, kMaxRigScale);
    // Hands turning one way turn the world with them: the rig the other way.
    const glm::vec2 h0(d0.x, d0.z), h1(d1.x, d1.z);
    if (glm::length(h0) > kMinHandSpan && glm::length(h1) > kMinHandSpan) r.yaw = start_.yaw + heading(d0) - heading(d1);
    const glm::vec3 m0 = 0.5f * (a0_ + b0_), m1 = 0.5f * (*navigationHand + *toolHand);
    r.origin = start_.toWorld(m0) - r.rotation() * (r.scale * m1);
    return r;
}

}  // namespace hg::xr
