#include "xr/walking.h"

#include <cmath>

namespace hg::xr {

float headHeading(const garden::Pose& headStage) {
    glm::vec3 f = headStage.forward();
    if (f.x * f.x + f.z * f.z < 1e-6f) f = f.y < 0.0f ? headStage.up() : -headStage.up();
    return std::atan2(f.x, -f.z);
}

glm::vec2 headRelativeStick(const glm::vec2& stick, const garden::Pose& headStage) {
    // ahead(a) = cos(h) ahead + sin(h) right, right(a) = cos(h) right - sin(h) ahead.
    const float h = headHeading(headStage), c = std::cos(h), s = std::sin(h);
    return {stick.x * c + stick.y * s, stick.y * c - stick.x * s};
}

}  // namespace hg::xr
