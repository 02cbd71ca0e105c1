#include "garden/render/occlusion_pass.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

constexpr int kMaxSamples = 32;

// Shared: the scene depth (sample 0) and view-space positions from it.
#define HG_VIEW_POSITION_GLSL                                                              \
    "uniform sampler2DMS uDepth;\n"                                                        \
    "uniform mat4 uInverseProjection;\n"                                                   \
    "uniform ivec2 uFullSize;\n"                                                           \
    "uniform int uScale;\n"                                                                \
    "float depthAt(ivec2 p) { return texelFetch(uDepth, clamp(p, ivec2(0), uFullSize - 1), 0).r; }\n" \
    "vec3 viewAt(ivec2 p, float d) {\n"                                                    \
    "    vec2 ndc = (vec2(p) + 0.5) / vec2(uFullSize) * 2.0 - 1.0;\n"                      \
    "    vec4 v = uInverseProjection * vec4(ndc, d * 2.0 - 1.0, 1.0);\n"                   \
    "    return v.xyz / v.w;\n"                                                            \
    "}\n"                                                                                  \
    "vec3 viewAt(ivec2 p) { return viewAt(p, depthAt(p)); }\n"

const char* const kOcclusionFragment = "#version 330 core\n" HG_VIEW_POSITION_GLSL R"(
uniform mat4 uProjection;
uniform int uSamples;
uniform float uRadius;
uniform vec3 uKernel[32];
out float open;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * uScale;
    float d = depthAt(p);
    if (d >= 1.0) { open = 1.0; return; }
    vec3 P = viewAt(p, d);
    // The normal from the neighbours on the nearer side in depth, so a
    // silhouette's pixel does not take the background's slope.
    vec3 l = viewAt(p - ivec2(1, 0)), r = viewAt(p + ivec2(1, 0));
    vec3 b = viewAt(p - ivec2(0, 1)), t = viewAt(p + ivec2(0, 1));
    vec3 dx = abs(r.z - P.z) < abs(P.z - l.z) ? r - P : P - l;
    vec3 dy = abs(t.z - P.z) < abs(P.z - b.z) ? t - P : P - b;
    vec3 N = normalize(cross(dx, dy));
    // Interleaved gradient noise turns the kernel per pixel; the blur
    // averages the pattern away.
    float a = 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec3 helper = vec3(cos(a), sin(a), 0.0);
    vec3 T = helper - N * dot(helper, N);
    T = length(T) > 1e-4 ? normalize(T) : normalize(cross(N, vec3(0.0, 0.0, 1.0)));
    mat3 tbn = mat3(T, cross(N, T), N);
    float bias = 0.02 * uRadius;
    float hidden = 0.0;
    for (int i = 0; i < uSamples; ++i) {
        // Spread over the radius whatever the count, denser near the point.
        float t = (float(i) + 0.5) / float(uSamples);
        vec3 s = P + tbn * uKernel[i] * (uRadius * (0.1 + 0.9 * t * t));
        vec4 c = uProjection * vec4(s, 1.0);
        vec2 uv = c.xy / c.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) continue;
        ivec2 q = ivec2(uv * vec2(uFullSize));
        float sceneZ = viewAt(q).z;
        // Something in front of the sample hides it, unless that something
        // is far in front of this point (a separate object: no contact).
        float near = smoothstep(0.0, 1.0, uRadius / max(abs(P.z - sceneZ), 1e-4));
        hidden += (sceneZ >= s.z + bias ? 1.0 : 0.0) * near;
    }
    open = clamp(1.0 - 1.5 * hidden / float(uSamples), 0.0, 1.0);
}
)";

const char* const kBlurFragment = "#version 330 core\n" HG_VIEW_POSITION_GLSL R"(
uniform sampler2D uOcclusion;
uniform ivec2 uDirection;
out float open;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uOcclusion, 0);
    float z = viewAt(p * uScale).z;
    float sum = 0.0, weights = 0.0;
    for (int i = -4; i <= 4; ++i) {
        ivec2 q = clamp(p + i * uDirection, ivec2(0), size - 1);
        float dz = abs(viewAt(q * uScale).z - z);
        // Gaussian in pixels, and nearly nothing from across a depth step.
        float w = exp(-float(i * i) / 8.0) * exp(-dz / (0.02 * abs(z) + 1e-3));
        sum += w * texelFetch(uOcclusion, q, 0).r;
        weights += w;
    }
    open = sum / weights;
}
)";

