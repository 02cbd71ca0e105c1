// The tool hand's thumbstick reshapes the tool live (docs/design.md §6, §8): up
// and down grow and shrink its size (radius, perturbation radii, impact
// size), right and left strengthen and weaken it (perturbation strength,
// impact compaction volume). Full tilt doubles or halves in a second;
// sizes and strengths stay in sane ranges.
#pragma once

#include <glm/vec2.hpp>

#include "garden/sculpt/tool_settings.h"

namespace hg::xr {

constexpr double kMinToolSize = 0.005, kMaxToolSize = 1.0;  // metres
constexpr double kMinToolStrength = 0.1, kMaxToolStrength = 20.0;  // voxels (perturb), cm^3 (impacts)
constexpr float kStickDeadZone = 0.15f;

void adjustTool(garden::ToolSettings& tool, glm::vec2 stick, double dt);

// With the move tool the stick's up and down scale the selected sculpture
// instead, at the same rate: the factor for this frame (1 in the dead zone).
double selectionScaleFactor(glm::vec2 stick, double dt);

}  // namespace hg::xr
