// The sky behind the garden: a gradient from the view's clear colour at the
// horizon to a deeper blue overhead, and the sun (the first directional
// light) as a disc with a glow, in linear HDR so the tone mapper rolls it to
// white; fair-weather clouds where View::clouds asks for them
// (docs/rendering.md, "Sky and ground"). Drawn after the opaque scene at
// the far plane, so only uncovered pixels are shaded.
#pragma once

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

struct View;

class SkyPass {
public:
    SkyPass();  // throws GlError naming a shader that fails
    // Into the bound scene target, where depth is still cleared.
    void draw(const View& view);

private:
    ShaderProgram program_;
    gl::VertexArray empty_;
    GLint inverseViewProjection_ = -1, horizon_ = -1, sun_ = -1, sunDirection_ = -1, sunColor_ = -1, clouds_ = -1;
};

}  // namespace hg::garden
