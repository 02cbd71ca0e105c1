#include "garden/render/offscreen_target.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "garden/render/gl_context.h"
#include "garden/render/render_targets.h"

namespace hg::garden {
namespace {

// glReadPixels returns rows bottom-up; images (PNG, tests) are top-down.
template <typename T>
void flipRows(std::vector<T>& data, std::size_t rowElements, int height) {
    for (int y = 0; y < height / 2; ++y) {
        T* top = data.data() + static_cast<std::size_t>(y) * rowElements;
        T* bottom = data.data() + static_cast<std::size_t>(height - 1 - y) * rowElements;
        std::swap_ranges(top, top + rowElements, bottom);
    }
}

// Runs read() with `fbo` bound for reading, then restores the binding.
template <typename Read>
auto readFrom(GLuint fbo, Read read) {
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    auto result = read();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
    return result;
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0) throw GlError("offscreen target size must be positive");
    fbo_ = gl::Framebuffer::create();
    color_ = makeTexture2D(GL_RGBA8, {width, height}, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR, GL_CLAMP_TO_EDGE);
    depth_ = gl::Renderbuffer::create();
    glBindTexture(GL_TEXTURE_2D, 0);

    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.get(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%x", status);
        throw GlError(std::string("offscreen framebuffer incomplete (status ") + hex + ")");
    }
}

void OffscreenTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glViewport(0, 0, width_, height_);
}

void OffscreenTarget::finish() { glFinish(); }

void OffscreenTarget::unbind() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

std::vector<std::uint8_t> OffscreenTarget::readColor() const {
    return readFrom(fbo_.get(), [this] { return readColorRows(width_, height_); });
}

std::vector<float> OffscreenTarget::readDepth() const {
    return readFrom(fbo_.get(), [this] { return readDepthRows(width_, height_); });
}

std::vector<std::uint8_t> readColorRows(int width, int height) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    flipRows(pixels, static_cast<std::size_t>(width) * 4, height);
    return pixels;
}

std::vector<float> readDepthRows(int width, int height) {
    std::vector<float> depth(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    flipRows(depth, static_cast<std::size_t>(width), height);
    return depth;
}

}  // namespace hg::garden
