#include "garden/render/post_process.h"

#include <algorithm>
#include <string>
#include <utility>

#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

// Units no other pass of the renderer binds (chunk_batch.h, impostor_atlas.h,
// sky_pass.cpp).
constexpr GLint kViewZUnit = 7;
constexpr GLint kResolvedUnit = 9;

// Compiled per configuration (PostProcess::variant): HG_SAMPLES, the scene's
// samples a pixel (and HG_SCENE_SAMPLER, the sampler type its targets take:
// render_targets.h); HG_OCCLUSION, 0 none, 1 at the scene's size, 2 coarser;
// HG_RESOLVE, 1 for the first of two passes where the scene is stretched
// over the output: each scene pixel resolved and sRGB-encoded once, at the
// scene's size, into an 8-bit texture that kStretchFragment then samples
// bilinearly (docs/rendering.md, "Quality": why the stretch is in display
// space).
const char* const kCompositeFragment = "#version 330 core\n" HG_SRGB_GLSL R"(
uniform HG_SCENE_SAMPLER uColor;
uniform HG_SCENE_SAMPLER uDepth;
uniform sampler2D uOcclusion;
uniform sampler2D uViewZ;       // the scene's view z at full size (the occlusion's pyramid, level 0)
uniform int uOcclusionScale;    // scene pixels per occlusion texel (2 or more)
uniform float uExposure;
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
    for (int i = 0; i < HG_SAMPLES; ++i) {
        vec4 c = texelFetch(uColor, p, i);
        // alpha: the share of this sample's light that occlusion dims.
        sum += toneMap(max(c.rgb, vec3(0.0)) * mix(1.0, open, c.a) * uExposure);
    }
    return sum / float(HG_SAMPLES);
}
// The occlusion at scene pixel p. At half resolution: the four texels
// around, each weighted bilinearly and by how near the depth it was
// computed at (level 0 at its own scene pixel) is to p's, with the blur's
// depth falloff; where none is near (a sliver thinner than a texel), the
// one nearest in depth.
float openAt(ivec2 p) {
#if HG_OCCLUSION == 0
    return 1.0;
#elif HG_OCCLUSION == 1
    return texelFetch(uOcclusion, p, 0).r;
#else
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
#endif
}
vec3 resolvedAt(ivec2 p) {
    return resolved(p, openAt(p));
}
void main() {
#if HG_RESOLVE
    fragColor = vec4(toSrgb(resolvedAt(ivec2(gl_FragCoord.xy))), 1.0);  // tone mapped, encoded
#else
    ivec2 p = ivec2(gl_FragCoord.xy * uToScene);
    fragColor = vec4(toSrgb(resolvedAt(p)), 1.0);
    gl_FragDepth = texelFetch(uDepth, p, 0).r;
#endif
}
)";

// The second pass of a stretch (render scale below 1): bilinear between
// the four resolved scene pixels around (the texture's own filtering), so a
// hard edge of the scene becomes a ramp instead of a staircase of doubled
// pixels. Resolving first costs a quarter of the output's pixels at half
// scale, where resolving the four neighbours of every output pixel cost a
// software renderer about as much as the rest of the composite. The pixels
// are already encoded, in 8 bits: llvmpipe filters those with integer
// arithmetic, and encodes a quarter of the pixels (docs/benchmarks.md,
// "The stretch in display space").
const char* const kStretchFragment = "#version 330 core\n" R"(
uniform sampler2D uResolved;
uniform HG_SCENE_SAMPLER uDepth;
uniform vec2 uSize;     // the scene's pixels
uniform vec2 uToScene;  // output pixel to scene pixel (the render scale)
out vec4 fragColor;
void main() {
    vec2 s = gl_FragCoord.xy * uToScene;
    fragColor = vec4(texture(uResolved, s / uSize).rgb, 1.0);
    gl_FragDepth = texelFetch(uDepth, ivec2(s), 0).r;
}
)";

}  // namespace

PostProcess::PostProcess()
    : resolved_(gl::Texture::create()), resolvedTarget_(gl::Framebuffer::create()), empty_(gl::VertexArray::create()) {
    variant(Configuration{});  // the common one now, and a broken shader fails here
    stretch(1);
}

