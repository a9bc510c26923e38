// SPDX-License-Identifier: Apache-2.0
#include "skinning/skin_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "base/geometry.h"
#include "collision/closest_point_on_triangle.h"
#include "skinning/contact_profile.h"
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

    // Smallest distance from p to an axis sample farther than `window` in arc length from s
    // (and that sample's arc length in *arc, when given).
    double nearest_other_fold(Vec3 p, double s, double window, double* arc = nullptr) const {
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
                        const double distance = (positions_[i] - p).norm();
                        if (distance < best && arc != nullptr) *arc = arc_[i];
                        best = std::min(best, distance);
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

    // The largest curvature of the axis within `reach` (m) of arc length s, 1/m (second
    // differences of the samples).
    double largest_curvature(double s, double reach) const {
        if (curvature_.empty()) {
            curvature_.assign(positions_.size(), 0.0);
            for (std::size_t i = 1; i + 1 < positions_.size(); ++i)
                curvature_[i] = (positions_[i + 1] - 2.0 * positions_[i] + positions_[i - 1]).norm() / (step_ * step_);
        }
        const double last = double(positions_.size() - 1);
        const auto lo = std::size_t(std::clamp(std::floor((s - reach) / step_), 0.0, last));
        const auto hi = std::size_t(std::clamp(std::ceil((s + reach) / step_), 0.0, last));
        double largest = 0.0;
        for (std::size_t i = lo; i <= hi; ++i) largest = std::max(largest, curvature_[i]);
        return largest;
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
    mutable std::vector<double> curvature_;  // made on first use
};

// The triangles of a mesh filed in the cells their bounding boxes overlap, with the
// pseudo-normals that sign a distance to them (Baerentzen and Aanaes 2005: the face's
// normal, the sum of an edge's two faces', the angle-weighted sum around a corner).
class TriangleGrid {
public:
    TriangleGrid(const Mesh& mesh, double cell) : mesh_(mesh), cell_(cell) {
        const std::size_t triangles = mesh.triangle_count(), vertices = mesh.vertex_count();
        face_normals_.resize(triangles);
        vertex_normals_.assign(vertices, Vec3::Zero());
        std::vector<std::pair<uint64_t, uint32_t>> entries;
        std::vector<uint32_t> corner_count(vertices + 1, 0);
        for (std::size_t t = 0; t < triangles; ++t) {
            const Vec3 p[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
            face_normals_[t] = normalized_or((p[1] - p[0]).cross(p[2] - p[0]), Vec3::Zero());
            for (int c = 0; c < 3; ++c) {
                const Vec3 e1 = p[(c + 1) % 3] - p[c], e2 = p[(c + 2) % 3] - p[c];
                const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
                vertex_normals_[mesh.indices[3 * t + std::size_t(c)]] += angle * face_normals_[t];
                edges_.push_back({edge_key(t, c), uint32_t(t)});
                ++corner_count[mesh.indices[3 * t + std::size_t(c)] + 1];
            }
            const std::array<long, 3> lo = cell_of(p[0].cwiseMin(p[1]).cwiseMin(p[2])),
                                      hi = cell_of(p[0].cwiseMax(p[1]).cwiseMax(p[2]));
            for (long z = lo[2]; z <= hi[2]; ++z)
                for (long y = lo[1]; y <= hi[1]; ++y)
                    for (long x = lo[0]; x <= hi[0]; ++x) entries.push_back({key({x, y, z}), uint32_t(t)});
        }
        std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) { return a.key < b.key; });
        // The triangles around each vertex (compressed rows).
        for (std::size_t v = 0; v < vertices; ++v) corner_count[v + 1] += corner_count[v];
        corner_begin_ = corner_count;
        corner_triangles_.resize(3 * triangles);
        for (std::size_t t = 0; t < triangles; ++t)
            for (int c = 0; c < 3; ++c) corner_triangles_[corner_count[mesh.indices[3 * t + std::size_t(c)]]++] = uint32_t(t);
        std::sort(entries.begin(), entries.end());
        triangles_.resize(entries.size());
        for (std::size_t i = 0; i < entries.size();) {
            std::size_t j = i;
            while (j < entries.size() && entries[j].first == entries[i].first) triangles_[j] = entries[j].second, ++j;
            cells_.emplace(entries[i].first, std::make_pair(uint32_t(i), uint32_t(j)));
            i = j;
        }
    }

    struct Closest {
        bool found = false;
        double distance = 0.0;  // m, signed: < 0 inside (behind the pseudo-normal)
        bool on_edge = false;   // on the border of the admitted triangles: the sign means nothing there
    };
    // The nearest of the triangles accept(t) admits within `reach` of p, searching shells of
    // cells outwards until no nearer triangle can remain; its signed distance.
    template <class Accept>
    Closest closest(const Vec3& p, double reach, Accept accept) const {
        Closest best;
        double best2 = reach * reach;
        std::size_t best_triangle = 0;
        collision::TrianglePoint best_point{Vec3::Zero(), collision::TriangleFeature::face};
        const std::array<long, 3> c = cell_of(p);
        for (long k = 0; double(k - 1) * cell_ < std::sqrt(best2); ++k) {
            for (long dz = -k; dz <= k; ++dz)
                for (long dy = -k; dy <= k; ++dy)
                    for (long dx = -k; dx <= k; ++dx) {
                        if (std::max({std::labs(dx), std::labs(dy), std::labs(dz)}) != k) continue;  // the shell only
                        const auto cell = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
                        if (cell == cells_.end()) continue;
                        for (uint32_t e = cell->second.first; e < cell->second.second; ++e) {
                            const std::size_t t = triangles_[e];
                            if (!accept(t)) continue;
                            const collision::TrianglePoint q =
                                collision::closest_point_on_triangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
                            const double d2 = (p - q.point).squaredNorm();
                            if (d2 < best2) best2 = d2, best.found = true, best_point = q, best_triangle = t;
                        }
                    }
        }
        if (best.found) {
            const double distance = std::sqrt(best2);
            best.on_edge = on_border(best_triangle, best_point.feature, accept);
            best.distance = (p - best_point.point).dot(pseudo_normal(best_triangle, best_point.feature)) < 0.0 ? -distance
                                                                                                                : distance;
        }
        return best;
    }

private:
    struct Edge {
        uint64_t key;
        uint32_t triangle;
    };
    Vec3 corner(std::size_t t, int c) const { return vertex_at(mesh_.positions, mesh_.indices[3 * t + std::size_t(c)]); }
    uint64_t edge_key(std::size_t t, int c) const {
        const uint32_t a = mesh_.indices[3 * t + std::size_t(c)], b = mesh_.indices[3 * t + std::size_t((c + 1) % 3)];
        return (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
    }
    template <class Visit>
    void edge_triangles(uint64_t k, Visit visit) const {
        for (auto it = std::lower_bound(edges_.begin(), edges_.end(), k, [](const Edge& e, uint64_t v) { return e.key < v; });
             it != edges_.end() && it->key == k; ++it)
            visit(it->triangle);
    }
    static int edge_of(collision::TriangleFeature feature) {
        using F = collision::TriangleFeature;
        return feature == F::edge_ab ? 0 : feature == F::edge_bc ? 1 : feature == F::edge_ca ? 2 : -1;
    }
    static int corner_of(collision::TriangleFeature feature) {
        using F = collision::TriangleFeature;
        return feature == F::corner_a ? 0 : feature == F::corner_b ? 1 : feature == F::corner_c ? 2 : -1;
    }
    Vec3 pseudo_normal(std::size_t t, collision::TriangleFeature feature) const {
        if (const int c = corner_of(feature); c >= 0) return vertex_normals_[mesh_.indices[3 * t + std::size_t(c)]];
        if (const int e = edge_of(feature); e >= 0) {
            Vec3 sum = Vec3::Zero();
            edge_triangles(edge_key(t, e), [&](uint32_t other) { sum += face_normals_[other]; });
            return sum;
        }
        return face_normals_[t];
    }
    // Whether the feature touches a triangle accept() refuses.
    template <class Accept>
    bool on_border(std::size_t t, collision::TriangleFeature feature, Accept accept) const {
        bool border = false;
        if (const int c = corner_of(feature); c >= 0) {
            const uint32_t v = mesh_.indices[3 * t + std::size_t(c)];
            for (uint32_t i = corner_begin_[v]; i < corner_begin_[v + 1]; ++i) border = border || !accept(corner_triangles_[i]);
        } else if (const int e = edge_of(feature); e >= 0) {
            edge_triangles(edge_key(t, e), [&](uint32_t other) { border = border || !accept(other); });
        }
        return border;
    }
    std::array<long, 3> cell_of(const Vec3& p) const {
        return {long(std::floor(p.x() / cell_)), long(std::floor(p.y() / cell_)), long(std::floor(p.z() / cell_))};
    }
    static uint64_t key(const std::array<long, 3>& c) {
        const auto m = [](long v) { return uint64_t(v + (1L << 20)) & 0x1fffffULL; };
        return (m(c[0]) << 42) | (m(c[1]) << 21) | m(c[2]);
    }

    const Mesh& mesh_;
    double cell_;
    std::vector<Vec3> face_normals_, vertex_normals_;
    std::vector<Edge> edges_;
    std::vector<uint32_t> corner_begin_, corner_triangles_;
    std::vector<uint32_t> triangles_;  // per cell entry
    std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> cells_;  // a cell's entries in triangles_
};

Vec3 axis_point(const double* points, std::size_t count, const spline::ArcLengthTable& table, double s) {
    return spline::evaluate(points, spline::weights_at(count, table.parameter_at(s), spline::Derivative::value));
}

Vec3 axis_tangent(const double* points, std::size_t count, const spline::ArcLengthTable& table, double s) {
    return normalized_or(spline::evaluate(points, spline::weights_at(count, table.parameter_at(s), spline::Derivative::first)),
                         Vec3::Zero());
}

// The mean of r(s)^2 over [0, length] (midpoints of 1024 steps: the profile is piecewise
// linear in rest arc length, smooth enough between its knots), m^2.
template <class RadiusAt>
double mean_square_radius(RadiusAt radius_at, double length) {
    constexpr int kSteps = 1024;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double r = radius_at((double(i) + 0.5) / kSteps * length);
        sum += r * r;
    }
    return sum / kSteps;
}

