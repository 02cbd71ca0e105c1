// The G-buffer of sculptures shaded once a pixel (docs/rendering.md,
// "Shaded once a pixel"): what the surface pass leaves at each pixel for
// the screen pass that lights it. Two RGBA32F images (the model-space
// position, and the draw's record and surface kind; the shading normal,
// its length the cavity factor, and the pattern's change across a pixel)
// beside the scene targets' depth, which the pass shares. Full floats, so
// the screen pass lights the very values the mesh program would have.
//
// And which kinds each tile of kTilePixels holds: a software rasterizer
// runs a fragment shader over every block its triangles cover, whatever a
// discard or a depth test says, so a kind's light is drawn as the tiles
// that hold it, not as one triangle over the view.
#pragma once

#include <glm/vec2.hpp>

#include <string>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class SceneTargets;

class SurfaceBuffer {
public:
    static constexpr int kTilePixels = 8;
    // "#define HG_TILE_PIXELS ...": for the programs that read or draw the tiles.
    static std::string tileDefines();

    SurfaceBuffer();  // throws GlError naming a shader that fails
    // Made or remade for `scene`'s size and its depth texture; `scene`
    // must have one sample a pixel. Throws GlError when incomplete.
    void ensure(const SceneTargets& scene);
    // Draws into the two images, depth-tested against the scene's depth.
    GLuint framebuffer() const { return fbo_.get(); }
    GLuint modelTexture() const { return model_.get(); }    // GL_TEXTURE_2D_MULTISAMPLE, one sample
    GLuint normalTexture() const { return normal_.get(); }  // GL_TEXTURE_2D_MULTISAMPLE, one sample
    // After the surfaces are drawn: each tile's kinds into tileKindsTexture
    // (R8UI, a bit a SurfaceKind). Leaves the tiles' framebuffer bound.
    void classifyTiles();
    GLuint tileKindsTexture() const { return tileKinds_.get(); }
    // Two triangles a tile, with the program in use (kSurfaceTileVertex).
    void drawTiles();

private:
    ShaderProgram classify_;
    gl::VertexArray empty_;
    gl::Framebuffer fbo_, tileFbo_;
    gl::Texture model_, normal_, tileKinds_;
    glm::ivec2 tiles_{0};
    unsigned sceneGeneration_ = 0;  // SceneTargets::generation of the depth attached
};

}  // namespace hg::garden
