// Move-only owners of OpenGL object names, so buffers, vertex arrays,
// programs and framebuffers are deleted exactly once, on the thread and
// context that created them (whoever destroys one must have that context
// current).
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace hg::garden::gl {

// Tag::destroy deletes a name; Tag::create (where GL has a glGen*) makes one.
template <typename Tag>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint name) : name_(name) {}
    static Handle create() { return Handle(Tag::create()); }
    ~Handle() { reset(); }
    Handle(Handle&& o) noexcept : name_(std::exchange(o.name_, 0u)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            name_ = std::exchange(o.name_, 0u);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_ != 0) Tag::destroy(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

struct BufferTag {
    static GLuint create() { GLuint n = 0; glGenBuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayTag {
    static GLuint create() { GLuint n = 0; glGenVertexArrays(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct FramebufferTag {
    static GLuint create() { GLuint n = 0; glGenFramebuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct RenderbufferTag {
    static GLuint create() { GLuint n = 0; glGenRenderbuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteRenderbuffers(1, &n); }
};
struct TextureTag {
    static GLuint create() { GLuint n = 0; glGenTextures(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct QueryTag {
    static GLuint create() { GLuint n = 0; glGenQueries(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};
struct ShaderTag {
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct ProgramTag {
    static void destroy(GLuint n) { glDeleteProgram(n); }
};

using Buffer = Handle<BufferTag>;
using VertexArray = Handle<VertexArrayTag>;
using Framebuffer = Handle<FramebufferTag>;
using Renderbuffer = Handle<RenderbufferTag>;
using Texture = Handle<TextureTag>;
using Query = Handle<QueryTag>;
using Shader = Handle<ShaderTag>;
using Program = Handle<ProgramTag>;

// The bound texture of `target` read with linear filtering, clamped at its
// edges, from level 0 alone (no mipmaps made).
inline void sampleLinearClamped(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
}

// The framebuffers bound for drawing and reading, and the viewport, as they
// were when it was made; put back when it goes. A pass that renders into its
// own target (a bake, a resolve, the UI board) holds one, so the caller's
// target is whole again whichever way the pass leaves.
class TargetKept {
public:
    TargetKept() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
    }
    ~TargetKept() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    }
    TargetKept(const TargetKept&) = delete;
    TargetKept& operator=(const TargetKept&) = delete;

private:
    GLint draw_ = 0;
    GLint read_ = 0;
    GLint viewport_[4] = {0, 0, 0, 0};
};

}  // namespace hg::garden::gl
