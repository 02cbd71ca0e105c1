// GLSL 3.30 core sources for the renderer's scene programs. Colours given
// to the renderer are sRGB display values; the scene is lit in linear
// space into a linear HDR target (the alpha channel carries the share of
// the light that ambient occlusion dims) and post_process.cpp encodes the
// result to sRGB. Lines and the detail sphere (the flat program) are drawn
// afterwards straight into the output framebuffer, as sRGB values.
#pragma once

// The sRGB transfer both ways, for any program that needs it.
#define HG_SRGB_GLSL                                                                  \
    "vec3 toLinear(vec3 c) {\n"                                                       \
    "    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));\n" \
    "}\n"                                                                             \
    "vec3 toSrgb(vec3 c) {\n"                                                         \
    "    c = clamp(c, 0.0, 1.0);\n"                                                   \
    "    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));\n" \
    "}\n"

// Value noise in the plane (hash after Dave Hoskins): 0..1, smooth, one
// lattice cell a unit; the lawn's and the clouds' patterns.
#define HG_VALUE_NOISE_2D_GLSL                                                        \
    "float hash(vec2 p) {\n"                                                          \
    "    p = fract(p * vec2(123.34, 456.21));\n"                                      \
    "    p += dot(p, p + 45.32);\n"                                                   \
    "    return fract(p.x * p.y);\n"                                                  \
    "}\n"                                                                             \
    "float noise(vec2 p) {\n"                                                         \
    "    vec2 i = floor(p), f = fract(p);\n"                                          \
    "    vec2 u = f * f * (3.0 - 2.0 * f);\n"                                         \
    "    return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), u.x),\n"                   \
    "               mix(hash(i + vec2(0.0, 1.0)), hash(i + 1.0), u.x), u.y);\n"       \
    "}\n"

// A batched chunk draw's record (chunk_batch.h): its model matrix, normal
// matrix and material, kDrawRecordTexels texels from texture unit
// kDrawRecordUnit. Texel 7 holds the sRGB base colour and the specular
// strength, texel 8 the shininess and whether the mesh has normals, texel 9
// the SurfaceKind, metalness and detail scale.
#define HG_DRAW_RECORD_GLSL                                                           \
    "uniform samplerBuffer uDrawRecords;\n"                                           \
    "vec4 drawRecord(int draw, int texel) { return texelFetch(uDrawRecords, draw * 10 + texel); }\n" \
    "mat4 drawModel(int d) {\n"                                                       \
    "    return mat4(drawRecord(d, 0), drawRecord(d, 1), drawRecord(d, 2), drawRecord(d, 3));\n" \
    "}\n"                                                                             \
    "mat3 drawNormalMatrix(int d) {\n"                                                \
    "    return mat3(drawRecord(d, 4).xyz, drawRecord(d, 5).xyz, drawRecord(d, 6).xyz);\n" \
    "}\n"

namespace hg::garden::shaders {

// Lit sculpture chunks: Blinn-Phong, up to kMaxLights directional and
// kMaxPointLights point lights (inverse square, windowed to their range);
// the first directional light (the sun) casts shadows.
extern const char* const kMeshVertex;
const char* meshFragment();

// The ground plane with its procedural grid.
extern const char* const kGroundVertex;
extern const char* const kGroundFragment;

// The lit programs' shared functions (after "#version"): the frame's
// lights, the sun's shadow and shade(), for programs built elsewhere (the
// impostor cards).
extern const char* const kLightingGlsl;

// A triangle over the whole viewport (no vertex buffer; vUv in [0, 1]).
extern const char* const kFullscreenVertex;

// Unlit lines and the detail sphere: one colour, pulled slightly towards
// the eye so lines lying on the ground or a surface do not z-fight it.
extern const char* const kFlatVertex;
extern const char* const kFlatFragment;

}  // namespace hg::garden::shaders
