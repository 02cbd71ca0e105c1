// The tool hand's thumbstick as tool intents (garden/hands/tool_intents.h;
// docs/design.md §6, §8): up and down grow and shrink the tool in hand (with
// the move tool, the selected sculpture's scale), right and left strengthen
// and weaken it. Full tilt doubles or halves in a second. The session
// applies the intents within the one set of bounds every device shares
// (garden/sculpt/tool_settings.h), and a push held out of the dead zone is
// one gesture: one undo step for the selection's scale.
#pragma once

#include <glm/vec2.hpp>

#include "garden/hands/tool_intents.h"

namespace hg::xr {

constexpr float kStickDeadZone = 0.15f;

// This frame's intents from the stick, held `dt` seconds: size and
// strength factors (1 in the dead zone), `held` while y is out of it.
garden::ToolIntents stickIntents(glm::vec2 stick, double dt);

}  // namespace hg::xr
