#include "garden/render/shaders.h"

namespace hg::garden::shaders {

// Shared by the lit programs: the frame's lights and the sRGB transfer.
#define HG_LIGHTING_GLSL                                                              \
    "uniform vec3 uEye;\n"                                                            \
    "uniform vec3 uAmbient;\n"                                                        \
    "uniform int uLightCount;\n"                                                      \
    "uniform vec3 uLightDir[3];\n"                                                    \
    "uniform vec3 uLightColor[3];\n"                                                  \
    "uniform int uPointCount;\n"                                                      \
    "uniform vec3 uPointPosition[8];\n"                                               \
    "uniform vec3 uPointColor[8];\n"                                                  \
    "uniform float uPointRange[8];\n"                                                 \
    "vec3 toLinear(vec3 c) {\n"                                                       \
    "    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));\n" \
    "}\n"                                                                             \
    "vec3 toSrgb(vec3 c) {\n"                                                         \
    "    c = clamp(c, 0.0, 1.0);\n"                                                   \
    "    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));\n" \
    "}\n"                                                                             \
    "vec3 blinnPhong(vec3 base, vec3 n, vec3 l, vec3 v, float specular, float shininess) {\n" \
    "    float ndl = dot(n, l);\n"                                                    \
    "    if (ndl <= 0.0) return vec3(0.0);\n"                                         \
    "    float ndh = max(dot(n, normalize(l + v)), 0.0);\n"                           \
    "    return base * ndl + vec3(specular * pow(ndh, shininess));\n"                 \
    "}\n"                                                                             \
    "vec3 shade(vec3 base, vec3 n, vec3 p, float specular, float shininess) {\n"      \
    "    vec3 v = normalize(uEye - p);\n"                                             \
    "    vec3 c = uAmbient * base;\n"                                                 \
    "    for (int i = 0; i < uLightCount; ++i)\n"                                     \
    "        c += uLightColor[i] * blinnPhong(base, n, uLightDir[i], v, specular, shininess);\n" \
    "    for (int i = 0; i < uPointCount; ++i) {\n"                                   \
    "        vec3 d = uPointPosition[i] - p;\n"                                       \
    "        float r = length(d);\n"                                                  \
    "        if (r >= uPointRange[i]) continue;\n"                                    \
    "        float x = r / uPointRange[i];\n"                                         \
    "        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);\n"                  \
    "        float falloff = window * window / max(r * r, 0.01);\n"                   \
    "        vec3 l = d / max(r, 1e-4);\n"                                            \
    "        c += falloff * uPointColor[i] * blinnPhong(base, n, l, v, specular, shininess);\n" \
    "    }\n"                                                                         \
    "    return c;\n"                                                                 \
    "}\n"

const char* const kMeshVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProjection;
out vec3 vWorld;
out vec3 vNormal;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    gl_Position = uViewProjection * world;
}
)";

const char* const kMeshFragment = "#version 330 core\n" HG_LIGHTING_GLSL R"(
in vec3 vWorld;
in vec3 vNormal;
uniform vec3 uBaseColor;
uniform float uSpecular;
uniform float uShininess;
uniform bool uHasNormals;
out vec4 fragColor;
void main() {
    // Without vertex normals, the face normal from screen-space derivatives
    // (it faces the viewer, and culling leaves only front faces).
    vec3 n = uHasNormals ? normalize(vNormal) : normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    vec3 c = shade(toLinear(uBaseColor), n, vWorld, uSpecular, uShininess);
    fragColor = vec4(toSrgb(c), 1.0);
}
)";

const char* const kGroundVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
out vec3 vWorld;
void main() {
    vWorld = aPosition;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* const kGroundFragment = "#version 330 core\n" HG_LIGHTING_GLSL R"(
in vec3 vWorld;
uniform vec3 uGroundColor;
uniform vec3 uLineColor;
uniform float uSpacing;
uniform float uLineWidth;   // pixels
uniform int uMajorEvery;
out vec4 fragColor;
// 1 on a line of the grid with the given spacing, 0 between, anti-aliased
// over a pixel; fades out where cells shrink to a few pixels (no moire).
float grid(vec2 coord, float width) {
    vec2 w = max(fwidth(coord), vec2(1e-6));
    vec2 d = abs(fract(coord - 0.5) - 0.5) / w;
    float line = 1.0 - smoothstep(0.5 * width - 0.5, 0.5 * width + 0.5, min(d.x, d.y));
    return line * (1.0 - smoothstep(0.15, 0.35, max(w.x, w.y)));
}
void main() {
    vec2 coord = vWorld.xz / uSpacing;
    float line = grid(coord, uLineWidth);
    if (uMajorEvery > 1) line = max(line, grid(coord / float(uMajorEvery), 2.0 * uLineWidth));
    vec3 base = mix(toLinear(uGroundColor), toLinear(uLineColor), line);
    vec3 c = shade(base, vec3(0.0, 1.0, 0.0), vWorld, 0.0, 1.0);
    fragColor = vec4(toSrgb(c), 1.0);
}
)";

const char* const kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;
uniform float uDepthPull;
void main() {
    vec4 eye = uView * uModel * vec4(aPosition, 1.0);
    // Scaling about the eye keeps the screen position and moves the depth
    // a fixed fraction of the distance nearer.
    eye.xyz *= 1.0 - uDepthPull;
    gl_Position = uProjection * eye;
}
)";

const char* const kFlatFragment = R"(#version 330 core
uniform vec4 uColor;
out vec4 fragColor;
void main() { fragColor = uColor; }
)";

#undef HG_LIGHTING_GLSL

}  // namespace hg::garden::shaders
