#include "garden/render/impostor_atlas.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

// One mip level of a layer from the level above: the mean of 2 x 2 texels.
// The texels are premultiplied by coverage, so the mean is too (a frame's
// edge fades instead of darkening, and its depth stays the surface's).
const char* const kDownsampleFragment = R"(#version 330 core
uniform sampler2DArray uAlbedo;
uniform sampler2DArray uNormalDepth;
uniform int uLayer;
uniform int uLevel;  // the level read
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normalDepth;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    vec4 a = vec4(0.0), n = vec4(0.0);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            a += texelFetch(uAlbedo, ivec3(p + ivec2(x, y), uLayer), uLevel);
            n += texelFetch(uNormalDepth, ivec3(p + ivec2(x, y), uLayer), uLevel);
        }
    albedo = 0.25 * a;
    normalDepth = 0.25 * n;
}
)";


void storage(GLuint texture, GLenum internalFormat, GLenum format, GLenum type, int size, int layers) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
    for (int level = 0; level <= kImpostorMipLevels; ++level)
        glTexImage3D(GL_TEXTURE_2D_ARRAY, level, static_cast<GLint>(internalFormat), std::max(1, size >> level),
                     std::max(1, size >> level), layers, 0, format, type, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, kImpostorMipLevels);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

}  // namespace

ImpostorAtlas::ImpostorAtlas(const ImpostorSettings& settings)
    : settings_(settings), downsample_("impostor mip", shaders::kFullscreenVertex, kDownsampleFragment) {
    settings_.views = std::clamp(settings_.views, 2, 32);
    // A whole number of texels down to the last mip level.
    settings_.framePixels = std::max(8, settings_.framePixels / 8 * 8);
    settings_.maxLayers = std::max(1, settings_.maxLayers);
    downsampleLevel_ = downsample_.uniform("uLevel");
    downsampleLayer_ = downsample_.uniform("uLayer");
    downsample_.use();
    glUniform1i(downsample_.uniform("uAlbedo"), kImpostorAlbedoUnit);
    glUniform1i(downsample_.uniform("uNormalDepth"), kImpostorNormalDepthUnit);
    glUseProgram(0);
    emptyVao_ = gl::VertexArray::create();
}

ImpostorAtlas::~ImpostorAtlas() = default;

std::size_t ImpostorAtlas::bytes() const {
    const std::size_t side = static_cast<std::size_t>(settings_.views * settings_.framePixels);
    std::size_t texels = 0;
    for (int level = 0; level <= kImpostorMipLevels; ++level) texels += (side >> level) * (side >> level);
    return texels * static_cast<std::size_t>(layers_) * (4 + 8);  // sRGB8 alpha8 + RGBA16F
}

bool ImpostorAtlas::has(ImpostorKey key, std::uint64_t version) const {
    const auto found = entries_.find(key);
    return found != entries_.end() && found->second.version == version;
}

const ImpostorEntry* ImpostorAtlas::use(ImpostorKey key, std::uint64_t version) {
    const auto found = entries_.find(key);
    if (found == entries_.end() || found->second.version != version) return nullptr;
    found->second.lastUsed = frame_;
    return &found->second.entry;
}

glm::vec3 ImpostorAtlas::frameDirection(int i, int j, int views) {
    // Hemi-octahedral: the square [-1, 1]^2 turned by 45 degrees onto the
    // diamond |x| + |z| <= 1, lifted to the upper hemisphere (shaders.h,
    // HG_IMPOSTOR_GLSL's octDecode: the same formula).
    const float a = 2.0f * static_cast<float>(i) / static_cast<float>(views - 1) - 1.0f;
    const float b = 2.0f * static_cast<float>(j) / static_cast<float>(views - 1) - 1.0f;
    const float x = 0.5f * (a + b), z = 0.5f * (a - b);
    return glm::normalize(glm::vec3(x, 1.0f - std::fabs(x) - std::fabs(z), z));
}

