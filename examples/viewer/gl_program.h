// SPDX-License-Identifier: Apache-2.0
// A linked GLSL program and its uniforms (OpenGL 3.3 core, through libepoxy).
#pragma once

#include <epoxy/gl.h>

#include <Eigen/Core>

#include <string>

namespace viewer {

class GlProgram {
public:
    GlProgram() = default;
    ~GlProgram();
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;

    // Compiles and links; false with the compiler's log in error.
    bool build(const char* name, const char* vertex_source, const char* fragment_source, std::string& error);
    void use() const { glUseProgram(id_); }

    void set(const char* name, int value) const { glUniform1i(location(name), value); }
    void set(const char* name, float value) const { glUniform1f(location(name), value); }
    void set(const char* name, const Eigen::Vector3f& value) const { glUniform3fv(location(name), 1, value.data()); }
    void set(const char* name, const Eigen::Vector4f& value) const { glUniform4fv(location(name), 1, value.data()); }
    void set(const char* name, const Eigen::Matrix3f& value) const {
        glUniformMatrix3fv(location(name), 1, GL_FALSE, value.data());
    }
    void set(const char* name, const Eigen::Matrix4f& value) const {
        glUniformMatrix4fv(location(name), 1, GL_FALSE, value.data());
    }

private:
    GLint location(const char* name) const { return glGetUniformLocation(id_, name); }
    GLuint id_ = 0;
};

}  // namespace viewer
