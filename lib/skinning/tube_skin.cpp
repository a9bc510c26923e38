#include "skinning/tube_skin.h"

#include <cmath>

namespace enteron::skinning {

void TubeSkin::rebuild() {
    const double R = settings_.radius;
    const std::size_t S = settings_.segments;
    rings_.build(table_, points_.data(), axis_count(), settings_.ring_spacing, 0.0);
    const std::size_t n = rings_.size();
    frames_.build(&rings_.position(0), &rings_.tangent(0), n);
    grid_.layout(n, S, settings_.cap_rings, mesh_.indices);
    mesh_.resize_vertices(grid_.vertex_count());
    const double length = rings_.length();
    for (std::size_t row = 0; row < grid_.rows(); ++row) {
        // Body rows sit on their ring; cap rows on a hemisphere around an end point.
        std::size_t k = 0;
        if (row > grid_.cap_rings()) k = std::min(row - grid_.cap_rings() - 1, n - 1);
        const double phi = grid_.cap_angle(row);
        const double along = std::sin(phi), across = std::cos(phi);  // once per row, not per vertex
        const Vec3 centre = rings_.position(k), t = rings_.tangent(k);
        const Vec3 nrm = frames_.normal(k), bin = frames_.binormal(k);
        const float u = float(length > 0.0 ? rings_.arc_length(k) / length : 0.0);
        const bool pole = row == 0 || row + 1 == grid_.rows();
        const std::size_t count = pole ? 1 : S;
        for (std::size_t j = 0; j < count; ++j) {
            Vec3 direction = pole ? (row == 0 ? -1.0 * t : t)
                                  : across * (grid_.cosine(j) * nrm + grid_.sine(j) * bin) + along * t;
            const std::size_t v = grid_.vertex(row, j);
            store_vec3(mesh_.positions, v, centre + R * direction);
            store_vec3(mesh_.normals, v, direction);
            mesh_.u[v] = u;
        }
    }
}

}  // namespace enteron::skinning
