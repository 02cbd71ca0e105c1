#include "garden/render/image_target.h"

#include "garden/render/gl_context.h"

namespace hg::garden {

ImageTarget::ImageTarget() : fbo_(gl::Framebuffer::create()) {}

void ImageTarget::bind(GLuint color, GLuint depth, glm::ivec2 size) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    if (depth != 0) {
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    } else {
        if (!depth_ || depthSize_ != size) {
            depth_ = gl::Renderbuffer::create();
            glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
            glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size.x, size.y);
            depthSize_ = size;
        }
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    }
    imageSize_ = size;
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the swapchain image cannot be drawn into (incomplete framebuffer)");
}

void ImageTarget::showIn(GLuint framebuffer, glm::ivec2 offset, glm::ivec2 extent) const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glBlitFramebuffer(0, 0, imageSize_.x, imageSize_.y, offset.x, offset.y, offset.x + extent.x, offset.y + extent.y,
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

}  // namespace hg::garden
