#include "garden/render/sky_pass.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

#include "garden/render/renderer.h"
#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

const char* const kSkyVertex = R"(#version 330 core
out vec2 vNdc;
void main() {
    vNdc = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    gl_Position = vec4(vNdc, 1.0, 1.0);  // on the far plane: behind everything drawn
}
)";

const char* const kSkyFragment = "#version 330 core\n" HG_SRGB_GLSL HG_VALUE_NOISE_2D_GLSL R"(
in vec2 vNdc;
uniform mat4 uInverseViewProjection;
uniform vec3 uHorizon;  // sRGB
uniform bool uSun;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;  // linear
uniform float uClouds;   // 0: a clear sky; 1: clouds over about half of it
out vec4 fragColor;
// Five octaves, about 0..1 with mean 0.5; each octave turned so the
// lattice does not line up.
float fbm(vec2 p) {
    float sum = 0.0, amplitude = 0.5;
    mat2 turn = mat2(0.8, 0.6, -0.6, 0.8);
    for (int i = 0; i < 5; ++i) {
        sum += amplitude * noise(p);
        p = turn * p * 2.03 + 11.7;
        amplitude *= 0.5;
    }
    return sum / 0.96875;
}
// Fair-weather clouds on a layer 1.5 km up (kilometres across the layer),
// fixed in the world so they do not move with the visitor's steps. Lit by
// one look towards the sun: where the layer is thicker sunward, this
// point is in its own cloud's shade. Thinned to nothing towards the
// horizon, where the layer's pattern would shrink below a pixel and the
// haze takes over. Returns the cloud's colour and its cover.
vec4 clouds(vec3 d, vec3 horizon) {
    if (uClouds <= 0.0 || d.y <= 0.0) return vec4(0.0);
    vec2 p = d.xz / max(d.y, 0.02) * 1.5 + vec2(3.1, 7.9);
    float density = fbm(p * 0.9);
    float cover = smoothstep(0.64 - 0.22 * uClouds, 0.8 - 0.22 * uClouds, density);
    cover *= smoothstep(0.03, 0.25, d.y);
    if (cover <= 0.0) return vec4(0.0);
    vec2 sunward = uSun ? normalize(uSunDirection.xz + vec2(1e-4)) * 0.12 : vec2(0.0);
    float lit = clamp(1.0 - 3.0 * (fbm((p + sunward) * 0.9) - density), 0.35, 1.0);
    vec3 sunlight = uSun ? uSunColor : vec3(1.0);
    vec3 shade = horizon * vec3(0.82, 0.86, 0.95);
    return vec4(mix(shade, 1.05 * sunlight, lit), cover);
}
void main() {
    vec4 a = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 b = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 d = normalize(b.xyz / b.w - a.xyz / a.w);
    vec3 horizon = toLinear(uHorizon);
    vec3 zenith = horizon * vec3(0.45, 0.6, 1.0);
    vec3 c = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y)) : horizon * mix(1.0, 0.6, sqrt(-d.y));
    vec4 cloud = clouds(d, horizon);
    c = mix(c, cloud.rgb, cloud.a);
    if (uSun) {
        float cosAngle = dot(d, uSunDirection);
        // A disc of about 0.7 degrees, its glow, and a wide haze.
        float disc = smoothstep(0.99992, 0.99996, cosAngle);
        float glow = pow(max(cosAngle, 0.0), 600.0) * 0.8 + pow(max(cosAngle, 0.0), 16.0) * 0.08;
        c += uSunColor * (disc * 40.0 * (1.0 - cloud.a) + glow);
    }
    fragColor = vec4(c, 0.0);  // alpha 0: occlusion leaves the sky alone
}
)";

}  // namespace

SkyPass::SkyPass() : program_("sky", kSkyVertex, kSkyFragment), empty_(gl::VertexArray::create()) {
    inverseViewProjection_ = program_.uniform("uInverseViewProjection");
    horizon_ = program_.uniform("uHorizon");
    sun_ = program_.uniform("uSun");
    sunDirection_ = program_.uniform("uSunDirection");
    sunColor_ = program_.uniform("uSunColor");
    clouds_ = program_.uniform("uClouds");
}

void SkyPass::draw(const View& view) {
    program_.use();
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    glUniformMatrix4fv(inverseViewProjection_, 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform3fv(horizon_, 1, glm::value_ptr(glm::vec3(view.clearColor)));
    const bool sun = !view.lights.empty() && glm::length(view.lights.front().direction) > 0.0f;
    glUniform1i(sun_, sun ? 1 : 0);
    glUniform1f(clouds_, std::clamp(view.clouds, 0.0f, 1.0f));
    if (sun) {
        const glm::vec3 direction = glm::normalize(view.lights.front().direction);
        glUniform3fv(sunDirection_, 1, glm::value_ptr(direction));
        glUniform3fv(sunColor_, 1, glm::value_ptr(view.lights.front().color));
    }
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace hg::garden
