// SPDX-License-Identifier: Apache-2.0
// The mesh file formats the library reads, each from the file's bytes in memory: OBJ, PLY
// (ASCII and binary, either byte order), OFF and STL (ASCII and binary). Our own readers,
// so that nothing compiled into libenteron.so carries another licence and a refusal names
// the line (or, in binary data, the byte offset) and what is wrong there; docs/anatomy.md
// has the choice and its measurements. Each returns the polygon soup of the file (polygons
// fanned into triangles), or throws Error(invalid_argument) "<line or byte>: <what>"
// (read_mesh_file adds the file's name). Only the geometry is read: normals, texture
// coordinates, colours, groups and materials are skipped.
#pragma once

#include <string_view>

#include "scene/mesh_soup.h"

namespace enteron::scene {

// Wavefront OBJ: "v x y z" vertices and "f a b c ..." faces (a corner "i", "i/t", "i//n" or
// "i/t/n", counted from 1, or from the end when negative); the other statements of the
// format are skipped, an unknown one is refused.
MeshSoup read_obj(std::string_view text);

// Stanford PLY: a "vertex" element with x, y and z, and a "face" element with a list
// "vertex_indices" (or "vertex_index"); other elements and properties are skipped.
MeshSoup read_ply(std::string_view bytes);

// Object File Format: "OFF" (also COFF, NOFF, STOFF...), the counts, the vertices, then the
// faces "n a b c ...", counted from 0; colours after them are skipped.
MeshSoup read_off(std::string_view text);

// STL, ASCII ("solid ... facet ... endsolid") or binary (an 80-byte header, a triangle
// count, 50 bytes per triangle). STL repeats each vertex in every triangle that has it:
// equal coordinates become one vertex (in the order they first appear), so that the mesh
// is connected.
MeshSoup read_stl(std::string_view bytes);

}  // namespace enteron::scene
