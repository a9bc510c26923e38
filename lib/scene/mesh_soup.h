// SPDX-License-Identifier: Apache-2.0
// What the mesh file readers (mesh_readers.h) collect: the vertices in file order and the
// polygons, each fanned into triangles (corners 0, k-1, k) as it arrives. A refusal names
// where in the file the fault is: a line of a text file, a byte offset of a binary one
// (MeshPlace), as the JSON errors name theirs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "collision/triangle_mesh.h"

namespace enteron::scene {

// Where a reader is in its file, for a message: "line 12" or "byte 4096" (both from 1 and
// 0, as editors and hex dumps count them).
struct MeshPlace {
    enum class Unit { line, byte };
    Unit unit = Unit::line;
    std::size_t at = 0;

    static MeshPlace line(std::size_t number) { return {Unit::line, number}; }
    static MeshPlace byte(std::size_t offset) { return {Unit::byte, offset}; }
    std::string describe() const;
};

// Throws Error(invalid_argument) "<place>: <why>" (read_mesh_file adds the file's name).
[[noreturn]] void refuse_mesh(const MeshPlace& place, const std::string& why);

class MeshSoup {
public:
    // `first_index`: how the file numbers its vertices (OBJ from 1, PLY and OFF from 0), for
    // the messages.
    explicit MeshSoup(uint32_t first_index = 0) : first_index_(first_index) {}

    // Room for what a header announces, capped by what the file's size can hold.
    void reserve(std::size_t vertices, std::size_t triangles);

    void add_vertex(double x, double y, double z) { mesh_.vertices.insert(mesh_.vertices.end(), {x, y, z}); }
    std::size_t vertex_count() const { return mesh_.vertex_count(); }

    // A polygon of `count` corners, vertex indices from 0 (which may name vertices the file
    // defines later: they are checked by finish()). Refuses fewer than 3 corners and a mesh
    // beyond collision::kMaxMeshTriangles.
    void add_polygon(const uint32_t* corners, std::size_t count, const MeshPlace& place);

    // The mesh, every coordinate times `scale`. Refuses a mesh without triangles (Error
    // "holds no triangle": no place) and a corner beyond the last vertex (naming the first
    // polygon with the largest corner).
    collision::TriangleMesh finish(double scale);

private:
    uint32_t first_index_;
    collision::TriangleMesh mesh_;
    int64_t largest_corner_ = -1;
    MeshPlace largest_corner_place_;
};

}  // namespace enteron::scene
