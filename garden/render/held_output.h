// A still view's output as the composite wrote it: the encoded colour and
// the depth (docs/rendering.md, "A still view"). Put back into the output
// framebuffer by one copy pass, it costs a held view two texel reads a
// pixel instead of the composite again (at 4x multisampling with
// occlusion brought up by depth, tone mapping four samples and reading
// twelve texels a pixel).
#pragma once

#include <glm/vec2.hpp>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class HeldOutput {
public:
    HeldOutput();  // throws GlError naming a shader that fails

    // Binds its framebuffer, made or resized to `size`, with that viewport,
    // for the composite to write into; what it held is gone.
    void bindForWriting(glm::ivec2 size);
    // Whether it holds a picture of `size`.
    bool holds(glm::ivec2 size) const { return held_ && size == size_; }
    void forget() { held_ = false; }
    // Writes the held colour and depth into the bound framebuffer (over its
    // viewport, of the held size), whatever was there.
    void copyOut() const;

private:
    ShaderProgram copy_;
    gl::VertexArray empty_;
    gl::Framebuffer fbo_;
    gl::Texture color_, depth_;
    glm::ivec2 size_{0};
    bool held_ = false;
};

}  // namespace hg::garden
