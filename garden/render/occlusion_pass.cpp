#include "garden/render/occlusion_pass.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "garden/render/shaders.h"
#include "garden/render/view_depth_pyramid.h"

namespace hg::garden {
namespace {

constexpr int kMaxSamples = 32;
constexpr int kPyramidUnit = 0;

const char* const kOcclusionBody = R"(
uniform mat4 uProjection;
uniform int uScale;
uniform int uSamples;
uniform float uRadius;
uniform float uFarZ;  // view z at depth 1, a hair nearer
uniform vec3 uKernel[32];
out float open;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * uScale;
    float z = zAt(p, 0);
    if (z <= uFarZ) { open = 1.0; return; }
    vec3 P = viewAt(p, z);
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
        // Samples 16 or more pixels out read a coarser level (one level a
        // doubling), so one pixel's reads stay close in memory.
        int level = clamp(int(log2(max(length(vec2(q - p)), 1.0))) - 3, 0, kPyramidTop);
        float sceneZ = zAt(q, level);
        // Something in front of the sample hides it, unless that something
        // is far in front of this point (a separate object: no contact).
        float near = smoothstep(0.0, 1.0, uRadius / max(abs(P.z - sceneZ), 1e-4));
        hidden += (sceneZ >= s.z + bias ? 1.0 : 0.0) * near;
    }
    open = clamp(1.0 - 1.5 * hidden / float(uSamples), 0.0, 1.0);
}
)";

const char* const kBlurBody = R"(
uniform sampler2D uOcclusion;
uniform int uScale;
uniform ivec2 uDirection;
out float open;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uOcclusion, 0);
    float z = zAt(p * uScale, 0);
    float sum = 0.0, weights = 0.0;
    for (int i = -4; i <= 4; ++i) {
        ivec2 q = clamp(p + i * uDirection, ivec2(0), size - 1);
        float dz = abs(zAt(q * uScale, 0) - z);
        // Gaussian in pixels, and nearly nothing from across a depth step.
        float w = exp(-float(i * i) / 8.0) * exp(-dz / (0.02 * abs(z) + 1e-3));
        sum += w * texelFetch(uOcclusion, q, 0).r;
        weights += w;
    }
    open = sum / weights;
}
)";

// The pass's fragment shader: the version, the pyramid's reader, `body`.
std::string fragmentSource(const char* body) {
    return std::string("#version 330 core\nconst int kPyramidTop = ") + std::to_string(ViewDepthPyramid::kLevels - 1) +
           ";\n" + kViewPositionGlsl + body;
}

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
    : occlusion_("ambient occlusion", shaders::kFullscreenVertex, fragmentSource(kOcclusionBody).c_str()),
      blur_("occlusion blur", shaders::kFullscreenVertex, fragmentSource(kBlurBody).c_str()),
      empty_(gl::VertexArray::create()),
      occlusionView_(occlusion_, kPyramidUnit),
      blurView_(blur_, kPyramidUnit) {
    const ShaderProgram& o = occlusion_;
    o_ = {o.uniform("uProjection"), o.uniform("uScale"), o.uniform("uSamples"), o.uniform("uRadius"),
          o.uniform("uFarZ")};
    o.use();
    const std::vector<glm::vec3> kernel = hemisphereKernel();
    glUniform3fv(o.uniform("uKernel"), kMaxSamples, glm::value_ptr(kernel[0]));
    const ShaderProgram& b = blur_;
    b_ = {b.uniform("uScale"), b.uniform("uDirection")};
    b.use();
    glUniform1i(b.uniform("uOcclusion"), 1);
}

OcclusionImage OcclusionPass::render(const SceneTargets& scene, const glm::mat4& projection,
                                     const RenderQuality& quality) {
    const int scale = quality.aoHalfResolution ? 2 : 1;
    const glm::ivec2 full = scene.size();
    const glm::ivec2 size = glm::max((full + scale - 1) / scale, glm::ivec2(1));
    raw_.ensure(size);
    blurred_.ensure(size);

    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    pyramid_.build(scene, projection);
    // View z of the far plane (depth 1), a hair nearer: what lies beyond is sky.
    const glm::mat4& p = projection;
    const float farZ = (p[3][2] - p[3][3]) / (p[2][3] - p[2][2]) * (1.0f - 1e-5f);

    glViewport(0, 0, size.x, size.y);
    glActiveTexture(GL_TEXTURE0 + kPyramidUnit);
    glBindTexture(GL_TEXTURE_2D, pyramid_.texture());
    glBindVertexArray(empty_.get());

    glBindFramebuffer(GL_FRAMEBUFFER, raw_.fbo.get());
    occlusion_.use();
    occlusionView_.set(projection, full);
    glUniformMatrix4fv(o_.projection, 1, GL_FALSE, glm::value_ptr(projection));
    glUniform1i(o_.scale, scale);
    glUniform1i(o_.samples, std::clamp(quality.aoSamples, 1, kMaxSamples));
    glUniform1f(o_.radius, std::max(quality.aoRadius, 1e-3f));
    glUniform1f(o_.farZ, farZ);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // Horizontal into `blurred_`, vertical back into `raw_`.
    blur_.use();
    blurView_.set(projection, full);
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
    glActiveTexture(GL_TEXTURE0 + kPyramidUnit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);

    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    return OcclusionImage{raw_.texture.get(), scale, pyramid_.texture()};
}

}  // namespace hg::garden
