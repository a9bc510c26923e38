// SPDX-License-Identifier: Apache-2.0
// The mesentery: tension-only springs that tie points of the axis to the mesenteric root,
// a short line (a segment, or a polyline: mechanics/mesentery_root.h) at the back of the
// abdomen, from which the mesentery fans out. Attachment k sits at the fraction
// f_k = (k + 1/2) / K of the axis (spline parameter f_k (n - 1), arc length s_k = f_k L at
// rest), evenly spread along it, and pulls toward the root point at the fraction t of the
// root's length: t = f_k, or t(s_k) from a mapping the scene gives (pairs (s, t), piecewise
// linear). A spring is slack below its rest length (the fold hangs freely) and pulls with
// k (d - L0) beyond it.
//
// Linearisation of a stretched spring (d > L0): H = k [u u^T + (1 - L0/d) (I - u u^T)],
// positive semi-definite; a slack spring adds nothing.
//
// The root may be attached to a rigid frame (the posterior wall as an organ mesh that the
// caller moves, mechanics/rigid_frames.h): it then moves with the frame, within the step
// as the frame does, and the springs' work on the bowel is the guard's to allow (twice the
// largest power of the tensions at the moving root in the step, times the step).
#pragma once

#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/rigid_frames.h"

namespace enteron::mechanics {

// One mesentery's settings (each tube may have its own).
struct MesenteryParameters {
    Vec3 root_start = Vec3::Zero();  // m: the root segment, when root_points is empty
    Vec3 root_end = Vec3::Zero();    // m
    std::size_t attachments = 0;
    double stiffness = 0.0;    // N/m per spring
    double rest_length = 0.0;  // m; 0: each spring's length in `initial`
    // The root as a polyline of two or more points (x, y, z each, m); empty: the segment.
    std::vector<double> root_points;
    // Pairs s_0, t_0, s_1, t_1, ...: the bowel at arc length s (m at rest, from its first
    // end) is tied to the root at fraction t, linear between pairs, held past the first and
    // last (spline/length_profile.h). Empty: t is the bowel's fraction f_k.
    std::vector<double> root_mapping;
    double bowel_length = 0.0;  // m at rest: s_k = f_k x bowel_length, for the mapping
};

class MesenteryForce final : public Effect {
public:
    MesenteryForce(const AxisModel& model, const MesenteryParameters& parameters,
                   const State& initial, std::pmr::memory_resource* memory);

    EffectId id() const override { return EffectId::mesentery; }
    void evaluate(const State& state, double* force, const Linearization* lin) override;
    double potential_energy(const State& state) const override;
    void add_stiffness_bound(numerics::ScalarBandMatrix& bound) const override;
    double external_work_bound() const override { return 2.0 * largest_power_ * step_dt_; }
    void begin_step(double dt) override;
    void begin_attempt() override { largest_power_ = 0.0; }

    // Between steps: the root follows frame `frame` of `frames` (outliving this) from where
    // it is now; kNoFrame leaves it where it is, in the world.
    static constexpr std::size_t kNoFrame = static_cast<std::size_t>(-1);
    void attach(const RigidFrames* frames, std::size_t frame, double time);

    // The frame the root follows and the roots in it: a section of a saved state. A state
    // whose root follows a frame restores only into a scene whose mesentery was attached
    // (to any frame) as well: frames_ is set by attach.
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

    // Spring k's root point (k < springs()), in the world at time t.
    std::size_t springs() const { return springs_.size(); }
    Vec3 root_point(std::size_t k, double t) const { return placement(t).to_world(springs_[k].root); }

private:
    struct Spring {
        spline::SegmentWeights weights;  // of the attachment point on the axis
        Vec3 root;                       // m: in the world, or in the frame when attached
        double rest_length;              // m
    };
    // The vector from the root (at `root`, world) to the attachment point.
    static Vec3 stretch_vector(const State& state, const Spring& spring, const Vec3& root);
    // Where the frame is at time t (identity when not attached).
    FramePlacement placement(double t) const;

    double stiffness_;
    std::pmr::vector<Spring> springs_;
    const RigidFrames* frames_ = nullptr;
    std::size_t frame_ = kNoFrame;
    double largest_power_ = 0.0;
    double step_dt_ = 0.0;
};

}  // namespace enteron::mechanics
