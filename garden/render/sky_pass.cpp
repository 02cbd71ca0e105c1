#include "garden/render/sky_pass.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

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

const char* const kSkyFragment = "#version 330 core\n" HG_SRGB_GLSL R"(
in vec2 vNdc;
uniform mat4 uInverseViewProjection;
uniform vec3 uHorizon;  // sRGB
uniform bool uSun;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;  // linear
out vec4 fragColor;
void main() {
    vec4 a = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 b = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 d = normalize(b.xyz / b.w - a.xyz / a.w);
    vec3 horizon = toLinear(uHorizon);
    vec3 zenith = horizon * vec3(0.45, 0.6, 1.0);
    vec3 c = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y)) : horizon * mix(1.0, 0.6, sqrt(-d.y));
    if (uSun) {
        float cosAngle = dot(d, uSunDirection);
        // A disc of about 0.7 degrees, its glow, and a wide haze.
        float disc = smoothstep(0.99992, 0.99996, cosAngle);
        float glow = pow(max(cosAngle, 0.0), 600.0) * 0.8 + pow(max(cosAngle, 0.0), 16.0) * 0.08;
        c += uSunColor * (disc * 40.0 + glow);
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
}

void SkyPass::draw(const View& view) {
    program_.use();
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    glUniformMatrix4fv(inverseViewProjection_, 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform3fv(horizon_, 1, glm::value_ptr(glm::vec3(view.clearColor)));
    const bool sun = !view.lights.empty() && glm::length(view.lights.front().direction) > 0.0f;
    glUniform1i(sun_, sun ? 1 : 0);
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
