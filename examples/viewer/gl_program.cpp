// SPDX-License-Identifier: Apache-2.0
#include "gl_program.h"

#include <vector>

namespace viewer {

namespace {

GLuint compile(GLenum stage, const char* source, std::string& log) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok == GL_TRUE) return shader;
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(text.size()), nullptr, text.data());
    log = text.data();
    glDeleteShader(shader);
    return 0;
}

}  // namespace

GlProgram::~GlProgram() {
    if (id_ != 0) glDeleteProgram(id_);
}

bool GlProgram::build(const char* name, const char* vertex_source, const char* fragment_source, std::string& error) {
    std::string log;
    const GLuint vertex = compile(GL_VERTEX_SHADER, vertex_source, log);
    if (vertex == 0) {
        error = std::string(name) + " vertex shader: " + log;
        return false;
    }
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragment_source, log);
    if (fragment == 0) {
        glDeleteShader(vertex);
        error = std::string(name) + " fragment shader: " + log;
        return false;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vertex);
    glAttachShader(id_, fragment);
    glLinkProgram(id_);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok == GL_TRUE) return true;
    std::vector<char> text(1024, '\0');
    glGetProgramInfoLog(id_, static_cast<GLsizei>(text.size()), nullptr, text.data());
    error = std::string(name) + " link: " + text.data();
    return false;
}

}  // namespace viewer
