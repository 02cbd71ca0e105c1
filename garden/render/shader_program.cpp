#include "garden/render/shader_program.h"

#include <vector>

#include "garden/render/gl_context.h"

namespace hg::garden {
namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.data();
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 1 ? length : 1), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    return log.data();
}

gl::Shader compile(const std::string& name, GLenum stage, const char* source) {
    gl::Shader shader(glCreateShader(stage));
    glShaderSource(shader.get(), 1, &source, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE)
        throw GlError(name + (stage == GL_VERTEX_SHADER ? " vertex" : " fragment") + " shader: " + shaderLog(shader.get()));
    return shader;
}

}  // namespace

std::string withDefines(const char* source, const std::string& defines) {
    std::string text = source;
    const std::size_t line = text.find('\n');
    text.insert(line == std::string::npos ? text.size() : line + 1, defines);
    return text;
}

ShaderProgram::ShaderProgram(const std::string& name, const char* vertexSource, const char* fragmentSource) {
    gl::Shader vs = compile(name, GL_VERTEX_SHADER, vertexSource);
    gl::Shader fs = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
    program_ = gl::Program(glCreateProgram());
    glAttachShader(program_.get(), vs.get());
    glAttachShader(program_.get(), fs.get());
    glLinkProgram(program_.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program_.get(), GL_LINK_STATUS, &ok);
    glDetachShader(program_.get(), vs.get());
    glDetachShader(program_.get(), fs.get());
    if (ok != GL_TRUE) throw GlError(name + " program link: " + programLog(program_.get()));
}

}  // namespace hg::garden
