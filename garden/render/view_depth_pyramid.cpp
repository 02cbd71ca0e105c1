#include "garden/render/view_depth_pyramid.h"

#include <glm/common.hpp>

#include <algorithm>

#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"

namespace hg::garden {

// A projection P (column-major, P[col][row]) takes view (x, y, z) to clip
// x' = P00 x + P20 z + P30, y' = P11 y + P21 z + P31, w' = P23 z + P33 for
// every perspective and orthographic projection the garden makes (no skew),
// so x = (ndc.x w' - P20 z - P30) / P00 and likewise y.
const char* const kViewPositionGlsl = R"(
uniform sampler2D uViewZ;
uniform ivec2 uFullSize;
uniform vec4 uUnproject;   // P00, P11, P20, P21
uniform vec4 uUnprojectW;  // P30, P31, P23, P33
float zAt(ivec2 p, int level) {
    ivec2 size = textureSize(uViewZ, level);
    return texelFetch(uViewZ, clamp(p >> level, ivec2(0), size - 1), level).r;
}
vec3 viewAt(ivec2 p, float z) {
    vec2 ndc = (vec2(p) + 0.5) / vec2(uFullSize) * 2.0 - 1.0;
    float w = uUnprojectW.z * z + uUnprojectW.w;
    return vec3((ndc * w - uUnproject.zw * z - uUnprojectW.xy) / uUnproject.xy, z);
}
vec3 viewAt(ivec2 p) { return viewAt(p, zAt(p, 0)); }
)";

namespace {

// Depth d in [0, 1] to view z: ndc n = 2d - 1 = (P22 z + P32) / (P23 z + P33).
const char* const kLinearizeFragment = R"(#version 330 core
uniform HG_SCENE_SAMPLER uDepth;  // render_targets.h
uniform vec4 uDepthToZ;  // P22, P32, P23, P33
out float z;
void main() {
    float n = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r * 2.0 - 1.0;
    z = (uDepthToZ.y - n * uDepthToZ.w) / (n * uDepthToZ.z - uDepthToZ.x);
}
)";

// One of each 2 x 2 of the level below (the texture's base level while
// this level is drawn), on a rotated grid so no column or row is skipped.
const char* const kReduceFragment = R"(#version 330 core
uniform sampler2D uViewZ;
out float z;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 q = p * 2 + ivec2((p.y & 1) ^ 1, (p.x & 1) ^ 1);
    z = texelFetch(uViewZ, min(q, textureSize(uViewZ, 0) - 1), 0).r;
}
)";

glm::ivec2 levelSize(glm::ivec2 size, int level) { return glm::max(size >> level, glm::ivec2(1)); }

}  // namespace

ViewPositionUniforms::ViewPositionUniforms(const ShaderProgram& program, int unit)
    : fullSize_(program.uniform("uFullSize")),
      unproject_(program.uniform("uUnproject")),
      unprojectW_(program.uniform("uUnprojectW")) {
    program.use();
    glUniform1i(program.uniform("uViewZ"), unit);
}

void ViewPositionUniforms::set(const glm::mat4& p, glm::ivec2 fullSize) const {
    glUniform2i(fullSize_, fullSize.x, fullSize.y);
    glUniform4f(unproject_, p[0][0], p[1][1], p[2][0], p[2][1]);
    glUniform4f(unprojectW_, p[3][0], p[3][1], p[2][3], p[3][3]);
}

ViewDepthPyramid::ViewDepthPyramid()
    : linearize_{Linearize(1), Linearize(2)},
      reduce_("view depth levels", shaders::kFullscreenVertex, kReduceFragment),
      empty_(gl::VertexArray::create()) {
    reduce_.use();
    glUniform1i(reduce_.uniform("uViewZ"), 0);
}

void ViewDepthPyramid::ensure(glm::ivec2 size) {
    size = glm::max(size, glm::ivec2(1));
    if (texture_ && size == size_) return;
    texture_ = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    for (int level = 0; level < kLevels; ++level) {
        const glm::ivec2 s = levelSize(size, level);
        glTexImage2D(GL_TEXTURE_2D, level, GL_R32F, s.x, s.y, 0, GL_RED, GL_FLOAT, nullptr);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, kLevels - 1);
    for (int level = 0; level < kLevels; ++level) {
        levels_[level] = gl::Framebuffer::create();
        glBindFramebuffer(GL_FRAMEBUFFER, levels_[level].get());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.get(), level);
        checkFramebuffer("view depth");
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    size_ = size;
}

// A scene of `samples` (its depth's sampler type: render_targets.h).
ViewDepthPyramid::Linearize::Linearize(int samples)
    : program("view depth", shaders::kFullscreenVertex,
              withDefines(kLinearizeFragment, SceneTargets::sceneSamplerDefine(samples)).c_str()),
      depthToZ(program.uniform("uDepthToZ")) {
    program.use();
    glUniform1i(program.uniform("uDepth"), 0);
}

void ViewDepthPyramid::build(const SceneTargets& scene, const glm::mat4& p) {
    ensure(scene.size());
    glBindVertexArray(empty_.get());
    glActiveTexture(GL_TEXTURE0);

    glBindFramebuffer(GL_FRAMEBUFFER, levels_[0].get());
    glViewport(0, 0, size_.x, size_.y);
    const Linearize& linearize = linearize_[scene.samples() > 1 ? 1 : 0];
    linearize.program.use();
    glUniform4f(linearize.depthToZ, p[2][2], p[3][2], p[2][3], p[3][3]);
    glBindTexture(scene.textureTarget(), scene.depthTexture());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(scene.textureTarget(), 0);

    // Each level reads only the one below: the texture's levels are narrowed
    // to it while the next is drawn, so nothing reads what it writes.
    reduce_.use();
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    for (int level = 1; level < kLevels; ++level) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, level - 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, level - 1);
        const glm::ivec2 s = levelSize(size_, level);
        glBindFramebuffer(GL_FRAMEBUFFER, levels_[level].get());
        glViewport(0, 0, s.x, s.y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, kLevels - 1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindVertexArray(0);
}

}  // namespace hg::garden
