// SPDX-License-Identifier: Apache-2.0
// Clamped ends: an end of the axis held where it started AND pointing where it started, as
// the bowel is held where it joins fixed anatomy (the duodenojejunal flexure, the
// ileocaecal junction). A boundary condition of the spline, not a second pinned point.
//
// The spline's end treatment at a clamped end is quadratic (spline/catmull_rom.h): the
// phantom q_{-1} = 3 q_0 - 3 q_1 + q_2, so the end segment is the parabola through q_0, q_1,
// q_2 and can carry the curvature a clamp carries, and the end tangent is
//   P'(0) = (4 q_1 - 3 q_0 - q_2) / 2.
// The end point q_0 is pinned (pinned_points.h); the clamp holds the tangent's direction d
// (unit, as at creation): its two components across d stay zero,
//   e_k . (4 q_1 - 3 q_0 - q_2) = 0,   k = 1, 2,   (e_1, e_2, d) orthonormal,
// two linear constraints, held in velocity form, e_k . (4 v_1 - 3 v_0 - v_2) = 0 (the
// positions then keep them exactly: they are linear in q). Its length is free: the end
// stretches as the stretch law says. The last end is the mirror image (q_{n-1}, q_{n-2},
// q_{n-3}).
//
// The constraint is eliminated from each linear system A x = b that the integrators solve
// (the implicit system, or the mass matrix for the explicit ones) by a change of variables
// that keeps the band: with u = 4 x_1 - x_2 written in the frame (d, e_1, e_2),
//   x_1 = (R u + x_2) / 4,   x_2 = x_2,   R = [d e_1 e_2],
// i.e. x = T x' with T the identity but for the blocks of points 1 and 2. T^T A T couples
// only the points A already coupled (points 1 and 2 reach points 0 .. 5 either way), so it
// is still a band matrix of half bandwidth 11; the two rows of u across d become identity
// rows whose right-hand sides are the constraint's values; after the solve, x = T x'.
// The cost is a few 3 x 3 block products per end and step.
//
// A clamp attached to a rigid frame (an organ the caller moves, rigid_frames.h) holds its
// direction in that frame: d = R d_local, e_k = R e_k,local, taken at the end of each step
// (where its end point, pinned to the same frame, goes). Before each attempt the two
// across-components of the end's velocity get the rate that brings the tangent onto the new
// direction by the end of the step, e_k . (4 v_1 - 3 v_0 - v_2) = -e_k . u(q) / dt with u =
// 4 q_1 - 3 q_0 - q_2 at the step's start (bounded like an attached pin after a jump), and
// the constraint rows hold that rate instead of zero.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include "base/geometry.h"
#include "base/state_io.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/state.h"
#include "mechanics/system_matrix.h"

namespace enteron::mechanics {

// The tangent dP/dt at an end of the axis through `points` (count x 3, m) with the quadratic
// end treatment there: (4 q_1 - 3 q_0 - q_2) / 2 at the first end, (3 q_{n-1} - 4 q_{n-2} +
// q_{n-3}) / 2 at the last (m per unit of spline parameter, towards the last end).
Vec3 clamped_end_tangent(const double* points, std::size_t count, bool first_end);

// True if that tangent is too short to have a direction (the end folds back on itself).
bool clamped_end_is_degenerate(const double* points, std::size_t count, bool first_end);

// The points of a clamped end, of an axis of `count` control points with the first and/or
// last end clamped: the end point (q_0 or q_{n-1}, pinned with its clamp: pinning or
// releasing it alone would leave the clamp half attached), and the two next to it (q_1,
// q_2 or q_{n-2}, q_{n-3}, whose motion across the held direction the clamp constrains: a
// point pin there would fight it). `none` when the point is neither.
enum class ClampedEnd { none, first, last };
inline ClampedEnd clamped_end_point(std::size_t point, std::size_t count, bool first, bool last) {
    if (first && point == 0) return ClampedEnd::first;
    if (last && point + 1 == count) return ClampedEnd::last;
    return ClampedEnd::none;
}
inline ClampedEnd clamped_end_neighbour(std::size_t point, std::size_t count, bool first, bool last) {
    if (first && (point == 1 || point == 2)) return ClampedEnd::first;
    if (last && (point + 2 == count || point + 3 == count)) return ClampedEnd::last;
    return ClampedEnd::none;
}

class ClampedEnds {
public:
    static constexpr std::size_t kWorld = std::numeric_limits<std::size_t>::max();