glm::mat4 ImpostorAtlas::frameViewProjection(const glm::vec3& toViewer, const glm::vec3& centre, float radius) {
    const float reach = radius * kReach;
    // The up vector the card's sampling uses too (HG_IMPOSTOR_GLSL's frameBasis).
    const glm::vec3 up = std::fabs(toViewer.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::mat4 view = glm::lookAt(centre + toViewer * (2.0f * reach), centre, up);
    return glm::ortho(-reach, reach, -reach, reach, 0.5f * reach, 3.5f * reach) * view;
}

void ImpostorAtlas::grow(int layers) {
    const int side = settings_.views * settings_.framePixels;
    gl::Texture albedo = gl::Texture::create();
    gl::Texture normalDepth = gl::Texture::create();
    storage(albedo.get(), GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, side, layers);
    storage(normalDepth.get(), GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, side, layers);
    // What was baked moves into the new textures on the GPU (GL 4.3's
    // image copy); without it, it is baked again as it is wanted.
    const bool copy = layers_ > 0 && (epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_ARB_copy_image"));
    if (copy)
        for (int level = 0; level <= kImpostorMipLevels; ++level) {
            const int s = std::max(1, side >> level);
            glCopyImageSubData(albedo_.get(), GL_TEXTURE_2D_ARRAY, level, 0, 0, 0, albedo.get(), GL_TEXTURE_2D_ARRAY,
                               level, 0, 0, 0, s, s, layers_);
            glCopyImageSubData(normalDepth_.get(), GL_TEXTURE_2D_ARRAY, level, 0, 0, 0, normalDepth.get(),
                               GL_TEXTURE_2D_ARRAY, level, 0, 0, 0, s, s, layers_);
        }
    albedo_ = std::move(albedo);
    normalDepth_ = std::move(normalDepth);
    if (!depth_) {
        depth_ = gl::Renderbuffer::create();
        glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, side, side);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        fbo_ = gl::Framebuffer::create();
    }
    if (!copy) {
        entries_.clear();
        owner_.assign(static_cast<std::size_t>(layers), 0);
        owned_.assign(static_cast<std::size_t>(layers), false);
    } else {
        owner_.resize(static_cast<std::size_t>(layers), 0);
        owned_.resize(static_cast<std::size_t>(layers), false);
    }
    layers_ = layers;
}

int ImpostorAtlas::layerFor(ImpostorKey key) {
    const auto found = entries_.find(key);
    if (found != entries_.end()) return found->second.entry.layer;
    for (int l = 0; l < layers_; ++l)
        if (!owned_[static_cast<std::size_t>(l)]) return l;
    if (layers_ < settings_.maxLayers) {
        const int first = layers_;
        grow(std::min(settings_.maxLayers, std::max(4, 2 * layers_)));
        for (int l = 0; l < layers_; ++l)
            if (!owned_[static_cast<std::size_t>(l)]) return l;
        return first;
    }
    // The least recently drawn, if it was not drawn in this frame.
    int oldest = -1;
    std::uint64_t when = std::numeric_limits<std::uint64_t>::max();
    for (const auto& [k, slot] : entries_)
        if (slot.lastUsed < when) {
            when = slot.lastUsed;
            oldest = slot.entry.layer;
        }
    if (oldest < 0 || when >= frame_) return -1;
    entries_.erase(owner_[static_cast<std::size_t>(oldest)]);
    owned_[static_cast<std::size_t>(oldest)] = false;
    return oldest;
}

bool ImpostorAtlas::bake(ImpostorKey key, std::uint64_t version, ChunkBatch& batch, ChunkArena& arena, bool multiDraw,
                         const ShaderProgram& program, const glm::vec3& centre, float radius) {
    const int layer = layerFor(key);
    if (layer < 0) return false;
    const int views = settings_.views, pixels = settings_.framePixels, side = views * pixels;

    const gl::TargetKept kept;
    const GLboolean srgb = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, albedo_.get(), 0, layer);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, normalDepth_.get(), 0, layer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    checkFramebuffer("impostor atlas");
    glEnable(GL_FRAMEBUFFER_SRGB);  // the colour is linear; the layer stores sRGB
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_MULTISAMPLE);
    glViewport(0, 0, side, side);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    program.use();
    const GLint viewProjection = program.uniform("uViewProjection");
    const GLint toViewer = program.uniform("uBakeToViewer");
    glUniform3fv(program.uniform("uBakeCentre"), 1, glm::value_ptr(centre));
    glUniform1f(program.uniform("uBakeReach"), radius * kReach);
    for (int j = 0; j < views; ++j)
        for (int i = 0; i < views; ++i) {
            const glm::vec3 d = frameDirection(i, j, views);
            const glm::mat4 m = frameViewProjection(d, centre, radius);
            glUniformMatrix4fv(viewProjection, 1, GL_FALSE, glm::value_ptr(m));
            glUniform3fv(toViewer, 1, glm::value_ptr(d));
            glViewport(i * pixels, j * pixels, pixels, pixels);
            batch.draw(arena, multiDraw);
        }
    downsample(layer);

    if (!srgb) glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_MULTISAMPLE);

    Slot& slot = entries_[key];
    slot.entry = ImpostorEntry{layer, centre, radius};
    slot.version = version;
    slot.lastUsed = frame_;
    owner_[static_cast<std::size_t>(layer)] = key;
    owned_[static_cast<std::size_t>(layer)] = true;
    ++bakes_;
    return true;
}

void ImpostorAtlas::downsample(int layer) {
    const int side = settings_.views * settings_.framePixels;
    downsample_.use();
    glUniform1i(downsampleLayer_, layer);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao_.get());
    glActiveTexture(GL_TEXTURE0 + kImpostorAlbedoUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, albedo_.get());
    glActiveTexture(GL_TEXTURE0 + kImpostorNormalDepthUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, normalDepth_.get());
    for (int level = 1; level <= kImpostorMipLevels; ++level) {
        // Only the level read is visible to the sampler while the one below
        // is drawn (no feedback loop): texelFetch's level counts from it.
        for (GLuint t : {albedo_.get(), normalDepth_.get()}) {
            glBindTexture(GL_TEXTURE_2D_ARRAY, t);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, level - 1);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, level - 1);
        }
        glActiveTexture(GL_TEXTURE0 + kImpostorAlbedoUnit);
        glBindTexture(GL_TEXTURE_2D_ARRAY, albedo_.get());
        glUniform1i(downsampleLevel_, 0);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, albedo_.get(), level, layer);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, normalDepth_.get(), level, layer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, 0);
        glViewport(0, 0, side >> level, side >> level);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    for (GLuint t : {albedo_.get(), normalDepth_.get()}) {
        glBindTexture(GL_TEXTURE_2D_ARRAY, t);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, kImpostorMipLevels);
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glActiveTexture(GL_TEXTURE0 + kImpostorAlbedoUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
}

}  // namespace hg::garden
