// A framebuffer object of W x H with an RGBA8 colour texture and a 24-bit
// depth buffer: what replay renders screenshots into and what the tests read
// back. Needs a current GL context for its whole life.
#pragma once

#include <cstdint>
#include <vector>

#include "garden/render/gl_objects.h"

namespace hg::garden {

class OffscreenTarget {
public:
    // Throws GlError when the framebuffer is incomplete.
    OffscreenTarget(int width, int height);

    // Draw into this target (and set the viewport to it); unbind() returns
    // to the window's default framebuffer.
    void bind() const;
    static void unbind();
    // Waits until the GPU has done everything asked of it (glFinish): a
    // frame's cost measured to its end.
    static void finish();

    int width() const { return width_; }
    int height() const { return height_; }
    GLuint colorTexture() const { return color_.get(); }

    // Rows top-down (row 0 is the top of the image), 4 bytes per pixel.
    std::vector<std::uint8_t> readColor() const;
    // Window-space depth in [0, 1] (1 = far plane or cleared), rows top-down.
    std::vector<float> readDepth() const;

private:
    int width_;
    int height_;
    gl::Framebuffer fbo_;
    gl::Texture color_;
    gl::Renderbuffer depth_;
};

// Reads the bound read framebuffer (a target, or the window's back buffer
// before swapBuffers for an F12 screenshot): RGBA8 rows, top-down.
std::vector<std::uint8_t> readColorRows(int width, int height);
std::vector<float> readDepthRows(int width, int height);

}  // namespace hg::garden
