#include "garden/render/render_targets.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

#include "garden/render/gl_context.h"

namespace hg::garden {

void checkFramebuffer(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%x", status);
    throw GlError(std::string(what) + " framebuffer incomplete (status " + hex + ")");
}

gl::Texture makeTexture2D(GLenum internalFormat, glm::ivec2 size, GLenum format, GLenum type, GLint filter,
                          GLint wrap) {
    gl::Texture t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, t.get());
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), size.x, size.y, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
    return t;
}

void SceneTargets::ensure(glm::ivec2 size, int samples) {
    size = glm::max(size, glm::ivec2(1));
    GLint maxColor = 1, maxDepth = 1;
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &maxColor);
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &maxDepth);
    samples = std::clamp(samples, 1, std::max(1, std::min(maxColor, maxDepth)));
    if (fbo_ && size == size_ && samples == samples_) return;

    fbo_ = gl::Framebuffer::create();
    const GLenum target = textureTargetFor(samples);
    if (samples > 1) {
        // Fixed sample locations: the composite reads sample i of colour and
        // depth as the same point.
        color_ = gl::Texture::create();
        depth_ = gl::Texture::create();
        glBindTexture(target, color_.get());
        glTexImage2DMultisample(target, samples, GL_RGBA16F, size.x, size.y, GL_TRUE);
        glBindTexture(target, depth_.get());
        glTexImage2DMultisample(target, samples, GL_DEPTH_COMPONENT24, size.x, size.y, GL_TRUE);
        glBindTexture(target, 0);
    } else {
        color_ = makeTexture2D(GL_RGBA16F, size, GL_RGBA, GL_FLOAT, GL_NEAREST, GL_CLAMP_TO_EDGE);
        depth_ = makeTexture2D(GL_DEPTH_COMPONENT24, size, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, GL_NEAREST,
                               GL_CLAMP_TO_EDGE);
        glBindTexture(target, 0);
    }

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, color_.get(), 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, target, depth_.get(), 0);
    checkFramebuffer("scene (HDR, multisampled)");
    size_ = size;
    samples_ = samples;
}

std::string SceneTargets::sceneSamplerDefine(int samples) {
    return samples > 1 ? "#define HG_SCENE_SAMPLER sampler2DMS\n" : "#define HG_SCENE_SAMPLER sampler2D\n";
}

void ScalarTarget::ensure(glm::ivec2 wanted) {
    wanted = glm::max(wanted, glm::ivec2(1));
    if (fbo && wanted == size) return;
    fbo = gl::Framebuffer::create();
    texture = makeTexture2D(GL_R8, wanted, GL_RED, GL_UNSIGNED_BYTE, GL_LINEAR, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.get(), 0);
    checkFramebuffer("ambient occlusion");
    size = wanted;
}

}  // namespace hg::garden
