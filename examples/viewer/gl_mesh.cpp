// SPDX-License-Identifier: Apache-2.0
#include "gl_mesh.h"

#include <cmath>
#include <cstdint>

namespace viewer {

namespace {
constexpr float kPi = 3.14159265358979f;

void add_vertex(ShapeData& shape, float x, float y, float z, float nx, float ny, float nz) {
    shape.positions.insert(shape.positions.end(), {x, y, z});
    shape.normals.insert(shape.normals.end(), {nx, ny, nz});
}

void add_quad(ShapeData& shape, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    shape.indices.insert(shape.indices.end(), {a, b, c, a, c, d});
}
}  // namespace

ShapeData unit_sphere(int slices, int stacks) {
    ShapeData shape;
    for (int j = 0; j <= stacks; ++j) {
        const float polar = kPi * static_cast<float>(j) / static_cast<float>(stacks);
        for (int i = 0; i <= slices; ++i) {
            const float azimuth = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
            const float x = std::sin(polar) * std::cos(azimuth), y = std::sin(polar) * std::sin(azimuth),
                        z = std::cos(polar);
            add_vertex(shape, x, y, z, x, y, z);
        }
    }
    const auto row = static_cast<std::uint32_t>(slices + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(stacks); ++j)
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i)
            add_quad(shape, j * row + i, (j + 1) * row + i, (j + 1) * row + i + 1, j * row + i + 1);
    return shape;
}

ShapeData unit_cylinder(int slices) {
    ShapeData shape;
    for (int i = 0; i <= slices; ++i) {
        const float azimuth = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
        const float x = std::cos(azimuth), y = std::sin(azimuth);
        add_vertex(shape, x, y, 0.0f, x, y, 0.0f);
        add_vertex(shape, x, y, 1.0f, x, y, 0.0f);
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i)
        add_quad(shape, 2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
    return shape;
}

ShapeData unit_cone(int slices) {
    ShapeData shape;
    const float slope = std::sqrt(0.5f);  // the side's normal leans up by 45 degrees
    for (int i = 0; i <= slices; ++i) {
        const float azimuth = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
        const float x = std::cos(azimuth), y = std::sin(azimuth);
        add_vertex(shape, x, y, 0.0f, slope * x, slope * y, slope);
        add_vertex(shape, 0.0f, 0.0f, 1.0f, slope * x, slope * y, slope);
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i)
        shape.indices.insert(shape.indices.end(), {2 * i, 2 * i + 2, 2 * i + 1});
    const auto centre = static_cast<std::uint32_t>(shape.positions.size() / 3);
    add_vertex(shape, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f);
    for (int i = 0; i <= slices; ++i) {
        const float azimuth = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
        add_vertex(shape, std::cos(azimuth), std::sin(azimuth), 0.0f, 0.0f, 0.0f, -1.0f);
    }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(slices); ++i)
        shape.indices.insert(shape.indices.end(), {centre, centre + 2 + i, centre + 1 + i});
    return shape;
}

ShapeData inward_box() {
    ShapeData shape;
    // Each face: its inward normal and two in-plane axes, wound counter-clockwise as seen
    // from inside the box.
    const float faces[6][9] = {{0, 0, 1, 1, 0, 0, 0, 1, 0},    // floor, seen from above
                               {0, 0, -1, 0, 1, 0, 1, 0, 0},   // ceiling
                               {1, 0, 0, 0, 1, 0, 0, 0, 1},    // wall at x = -1
                               {-1, 0, 0, 0, 0, 1, 0, 1, 0},   // wall at x = +1
                               {0, 1, 0, 0, 0, 1, 1, 0, 0},    // wall at y = -1
                               {0, -1, 0, 1, 0, 0, 0, 0, 1}};  // wall at y = +1
    for (const auto& f : faces) {
        const auto first = static_cast<std::uint32_t>(shape.positions.size() / 3);
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners)
            add_vertex(shape, -f[0] + c[0] * f[3] + c[1] * f[6], -f[1] + c[0] * f[4] + c[1] * f[7],
                       -f[2] + c[0] * f[5] + c[1] * f[8], f[0], f[1], f[2]);
        add_quad(shape, first, first + 1, first + 2, first + 3);
    }
    return shape;
}

