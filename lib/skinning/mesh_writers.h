// SPDX-License-Identifier: Apache-2.0
// Exports a skin mesh for people and other tools: Wavefront OBJ (positions, normals, u as
// a 1-D texture coordinate) and binary little-endian PLY (float x y z nx ny nz u, uint32
// triangle lists). Both keep the vertex order and the outward winding.
#pragma once

#include <ostream>

#include "skinning/mesh.h"

namespace enteron::skinning {

// Writes `mesh` as OBJ text. Returns false if the stream failed.
bool write_obj(const Mesh& mesh, std::ostream& out);

// Writes `mesh` as binary little-endian PLY. Returns false if the stream failed.
bool write_ply(const Mesh& mesh, std::ostream& out);

}  // namespace enteron::skinning
