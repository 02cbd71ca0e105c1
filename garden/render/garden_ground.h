// The garden's ground and air as every garden view draws them (desktop,
// headset, offscreen, turntable): a mown lawn with a survey grid near the
// eye, a meadow beyond it to the far plane, and haze where the meadow meets
// the sky. docs/rendering.md, "The ground and the haze".
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "garden/render/renderer.h"

namespace hg::garden {

// The near and far planes of every garden view: 5 cm keeps a sculpture held
// close in the headset; the meadow reaches the far plane, and the haze has
// covered it there.
constexpr float kGardenNearPlane = 0.05f;
constexpr float kGardenFarPlane = 500.0f;
// A garden view's projection for a viewport of `size` pixels.
glm::mat4 gardenProjection(float fovY, glm::ivec2 size);
// Aerial perspective (View::hazeDistance): 63% haze at this distance, 99%
// at the far plane; under 1% within 20 m, about 19% at 100 m.
constexpr float kGardenHazeDistance = 220.0f;
// The survey grid shows whole within this many metres of the eye (gone by
// twice): scale by one's feet, not a tiled floor to the horizon.
constexpr float kGardenGridReach = 6.0f;
// The garden's sky: scattered fair-weather clouds (View::clouds).
constexpr float kGardenClouds = 0.55f;
// Metres a mown stripe of the garden's lawn.
constexpr float kGardenStripeWidth = 1.5f;

// The ground of a garden whose lawn has this colour (sRGB) and spans
// gardenSize metres along x and z about the origin.
GroundStyle gardenGround(const glm::vec3& lawnColor, const glm::vec2& gardenSize);

}  // namespace hg::garden
