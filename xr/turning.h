// Turning with the navigation thumbstick's x (docs/design.md §8: snap turn is the
// comfort default): a snap (30 degrees unless the user's settings say
// otherwise) each time the stick is pushed past 70 % of its reach, or,
// smooth, 90 degrees a second at full tilt past a dead zone. The stick's x
// then does not strafe.
#pragma once

#include "garden/hands/hand_state.h"

namespace hg::xr {

constexpr float kSnapTurn = 0.5235988f;      // 30 degrees, the default
constexpr float kSnapThreshold = 0.7f;       // of the stick's reach
constexpr float kSmoothTurnRate = 1.5707963f;  // radians a second at full tilt
constexpr float kTurnDeadZone = 0.15f;

class Turning {
public:
    explicit Turning(bool smooth = false, float snap = kSnapTurn) : smooth_(smooth), snap_(snap) {}
    // The hand panel changed the way of turning: in effect from the next
    // frame (a stick held past the threshold does not snap again).
    void set(bool smooth, float snap) {
        smooth_ = smooth;
        snap_ = snap;
    }
    // Radians to turn this frame (positive: right), for Hands::look.x;
    // clears the navigation stick's x.
    float apply(garden::Hands& h, double dt);

private:
    bool smooth_;
    float snap_;  // radians
    int lastSide_ = 0;
};

}  // namespace hg::xr
