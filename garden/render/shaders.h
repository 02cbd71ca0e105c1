// GLSL 3.30 core sources for the renderer's three programs. Colours given
// to the renderer are sRGB display values; lighting happens in linear space
// and the result is encoded back to sRGB here (the framebuffer is plain
// RGBA8, so no GL_FRAMEBUFFER_SRGB).
#pragma once

namespace hg::garden::shaders {

// Lit sculpture chunks: Blinn-Phong, up to kMaxLights directional and
// kMaxPointLights point lights (inverse square, windowed to their range).
extern const char* const kMeshVertex;
extern const char* const kMeshFragment;

// The ground plane with its procedural grid.
extern const char* const kGroundVertex;
extern const char* const kGroundFragment;

// Unlit lines and the detail sphere: one colour, pulled slightly towards
// the eye so lines lying on the ground or a surface do not z-fight it.
extern const char* const kFlatVertex;
extern const char* const kFlatFragment;

}  // namespace hg::garden::shaders
