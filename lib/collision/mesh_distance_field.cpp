// SPDX-License-Identifier: Apache-2.0
#include "collision/mesh_distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/error.h"
#include "collision/triangle_bvh.h"

namespace enteron::collision {

namespace {

constexpr std::size_t kBlock = 4;  // voxels per side of a block sharing one coarse estimate

std::string metres(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

MeshDistanceField::MeshDistanceField(const TriangleMesh& mesh, const DistanceFieldSettings& settings,
                                     std::pmr::memory_resource* memory)
    : mesh_(mesh, memory),
      topology_(mesh_, memory),
      settings_(settings),
      voxel_(settings.voxel_size),
      inverse_voxel_(1.0 / settings.voxel_size),
      distances_(memory),
      triangles_(memory) {
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 high = -low;
    for (std::size_t v = 0; v < mesh_.vertex_count(); ++v) {
        low = low.cwiseMin(mesh_.vertex(v));
        high = high.cwiseMax(mesh_.vertex(v));
    }
    low_ = low.array() - settings.band;
    const Vec3 cells = ((high.array() + settings.band - low_.array()) * inverse_voxel_).ceil();
    // Counted in double first: a far vertex must not overflow the count.
    const double voxels = (cells.x() + 1.0) * (cells.y() + 1.0) * (cells.z() + 1.0);
    if (!(voxels <= double(kMaxFieldVoxels))) {
        const double extent = (high - low).maxCoeff() + 2.0 * settings.band;
        const double fitting = voxel_ * std::cbrt(voxels / double(kMaxFieldVoxels)) * 1.01;
        throw Error(ErrorCode::invalid_argument,
                    "a voxel size of " + metres(voxel_) + " m over this mesh (" + metres(extent) + " m across) needs " +
                        metres(voxels) + " voxels, more than the " + std::to_string(kMaxFieldVoxels) +
                        " a distance field may have: give a voxel size of at least " + metres(fitting) + " m");
    }
    nx_ = std::size_t(cells.x()) + 1;
    ny_ = std::size_t(cells.y()) + 1;
    nz_ = std::size_t(cells.z()) + 1;
    high_ = voxel_position(nx_ - 1, ny_ - 1, nz_ - 1);
    distances_.assign(nx_ * ny_ * nz_, 0.0f);
    triangles_.assign(distances_.size(), 0);
    build();
}

void MeshDistanceField::build() {
    const TriangleBvh bvh(mesh_, topology_);
    // The signed distance and its direction at p from the closest point of the mesh.
    struct Exact {
        double distance;
        Vec3 normal;
        uint32_t triangle;
    };
    const auto exact = [&](const Vec3& p, double bound) {
        const TriangleBvh::Closest c = bvh.closest(p, bound);
        const Vec3 away = p - c.point.point;
        const Vec3 pseudo = topology_.pseudo_normal(c.triangle, c.point.feature);
        const double sign = away.dot(pseudo) < 0.0 ? -1.0 : 1.0;
        const Vec3 normal = c.distance > 1e-12 ? Vec3(sign * away / c.distance) : normalized_or(pseudo, Vec3::UnitZ());
        return Exact{sign * c.distance, normal, c.triangle};
    };
    const double half_diagonal = 0.5 * std::sqrt(3.0) * double(kBlock - 1) * voxel_;
    for (std::size_t bz = 0; bz < nz_; bz += kBlock)
        for (std::size_t by = 0; by < ny_; by += kBlock)
            for (std::size_t bx = 0; bx < nx_; bx += kBlock) {
                const std::size_t ex = std::min(bx + kBlock, nx_), ey = std::min(by + kBlock, ny_),
                                  ez = std::min(bz + kBlock, nz_);
                const Vec3 centre = 0.5 * (voxel_position(bx, by, bz) + voxel_position(ex - 1, ey - 1, ez - 1));
                const Exact middle = exact(centre, std::numeric_limits<double>::infinity());
                const bool near = std::fabs(middle.distance) < settings_.band + half_diagonal;
                for (std::size_t z = bz; z < ez; ++z)
                    for (std::size_t y = by; y < ey; ++y)
                        for (std::size_t x = bx; x < ex; ++x) {
                            const Vec3 p = voxel_position(x, y, z);
                            const std::size_t i = index(x, y, z);
                            if (!near) {
                                distances_[i] = float(middle.distance + middle.normal.dot(p - centre));
                                triangles_[i] = int32_t(middle.triangle);
                                continue;
                            }
                            // The closest point is no farther than the centre's plus the way there.
                            const Exact e = exact(p, std::fabs(middle.distance) + (p - centre).norm());
                            distances_[i] = float(e.distance);
                            triangles_[i] = int32_t(e.triangle);
                        }
            }
    outside_solid_ = distances_.front() < 0.0f;
}

MeshDistanceField::Cell MeshDistanceField::interpolate(const Vec3& p) const {
    const Vec3 u = (p - low_) * inverse_voxel_;
    const auto cell = [](double value, std::size_t count) {
        return std::size_t(std::clamp(std::floor(value), 0.0, double(count - 2)));
    };
    const std::size_t x = cell(u.x(), nx_), y = cell(u.y(), ny_), z = cell(u.z(), nz_);
    const double fx = u.x() - double(x), fy = u.y() - double(y), fz = u.z() - double(z);
    const std::size_t base = index(x, y, z), dy = nx_, dz = nx_ * ny_;
    const float* d = distances_.data() + base;
    const double c000 = d[0], c100 = d[1], c010 = d[dy], c110 = d[dy + 1];
    const double c001 = d[dz], c101 = d[dz + 1], c011 = d[dz + dy], c111 = d[dz + dy + 1];
    // Along x, then y, then z; the gradient is the derivative of the same polynomial.
    const double c00 = c000 + fx * (c100 - c000), c10 = c010 + fx * (c110 - c010);
    const double c01 = c001 + fx * (c101 - c001), c11 = c011 + fx * (c111 - c011);
    const double c0 = c00 + fy * (c10 - c00), c1 = c01 + fy * (c11 - c01);
    Cell out;
    out.base = base;
    out.distance = c0 + fz * (c1 - c0);
    const double gx0 = (1.0 - fy) * (c100 - c000) + fy * (c110 - c010);
    const double gx1 = (1.0 - fy) * (c101 - c001) + fy * (c111 - c011);
    out.gradient = Vec3((1.0 - fz) * gx0 + fz * gx1, (1.0 - fz) * ((1.0 - fx) * (c010 - c000) + fx * (c110 - c100)) +
                                                          fz * ((1.0 - fx) * (c011 - c001) + fx * (c111 - c101)),
                        c1 - c0) *
                   inverse_voxel_;
    return out;
}

MeshDistanceField::Sample MeshDistanceField::refined(const Vec3& p, const Cell& cell) const {
    const std::size_t dy = nx_, dz = nx_ * ny_;
    const std::size_t corners[8] = {0, 1, dy, dy + 1, dz, dz + 1, dz + dy, dz + dy + 1};
    int32_t tried[8];
    int count = 0;
    double best = std::numeric_limits<double>::infinity();
    Sample out{cell.distance, normalized_or(cell.gradient, Vec3::UnitZ())};
    for (std::size_t corner : corners) {
        const int32_t t = triangles_[cell.base + corner];
        if (std::find(tried, tried + count, t) != tried + count) continue;
        tried[count++] = t;
        const TrianglePoint q = closest_point_on_triangle(p, mesh_.corner(t, 0), mesh_.corner(t, 1), mesh_.corner(t, 2));
        const Vec3 away = p - q.point;
        const double distance = away.norm();
        if (!(distance < best)) continue;
        best = distance;
        const Vec3 pseudo = topology_.pseudo_normal(std::size_t(t), q.feature);
        const double sign = away.dot(pseudo) < 0.0 ? -1.0 : 1.0;
        out.distance = sign * distance;
        out.normal = distance > 1e-12 ? Vec3(sign * away / distance) : normalized_or(pseudo, Vec3::UnitZ());
    }
    return out;
}

MeshDistanceField::Sample MeshDistanceField::sample_in_grid(const Vec3& p, const Cell& cell) const {
    if (settings_.refine) return refined(p, cell);
    return {cell.distance, normalized_or(cell.gradient, Vec3::UnitZ())};
}

bool MeshDistanceField::sample_within(const Vec3& p, double reach, Sample* out) const {
    const bool inside_grid = (p.array() >= low_.array()).all() && (p.array() <= high_.array()).all();
    if (inside_grid) {
        const Cell cell = interpolate(p);
        // Trilinear interpolation of a 1-Lipschitz field is off by at most sqrt(3) voxels:
        // farther than reach plus two cannot touch.
        if (cell.distance >= reach + 2.0 * voxel_) return false;
        *out = sample_in_grid(p, cell);
        return out->distance < reach;
    }
    // Beyond the grid, the bowel's side is at least `band` away; a cavity's solid goes on.
    if (!outside_solid_) return false;
    const Vec3 nearest = p.cwiseMax(low_).cwiseMin(high_);
    const Cell cell = interpolate(nearest);
    *out = sample_in_grid(nearest, cell);
    out->distance -= (p - nearest).norm();
    return out->distance < reach;
}

double MeshDistanceField::distance(const Vec3& p) const {
    const Vec3 nearest = p.cwiseMax(low_).cwiseMin(high_);
    const Cell cell = interpolate(nearest);
    const double d = sample_in_grid(nearest, cell).distance;
    const double beyond = (p - nearest).norm();
    return d < 0.0 ? d - beyond : d + beyond;
}

std::size_t MeshDistanceField::memory_bytes() const {
    return distances_.size() * (sizeof(float) + sizeof(int32_t)) + mesh_.vertices.size() * sizeof(double) +
           mesh_.indices.size() * sizeof(uint32_t) + (3 + 9) * sizeof(float) * mesh_.triangle_count() +
           3 * sizeof(float) * mesh_.vertex_count();
}

}  // namespace enteron::collision
