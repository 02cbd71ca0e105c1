#include "garden/render/surface_buffer.h"

#include <string>

#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"

namespace hg::garden {

namespace {
// The texture unit the classification reads the surfaces from.
constexpr GLint kSurfaceUnit = 0;

gl::Texture floatImage(glm::ivec2 size) {
    gl::Texture t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.get());
    glTexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 1, GL_RGBA32F, size.x, size.y, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    return t;
}
}  // namespace

std::string SurfaceBuffer::tileDefines() { return "#define HG_TILE_PIXELS " + std::to_string(kTilePixels) + "\n"; }

SurfaceBuffer::SurfaceBuffer()
    : classify_("surface tiles", shaders::kFullscreenVertex,
                withDefines(shaders::kSurfaceTileKindsFragment, tileDefines()).c_str()),
      empty_(gl::VertexArray::create()) {
    classify_.use();
    glUniform1i(classify_.uniform("uSurfaceModel"), kSurfaceUnit);
    glUseProgram(0);
}

void SurfaceBuffer::ensure(const SceneTargets& scene) {
    if (fbo_ && sceneGeneration_ == scene.generation()) return;
    sceneGeneration_ = scene.generation();
    const glm::ivec2 size = scene.size();
    model_ = floatImage(size);
    normal_ = floatImage(size);
    fbo_ = gl::Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, model_.get(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D_MULTISAMPLE, normal_.get(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D_MULTISAMPLE, scene.depthTexture(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    checkFramebuffer("sculpture surfaces (shaded once a pixel)");

    tiles_ = (size + (kTilePixels - 1)) / kTilePixels;
    tileKinds_ = makeTexture2D(GL_R8UI, tiles_, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    tileFbo_ = gl::Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, tileFbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tileKinds_.get(), 0);
    checkFramebuffer("sculpture surface tiles");
}

void SurfaceBuffer::classifyTiles() {
    glBindFramebuffer(GL_FRAMEBUFFER, tileFbo_.get());
    glViewport(0, 0, tiles_.x, tiles_.y);
    classify_.use();
    glActiveTexture(GL_TEXTURE0 + kSurfaceUnit);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, model_.get());
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
}

void SurfaceBuffer::drawTiles() {
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 6 * tiles_.x * tiles_.y);
}

}  // namespace hg::garden
