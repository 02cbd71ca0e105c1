// The renderer's own framebuffer for one view: multisampled linear HDR colour
// (RGBA16F) and depth, both textures so the post passes can read every
// sample. Reallocated only when the size or sample count changes.
//
// One sample a pixel is a plain 2D texture, not a multisample texture of
// one sample: a driver may make that four (llvmpipe does), and every clear
// and write of the scene then paid for four (docs/rendering.md, "One
// sample is one sample"). The programs that read the targets declare them
// as HG_SCENE_SAMPLER (sceneSamplerDefine) and read them with texelFetch(s,
// p, i), which is sample i of a multisample texture and level i of a plain
// one, where only 0 is asked.
#pragma once

#include <glm/vec2.hpp>

#include <string>

#include "garden/render/gl_objects.h"

namespace hg::garden {

class SceneTargets {
public:
    // Makes the targets `size` with `samples` per pixel (clamped to the
    // driver's limits, at least 1). Throws GlError when incomplete.
    void ensure(glm::ivec2 size, int samples);

    GLuint framebuffer() const { return fbo_.get(); }
    GLuint colorTexture() const { return color_.get(); }  // RGBA16F, bound to textureTarget()
    GLuint depthTexture() const { return depth_.get(); }  // DEPTH24, bound to textureTarget()
    // GL_TEXTURE_2D for one sample, else GL_TEXTURE_2D_MULTISAMPLE.
    GLenum textureTarget() const { return textureTargetFor(samples_); }
    glm::ivec2 size() const { return size_; }
    int samples() const { return samples_; }

    static GLenum textureTargetFor(int samples) { return samples > 1 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D; }
    // "#define HG_SCENE_SAMPLER sampler2DMS" (or sampler2D for one sample).
    static std::string sceneSamplerDefine(int samples);

private:
    gl::Framebuffer fbo_;
    gl::Texture color_;
    gl::Texture depth_;
    glm::ivec2 size_{0};
    int samples_ = 0;
};

// A single-channel texture with its framebuffer (ambient occlusion).
struct ScalarTarget {
    gl::Framebuffer fbo;
    gl::Texture texture;
    glm::ivec2 size{0};
    // (Re)allocates an R8 target of `size`, linear filtered, clamped.
    void ensure(glm::ivec2 size);
};

// Throws GlError naming `what` when the bound framebuffer is incomplete.
void checkFramebuffer(const char* what);

// A 2D texture without mipmaps of `size`, filtered and wrapped the same
// both ways; left bound to GL_TEXTURE_2D for further parameters.
gl::Texture makeTexture2D(GLenum internalFormat, glm::ivec2 size, GLenum format, GLenum type, GLint filter,
                          GLint wrap);

}  // namespace hg::garden
