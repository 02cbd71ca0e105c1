// Walking in the headset follows the head (issue 13): the navigation
// stick's forward is where the head looks, projected on the ground, not
// the rig's yaw (which the navigator moves along). Pure math.
#pragma once

#include <glm/vec2.hpp>

#include "garden/hands/hand_state.h"

namespace hg::xr {

// The head's heading in the stage about the vertical (0: along -z,
// positive: turned right). Looking straight down (or up) the head's top
// (or its bottom) points where the face is turned.
float headHeading(const garden::Pose& headStage);

// The stick (x right, y forward, in the head's heading) as the navigator
// reads it (in the rig's heading): turned by the head's heading.
glm::vec2 headRelativeStick(const glm::vec2& stick, const garden::Pose& headStage);

}  // namespace hg::xr
