// SPDX-License-Identifier: Apache-2.0
// Control points held in place: fixed in space, or attached to a rigid frame (an organ,
// mechanics/rigid_frames.h) and carried with it. A pinned point's three coordinates become
// constraints: their rows of the mass matrix and of the implicit system are replaced by
// identity rows and their generalised forces by zero, so their acceleration stays exactly
// zero and the free points see the pinned ones as walls. A point attached to a moving frame
// gets, before each attempt of a step, the constant velocity that takes it to where its
// frame puts it at the end of the step (every integrator then moves it there in a straight
// line); after a jump of its frame it follows at no more than half the guard's max_speed
// and catches up over the next steps.
//
// Pins are made and released between steps (ent_scene_pin_point, ent_scene_unpin_point);
// the scene then factors the mass matrix again.
//
// Runs after every other effect (Dynamics puts it last) because it overwrites the rows the
// others have filled. The work an attached pin does on the bowel is allowed by the guard:
// twice the largest power |F| |v| of the pinned rows' forces in the step, times the step.
#pragma once

#include <cstdint>
#include <limits>
#include <memory_resource>
#include <vector>

#include "mechanics/effect.h"
#include "mechanics/rigid_frames.h"

namespace enteron::mechanics {

class PinnedPoints final : public Effect {
public:
    static constexpr std::size_t kWorld = std::numeric_limits<std::size_t>::max();

    // `points` are control point indices (< control point count) held where they are;
    // duplicates are harmless. `frames` (outliving this) are those pins may attach to;
    // `max_speed` is the guard's (m/s).
    PinnedPoints(const std::vector<uint32_t>& points, const RigidFrames& frames, double max_speed,
                 std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::pinned; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    double external_work_bound() const override { return 2.0 * largest_power_ * step_dt_; }
    void begin_step(double dt) override;
    void begin_attempt() override { largest_power_ = 0.0; }

    // Holds control point `point` where it is in `state`, in the world (kWorld) or in frame
    // `frame`, whose motion it then follows; its velocity becomes zero (it is between steps).
    // Pinning a pinned point again re-attaches it. Allocates.
    void pin(uint32_t point, std::size_t frame, State& state);
    // Room for `more` attachments to frames: pinning that many points already pinned then
    // allocates nothing and cannot fail (an all-or-nothing change of several pins).
    void reserve_attachments(std::size_t more) { attached_.reserve(attached_.size() + more); }
    // Lets a point go; false if it was not pinned.
    bool unpin(uint32_t point);
    bool pinned(uint32_t point) const;

    // The pinned points and their attachments (made at run time or by the description): a
    // section of a saved state. Restore checks the points against `control_points` and the
    // frames against those there are; it allocates (between steps, never in one).
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in, std::size_t control_points);
    std::size_t size() const { return points_.size(); }
    // How fast an attached point catches up with its frame after a jump, m/s.
    double speed_limit() const { return speed_limit_; }

    // Before each attempt of a step of dt seconds: the velocities of the points attached to
    // frames (state holds the step's start). True if one of them is not zero.
    bool prescribe(State& state, double dt) const;

    // Makes the pinned rows of a per-point matrix (the mass matrix) identity rows.
    void constrain(numerics::ScalarBandMatrix& per_point) const;
    // Makes the pinned rows of the coordinate system identity rows.
    void constrain(SystemMatrix& system) const;
    // Zeroes the pinned entries of a 3n vector.
    void zero_rows(double* values) const;

private:
    struct Attachment {
        uint32_t point;
        std::size_t frame;
        Vec3 local;  // the point in its frame, m
    };

    const RigidFrames& frames_;
    double speed_limit_;  // m/s
    std::pmr::vector<uint32_t> points_;  // every pinned point, ascending
    std::pmr::vector<Attachment> attached_;
    double largest_power_ = 0.0;
    double step_dt_ = 0.0;
};

}  // namespace enteron::mechanics
