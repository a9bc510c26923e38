// SPDX-License-Identifier: Apache-2.0
#include "skinning/skin_metrics.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "base/geometry.h"
#include "spline/catmull_rom.h"

namespace enteron::skinning {

namespace {

Vec3 vertex_at(const std::vector<float>& buffer, std::size_t i) {
    return {buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]};
}

// Dense samples of the axis in a uniform grid, to find the axis points near a vertex.
class AxisPointGrid {
public:
    AxisPointGrid(const spline::ArcLengthTable& table, const double* points, std::size_t count, double spacing,
                  double cell)
        : cell_(cell) {
        const double length = table.total_length();
        const auto n = std::max<std::size_t>(2, std::size_t(std::ceil(length / spacing)) + 1);
        for (std::size_t i = 0; i < n; ++i) {
            const double s = length * double(i) / double(n - 1);
            const Vec3 p =
                spline::evaluate(points, spline::weights_at(count, table.parameter_at(s), spline::Derivative::value));
            positions_.push_back(p);
            arc_.push_back(s);
            cells_[key(p)].push_back(uint32_t(i));
        }
    }

    // Smallest distance from p to an axis sample farther than `window` in arc length from s.
    double nearest_other_fold(Vec3 p, double s, double window) const {
        double best = 1e300;
        const long cx = long(std::floor(p.x() / cell_)), cy = long(std::floor(p.y() / cell_)),
                   cz = long(std::floor(p.z() / cell_));
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(pack(cx + dx, cy + dy, cz + dz));
                    if (it == cells_.end()) continue;
                    for (uint32_t i : it->second) {
                        if (std::fabs(arc_[i] - s) <= window) continue;
                        best = std::min(best, (positions_[i] - p).norm());
                    }
                }
        return best;
    }

private:
    static uint64_t pack(long x, long y, long z) {
        const auto m = [](long v) { return uint64_t(v + (1L << 20)) & 0x1fffffULL; };
        return (m(x) << 42) | (m(y) << 21) | m(z);
    }
    uint64_t key(Vec3 p) const {
        return pack(long(std::floor(p.x() / cell_)), long(std::floor(p.y() / cell_)), long(std::floor(p.z() / cell_)));
    }

    double cell_;
    std::vector<Vec3> positions_;
    std::vector<double> arc_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// The axis as a dense polyline (spacing R / 16: it departs from the spline by about
// (R / 16)^2 / (8 rho), 2e-4 R at a bend of radius 3 R), for the distance of a point to the
// axis near a given arc length.
class AxisPolyline {
public:
    AxisPolyline(const spline::ArcLengthTable& table, const double* points, std::size_t count, double spacing) {
        const double length = table.total_length();
        const auto n = std::max<std::size_t>(2, std::size_t(std::ceil(length / spacing)) + 1);
        step_ = length / double(n - 1);
        for (std::size_t i = 0; i < n; ++i) {
            positions_.push_back(spline::evaluate(
                points, spline::weights_at(count, table.parameter_at(step_ * double(i)), spline::Derivative::value)));
        }
    }

