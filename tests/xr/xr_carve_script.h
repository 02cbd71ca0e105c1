// A replay script's steps in which the headset's right hand carves sculpture
// 'a' of the small garden (tests/garden/session_garden.h) seen from the
// origin, for the XR tests that carve through the mock runtime.
#pragma once

namespace hg::xr::test {

// The right hand aims at sculpture 'a' (a ball of radius 0.5 at (0, 0.5,
// -2.31)) from the viewer at the origin, pulls the trigger and sweeps.
inline constexpr const char* kCarveSteps = R"([
  {"frames": 2, "commands": [{"sculpt_tool": {"kind": "carve", "radius": 0.12}}]},
  {"frames": 5, "tool": {"aim": {"position": [0.3, 1.2, -1.0], "direction": [-0.35, -0.6, -1.3]}, "trigger": 1}},
  {"frames": 5, "tool": {"aim": {"position": [0.2, 1.2, -1.0], "direction": [-0.15, -0.6, -1.3]}, "trigger": 1}},
  {"frames": 5, "tool": {"aim": {"position": [0.1, 1.2, -1.0], "direction": [0.05, -0.65, -1.3]}, "trigger": 1}},
  {"frames": 4, "tool": {"aim": {"position": [0.1, 1.2, -1.0], "direction": [0.05, -0.65, -1.3]}, "trigger": 0}}
])";

}  // namespace hg::xr::test
