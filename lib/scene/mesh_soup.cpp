// SPDX-License-Identifier: Apache-2.0
#include "scene/mesh_soup.h"

#include <algorithm>

#include "base/error.h"

namespace enteron::scene {

std::string MeshPlace::describe() const {
    return (unit == Unit::line ? "line " : "byte ") + std::to_string(at);
}

void refuse_mesh(const MeshPlace& place, const std::string& why) {
    throw Error(ErrorCode::invalid_argument, place.describe() + ": " + why);
}

void MeshSoup::reserve(std::size_t vertices, std::size_t triangles) {
    mesh_.vertices.reserve(3 * std::min(vertices, collision::kMaxMeshTriangles));
    mesh_.indices.reserve(3 * std::min(triangles, collision::kMaxMeshTriangles));
}

void MeshSoup::add_polygon(const uint32_t* corners, std::size_t count, const MeshPlace& place) {
    if (count < 3)
        refuse_mesh(place, "a face of " + std::to_string(count) + (count == 1 ? " corner" : " corners") +
                               " (a face needs at least 3)");
    if (mesh_.triangle_count() + (count - 2) > collision::kMaxMeshTriangles)
        refuse_mesh(place, "more than the " + std::to_string(collision::kMaxMeshTriangles) +
                               " triangles a mesh obstacle may have");
    for (std::size_t k = 0; k < count; ++k)
        if (corners[k] > largest_corner_) {
            largest_corner_ = corners[k];
            largest_corner_place_ = place;
        }
    for (std::size_t k = 2; k < count; ++k)
        mesh_.indices.insert(mesh_.indices.end(), {corners[0], corners[k - 1], corners[k]});
}

collision::TriangleMesh MeshSoup::finish(double scale) {
    if (mesh_.indices.empty()) throw Error(ErrorCode::invalid_argument, "holds no triangle");
    if (largest_corner_ >= static_cast<int64_t>(vertex_count()))
        refuse_mesh(largest_corner_place_, "a face refers to vertex " +
                                               std::to_string(largest_corner_ + first_index_) + ", but the file has " +
                                               std::to_string(vertex_count()) + " vertices (numbered from " +
                                               std::to_string(first_index_) + ")");
    for (double& coordinate : mesh_.vertices) coordinate *= scale;
    return std::move(mesh_);
}

}  // namespace enteron::scene