#undef HG_VIEW_POSITION_GLSL

// Fixed directions in the hemisphere (z up) with lengths in [0.5, 1] (the
// shader scales them by the sample's place in the count): the same picture
// on every run and every machine (no std:: distributions).
std::vector<glm::vec3> hemisphereKernel() {
    std::vector<glm::vec3> k;
    std::uint32_t state = 0x9e3779b9u;
    auto next = [&state] {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return static_cast<float>(state & 0xffffffu) / static_cast<float>(0x1000000);
    };
    while (static_cast<int>(k.size()) < kMaxSamples) {
        glm::vec3 v(next() * 2.0f - 1.0f, next() * 2.0f - 1.0f, next());
        const float len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        // Inside the unit hemisphere, away from the tangent plane (with
        // normals rebuilt from depth, grazing samples would hit the surface).
        if (len > 1.0f || len < 1e-3f || v.z / len < 0.15f) continue;
        k.push_back(v / len * (0.5f + 0.5f * len));
    }
    return k;
}

}  // namespace

OcclusionPass::OcclusionPass()
    : occlusion_("ambient occlusion", shaders::kFullscreenVertex, kOcclusionFragment),
      blur_("occlusion blur", shaders::kFullscreenVertex, kBlurFragment),
      empty_(gl::VertexArray::create()) {
    const ShaderProgram& o = occlusion_;
    o_ = {o.uniform("uInverseProjection"), o.uniform("uProjection"), o.uniform("uFullSize"),
          o.uniform("uScale"), o.uniform("uSamples"), o.uniform("uRadius")};
    o.use();
    glUniform1i(o.uniform("uDepth"), 0);
    const std::vector<glm::vec3> kernel = hemisphereKernel();
    glUniform3fv(o.uniform("uKernel"), kMaxSamples, glm::value_ptr(kernel[0]));
    const ShaderProgram& b = blur_;
    b_ = {b.uniform("uInverseProjection"), b.uniform("uFullSize"), b.uniform("uScale"), b.uniform("uDirection")};
    b.use();
    glUniform1i(b.uniform("uDepth"), 0);
    glUniform1i(b.uniform("uOcclusion"), 1);
}

GLuint OcclusionPass::render(const SceneTargets& scene, const glm::mat4& projection, const RenderQuality& quality) {
    const int scale = quality.aoHalfResolution ? 2 : 1;
    const glm::ivec2 full = scene.size();
    const glm::ivec2 size = glm::max((full + scale - 1) / scale, glm::ivec2(1));
    raw_.ensure(size);
    blurred_.ensure(size);
    const glm::mat4 inverse = glm::inverse(projection);

    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glViewport(0, 0, size.x, size.y);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, scene.depthTexture());
    glBindVertexArray(empty_.get());

    glBindFramebuffer(GL_FRAMEBUFFER, raw_.fbo.get());
    occlusion_.use();
    glUniformMatrix4fv(o_.inverseProjection, 1, GL_FALSE, glm::value_ptr(inverse));
    glUniformMatrix4fv(o_.projection, 1, GL_FALSE, glm::value_ptr(projection));
    glUniform2i(o_.fullSize, full.x, full.y);
    glUniform1i(o_.scale, scale);
    glUniform1i(o_.samples, std::clamp(quality.aoSamples, 1, kMaxSamples));
    glUniform1f(o_.radius, std::max(quality.aoRadius, 1e-3f));
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Horizontal into `blurred_`, vertical back into `raw_`.
    blur_.use();
    glUniformMatrix4fv(b_.inverseProjection, 1, GL_FALSE, glm::value_ptr(inverse));
    glUniform2i(b_.fullSize, full.x, full.y);
    glUniform1i(b_.scale, scale);
    glActiveTexture(GL_TEXTURE1);
    glBindFramebuffer(GL_FRAMEBUFFER, blurred_.fbo.get());
    glBindTexture(GL_TEXTURE_2D, raw_.texture.get());
    glUniform2i(b_.direction, 1, 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, raw_.fbo.get());
    glBindTexture(GL_TEXTURE_2D, blurred_.texture.get());
    glUniform2i(b_.direction, 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);

    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    return raw_.texture.get();
}

}  // namespace hg::garden
