// Turning with the navigation thumbstick's x (DESIGN §8: snap turn is the
// comfort default): a snap of 30 degrees each time the stick is pushed past
// 70 % of its reach, or, smooth, 90 degrees a second at full tilt past a
// dead zone. The stick's x then does not strafe.
#pragma once

#include "garden/hands/hand_state.h"

namespace hg::xr {

constexpr float kSnapTurn = 0.5235988f;      // 30 degrees
constexpr float kSnapThreshold = 0.7f;       // of the stick's reach
constexpr float kSmoothTurnRate = 1.5707963f;  // radians a second at full tilt
constexpr float kTurnDeadZone = 0.15f;

class Turning {
public:
    explicit Turning(bool smooth = false) : smooth_(smooth) {}
    // Radians to turn this frame (positive: right), for Hands::look.x;
    // clears the navigation stick's x.
    float apply(garden::Hands& h, double dt);

private:
    bool smooth_;
    int lastSide_ = 0;
};

}  // namespace hg::xr
