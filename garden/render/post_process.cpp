#include "garden/render/post_process.h"

#include <algorithm>

#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

// A unit no other pass of the renderer binds (chunk_batch.h, impostor_atlas.h).
constexpr GLint kViewZUnit = 7;

const char* const kCompositeFragment = "#version 330 core\n" HG_SRGB_GLSL R"(
uniform sampler2DMS uColor;
uniform sampler2DMS uDepth;
uniform sampler2D uOcclusion;
uniform sampler2D uViewZ;       // the scene's view z at full size (the occlusion's pyramid, level 0)
uniform int uOcclusionScale;    // scene pixels per occlusion texel (1 or 2)
uniform int uSamples;
uniform float uExposure;
uniform bool uUseOcclusion;
uniform bool uSmooth;   // the scene is stretched over more pixels than it has
uniform vec2 uSize;     // the scene's pixels
uniform vec2 uToScene;  // output pixel to scene pixel (the render scale)
out vec4 fragColor;
// Khronos PBR Neutral's highlight roll-off without its toe: colours below
// 0.76 pass unchanged (the garden file's colours stay what they say),
// brighter ones roll off towards white keeping their hue.
vec3 toneMap(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}
// One scene pixel resolved: each sample exposed, dimmed by the occlusion
// where it is ambient light, tone mapped, then averaged.
vec3 resolved(ivec2 p, float open) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < uSamples; ++i) {
        vec4 c = texelFetch(uColor, p, i);
        // alpha: the share of this sample's light that occlusion dims.
        sum += toneMap(max(c.rgb, vec3(0.0)) * mix(1.0, open, c.a) * uExposure);
    }
    return sum / float(uSamples);
}
// The occlusion at scene pixel p. At half resolution: the four texels
// around, each weighted bilinearly and by how near the depth it was
// computed at (level 0 at its own scene pixel) is to p's, with the blur's
// depth falloff; where none is near (a sliver thinner than a texel), the
// one nearest in depth.
float openAt(ivec2 p) {
    if (!uUseOcclusion) return 1.0;
    if (uOcclusionScale == 1) return texelFetch(uOcclusion, p, 0).r;
    float z = texelFetch(uViewZ, p, 0).r;
    vec2 t = (vec2(p) + 0.5) / float(uOcclusionScale) - 0.5;
    ivec2 lo = ivec2(floor(t)), last = textureSize(uOcclusion, 0) - 1;
    vec2 f = t - vec2(lo);
    float sum = 0.0, weights = 0.0, nearest = 1e30, nearestOpen = 1.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        ivec2 q = clamp(lo + o, ivec2(0), last);
        float dz = abs(texelFetch(uViewZ, q * uOcclusionScale, 0).r - z);
        float open = texelFetch(uOcclusion, q, 0).r;
        vec2 b = mix(1.0 - f, f, vec2(o));
        float w = b.x * b.y * exp(-dz / (0.02 * abs(z) + 1e-3));
        sum += w * open;
        weights += w;
        if (dz < nearest) {
            nearest = dz;
            nearestOpen = open;
        }
    }
    return weights > 1e-4 ? sum / weights : nearestOpen;
}
vec3 resolvedAt(ivec2 p) {
    return resolved(p, openAt(p));
}
void main() {
    vec2 s = gl_FragCoord.xy * uToScene;
    ivec2 p = ivec2(s);
    vec3 color;
    if (uSmooth) {
        // Stretched (render scale below 1): bilinear between the four scene
        // pixels around, each resolved first, so a hard edge of the scene
        // becomes a ramp instead of a staircase of doubled pixels.
        vec2 t = s - 0.5;
        ivec2 lo = ivec2(floor(t)), last = ivec2(uSize) - 1;
        vec2 f = t - vec2(lo);
        ivec2 a = clamp(lo, ivec2(0), last), b = clamp(lo + 1, ivec2(0), last);
        color = mix(mix(resolvedAt(a), resolvedAt(ivec2(b.x, a.y)), f.x),
                    mix(resolvedAt(ivec2(a.x, b.y)), resolvedAt(b), f.x), f.y);
    } else {
        color = resolvedAt(p);
    }
    fragColor = vec4(toSrgb(color), 1.0);
    gl_FragDepth = texelFetch(uDepth, p, 0).r;
}
)";

}  // namespace

PostProcess::PostProcess()
    : program_("composite", shaders::kFullscreenVertex, kCompositeFragment), empty_(gl::VertexArray::create()) {
    program_.use();
    glUniform1i(program_.uniform("uColor"), 0);
    glUniform1i(program_.uniform("uDepth"), 1);
    glUniform1i(program_.uniform("uOcclusion"), 2);
    glUniform1i(program_.uniform("uViewZ"), kViewZUnit);
    samples_ = program_.uniform("uSamples");
    exposure_ = program_.uniform("uExposure");
    useOcclusion_ = program_.uniform("uUseOcclusion");
    size_ = program_.uniform("uSize");
    toScene_ = program_.uniform("uToScene");
    smooth_ = program_.uniform("uSmooth");
    occlusionScale_ = program_.uniform("uOcclusionScale");
}

void PostProcess::composite(const SceneTargets& scene, const OcclusionImage& occlusion, float exposure,
                            glm::ivec2 output, bool smooth) {
    program_.use();
    glUniform1i(samples_, scene.samples());
    glUniform1f(exposure_, exposure);
    glUniform1i(useOcclusion_, occlusion.texture != 0 ? 1 : 0);
    glUniform1i(occlusionScale_, occlusion.viewZ != 0 ? std::max(occlusion.scale, 1) : 1);
    glUniform2f(size_, static_cast<float>(scene.size().x), static_cast<float>(scene.size().y));
    glUniform1i(smooth_, smooth && scene.size() != output ? 1 : 0);
    glUniform2f(toScene_, static_cast<float>(scene.size().x) / static_cast<float>(std::max(output.x, 1)),
                static_cast<float>(scene.size().y) / static_cast<float>(std::max(output.y, 1)));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, scene.colorTexture());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, scene.depthTexture());
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, occlusion.texture);
    glActiveTexture(GL_TEXTURE0 + kViewZUnit);
    glBindTexture(GL_TEXTURE_2D, occlusion.viewZ);
    glActiveTexture(GL_TEXTURE0);

    // Every pixel is written, colour and depth, whatever was there.
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glActiveTexture(GL_TEXTURE0 + kViewZUnit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace hg::garden
