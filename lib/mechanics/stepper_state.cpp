// SPDX-License-Identifier: Apache-2.0
// Save and restore of what the next step reads (stepper.h, docs/scoring-and-state.md): the
// section "scene" (named for the scene that wrote it before the stepper held it: the axis
// state, the counters, the guard's reference energies), then the frames', the dynamics'
// (effect counters, then each effect's own) and the integrator's.
//
// No wall-clock figure goes into the image (the last step's time, the effects' times: they
// measure this process, not the simulation), so two runs that are bit-identical save
// bit-identical images; a restore leaves this scene's figures as they are. Older images
// (scene version 1, dynamics 1 and 2) held them: read and dropped.
#include "base/state_io.h"
#include "mechanics/stepper.h"

namespace enteron::mechanics {

void Stepper::save_state(StateWriter& out) const {
    out.begin_section("scene", 2);
    out.u32(static_cast<uint32_t>(state_.count()));
    out.f64(state_.time);
    out.f64s(state_.q.data(), state_.q.size());
    out.f64s(state_.v.data(), state_.v.size());
    out.u64(counters_.steps);
    out.u64(counters_.substeps);
    out.u64(guard_.rollbacks());
    const Dynamics::Energies& reference = guard_.reference();
    out.f64(reference.kinetic);
    out.f64(reference.potential);
    out.f64(reference.deformation);
    out.end_section();
    frames_.save_state(out);
    dynamics_.save_state(out);
    integrator_->save_state(out);
}

void Stepper::restore_state(StateReader& in) {
    const uint32_t version = in.begin_section("scene", 2);
    if (in.u32("control points") != state_.count()) in.fail("saved with another number of control points");
    const double time = in.f64("time");
    in.f64s("control point positions", state_.q.size(), in.checking() ? nullptr : state_.q.data());
    in.f64s("control point velocities", state_.v.size(), in.checking() ? nullptr : state_.v.data());
    StepCounters counters;
    counters.steps = in.u64("steps");
    counters.substeps = in.u64("substeps");
    const uint64_t rollbacks = in.u64("rollbacks");
    if (version < 2) in.u64("last step wall time");  // version 1: dropped
    Dynamics::Energies reference;
    reference.kinetic = in.f64("kinetic energy");
    reference.potential = in.f64("potential energy");
    reference.deformation = in.f64("deformation energy");
    in.end_section();
    if (!in.checking()) {
        state_.time = time;
        counters.last_step_ns = counters_.last_step_ns;  // this process's, not the image's
        counters_ = counters;
        guard_.set_rollbacks(rollbacks);
        guard_.set_reference(reference);
    }
    frames_.restore_state(in);
    dynamics_.restore_state(in, frames_);
    integrator_->restore_state(in);
}

void Stepper::restored() {
    // The stability bounds follow the restored obstacles' friction and gravity (the same
    // bits when they did not change); the guard keeps the saved reference.
    const Dynamics::Energies reference = guard_.reference();
    effects_changed();
    guard_.set_reference(reference);
}

}  // namespace enteron::mechanics
