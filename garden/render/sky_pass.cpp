#include "garden/render/sky_pass.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "garden/render/renderer.h"
#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

// A unit no other pass of the renderer binds (chunk_batch.h, impostor_atlas.h,
// post_process.cpp, the shadow map's 3).
constexpr GLint kSkyUnit = 8;

const char* const kSkyVertex = R"(#version 330 core
out vec2 vNdc;
void main() {
    vNdc = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    gl_Position = vec4(vNdc, 1.0, 1.0);  // on the far plane: behind everything drawn
}
)";

// Compiled three ways (HG_SKY): 0 the whole sky per pixel, 1 the cube map
// then the sun per pixel, 2 one face of the cube map (uFace, the GL order
// +x -x +y -y +z -z).
const char* const kSkyFragment = "#version 330 core\n" HG_SRGB_GLSL HG_VALUE_NOISE_2D_GLSL R"(
in vec2 vNdc;
uniform mat4 uInverseViewProjection;
uniform vec3 uHorizon;  // sRGB
uniform bool uSun;
uniform vec3 uSunDirection;
uniform vec3 uSunColor;  // linear
uniform float uClouds;   // 0: a clear sky; 1: clouds over about half of it
uniform samplerCube uSky;
uniform int uFace;
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
// The gradient with the clouds over it; alpha, the clouds' cover.
vec4 skyAndClouds(vec3 d) {
    vec3 horizon = toLinear(uHorizon);
    vec3 zenith = horizon * vec3(0.45, 0.6, 1.0);
    vec3 c = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y)) : horizon * mix(1.0, 0.6, sqrt(-d.y));
    vec4 cloud = clouds(d, horizon);
    return vec4(mix(c, cloud.rgb, cloud.a), cloud.a);
}
// A disc of about 0.7 degrees, its glow, and a wide haze; a cloud hides
// the disc, not the glow.
vec3 sunAt(vec3 d, float cover) {
    if (!uSun) return vec3(0.0);
    float cosAngle = dot(d, uSunDirection);
    float disc = smoothstep(0.99992, 0.99996, cosAngle);
    float glow = pow(max(cosAngle, 0.0), 600.0) * 0.8 + pow(max(cosAngle, 0.0), 16.0) * 0.08;
    return uSunColor * (disc * 40.0 * (1.0 - cover) + glow);
}
vec3 viewDirection() {
    vec4 a = uInverseViewProjection * vec4(vNdc, -1.0, 1.0);
    vec4 b = uInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    return normalize(b.xyz / b.w - a.xyz / a.w);
}
void main() {
#if HG_SKY == 2
    // The face's texel as a direction (the GL spec's cube map table).
    float u = vNdc.x, v = vNdc.y;
    vec3 d = uFace == 0 ? vec3(1.0, -v, -u) : uFace == 1 ? vec3(-1.0, -v, u)
           : uFace == 2 ? vec3(u, 1.0, v)   : uFace == 3 ? vec3(u, -1.0, -v)
           : uFace == 4 ? vec3(u, -v, 1.0)  : vec3(-u, -v, -1.0);
    fragColor = skyAndClouds(normalize(d));
#else
    vec3 d = viewDirection();
#if HG_SKY == 1
    vec4 s = texture(uSky, d);
#else
    vec4 s = skyAndClouds(d);
#endif
    fragColor = vec4(s.rgb + sunAt(d, s.a), 0.0);  // alpha 0: occlusion leaves the sky alone
#endif
}
)";

}  // namespace

SkyPass::Program SkyPass::compile(const char* name, const char* vertex, const char* defines) {
    Program p;
    p.program = ShaderProgram(name, vertex, withDefines(kSkyFragment, defines).c_str());
    const ShaderProgram& s = p.program;
    p.inverseViewProjection = s.uniform("uInverseViewProjection");
    p.horizon = s.uniform("uHorizon");
    p.sun = s.uniform("uSun");
    p.sunDirection = s.uniform("uSunDirection");
    p.sunColor = s.uniform("uSunColor");
    p.clouds = s.uniform("uClouds");
    p.face = s.uniform("uFace");
    s.use();
    glUniform1i(s.uniform("uSky"), kSkyUnit);
    return p;
}

SkyPass::SkyPass()
    : direct_(compile("sky", kSkyVertex, "#define HG_SKY 0\n")),
      lookup_(compile("sky (cube map)", kSkyVertex, "#define HG_SKY 1\n")),
      bake_(compile("sky (cube face)", kSkyVertex, "#define HG_SKY 2\n")),
      empty_(gl::VertexArray::create()),
      cube_(gl::Texture::create()),
      bakeTarget_(gl::Framebuffer::create()) {
    // Filtering across the faces' edges, so the seams do not show.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

void SkyPass::setLook(const Program& p, const Look& look) {
    p.program.use();
    glUniform3fv(p.horizon, 1, glm::value_ptr(look.horizon));
    glUniform1i(p.sun, look.sun ? 1 : 0);
    glUniform1f(p.clouds, look.clouds);
    glUniform3fv(p.sunDirection, 1, glm::value_ptr(look.sunDirection));
    glUniform3fv(p.sunColor, 1, glm::value_ptr(look.sunColor));
}

void SkyPass::bake(const Look& look) {
    const gl::TargetKept kept;
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
    const GLboolean multisample = glIsEnabled(GL_MULTISAMPLE);

    if (look.faceSize != allocatedFaceSize_) {
        glActiveTexture(GL_TEXTURE0 + kSkyUnit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube_.get());
        for (int face = 0; face < 6; ++face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA16F, look.faceSize, look.faceSize, 0, GL_RGBA,
                         GL_FLOAT, nullptr);
        gl::sampleLinearClamped(GL_TEXTURE_CUBE_MAP);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        glActiveTexture(GL_TEXTURE0);
        allocatedFaceSize_ = look.faceSize;
    }
    setLook(bake_, look);
    glBindFramebuffer(GL_FRAMEBUFFER, bakeTarget_.get());
    glViewport(0, 0, look.faceSize, look.faceSize);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_MULTISAMPLE);
    glBindVertexArray(empty_.get());
    for (int face = 0; face < 6; ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                               cube_.get(), 0);
        glUniform1i(bake_.face, face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glBindVertexArray(0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);

    if (depthTest) glEnable(GL_DEPTH_TEST);
    if (multisample) glEnable(GL_MULTISAMPLE);
    inCube_ = look;
    ++bakes_;
}

void SkyPass::draw(const View& view, int faceSize) {
    Look look;
    look.faceSize = std::clamp(faceSize, 16, 4096);
    look.horizon = glm::vec3(view.clearColor);
    look.sun = !view.lights.empty() && glm::length(view.lights.front().direction) > 0.0f;
    look.clouds = std::clamp(view.clouds, 0.0f, 1.0f);
    if (look.sun) {
        look.sunDirection = glm::normalize(view.lights.front().direction);
        look.sunColor = view.lights.front().color;
    }
    if (baked_ && !(inCube_ && *inCube_ == look)) bake(look);

    const Program& p = baked_ ? lookup_ : direct_;
    setLook(p, look);
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    glUniformMatrix4fv(p.inverseViewProjection, 1, GL_FALSE, glm::value_ptr(inverse));
    glActiveTexture(GL_TEXTURE0 + kSkyUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, baked_ ? cube_.get() : 0);
    glActiveTexture(GL_TEXTURE0);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace hg::garden
