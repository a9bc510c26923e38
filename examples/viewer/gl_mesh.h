// SPDX-License-Identifier: Apache-2.0
// Triangle and line meshes on the GPU, and the unit shapes the scene is drawn with. Every
// program reads the same attribute locations, so any mesh works with any program.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace viewer {

enum Attribute : GLuint {
    kPositionAttribute = 0,  // vec3, m
    kNormalAttribute = 1,    // vec3, unit
    kAxisUAttribute = 2,     // float: the bowel's axis parameter (0 elsewhere)
    kInstanceAttribute = 3,  // vec4 per instance: centre xyz and scale (1 when not instanced)
};

struct ShapeData {
    std::vector<float> positions;   // 3 per vertex
    std::vector<float> normals;     // 3 per vertex
    std::vector<std::uint32_t> indices;
};

ShapeData unit_sphere(int slices, int stacks);  // radius 1 at the origin
ShapeData unit_cylinder(int slices);            // radius 1, z from 0 to 1, open ends
ShapeData unit_cone(int slices);                // base radius 1 at z = 0, apex at z = 1, closed
ShapeData inward_box();                         // [-1, 1]^3 seen from inside: normals point in
ShapeData unit_square();                        // z = 0, [-1, 1]^2, normal +z

class GlMesh {
public:
    GlMesh();
    ~GlMesh();
    GlMesh(const GlMesh&) = delete;
    GlMesh& operator=(const GlMesh&) = delete;

    // Replaces the contents. normals and axis_u may be null (then their attribute is
    // constant); indices may be null (then draw() draws the vertices in order).
    void upload(const float* positions, const float* normals, const float* axis_u, std::uint32_t vertex_count,
                const std::uint32_t* indices, std::uint32_t index_count, GLenum usage = GL_STREAM_DRAW);
    void upload(const ShapeData& shape) {
        upload(shape.positions.data(), shape.normals.data(), nullptr,
               static_cast<std::uint32_t>(shape.positions.size() / 3), shape.indices.data(),
               static_cast<std::uint32_t>(shape.indices.size()), GL_STATIC_DRAW);
    }
    // Per-instance centre and scale (vec4) for draw_instanced.
    void upload_instances(const float* centre_scale, std::uint32_t count);

    void draw(GLenum mode = GL_TRIANGLES) const;
    void draw_instanced(GLenum mode = GL_TRIANGLES) const;

private:
    static void set_constant_attributes();
    GLuint vao_ = 0, vertices_ = 0, indices_ = 0, instances_ = 0;
    std::uint32_t vertex_count_ = 0, index_count_ = 0, instance_count_ = 0;
};

}  // namespace viewer
