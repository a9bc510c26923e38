// SPDX-License-Identifier: Apache-2.0
#include "collision/mesh_topology.h"

#include <algorithm>
#include <cmath>

namespace enteron::collision {

namespace {

Vec3 load(const std::pmr::vector<float>& values, std::size_t i) {
    return Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
}
void store(std::pmr::vector<float>& values, std::size_t i, const Vec3& v) {
    for (int c = 0; c < 3; ++c) values[3 * i + c] = static_cast<float>(v[c]);
}

// One side of a triangle: the vertices it joins (low first), whether the triangle runs
// from low to high, and which triangle and side it is.
struct HalfEdge {
    uint32_t low, high;
    bool forward;
    uint32_t triangle;
    uint8_t side;  // 0: ab, 1: bc, 2: ca
    bool operator<(const HalfEdge& o) const { return low != o.low ? low < o.low : high < o.high; }
};

}  // namespace

MeshTopology::MeshTopology(const TriangleMesh& mesh, std::pmr::memory_resource* memory)
    : mesh_(mesh),
      face_normals_(memory),
      edge_normals_(memory),
      vertex_normals_(memory),
      usable_(memory) {
    const std::size_t triangles = mesh.triangle_count();
    face_normals_.assign(3 * triangles, 0.0f);
    edge_normals_.assign(9 * triangles, 0.0f);
    vertex_normals_.assign(3 * mesh.vertex_count(), 0.0f);
    usable_.assign(triangles, 0);

    std::vector<Vec3> vertex_sums(mesh.vertex_count(), Vec3::Zero());
    for (std::size_t t = 0; t < triangles; ++t) {
        const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
        const Vec3 cross = (b - a).cross(c - a);
        const double area2 = cross.norm();
        // Tetrahedra from the origin: the divergence theorem's volume.
        report_.signed_volume += a.dot(b.cross(c)) / 6.0;
        if (!(area2 > 1e-300) || !std::isfinite(area2)) {
            report_.degenerate_triangles += 1;
            continue;
        }
        usable_[t] = 1;
        const Vec3 n = cross * (1.0 / area2);
        store(face_normals_, t, n);
        // Angle-weighted vertex normals: each corner adds the face normal times its angle.
        const Vec3 corners[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
            const Vec3 e1 = corners[(k + 1) % 3] - corners[k], e2 = corners[(k + 2) % 3] - corners[k];
            const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
            vertex_sums[mesh.indices[3 * t + k]] += angle * n;
        }
    }
    for (std::size_t v = 0; v < vertex_sums.size(); ++v) store(vertex_normals_, v, vertex_sums[v]);

    // Edges: sort the sides of every usable triangle by the pair of vertices they join.
    std::vector<HalfEdge> sides;
    sides.reserve(3 * triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        if (!usable_[t]) continue;
        for (uint8_t k = 0; k < 3; ++k) {
            const uint32_t from = mesh.indices[3 * t + k], to = mesh.indices[3 * t + (k + 1) % 3];
            sides.push_back({std::min(from, to), std::max(from, to), from < to, static_cast<uint32_t>(t), k});
        }
    }
    std::sort(sides.begin(), sides.end());
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        Vec3 sum = Vec3::Zero();
        std::size_t forward = 0;
        while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high) {
            sum += load(face_normals_, sides[j].triangle);
            forward += sides[j].forward ? 1 : 0;
            ++j;
        }
        const std::size_t count = j - i;
        if (count == 1) report_.open_edges += 1;
        if (count > 2) report_.nonmanifold_edges += 1;
        if (count == 2 && forward != 1) report_.flipped_edges += 1;
        for (std::size_t k = i; k < j; ++k) store(edge_normals_, 3 * sides[k].triangle + sides[k].side, sum);
        i = j;
    }
}

Vec3 MeshTopology::pseudo_normal(std::size_t t, TriangleFeature feature) const {
    switch (feature) {
        case TriangleFeature::corner_a: return load(vertex_normals_, mesh_.indices[3 * t]);
        case TriangleFeature::corner_b: return load(vertex_normals_, mesh_.indices[3 * t + 1]);
        case TriangleFeature::corner_c: return load(vertex_normals_, mesh_.indices[3 * t + 2]);
        case TriangleFeature::edge_ab: return load(edge_normals_, 3 * t);
        case TriangleFeature::edge_bc: return load(edge_normals_, 3 * t + 1);
        case TriangleFeature::edge_ca: return load(edge_normals_, 3 * t + 2);
        case TriangleFeature::face: return load(face_normals_, t);
    }
    return Vec3::Zero();
}

}  // namespace enteron::collision
