// SPDX-License-Identifier: Apache-2.0
#include "skinning/tube_skin.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skinning/fold_over_limit.h"

namespace enteron::skinning {

void TubeSkin::rebuild() {
    const std::size_t S = settings_.segments;
    rings_.build(table_, points_.data(), axis_count(), ring_intervals(table_.total_length()), 0.0,
                 AxisSamples::Curvature::skip);
    const std::size_t n = rings_.size();
    frames_.build(&rings_.position(0), &rings_.tangent(0), n);
    if (grid_.layout(n, S, settings_.cap_rings, mesh_.indices)) {
        topology_changed_ = true;
        mesh_.resize_vertices(grid_.vertex_count());
        grid_.around(mesh_.v.data());
    }
    for (std::size_t row = 0; row < grid_.rows(); ++row) {
        // Body rows sit on their ring; cap rows on a hemisphere around an end point.
        std::size_t k = 0;
        if (row > grid_.cap_rings()) k = std::min(row - grid_.cap_rings() - 1, n - 1);
        const double phi = grid_.cap_angle(row);
        const double along = std::sin(phi), across = std::cos(phi);  // once per row, not per vertex
        const Vec3 centre = rings_.position(k), t = rings_.tangent(k);
        // The ring's own radius (the profile's at its place; caps take their end ring's).
        const double R = settings_.radius_along.at_parameter(rings_.parameter(k), settings_.radius);
        const Vec3 nrm = frames_.normal(k), bin = frames_.binormal(k);
        const auto u = float(rings_.fraction(k));
        const bool pole = row == 0 || row + 1 == grid_.rows();
        const std::size_t count = pole ? 1 : S;
        // Body rings stop short of their neighbours' planes (no fold-over, fold_over_limit.h).
        const bool body = phi == 0.0;
        const Vec3* previous = body && k > 0 ? &rings_.position(k - 1) : nullptr;
        const Vec3* next = body && k + 1 < n ? &rings_.position(k + 1) : nullptr;
        for (std::size_t j = 0; j < count; ++j) {
            // The outward direction at (phi, angle j), and its derivative in phi: the tangent
            // along the meridian, towards the last pole (the axis tangent on body rows).
            const Vec3 radial = grid_.cosine(j) * nrm + grid_.sine(j) * bin;
            const Vec3 direction = pole ? (row == 0 ? -1.0 * t : t) : across * radial + along * t;
            const Vec3 tangent = across * t - along * radial;
            const std::size_t v = grid_.vertex(row, j);
            double limit = std::numeric_limits<double>::infinity();
            for (const Vec3* neighbour : {previous, next})
                if (neighbour != nullptr) limit = std::min(limit, fold_over_limit(centre, radial, *neighbour));
            store_vec3(mesh_.positions, v, centre + below_fold_over_limit(R, limit) * direction);
            store_vec3(mesh_.normals, v, direction);
            store_vec3(mesh_.tangents, v, tangent);
            mesh_.u[v] = u;
        }
    }
}

}  // namespace enteron::skinning
