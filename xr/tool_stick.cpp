#include "xr/tool_stick.h"

#include <algorithm>
#include <cmath>

namespace hg::xr {

namespace {

// The stick past its dead zone, rescaled to [-1, 1].
double live(float v) {
    const float a = std::fabs(v);
    if (a <= kStickDeadZone) return 0.0;
    return std::copysign(static_cast<double>((a - kStickDeadZone) / (1.0f - kStickDeadZone)), static_cast<double>(v));
}

double scaled(double v, double factor, double lo, double hi) { return std::clamp(v * factor, lo, hi); }

}  // namespace

double selectionScaleFactor(glm::vec2 stick, double dt) { return std::exp2(live(stick.y) * dt); }

void adjustTool(garden::ToolSettings& tool, glm::vec2 stick, double dt) {
    const double size = std::exp2(live(stick.y) * dt), strength = std::exp2(live(stick.x) * dt);
    if (size != 1.0) {
        tool.radius = scaled(tool.radius, size, kMinToolSize, kMaxToolSize);
        for (double& r : tool.radii) r = scaled(r, size, kMinToolSize, kMaxToolSize);
        tool.impactSize = scaled(tool.impactSize, size, kMinToolSize, kMaxToolSize);
    }
    if (strength != 1.0) {
        // A perturbation's sign (pull or push) stays; its size changes.
        const double k = scaled(std::fabs(tool.strength), strength, kMinToolStrength, kMaxToolStrength);
        tool.strength = std::copysign(k, tool.strength);
        tool.compactionCm3 = scaled(tool.compactionCm3, strength, kMinToolStrength, kMaxToolStrength);
    }
}

}  // namespace hg::xr
