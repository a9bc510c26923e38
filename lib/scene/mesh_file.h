// Reads an organ's triangle mesh from a file: OBJ or PLY (also OFF and STL), through CGAL's
// polygon soup readers (Debian's libcgal-dev, header-only: nothing is added to what
// libenteron.so loads; docs/anatomy.md has the measurements). Polygons with more than three
// corners become fans of triangles.
#pragma once

#include <string>

#include "base/error.h"
#include "collision/triangle_mesh.h"

namespace enteron::scene {

// The mesh in `path` with every coordinate multiplied by `scale` (a CT mesh in millimetres:
// 0.001). `name` is the scene's name for it ("environment[2].file"). Throws Error(code) naming
// the file: missing, unreadable, an unknown extension, not a mesh, or no triangle in it.
collision::TriangleMesh read_mesh_file(const std::string& path, double scale, const std::string& name,
                                       ErrorCode code);

}  // namespace enteron::scene
