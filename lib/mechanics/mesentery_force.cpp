// SPDX-License-Identifier: Apache-2.0
#include "mechanics/mesentery_force.h"

#include <algorithm>
#include <cmath>

#include "base/state_io.h"
#include "mechanics/mesentery_root.h"
#include "spline/length_profile.h"

namespace enteron::mechanics {

MesenteryForce::MesenteryForce(const AxisModel& model, const MesenteryParameters& parameters,
                               const State& initial, std::pmr::memory_resource* memory)
    : stiffness_(parameters.stiffness), springs_(memory) {
    // The mesentery holds the first tube (axis_model.h).
    const TubeModel tube = model.tube_list().front();
    const std::size_t n = tube.control_points;
    const std::size_t count = parameters.attachments;
    std::pmr::vector<Vec3> root(memory);
    for (std::size_t k = 0; k < parameters.root_points.size() / 3; ++k)
        root.push_back(point_at(parameters.root_points.data(), k));
    if (root.empty()) root.assign({parameters.root_start, parameters.root_end});
    const spline::LengthProfile mapping(parameters.root_mapping, memory);
    springs_.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double fraction = (static_cast<double>(k) + 0.5) / static_cast<double>(count);
        Spring spring;
        spring.weights = spline::weights_at(n, fraction * static_cast<double>(n - 1),
                                            spline::Derivative::value, tube.ends);
        spring.weights.first += tube.first;
        const double t = mapping.empty() ? fraction : mapping.at(fraction * parameters.bowel_length);
        spring.root = point_along_root(root, t);
        spring.rest_length = parameters.rest_length > 0.0 ? parameters.rest_length
                                                          : stretch_vector(initial, spring, spring.root).norm();
        springs_.push_back(spring);
    }
}

Vec3 MesenteryForce::stretch_vector(const State& state, const Spring& spring, const Vec3& root) {
    return spline::evaluate(state.q.data(), spring.weights) - root;
}

FramePlacement MesenteryForce::placement(double t) const {
    return frame_ != kNoFrame ? frames_->at(frame_, t) : FramePlacement{};
}

void MesenteryForce::attach(const RigidFrames* frames, std::size_t frame, double time) {
    const FramePlacement from = placement(time);
    frames_ = frames;
    frame_ = frame;
    const FramePlacement to = placement(time);
    for (Spring& spring : springs_) spring.root = to.to_local(from.to_world(spring.root));
}

void MesenteryForce::begin_step(double dt) {
    step_dt_ = dt;
    largest_power_ = 0.0;
}

void MesenteryForce::evaluate(const State& state, double* force, const Linearization* lin) {
    // The implicit step solves for the end of the substep: the root where it is then.
    const FramePlacement frame = placement(state.time + (lin != nullptr ? lin->h : 0.0));
    double power = 0.0;
    for (const Spring& spring : springs_) {
        const Vec3 root = frame.to_world(spring.root);
        const Vec3 d = stretch_vector(state, spring, root);
        const double length = d.norm();
        if (!(length > spring.rest_length)) continue;  // slack (or NaN: the guard sees it)
        const double inv = 1.0 / length;
        const Vec3 u = d * inv;
        const double tension = stiffness_ * (length - spring.rest_length);
        if (frame.moving) power += tension * frame.velocity_at(root).norm();
        const spline::SegmentWeights& sw = spring.weights;
        add_point_force(sw, -tension * u, force);
        if (lin != nullptr) {
            const double transverse = stiffness_ * (1.0 - spring.rest_length * inv);
            const double axial = stiffness_ - transverse;
            add_axial_block(*lin->system, sw, u, axial, transverse, lin->h * lin->h);
            const Vec3 velocity = spline::evaluate(state.v.data(), sw);
            add_point_force(sw, axial_times(u, axial, transverse, velocity), lin->stiffness_times_velocity);
        }
    }
    largest_power_ = std::max(largest_power_, power);
}

double MesenteryForce::potential_energy(const State& state) const {
    const FramePlacement frame = placement(state.time);
    double energy = 0.0;
    for (const Spring& spring : springs_) {
        const double excess = stretch_vector(state, spring, frame.to_world(spring.root)).norm() - spring.rest_length;
        if (excess > 0.0) energy += 0.5 * stiffness_ * excess * excess;
    }
    return energy;
}

void MesenteryForce::add_stiffness_bound(numerics::ScalarBandMatrix& bound) const {
    // H <= k I for every spring, so per coordinate k w w^T bounds it.
    for (const Spring& spring : springs_) {
        const spline::SegmentWeights& sw = spring.weights;
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k <= j; ++k)
                bound.add(sw.first + j, sw.first + k, stiffness_ * sw.w[j] * sw.w[k]);
    }
}

void MesenteryForce::save_state(StateWriter& out) const {
    out.begin_section("mesentery", 1);
    out.u8(frame_ != kNoFrame ? 1 : 0);
    out.u32(frame_ != kNoFrame ? static_cast<uint32_t>(frame_) : 0);
    out.u32(static_cast<uint32_t>(springs_.size()));
    for (const Spring& spring : springs_) out.f64s(spring.root.data(), 3);
    out.end_section();
}

void MesenteryForce::restore_state(StateReader& in) {
    in.begin_section("mesentery", 1);
    const bool attached = in.flag("mesentery attached");
    const uint32_t frame = in.u32("mesentery frame");
    if (attached && frames_ == nullptr)
        in.fail("the saved mesentery follows an obstacle (ent_scene_attach_mesentery) and this scene's does not: "
                "attach it to the same obstacle before restoring");
    if (attached && frame >= frames_->size()) in.fail("the mesentery's frame does not exist in this scene");
    if (in.u32("mesentery springs") != springs_.size()) in.fail("saved with another number of mesentery springs");
    for (std::size_t k = 0; k < springs_.size(); ++k) {
        Vec3 root;
        in.f64s("mesentery root", 3, root.data());
        if (!in.checking()) springs_[k].root = root;
    }
    in.end_section();
    if (!in.checking()) frame_ = attached ? frame : kNoFrame;
}

}  // namespace enteron::mechanics
