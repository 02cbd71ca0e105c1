// The scene's depth as view-space z (metres, negative in front of the eye)
// in one R32F texture with a few mip levels, made once per view for the
// ambient occlusion (docs/rendering.md, "Ambient occlusion").
//
// Why: the occlusion's samples used to read the multisampled depth texture
// and undo the projection with a 4x4 inverse each; a plain float texture
// read with a few multiplies is cheaper, and far samples read a coarser
// level, so the reads of one pixel's samples stay near each other in
// memory (McGuire et al., "Scalable Ambient Obscurance", 2012). Each level
// keeps one real depth of each 2 x 2 (on a rotated grid, not a mean: a mean
// across a silhouette is a depth where nothing is).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class SceneTargets;

class ViewDepthPyramid {
public:
    static constexpr int kLevels = 6;  // 0 (full size) .. 5 (1/32)

    ViewDepthPyramid();  // throws GlError naming a shader that fails

    // Fills every level from sample 0 of `scene`'s depth as seen through
    // `projection` (any perspective or orthographic projection: headset
    // eyes are asymmetric). Changes the framebuffer binding, the viewport,
    // the program, the vertex array and texture unit 0's 2D bindings.
    void build(const SceneTargets& scene, const glm::mat4& projection);

    GLuint texture() const { return texture_.get(); }  // GL_TEXTURE_2D, R32F, levels 0..kLevels-1
    glm::ivec2 size() const { return size_; }

private:
    void ensure(glm::ivec2 size);

    struct Linearize {
        explicit Linearize(int samples);
        ShaderProgram program;
        GLint depthToZ = -1;
    };
    Linearize linearize_[2];  // for a scene of one sample, of several
    ShaderProgram reduce_;
    gl::VertexArray empty_;
    gl::Texture texture_;
    gl::Framebuffer levels_[kLevels];
    glm::ivec2 size_{0};
    GLint reduceLevel_ = -1;
};

// The GLSL that reads the pyramid back as view-space positions, for the
// passes that use it: zAt(pixel, level), viewAt(pixel, z), viewAt(pixel),
// with pixels counted at full size.
extern const char* const kViewPositionGlsl;

// kViewPositionGlsl's uniforms in one program.
class ViewPositionUniforms {
public:
    ViewPositionUniforms() = default;
    // Finds them in `program` and points its pyramid sampler at `unit`.
    ViewPositionUniforms(const ShaderProgram& program, int unit);
    // For `projection` and a full-size frame of `fullSize`; the program in use.
    void set(const glm::mat4& projection, glm::ivec2 fullSize) const;

private:
    GLint fullSize_ = -1, unproject_ = -1, unprojectW_ = -1;
};

}  // namespace hg::garden
