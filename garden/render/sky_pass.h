// The sky behind the garden: a gradient from the view's clear colour at the
// horizon to a deeper blue overhead, and the sun (the first directional
// light) as a disc with a glow, in linear HDR so the tone mapper rolls it to
// white; fair-weather clouds where View::clouds asks for them
// (docs/rendering.md, "Sky and ground"). Drawn after the opaque scene at
// the far plane, so only uncovered pixels are shaded.
//
// The gradient and the clouds depend on the direction alone, so they are
// baked into a cube map when the sky's look changes (the horizon, the sun,
// the clouds) and each pixel then takes one filtered lookup; only the sun's
// disc and glow, too sharp for the map, are computed per pixel. Ten octaves
// of noise a sky pixel cost a software renderer about a sixth of its frame
// (docs/benchmarks.md, "The software renderer's frame").
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

struct View;

class SkyPass {
public:
    SkyPass();  // throws GlError naming a shader that fails
    // Into the bound scene target, where depth is still cleared. Bakes the
    // cube map first, `faceSize` texels on a side of each face
    // (RenderQuality::skyMapSize), when the view's sky or the size differs
    // from the one baked (the bound framebuffer and viewport are restored).
    void draw(const View& view, int faceSize);
    // Off: every pixel evaluates the sky itself, as before the cube map
    // (the peer of tests and benches). On by default.
    void setBaked(bool on) { baked_ = on; }
    bool baked() const { return baked_; }
    // Cube maps baked so far.
    std::size_t bakes() const { return bakes_; }

private:
    struct Look {
        glm::vec3 horizon{0.0f};
        bool sun = false;
        glm::vec3 sunDirection{0.0f};
        glm::vec3 sunColor{0.0f};
        float clouds = 0.0f;
        int faceSize = 0;
        bool operator==(const Look& o) const {
            return horizon == o.horizon && sun == o.sun && sunDirection == o.sunDirection &&
                   sunColor == o.sunColor && clouds == o.clouds && faceSize == o.faceSize;
        }
    };
    struct Program {
        ShaderProgram program;
        GLint inverseViewProjection = -1, horizon = -1, sun = -1, sunDirection = -1, sunColor = -1, clouds = -1,
              face = -1;
    };
    static Program compile(const char* name, const char* vertex, const char* defines);
    static void setLook(const Program& p, const Look& look);
    void bake(const Look& look);

    Program direct_;  // the whole sky per pixel
    Program lookup_;  // the cube map, then the sun
    Program bake_;    // one cube face
    gl::VertexArray empty_;
    gl::Texture cube_;
    gl::Framebuffer bakeTarget_;
    std::optional<Look> inCube_;  // what the cube map holds
    int allocatedFaceSize_ = 0;
    bool baked_ = true;
    std::size_t bakes_ = 0;
};

}  // namespace hg::garden
