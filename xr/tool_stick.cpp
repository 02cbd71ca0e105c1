#include "xr/tool_stick.h"

#include <cmath>

namespace hg::xr {

namespace {

// The stick past its dead zone, rescaled to [-1, 1].
double live(float v) {
    const float a = std::fabs(v);
    if (!(a > kStickDeadZone)) return 0.0;  // NaN too
    return std::copysign(static_cast<double>((std::fmin(a, 1.0f) - kStickDeadZone) / (1.0f - kStickDeadZone)),
                         static_cast<double>(v));
}

}  // namespace

garden::ToolIntents stickIntents(glm::vec2 stick, double dt) {
    garden::ToolIntents intents;
    const double y = live(stick.y), x = live(stick.x);
    if (y != 0.0) intents.size = std::exp2(y * dt);
    if (x != 0.0) intents.strength = std::exp2(x * dt);
    intents.held = y != 0.0;
    return intents;
}

}  // namespace hg::xr