    // Clamps the first and/or last end of the axis through `start_points` (count x 3, m),
    // each along its tangent there (spline with quadratic ends at the clamped ones).
    // Requires count >= 4, and >= 6 with both ends (the two constraints share no point).
    // Throws Error(internal) if a clamped end's tangent is degenerate (validate() refuses such
    // a scene first, naming the key).
    ClampedEnds(bool first, bool last, const double* start_points, std::size_t count);

    // The direction held at an end (unit, dP/dt's), or zero if that end is free.
    Vec3 direction(bool first_end) const;
    bool clamped(bool first_end) const { return find(first_end) != nullptr; }

    // Between steps: holds a clamped end's direction in frame `frame` of `frames` (which
    // outlive this) from now on, as it is at time t, or in the world again (kWorld). The end
    // point itself is attached by the pins. Requires clamped(first_end).
    void attach(bool first_end, const RigidFrames& frames, std::size_t frame, double t);

    // Before each attempt of a step of dt seconds (state holds the step's start, the end
    // points' velocities already prescribed): the attached clamps take the directions of
    // their frames at the end of the step, and the near points' velocities the rate that
    // turns the tangent there. `speed_limit` (m/s) bounds that change of a near point's
    // velocity. True if a direction changed: the mass matrix's reduction is then stale.
    bool prescribe(State& state, double dt, double speed_limit);

    // The attachments, in the "dynamics" section of a saved state (Dynamics::save_state).
    // Restore checks the frames against `frames`, assigns only when !in.checking(), and
    // needs the frames to outlive this.
    void save_attachments(StateWriter& out) const;
    void restore_attachments(StateReader& in, const RigidFrames& frames);

    // The control points the clamps constrain besides their end points: 1, 2 and n-2, n-3
    // for the clamped ends. A point pin on one of them would fight the change of variables.
    bool constrains(std::size_t control_point) const;

    // A x = b  ->  (T^T A T) x' = T^T b with the constraint rows made identity. `reduce_rhs`
    // sets those rows of the right-hand side to the change that brings the velocity
    // `velocity` (3n, m/s) back onto the constraint, e_k . (4 dv_1 - dv_2) =
    // -e_k . (4 v_1 - 3 v_0 - v_2) (the end point's dv_0 is zero: it is pinned); null for a
    // system whose solution must itself satisfy the constraint (accelerations): zero.
    void reduce(SystemMatrix& system) const;
    void reduce_rhs(double* rhs, const double* velocity) const;
    // x = T x' (the solution in the original coordinates).
    void expand(double* x) const;

private:
    struct Clamp {
        std::size_t end;     // q_0 (pinned)
        std::size_t near;    // q_1
        std::size_t far;     // q_2
        Vec3 direction;      // d
        Vec3 across[2];      // e_1, e_2
        // Attached to a frame: d and e_k in it, and the rates e_k . (4 v_1 - 3 v_0 - v_2)
        // the constraint rows hold in the current step (zero in the world).
        std::size_t frame = kWorld;
        Vec3 local_direction = Vec3::Zero();
        Vec3 local_across[2] = {Vec3::Zero(), Vec3::Zero()};
        double rate[2] = {0.0, 0.0};
    };
    const Clamp* find(bool first_end) const;
    Clamp* find(bool first_end) { return const_cast<Clamp*>(static_cast<const ClampedEnds*>(this)->find(first_end)); }
    // u = 4 x_1 - 3 x_0 - x_2 of a 3n vector (twice the end tangent, or its rate).
    static Vec3 tangent_sum(const Clamp& c, const double* x) {
        return 4.0 * point_at(x, c.near) - 3.0 * point_at(x, c.end) - point_at(x, c.far);
    }

    const RigidFrames* frames_ = nullptr;

    std::array<Clamp, 2> clamps_{};
    std::size_t count_ = 0;  // clamps in use
    std::size_t control_points_ = 0;
};

}  // namespace enteron::mechanics
