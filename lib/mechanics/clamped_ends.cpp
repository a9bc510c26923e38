#include "mechanics/clamped_ends.h"

#include <algorithm>

#include "base/error.h"

namespace enteron::mechanics {

namespace {

using Mat3 = Eigen::Matrix3d;

// Block (i, j) of the symmetric system between control points i and j (|i - j| <= 3).
Mat3 block(const SystemMatrix& system, std::size_t i, std::size_t j) {
    Mat3 m;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) m(r, c) = system.at(3 * i + r, 3 * j + c);
    return m;
}

// Writes block (i, j) (and so, by symmetry, block (j, i)) into the lower band.
void set_block(SystemMatrix& system, std::size_t i, std::size_t j, const Mat3& m) {
    if (i < j) return set_block(system, j, i, m.transpose());
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c)
            if (i != j || c <= r) system.lower(3 * i + r, 3 * j + c) = m(r, c);
}

std::size_t distance(std::size_t a, std::size_t b) { return a > b ? a - b : b - a; }

// Control points more than this apart share no segment: their block is zero.
constexpr std::size_t kCoupledPoints = 3;

}  // namespace

Vec3 clamped_end_tangent(const double* points, std::size_t count, bool first_end) {
    if (first_end) return 0.5 * (4.0 * point_at(points, 1) - 3.0 * point_at(points, 0) - point_at(points, 2));
    return 0.5 * (3.0 * point_at(points, count - 1) - 4.0 * point_at(points, count - 2) + point_at(points, count - 3));
}

bool clamped_end_is_degenerate(const double* points, std::size_t count, bool first_end) {
    const std::size_t end = first_end ? 0 : count - 1, near = first_end ? 1 : count - 2, far = first_end ? 2 : count - 3;
    // Against the chords' own length: a tangent at round-off level of them has no direction.
    const double scale = (point_at(points, near) - point_at(points, end)).norm() +
                         (point_at(points, far) - point_at(points, near)).norm();
    return !(clamped_end_tangent(points, count, first_end).norm() > 1e-9 * scale);
}

ClampedEnds::ClampedEnds(bool first, bool last, const double* start_points, std::size_t count)
    : control_points_(count) {
    if (count < 4 || (first && last && count < 6))
        throw Error(ErrorCode::internal, "clamped ends need 4 control points, 6 with both ends");
    for (const bool first_end : {true, false}) {
        if (!(first_end ? first : last)) continue;
        if (clamped_end_is_degenerate(start_points, count, first_end))
            throw Error(ErrorCode::internal, "a clamped end's tangent is degenerate");
        Clamp& clamp = clamps_[count_++];
        clamp.end = first_end ? 0 : count - 1;
        clamp.near = first_end ? 1 : count - 2;
        clamp.far = first_end ? 2 : count - 3;
        clamp.direction = clamped_end_tangent(start_points, count, first_end).normalized();
        // e_1: across d, from the coordinate axis least aligned with it; e_2 = d x e_1.
        Vec3 axis = Vec3::Zero();
        int least = 0;
        clamp.direction.cwiseAbs().minCoeff(&least);
        axis[least] = 1.0;
        clamp.across[0] = (axis - axis.dot(clamp.direction) * clamp.direction).normalized();
        clamp.across[1] = clamp.direction.cross(clamp.across[0]);
    }
}

Vec3 ClampedEnds::direction(bool first_end) const {
    for (std::size_t k = 0; k < count_; ++k)
        if ((clamps_[k].end == 0) == first_end) return clamps_[k].direction;
    return Vec3::Zero();
}

bool ClampedEnds::constrains(std::size_t control_point) const {
    for (std::size_t k = 0; k < count_; ++k)
        if (control_point == clamps_[k].near || control_point == clamps_[k].far) return true;
    return false;
}

void ClampedEnds::reduce(SystemMatrix& system) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        Mat3 frame;  // R = [d e_1 e_2]
        frame << c.direction, c.across[0], c.across[1];
        const Mat3 a11 = block(system, c.near, c.near);
        const Mat3 a12 = block(system, c.near, c.far);
        const Mat3 a22 = block(system, c.far, c.far);
        // Every other point that shares a segment with q_1 or q_2:
        //   A'_1j = R^T A_1j / 4,   A'_2j = A_1j / 4 + A_2j.
        const std::size_t low = std::min(c.near, c.far), high = std::max(c.near, c.far);
        const std::size_t first = low >= kCoupledPoints ? low - kCoupledPoints : 0;
        const std::size_t last = std::min(control_points_ - 1, high + kCoupledPoints);
        for (std::size_t j = first; j <= last; ++j) {
            if (j == c.near || j == c.far) continue;
            const bool near_coupled = distance(j, c.near) <= kCoupledPoints;
            const Mat3 a1j = near_coupled ? block(system, c.near, j) : Mat3::Zero();
            if (near_coupled) set_block(system, c.near, j, frame.transpose() * a1j / 4.0);
            if (distance(j, c.far) <= kCoupledPoints) set_block(system, c.far, j, a1j / 4.0 + block(system, c.far, j));
        }
        //   A'_11 = R^T A_11 R / 16,   A'_12 = R^T (A_11 / 4 + A_12) / 4,
        //   A'_22 = A_11 / 16 + (A_12 + A_21) / 4 + A_22.
        set_block(system, c.near, c.near, frame.transpose() * a11 * frame / 16.0);
        set_block(system, c.near, c.far, frame.transpose() * (a11 / 4.0 + a12) / 4.0);
        set_block(system, c.far, c.far, a11 / 16.0 + (a12 + a12.transpose()) / 4.0 + a22);
        // The components of u across d are the constraint's: identity rows.
        system.make_identity_row(3 * c.near + 1);
        system.make_identity_row(3 * c.near + 2);
    }
}

void ClampedEnds::reduce_rhs(double* rhs, const double* velocity) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        const Vec3 b1 = point_at(rhs, c.near);
        // b'_1 = R^T b_1 / 4 (its components on d, e_1, e_2), b'_2 = b_1 / 4 + b_2.
        Vec3 reduced(c.direction.dot(b1) / 4.0, 0.0, 0.0);
        for (int e = 0; e < 2; ++e) {
            // The rows across d: the change that puts u = 4 v_1 - v_2 (with v_0) back on d.
            const double off = velocity == nullptr ? 0.0
                                                   : c.across[e].dot(4.0 * point_at(velocity, c.near) -
                                                                     3.0 * point_at(velocity, c.end) -
                                                                     point_at(velocity, c.far));
            reduced[1 + e] = -off;
        }
        point_at(rhs, c.far) += b1 / 4.0;
        point_at(rhs, c.near) = reduced;
    }
}

void ClampedEnds::expand(double* x) const {
    for (std::size_t k = 0; k < count_; ++k) {
        const Clamp& c = clamps_[k];
        const Vec3 u = point_at(x, c.near);  // in the frame (d, e_1, e_2)
        // x_1 = (R u + x_2) / 4.
        point_at(x, c.near) = (u[0] * c.direction + u[1] * c.across[0] + u[2] * c.across[1] + point_at(x, c.far)) / 4.0;
    }
}

}  // namespace enteron::mechanics
