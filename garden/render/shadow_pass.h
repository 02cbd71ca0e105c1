// The sun's shadow map: one orthographic depth map fitted each view to the
// bounds of the sculptures in view (snapped to whole texels so it does not
// shimmer as the camera moves), sampled by the lit programs with 3 x 3 PCF
// and a normal offset (docs/rendering.md).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "garden/render/chunk_batch.h"
#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class ShadowPass {
public:
    ShadowPass();  // throws GlError naming a shader that fails

    // Renders the depth of the casters' chunks (those of the view's chunks
    // within the shadow distance) as seen from `toLight` (towards the sun)
    // over the world box [lo, hi], into a map of `size` texels a side.
    // Leaves its framebuffer bound; returns the draw calls made.
    std::size_t render(ChunkBatch& casters, ChunkArena& arena, bool multiDraw, const glm::vec3& lo,
                       const glm::vec3& hi, const glm::vec3& toLight, int size);

    // World point to shadow-map texture coordinates and depth, all in [0, 1].
    const glm::mat4& worldToTexture() const { return worldToTexture_; }
    // World point to the map's clip space (what render drew with).
    const glm::mat4& lightViewProjection() const { return lightMatrix_; }
    // Metres one texel spans: how far the lit programs offset along the normal.
    float texelWorld() const { return texelWorld_; }
    int size() const { return size_; }
    GLuint texture() const { return depth_.get(); }

private:
    void ensure(int size);

    ShaderProgram program_;
    GLint lightViewProjection_ = -1;
    gl::Framebuffer fbo_;
    gl::Texture depth_;
    int size_ = 0;
    glm::mat4 worldToTexture_{1.0f};
    glm::mat4 lightMatrix_{1.0f};
    float texelWorld_ = 0.0f;
};

}  // namespace hg::garden
