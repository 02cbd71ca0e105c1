// Drawing into textures someone else owns: a headset's swapchain images
// (xr/xr_garden.cpp draws each eye through one). A frame buffer that takes
// the image's colour texture, and its depth texture where the runtime gives
// one, else a depth buffer of its own (kept while the image size is the
// same). The picture can then be shown in the window, scaled (the
// headset's mirror).
#pragma once

#include <glm/vec2.hpp>

#include "garden/render/gl_objects.h"

namespace hg::garden {

class ImageTarget {
public:
    ImageTarget();
    // Binds the frame buffer with these images attached (depth 0: our own
    // depth buffer); throws GlError when it cannot be drawn into.
    void bind(GLuint color, GLuint depth, glm::ivec2 size);
    // The last bound image's picture into `framebuffer`'s `offset`..
    // `offset + extent` rectangle (pixels from its bottom left), scaled
    // linearly, the rest of it black; kWindowFramebuffer is the window.
    void showIn(GLuint framebuffer, glm::ivec2 offset, glm::ivec2 extent) const;

private:
    gl::Framebuffer fbo_;
    gl::Renderbuffer depth_;
    glm::ivec2 depthSize_{0}, imageSize_{0};
};

// The window's own frame buffer (OffscreenTarget::unbind binds it again).
constexpr GLuint kWindowFramebuffer = 0;

}  // namespace hg::garden
