#include "garden/render/shadow_pass.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

const char* const kDepthVertex = "#version 330 core\n" HG_DRAW_RECORD_GLSL R"(
layout(location = 0) in vec3 aPosition;
layout(location = 2) in uint aDraw;
uniform mat4 uLightViewProjection;
void main() { gl_Position = uLightViewProjection * (drawModel(int(aDraw)) * vec4(aPosition, 1.0)); }
)";

const char* const kDepthFragment = R"(#version 330 core
void main() {}
)";

// Depth bias in the map itself, as slope and constant: with the lit
// programs' normal offset it keeps lit faces free of acne.
constexpr float kSlopeBias = 2.0f;
constexpr float kConstantBias = 4.0f;

}  // namespace

ShadowPass::ShadowPass() : program_("shadow depth", kDepthVertex, kDepthFragment) {
    lightViewProjection_ = program_.uniform("uLightViewProjection");
    program_.use();
    glUniform1i(program_.uniform("uDrawRecords"), kDrawRecordUnit);
}

void ShadowPass::ensure(int size) {
    if (fbo_ && size == size_) return;
    fbo_ = gl::Framebuffer::create();
    // Linear filtering of a compared texture: each tap is itself a 2 x 2
    // PCF, so 3 x 3 taps give smooth edges. Outside the fitted box nothing
    // casts: the border is the far plane.
    depth_ = makeTexture2D(GL_DEPTH_COMPONENT24, glm::ivec2(size), GL_DEPTH_COMPONENT, GL_FLOAT, GL_LINEAR,
                           GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    checkFramebuffer("shadow map");
    size_ = size;
}

std::size_t ShadowPass::render(ChunkBatch& casters, ChunkArena& arena, bool multiDraw, const glm::vec3& lo,
                               const glm::vec3& hi, const glm::vec3& toLight, int size) {
    ensure(std::clamp(size, 64, 8192));
    const glm::vec3 l = glm::normalize(toLight);
    const glm::vec3 up = std::fabs(l.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    // A rotation only, so the box below moves in whole texels as the
    // bounds change and the map does not swim.
    const glm::mat4 rotation = glm::lookAt(glm::vec3(0.0f), -l, up);
    glm::vec3 bmin(1e30f), bmax(-1e30f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        const glm::vec3 p = glm::vec3(rotation * glm::vec4(corner, 1.0f));
        bmin = glm::min(bmin, p);
        bmax = glm::max(bmax, p);
    }
    // A square window a little wider than the casters (PCF reaches a texel
    // or two beyond them), in whole texels.
    const float side = std::max(bmax.x - bmin.x, bmax.y - bmin.y) * 1.05f + 1e-3f;
    const float texel = side / static_cast<float>(size_);
    const glm::vec2 centre = 0.5f * (glm::vec2(bmin) + glm::vec2(bmax));
    const glm::vec2 origin = glm::floor((centre - 0.5f * side) / texel) * texel;
    // The view looks down -z: nearest is the largest z.
    const float depthMargin = 0.05f * (bmax.z - bmin.z) + 0.1f;
    const glm::mat4 projection = glm::ortho(origin.x, origin.x + side, origin.y, origin.y + side,
                                            -(bmax.z + depthMargin), -(bmin.z - depthMargin));
    const glm::mat4 lightViewProjection = projection * rotation;
    const glm::mat4 bias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    worldToTexture_ = bias * lightViewProjection;
    lightMatrix_ = lightViewProjection;
    texelWorld_ = texel;

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glViewport(0, 0, size_, size_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Both faces cast: chunks of a sculpture are open at their seams.
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kSlopeBias, kConstantBias);
    program_.use();
    glUniformMatrix4fv(lightViewProjection_, 1, GL_FALSE, glm::value_ptr(lightViewProjection));
    const std::size_t calls = casters.draw(arena, multiDraw);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_CULL_FACE);
    return calls;
}

}  // namespace hg::garden
