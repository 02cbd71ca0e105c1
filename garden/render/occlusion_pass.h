// Screen-space ambient occlusion from the scene's depth: a normal-oriented
// hemisphere of samples per pixel (normals rebuilt from depth), rotated per
// pixel, then a separable depth-aware (bilateral) blur that smooths the
// noise without bleeding across silhouettes. Full or half resolution. The
// depth is read as view z from a pyramid made first (view_depth_pyramid.h).
// docs/rendering.md has the parameters and their cost.
#pragma once

#include <glm/mat4x4.hpp>

#include "garden/render/gl_objects.h"
#include "garden/render/render_quality.h"
#include "garden/render/render_targets.h"
#include "garden/render/shader_program.h"
#include "garden/render/view_depth_pyramid.h"

namespace hg::garden {

// What the composite needs to read the occlusion at the scene's pixels.
struct OcclusionImage {
    GLuint texture = 0;  // R8, 1 where open, towards 0 in hollows; 0: none
    int scale = 1;       // scene pixels per occlusion texel along each axis (2: half resolution)
    GLuint viewZ = 0;    // the scene's view z (ViewDepthPyramid, level 0 at full size)
};

class OcclusionPass {
public:
    OcclusionPass();  // throws GlError naming a shader that fails

    // The occlusion of the scene seen through `projection`. Changes
    // framebuffer bindings and the viewport.
    OcclusionImage render(const SceneTargets& scene, const glm::mat4& projection, const RenderQuality& quality);

private:
    ShaderProgram occlusion_;
    ShaderProgram blur_;
    gl::VertexArray empty_;
    ViewDepthPyramid pyramid_;
    ViewPositionUniforms occlusionView_, blurView_;
    ScalarTarget raw_, blurred_;
    struct {
        GLint projection, scale, samples, radius, farZ;
    } o_{};
    struct {
        GLint scale, direction;
    } b_{};
};

}  // namespace hg::garden