const PostProcess::Stretch& PostProcess::stretch(int samples) {
    std::optional<Stretch>& s = stretches_[samples > 1 ? 1 : 0];
    if (s) return *s;
    s.emplace();
    s->program = ShaderProgram("composite (stretch)", shaders::kFullscreenVertex,
                               withDefines(kStretchFragment, SceneTargets::sceneSamplerDefine(samples)).c_str());
    s->program.use();
    glUniform1i(s->program.uniform("uResolved"), kResolvedUnit);
    glUniform1i(s->program.uniform("uDepth"), 1);
    s->size = s->program.uniform("uSize");
    s->toScene = s->program.uniform("uToScene");
    return *s;
}

PostProcess::~PostProcess() = default;

const PostProcess::Variant& PostProcess::variant(const Configuration& c) {
    auto found = variants_.find(c);
    if (found != variants_.end()) return found->second;
    const std::string defines = "#define HG_SAMPLES " + std::to_string(c.samples) + "\n#define HG_OCCLUSION " +
                                std::to_string(c.occlusion) + "\n#define HG_RESOLVE " + (c.resolve ? "1" : "0") +
                                "\n" + SceneTargets::sceneSamplerDefine(c.samples);
    Variant v;
    v.program = ShaderProgram("composite", shaders::kFullscreenVertex, withDefines(kCompositeFragment, defines).c_str());
    const ShaderProgram& p = v.program;
    p.use();
    glUniform1i(p.uniform("uColor"), 0);
    glUniform1i(p.uniform("uDepth"), 1);
    glUniform1i(p.uniform("uOcclusion"), 2);
    glUniform1i(p.uniform("uViewZ"), kViewZUnit);
    v.exposure = p.uniform("uExposure");
    v.toScene = p.uniform("uToScene");
    v.occlusionScale = p.uniform("uOcclusionScale");
    return variants_.emplace(c, std::move(v)).first->second;
}

void PostProcess::ensureResolved(glm::ivec2 size) {
    if (size == resolvedSize_) return;
    glActiveTexture(GL_TEXTURE0 + kResolvedUnit);
    glBindTexture(GL_TEXTURE_2D, resolved_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl::sampleLinearClamped(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    const gl::TargetKept kept;
    glBindFramebuffer(GL_FRAMEBUFFER, resolvedTarget_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolved_.get(), 0);
    resolvedSize_ = size;
}

void PostProcess::composite(const SceneTargets& scene, const OcclusionImage& occlusion, float exposure,
                            glm::ivec2 output, bool smooth) {
    Configuration c;
    c.samples = std::max(scene.samples(), 1);
    c.occlusion = occlusion.texture == 0 ? 0 : occlusion.viewZ != 0 && occlusion.scale > 1 ? 2 : 1;
    c.resolve = smooth && scene.size() != output;
    const glm::vec2 toScene(static_cast<float>(scene.size().x) / static_cast<float>(std::max(output.x, 1)),
                            static_cast<float>(scene.size().y) / static_cast<float>(std::max(output.y, 1)));
    const Variant& v = variant(c);
    v.program.use();
    glUniform1f(v.exposure, exposure);
    glUniform1i(v.occlusionScale, std::max(occlusion.scale, 1));
    glUniform2f(v.toScene, toScene.x, toScene.y);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(scene.textureTarget(), scene.colorTexture());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(scene.textureTarget(), scene.depthTexture());
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, occlusion.texture);
    glActiveTexture(GL_TEXTURE0 + kViewZUnit);
    glBindTexture(GL_TEXTURE_2D, occlusion.viewZ);
    glActiveTexture(GL_TEXTURE0);

    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(empty_.get());
    if (c.resolve) {
        // First each scene pixel once, into the resolved texture.
        ensureResolved(scene.size());
        {
            const gl::TargetKept kept;
            glBindFramebuffer(GL_FRAMEBUFFER, resolvedTarget_.get());
            glViewport(0, 0, scene.size().x, scene.size().y);
            glDisable(GL_DEPTH_TEST);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        const Stretch& s = stretch(c.samples);
        s.program.use();
        glUniform2f(s.size, static_cast<float>(scene.size().x), static_cast<float>(scene.size().y));
        glUniform2f(s.toScene, toScene.x, toScene.y);
        glActiveTexture(GL_TEXTURE0 + kResolvedUnit);
        glBindTexture(GL_TEXTURE_2D, resolved_.get());
        glActiveTexture(GL_TEXTURE0);
    }
    // Every output pixel is written, colour and depth, whatever was there.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glActiveTexture(GL_TEXTURE0 + kResolvedUnit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0 + kViewZUnit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace hg::garden
