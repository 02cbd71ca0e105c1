#include "garden/render/held_output.h"

#include <glm/common.hpp>

#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"

namespace hg::garden {

namespace {

const char* const kCopyFragment = R"(#version 330 core
uniform sampler2D uColor;
uniform sampler2D uDepth;
out vec4 fragColor;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    fragColor = texelFetch(uColor, p, 0);
    gl_FragDepth = texelFetch(uDepth, p, 0).r;
}
)";

}  // namespace

HeldOutput::HeldOutput() : copy_("held output copy", shaders::kFullscreenVertex, kCopyFragment) {
    empty_ = gl::VertexArray::create();
    copy_.use();
    glUniform1i(copy_.uniform("uColor"), 0);
    glUniform1i(copy_.uniform("uDepth"), 1);
}

void HeldOutput::bindForWriting(glm::ivec2 size) {
    size = glm::max(size, glm::ivec2(1));
    if (!fbo_ || size != size_) {
        fbo_ = gl::Framebuffer::create();
        color_ = makeTexture2D(GL_RGBA8, size, GL_RGBA, GL_UNSIGNED_BYTE, GL_NEAREST, GL_CLAMP_TO_EDGE);
        // Float, so the depth the composite wrote comes back as the same
        // float and the output rounds it as it would have (a 24-bit copy
        // between them moved some by one step).
        depth_ = makeTexture2D(GL_DEPTH_COMPONENT32F, size, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.get(), 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.get(), 0);
        checkFramebuffer("held output");
        size_ = size;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glViewport(0, 0, size_.x, size_.y);
    held_ = true;
}

void HeldOutput::copyOut() const {
    copy_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, color_.get());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, depth_.get());
    glActiveTexture(GL_TEXTURE0);
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
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace hg::garden