double triangle_area(const Mesh& mesh, std::size_t t) {
    const Vec3 a = vertex_at(mesh.positions, mesh.indices[3 * t]), b = vertex_at(mesh.positions, mesh.indices[3 * t + 1]),
               c = vertex_at(mesh.positions, mesh.indices[3 * t + 2]);
    return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace

SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius, const PreviousFrame* previous) {
    return measure_skin(mesh, points_xyz, count, table, radius, TubeRadius{}, previous);
}

SkinMetrics measure_skin(const Mesh& mesh, const double* points_xyz, std::size_t count,
                         const spline::ArcLengthTable& table, double radius, const TubeRadius& along,
                         const PreviousFrame* previous) {
    SkinMetrics m;
    const double R = radius;
    // The ideal tube's radius at arc length s of the axis (its place at rest, tube_radius.h).
    const auto radius_at = [&](double s) { return along.varies() ? along.at_parameter(table.parameter_at(s), R) : R; };
    const double length = table.total_length();
    m.axis_length = length;
    m.vertices = mesh.vertex_count();
    m.triangles = mesh.triangle_count();
    if (m.vertices == 0) return m;

    // Per vertex: radius error, normal deviation, blending; keep the analytic directions.
    const AxisPointGrid grid(table, points_xyz, count, R / 8.0, 2.0 * R);
    const AxisPolyline polyline(table, points_xyz, count, R / 16.0);
    std::vector<Vec3> radial(m.vertices), on_tube(m.vertices);
    std::vector<double> other_fold(m.vertices);  // distance to the nearest other fold's axis (kOtherFoldArc), m
    std::vector<double> other_radius(m.vertices, R);  // that fold's radius there, m
    double sum_radius2 = 0.0, sum_normal2 = 0.0, sum_free2 = 0.0;
    for (std::size_t i = 0; i < m.vertices; ++i) {
        const double s = double(mesh.u[i]) * length;
        const Vec3 a = axis_point(points_xyz, count, table, s);
        const Vec3 v = vertex_at(mesh.positions, i);
        const Vec3 r = v - a;
        const double distance = r.norm();
        radial[i] = normalized_or(r, Vec3{0, 0, 0});
        const double r_here = radius_at(s);
        on_tube[i] = a + r_here * radial[i];
        const double error = std::fabs(distance - r_here) / r_here;
        sum_radius2 += error * error;
        m.radius_error_max = std::max(m.radius_error_max, error);
        const Vec3 n = normalized_or(vertex_at(mesh.normals, i), Vec3{0, 0, 0});
        const double angle = std::acos(std::clamp(n.dot(radial[i]), -1.0, 1.0));
        sum_normal2 += angle * angle;
        m.normal_deviation_max = std::max(m.normal_deviation_max, angle);
        if (grid.nearest_other_fold(v, s, kNeighbourWindow * R) < kBlendBand * R) ++m.blended_vertices;
        double other_arc = s;
        other_fold[i] = grid.nearest_other_fold(v, s, kOtherFoldArc * R, &other_arc);
        other_radius[i] = radius_at(other_arc);
        // Free: beyond any bulge's reach from another fold, on a stretch bending with a
        // radius above R.
        if (other_fold[i] >= (1.0 + kMaxBulgeReach) * R && polyline.largest_curvature(s, R) * R <= 1.0) {
            sum_free2 += error * error;
            ++m.free_vertices;
        }
    }
    m.radius_error_rms = std::sqrt(sum_radius2 / double(m.vertices));
    m.normal_deviation_rms = std::sqrt(sum_normal2 / double(m.vertices));
    m.free_radius_error_rms = m.free_vertices > 0 ? std::sqrt(sum_free2 / double(m.free_vertices)) : 0.0;

    // Where folds meet: each vertex near another fold against that fold's ideal tube and its
    // triangles (those whose corners are all another fold's to the vertex).
    std::vector<double> skin_depth(m.vertices, 0.0), tube_depth(m.vertices, 0.0);
    if (m.triangles > 0) {
        const TriangleGrid triangles(mesh, 0.25 * R);
        for (std::size_t i = 0; i < m.vertices; ++i) {
            if (!(other_fold[i] < 1.25 * R)) continue;  // no skin reaches it: R, a bulge and the radius error
            const double s = double(mesh.u[i]) * length;
            tube_depth[i] = std::max(0.0, other_radius[i] - other_fold[i]);
            m.tube_overlap_depth_max = std::max(m.tube_overlap_depth_max, tube_depth[i] / R);
            const auto other = [&](std::size_t t) {
                for (int c = 0; c < 3; ++c)
                    if (std::fabs(double(mesh.u[mesh.indices[3 * t + std::size_t(c)]]) * length - s) <= kOtherFoldArc * R)
                        return false;
                return true;
            };
            const TriangleGrid::Closest closest = triangles.closest(vertex_at(mesh.positions, i), R, other);
            // On the border of the other fold's triangles (where a union's crease joins the
            // two folds) neither inside nor a gap can be told.
            if (closest.on_edge) continue;
            if (closest.found && closest.distance < 0.0) {
                skin_depth[i] = -closest.distance;
                m.overlap_depth_max = std::max(m.overlap_depth_max, skin_depth[i] / R);
            } else if (tube_depth[i] > 0.0) {
                // Pressed into another fold, outside its skin: a gap (at least R when none is near).
                m.contact_gap_max = std::max(m.contact_gap_max, closest.found ? closest.distance / R : 1.0);
            }
        }
        for (std::size_t t = 0; t < m.triangles; ++t) {
            const uint32_t* corners = &mesh.indices[3 * t];
            const auto deeper = [&](const std::vector<double>& depth) {
                return depth[corners[0]] > kOverlapFloor * R && depth[corners[1]] > kOverlapFloor * R &&
                       depth[corners[2]] > kOverlapFloor * R;
            };
            if (deeper(skin_depth)) m.overlap_area += triangle_area(mesh, t);
            if (deeper(tube_depth)) m.tube_overlap_area += triangle_area(mesh, t);
        }
    }

    // Motion since the previous update: each vertex's distance to the previous mesh (the
    // surface's change, whether or not the vertices are the same), beyond what the tube
    // around its axis point moved there: the point's motion and R times its tangent's turn
    // (the local tube moved rigidly).
    if (previous != nullptr && previous->mesh != nullptr && previous->mesh->triangle_count() > 0 &&
        previous->table != nullptr) {
        const TriangleGrid before(*previous->mesh, 0.25 * R);
        const double before_length = previous->table->total_length();
        for (std::size_t i = 0; i < m.vertices; ++i) {
            const TriangleGrid::Closest closest =
                before.closest(vertex_at(mesh.positions, i), R, [](std::size_t) { return true; });
            const double motion = closest.found ? std::fabs(closest.distance) : R;  // at least R
            const double u = mesh.u[i];
            const Vec3 a = axis_point(points_xyz, count, table, u * length);
            const Vec3 a_before = axis_point(previous->points_xyz, previous->count, *previous->table, u * before_length);
            const Vec3 turn = axis_tangent(points_xyz, count, table, u * length) -
                              axis_tangent(previous->points_xyz, previous->count, *previous->table, u * before_length);
            const double tube_motion = (a - a_before).norm() + R * turn.norm();
            m.vertex_motion_max = std::max(m.vertex_motion_max, motion / R);
            m.vertex_excess_motion_max = std::max(m.vertex_excess_motion_max, (motion - tube_motion) / R);
        }
    }

    // Per triangle: facet error, orientation against the axis, volume (also of the ideal
    // tube through the same triangles), edges.
    double sum_facet2 = 0.0, ideal_volume6 = 0.0;
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
            const double r_here = radius_at((u0 + u1 + u2) / 3.0 * length);
            const double error = std::fabs(distance - r_here) / r_here;
            sum_facet2 += error * error;
            m.facet_error_max = std::max(m.facet_error_max, error);
        }
        volume6 += p0.dot(p1.cross(p2));
        {
            const Vec3 q0 = on_tube[i0] - origin, q1 = on_tube[i1] - origin, q2 = on_tube[i2] - origin;
            ideal_volume6 += q0.dot(q1.cross(q2));
        }
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
    const double ideal = kPi * (along.varies() ? mean_square_radius(radius_at, length) : R * R) * length;
    m.volume_error = ideal > 0.0 ? (m.volume - ideal) / ideal : 0.0;
    m.shape_volume_error = ideal_volume6 != 0.0 ? (volume6 - ideal_volume6) / ideal_volume6 : 0.0;
    return m;
}

}  // namespace enteron::skinning