    // Distance from p to the axis, searching downhill from arc length s.
    double distance(Vec3 p, double s) const {
        const std::size_t last = positions_.size() - 1;
        auto d2 = [&](std::size_t i) { return (p - positions_[i]).squaredNorm(); };
        std::size_t i = std::min(last, std::size_t(std::max(0.0, std::round(s / step_))));
        while (i > 0 && d2(i - 1) < d2(i)) --i;
        while (i < last && d2(i + 1) < d2(i)) ++i;
        double best = d2(i);
        for (std::size_t a : {i - 1, i}) {  // the segments on either side of the nearest sample
            if (i == 0 && a != i) continue;
            if (a + 1 > last) continue;
            const Vec3 d = positions_[a + 1] - positions_[a];
            const double w = std::clamp((p - positions_[a]).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
            const Vec3 foot = positions_[a] + w * d;
            best = std::min(best, (p - foot).squaredNorm());
        }
        return std::sqrt(best);
    }

private:
    double step_ = 0.0;
    std::vector<Vec3> positions_;
};

}  // namespace

SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius) {
    SkinMetrics m;
    const double R = radius;
    const double length = table.total_length();
    m.axis_length = length;
    m.vertices = mesh.vertex_count();
    m.triangles = mesh.triangle_count();
    if (m.vertices == 0) return m;

    // Per vertex: radius error, normal deviation, blending; keep the analytic directions.
    const AxisPointGrid grid(table, points_xyz, count, R / 8.0, 2.0 * R);
    std::vector<Vec3> radial(m.vertices);
    double sum_radius2 = 0.0, sum_normal2 = 0.0;
    for (std::size_t i = 0; i < m.vertices; ++i) {
        const double s = double(mesh.u[i]) * length;
        const Vec3 a =
            spline::evaluate(points_xyz, spline::weights_at(count, table.parameter_at(s), spline::Derivative::value));
        const Vec3 v = vertex_at(mesh.positions, i);
        const Vec3 r = v - a;
        const double distance = r.norm();
        radial[i] = normalized_or(r, Vec3{0, 0, 0});
        const double error = std::fabs(distance - R) / R;
        sum_radius2 += error * error;
        m.radius_error_max = std::max(m.radius_error_max, error);
        const Vec3 n = normalized_or(vertex_at(mesh.normals, i), Vec3{0, 0, 0});
        const double angle = std::acos(std::clamp(n.dot(radial[i]), -1.0, 1.0));
        sum_normal2 += angle * angle;
        m.normal_deviation_max = std::max(m.normal_deviation_max, angle);
        if (grid.nearest_other_fold(v, s, kNeighbourWindow * R) < kBlendBand * R) ++m.blended_vertices;
    }
    m.radius_error_rms = std::sqrt(sum_radius2 / double(m.vertices));
    m.normal_deviation_rms = std::sqrt(sum_normal2 / double(m.vertices));

    // Per triangle: facet error, orientation against the axis, volume, edges.
    const AxisPolyline polyline(table, points_xyz, count, R / 16.0);
    double sum_facet2 = 0.0;
    std::vector<uint64_t> edges;
    edges.reserve(3 * m.triangles);
    const Vec3 origin = vertex_at(mesh.positions, 0);
    double volume6 = 0.0;
    for (std::size_t t = 0; t < m.triangles; ++t) {
        const uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1], i2 = mesh.indices[3 * t + 2];
        const Vec3 p0 = vertex_at(mesh.positions, i0) - origin, p1 = vertex_at(mesh.positions, i1) - origin,
                   p2 = vertex_at(mesh.positions, i2) - origin;
        const Vec3 face = (p1 - p0).cross(p2 - p0);
        {
            // The centroid's distance to the axis, near its corners' axis points (all three
            // when they lie on different folds).
            const Vec3 centroid = (1.0 / 3.0) * (p0 + p1 + p2) + origin;
            const double u0 = mesh.u[i0], u1 = mesh.u[i1], u2 = mesh.u[i2];
            const double spread = (std::max({u0, u1, u2}) - std::min({u0, u1, u2})) * length;
            double distance = polyline.distance(centroid, (u0 + u1 + u2) / 3.0 * length);
            if (spread > kNeighbourWindow * R)
                for (double u : {u0, u1, u2}) distance = std::min(distance, polyline.distance(centroid, u * length));
            const double error = std::fabs(distance - R) / R;
            sum_facet2 += error * error;
            m.facet_error_max = std::max(m.facet_error_max, error);
        }
        volume6 += p0.dot(p1.cross(p2));
        // Facing the axis as seen from each corner's own axis point. (Not the sum of the
        // three radial directions: where two folds touch, marching cubes joins them with
        // triangles whose corners belong to different folds, radial directions nearly
        // opposite, and a correctly wound triangle there can face against their sum.)
        if (face.dot(radial[i0]) < 0.0 && face.dot(radial[i1]) < 0.0 && face.dot(radial[i2]) < 0.0)
            ++m.inverted_triangles;
        const uint32_t corners[3] = {i0, i1, i2};
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = corners[e], b = corners[(e + 1) % 3];
            edges.push_back((uint64_t(std::min(a, b)) << 32) | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) ++m.open_edges;
        if (j - i > 2) ++m.nonmanifold_edges;
        i = j;
    }
    m.facet_error_rms = std::sqrt(sum_facet2 / double(m.triangles));
    m.watertight = m.triangles > 0 && m.open_edges == 0 && m.nonmanifold_edges == 0;
    m.volume = volume6 / 6.0;
    const double ideal = kPi * R * R * length;
    m.volume_error = ideal > 0.0 ? (m.volume - ideal) / ideal : 0.0;
    return m;
}

}  // namespace enteron::skinning
