// A linked GLSL program built from vertex and fragment source; compile and
// link logs become the exception's message, so a broken shader names itself.
#pragma once

#include <string>

#include "garden/render/gl_objects.h"

namespace hg::garden {

// `source` with `defines` ("#define NAME VALUE" lines) after its #version
// line: one program text specialized to a configuration. Software
// rasterizers (llvmpipe) run both sides of every branch, uniform or not, so
// a feature switched off by a uniform still costs them its full price;
// compiled out it costs nothing (docs/rendering.md, "Programs made to
// measure").
std::string withDefines(const char* source, const std::string& defines);

class ShaderProgram {
public:
    ShaderProgram() = default;
    // Throws GlError ("<name> vertex shader: <log>") on failure.
    ShaderProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);

    GLuint id() const { return program_.get(); }
    void use() const { glUseProgram(program_.get()); }
    // -1 when the uniform is absent or unused (GL ignores writes to -1).
    GLint uniform(const char* name) const { return glGetUniformLocation(program_.get(), name); }

private:
    gl::Program program_;
};

}  // namespace hg::garden