ShapeData unit_square() {
    ShapeData shape;
    add_vertex(shape, -1, -1, 0, 0, 0, 1);
    add_vertex(shape, 1, -1, 0, 0, 0, 1);
    add_vertex(shape, 1, 1, 0, 0, 0, 1);
    add_vertex(shape, -1, 1, 0, 0, 0, 1);
    add_quad(shape, 0, 1, 2, 3);
    return shape;
}

GlMesh::GlMesh() {
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vertices_);
    glGenBuffers(1, &indices_);
}

GlMesh::~GlMesh() {
    glDeleteBuffers(1, &vertices_);
    glDeleteBuffers(1, &indices_);
    if (instances_ != 0) glDeleteBuffers(1, &instances_);
    glDeleteVertexArrays(1, &vao_);
}

void GlMesh::upload(const float* positions, const float* normals, const float* axis_u, std::uint32_t vertex_count,
                    const std::uint32_t* indices, std::uint32_t index_count, GLenum usage) {
    vertex_count_ = vertex_count;
    index_count_ = indices != nullptr ? index_count : 0;
    // One buffer, three blocks: positions, normals, axis u.
    const GLsizeiptr position_bytes = static_cast<GLsizeiptr>(3 * sizeof(float) * vertex_count);
    const GLsizeiptr normal_bytes = normals != nullptr ? position_bytes : 0;
    const GLsizeiptr u_bytes = axis_u != nullptr ? static_cast<GLsizeiptr>(sizeof(float) * vertex_count) : 0;
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_);
    glBufferData(GL_ARRAY_BUFFER, position_bytes + normal_bytes + u_bytes, nullptr, usage);  // orphan the old one
    glBufferSubData(GL_ARRAY_BUFFER, 0, position_bytes, positions);
    glEnableVertexAttribArray(kPositionAttribute);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    if (normals != nullptr) {
        glBufferSubData(GL_ARRAY_BUFFER, position_bytes, normal_bytes, normals);
        glEnableVertexAttribArray(kNormalAttribute);
        glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, 0,
                              reinterpret_cast<const void*>(static_cast<std::uintptr_t>(position_bytes)));
    } else {
        glDisableVertexAttribArray(kNormalAttribute);
    }
    if (axis_u != nullptr) {
        glBufferSubData(GL_ARRAY_BUFFER, position_bytes + normal_bytes, u_bytes, axis_u);
        glEnableVertexAttribArray(kAxisUAttribute);
        glVertexAttribPointer(kAxisUAttribute, 1, GL_FLOAT, GL_FALSE, 0,
                              reinterpret_cast<const void*>(static_cast<std::uintptr_t>(position_bytes + normal_bytes)));
    } else {
        glDisableVertexAttribArray(kAxisUAttribute);
    }
    if (indices != nullptr) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(sizeof(std::uint32_t) * index_count), indices,
                     usage);
    }
    glBindVertexArray(0);
}

void GlMesh::upload_instances(const float* centre_scale, std::uint32_t count) {
    glBindVertexArray(vao_);
    if (instances_ == 0) glGenBuffers(1, &instances_);
    glBindBuffer(GL_ARRAY_BUFFER, instances_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(4 * sizeof(float) * count), centre_scale, GL_STREAM_DRAW);
    glEnableVertexAttribArray(kInstanceAttribute);
    glVertexAttribPointer(kInstanceAttribute, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    glVertexAttribDivisor(kInstanceAttribute, 1);
    glBindVertexArray(0);
    instance_count_ = count;
}

void GlMesh::set_constant_attributes() {
    // What an attribute without an array reads: a normal up, u = 0, no instance offset.
    glVertexAttrib3f(kNormalAttribute, 0.0f, 0.0f, 1.0f);
    glVertexAttrib1f(kAxisUAttribute, 0.0f);
    glVertexAttrib4f(kInstanceAttribute, 0.0f, 0.0f, 0.0f, 1.0f);
}

void GlMesh::draw(GLenum mode) const {
    if (vertex_count_ == 0) return;
    glBindVertexArray(vao_);
    set_constant_attributes();
    if (index_count_ > 0)
        glDrawElements(mode, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
    else
        glDrawArrays(mode, 0, static_cast<GLsizei>(vertex_count_));
    glBindVertexArray(0);
}

void GlMesh::draw_instanced(GLenum mode) const {
    if (vertex_count_ == 0 || instance_count_ == 0) return;
    glBindVertexArray(vao_);
    set_constant_attributes();
    glDrawElementsInstanced(mode, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr,
                            static_cast<GLsizei>(instance_count_));
    glBindVertexArray(0);
}

}  // namespace viewer
