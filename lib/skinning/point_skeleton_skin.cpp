#include "skinning/point_skeleton_skin.h"

#include <algorithm>
#include <cmath>

namespace enteron::skinning {

namespace {

Vec3 any_perpendicular(Vec3 t) {
    const Vec3 axis = std::fabs(t.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    return normalized(cross(t, axis), Vec3{0, 0, 1});
}

}  // namespace

PointSkeletonSkin::PointSkeletonSkin(const SkinSettings& settings) : Skin(settings) {
    const double R = settings_.radius, D = settings_.window, h = settings_.skeleton_spacing;
    support2_ = R * R + D * D;
    window_points_ = static_cast<std::size_t>(std::ceil(D / h));
    // Calibration on a straight skeleton, averaged over the two extreme phases of the
    // points (a surface point level with a skeleton point, and half-way between two).
    double sum = 0.0;
    for (double phase : {0.0, 0.5}) {
        double f = 0.0;
        const auto w = long(window_points_) + 1;
        for (long j = -w; j <= w; ++j) {
            const double x = (double(j) + phase) * h;
            const double d2 = R * R + x * x;
            if (d2 < support2_) {
                const double q = 1.0 - d2 / support2_;
                f += h * q * q * q;
            }
        }
        sum += f;
    }
    iso_ = 0.5 * sum;
}

std::size_t PointSkeletonSkin::nearest_from(Vec3 p, std::size_t k) const {
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    k = std::clamp(k, first, last);
    double best = dot(p - skeleton_.position(k), p - skeleton_.position(k));
    for (bool moved = true; moved;) {
        moved = false;
        for (std::size_t candidate : {k - 1, k + 1}) {
            if (candidate < first || candidate > last) continue;
            const Vec3 d = p - skeleton_.position(candidate);
            if (dot(d, d) < best) {
                best = dot(d, d);
                k = candidate;
                moved = true;
                break;
            }
        }
    }
    return k;
}

double PointSkeletonSkin::field(Vec3 p, std::size_t k, Vec3* gradient) const {
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    const double h = skeleton_.spacing();
    // Beyond an end: the field of the straight continuation, made radial about the end
    // point, so the surface closes as a hemisphere of radius R.
    Vec3 centre{}, q = p;
    bool radial = false;
    if (k == first || k == last) {
        const Vec3 end = skeleton_.position(k), t = skeleton_.tangent(k);
        const Vec3 d = p - end;
        const double along = dot(d, t);
        if ((k == first && along < 0.0) || (k == last && along > 0.0)) {
            const Vec3 side = d - along * t;
            // On (or within round-off of) the axis line: any perpendicular will do.
            const Vec3 direction = norm(side) > 1e-9 * norm(d) ? normalized(side, side) : any_perpendicular(t);
            q = end + norm(d) * direction;
            centre = end;
            radial = true;
        }
    }
    double f = 0.0;
    Vec3 g{};
    const std::size_t lo = k - std::min(k, window_points_), hi = std::min(skeleton_.size() - 1, k + window_points_);
    for (std::size_t j = lo; j <= hi; ++j) {
        const Vec3 d = q - skeleton_.position(j);
        const double d2 = dot(d, d);
        if (d2 >= support2_) continue;
        const double s = 1.0 - d2 / support2_;
        f += h * s * s * s;
        g = g + (-6.0 * h * s * s / support2_) * d;
    }
    if (gradient != nullptr) {
        if (radial) {
            // F(p) = G(|p - end|): the gradient is radial with the slope of G.
            const Vec3 r = q - centre;
            const double rn = norm(r);
            const Vec3 dir = normalized(p - centre, Vec3{0, 0, 1});
            *gradient = (rn > 0.0 ? dot(g, r) / rn : 0.0) * dir;
        } else {
            *gradient = g;
        }
    }
    return f;
}

void PointSkeletonSkin::splat() {
    const double R = settings_.radius, v = settings_.voxel_size;
    const double reach = R + 2.0 * v, reach2 = reach * reach;
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    grid_.reset(v, grid_.block_count() + 64);
    for (std::size_t k = first; k <= last; ++k) {
        const Vec3 c = skeleton_.position(k);
        const auto lo_x = int32_t(std::ceil((c.x - reach) / v)), hi_x = int32_t(std::floor((c.x + reach) / v));
        const auto lo_y = int32_t(std::ceil((c.y - reach) / v)), hi_y = int32_t(std::floor((c.y + reach) / v));
        const auto lo_z = int32_t(std::ceil((c.z - reach) / v)), hi_z = int32_t(std::floor((c.z + reach) / v));
        auto block_of = [](int32_t i) { return i >= 0 ? i / kBlockSize : -((-i + kBlockSize - 1) / kBlockSize); };
        for (int32_t bz = block_of(lo_z); bz <= block_of(hi_z); ++bz)
            for (int32_t by = block_of(lo_y); by <= block_of(hi_y); ++by)
                for (int32_t bx = block_of(lo_x); bx <= block_of(hi_x); ++bx) {
                    VoxelBlock* block = nullptr;
                    const int32_t x0 = std::max(lo_x, bx * kBlockSize), x1 = std::min(hi_x, bx * kBlockSize + kBlockSize - 1);
                    const int32_t y0 = std::max(lo_y, by * kBlockSize), y1 = std::min(hi_y, by * kBlockSize + kBlockSize - 1);
                    const int32_t z0 = std::max(lo_z, bz * kBlockSize), z1 = std::min(hi_z, bz * kBlockSize + kBlockSize - 1);
                    for (int32_t z = z0; z <= z1; ++z)
                        for (int32_t y = y0; y <= y1; ++y) {
                            const double dz = z * v - c.z, dy = y * v - c.y;
                            const double rest = dz * dz + dy * dy;
                            if (rest >= reach2) continue;
                            for (int32_t x = x0; x <= x1; ++x) {
                                const double dx = x * v - c.x;
                                const double d2 = rest + dx * dx;
                                if (d2 >= reach2) continue;
                                if (block == nullptr) block = &grid_.touch(bx, by, bz);
                                VoxelCorner& corner = block->corners[SparseVoxelGrid::local_index(
                                    x - bx * kBlockSize, y - by * kBlockSize, z - bz * kBlockSize)];
                                if (corner.nearest < 0 || d2 < double(corner.distance2)) {
                                    corner.nearest = int32_t(k);
                                    corner.distance2 = float(d2);
                                }
                            }
                        }
                }
    }
    for (std::size_t b = 0; b < grid_.block_count(); ++b) {
        VoxelBlock& block = grid_.block(b);
        for (int z = 0; z < kBlockSize; ++z)
            for (int y = 0; y < kBlockSize; ++y)
                for (int x = 0; x < kBlockSize; ++x) {
                    VoxelCorner& corner = block.corners[SparseVoxelGrid::local_index(x, y, z)];
                    if (corner.nearest < 0) continue;
                    const Vec3 p{(block.coordinates[0] * kBlockSize + x) * v, (block.coordinates[1] * kBlockSize + y) * v,
                                 (block.coordinates[2] * kBlockSize + z) * v};
                    corner.field = float(field(p, std::size_t(corner.nearest), nullptr));
                }
    }
}

void PointSkeletonSkin::rebuild() {
    const double R = settings_.radius, D = settings_.window, v = settings_.voxel_size;
    const double h = settings_.skeleton_spacing;
    skeleton_.build(table_, points_.data(), axis_count(), h, D + 2.0 * h);
    splat();
    cubes_.extract(grid_, iso_, mesh_, seeds_);

    const double length = skeleton_.length();
    const std::size_t first = skeleton_.phantoms(), last = first + skeleton_.intervals();
    for (std::size_t i = 0; i < seeds_.size(); ++i) {
        Vec3 p{mesh_.positions[3 * i], mesh_.positions[3 * i + 1], mesh_.positions[3 * i + 2]};
        std::size_t k = nearest_from(p, std::size_t(seeds_[i]));
        Vec3 g{};
        // Newton steps along the gradient onto the iso-surface, each at most a voxel.
        for (int iteration = 0; iteration < 3; ++iteration) {
            const double f = field(p, k, &g);
            const double g2 = dot(g, g);
            if (!(g2 > 0.0)) break;
            Vec3 step = ((f - iso_) / g2) * g;
            const double length_step = norm(step);
            if (length_step > v) step = (v / length_step) * step;
            p = p - step;
            k = nearest_from(p, k);
            if (length_step < 1e-6 * R) break;
        }
        field(p, k, &g);
        const Vec3 n = normalized(-1.0 * g, Vec3{0, 0, 1});
        // u: project p on the axis polyline next to its nearest skeleton point.
        double s = skeleton_.arc_length(k);
        double best = 1e300;
        for (std::size_t a : {k - 1, k}) {
            if (a < first || a + 1 > last) continue;
            const Vec3 d = skeleton_.position(a + 1) - skeleton_.position(a);
            const double w = std::clamp(dot(p - skeleton_.position(a), d) / std::max(dot(d, d), 1e-300), 0.0, 1.0);
            const Vec3 foot = skeleton_.position(a) + w * d;
            const double distance2 = dot(p - foot, p - foot);
            if (distance2 < best) {
                best = distance2;
                s = skeleton_.arc_length(a) + w * skeleton_.spacing();
            }
        }
        mesh_.positions[3 * i] = float(p.x);
        mesh_.positions[3 * i + 1] = float(p.y);
        mesh_.positions[3 * i + 2] = float(p.z);
        mesh_.normals[3 * i] = float(n.x);
        mesh_.normals[3 * i + 1] = float(n.y);
        mesh_.normals[3 * i + 2] = float(n.z);
        mesh_.u[i] = float(length > 0.0 ? std::clamp(s / length, 0.0, 1.0) : 0.0);
    }
}

}  // namespace enteron::skinning
