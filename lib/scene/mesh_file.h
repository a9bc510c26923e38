// SPDX-License-Identifier: Apache-2.0
// Reads an organ's triangle mesh from a file: OBJ or PLY (also OFF and STL), by the
// library's own readers (mesh_readers.h: no third-party code, nothing added to what
// libenteron.so loads; docs/anatomy.md has the choice and the measurements). Polygons with
// more than three corners become fans of triangles.
#pragma once

#include <string>
#include <string_view>

#include "base/error.h"
#include "collision/triangle_mesh.h"

namespace enteron::scene {

enum class MeshFormat { obj, ply, off, stl };

// The format a file's extension names (any case); false for another extension.
bool mesh_format_of(const std::string& path, MeshFormat& format);

// The mesh in a file's bytes, every coordinate multiplied by `scale`. Throws
// Error(invalid_argument) "<line N or byte N>: <what is wrong there>", or "holds no triangle".
collision::TriangleMesh parse_mesh(std::string_view bytes, MeshFormat format, double scale);

// The mesh in `path` with every coordinate multiplied by `scale` (a CT mesh in millimetres:
// 0.001). `name` is the scene's name for it ("environment[2].file"). Throws Error(code)
// "<name> \"<path>\": <why>": missing or unreadable, an unknown extension, or what
// parse_mesh refuses, with its line (or, in binary data, its byte offset).
collision::TriangleMesh read_mesh_file(const std::string& path, double scale, const std::string& name,
                                       ErrorCode code);

}  // namespace enteron::scene
