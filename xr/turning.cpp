#include "xr/turning.h"

#include <cmath>

namespace hg::xr {

float Turning::apply(garden::Hands& h, double dt) {
    const float x = h.navigation.thumbstick.x;
    h.navigation.thumbstick.x = 0.0f;
    if (smooth_) {
        const float a = std::fabs(x);
        if (a <= kTurnDeadZone) return 0.0f;
        return std::copysign((a - kTurnDeadZone) / (1.0f - kTurnDeadZone), x) * kSmoothTurnRate * static_cast<float>(dt);
    }
    const int side = x > kSnapThreshold ? 1 : x < -kSnapThreshold ? -1 : 0;
    const float turn = side != 0 && side != lastSide_ ? static_cast<float>(side) * snap_ : 0.0f;
    lastSide_ = side;
    return turn;
}

}  // namespace hg::xr
