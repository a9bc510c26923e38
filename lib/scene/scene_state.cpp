// SPDX-License-Identifier: Apache-2.0
// Save and restore of a scene (scene.h, docs/scoring-and-state.md): the scene's own section (the
// axis state, the counters, the guard's reference energies), then the dynamics' sections
// (effect counters, then each effect's own), then the integrator's.
//
// The continuation of a restored scene is bit-identical to the original's: everything the
// next steps read is either saved (the state, the tools, the near pairs of the self-contact
// with the grid's filing order, the guard's reference) or a pure function of the control
// points that is computed again (the collision spheres' placement and every cache keyed on
// it, which the restore drops).
//
// No wall-clock figure goes into the image (the last step's time, the effects' times: they
// measure this process, not the simulation), so two runs that are bit-identical save
// bit-identical images; a restore leaves this scene's figures as they are. Older images
// (scene version 1, dynamics 1 and 2) held them: read and dropped.
#include <cstdio>

#include "base/error.h"
#include "scene/scene.h"

namespace enteron::scene {

uint64_t Scene::fingerprint() const {
    Fingerprint fingerprint = description_;
    dynamics_.add_layout(fingerprint);
    return fingerprint.value();
}

void Scene::save_sections(StateWriter& out) const {
    out.begin_section("scene", 2);
    out.u32(static_cast<uint32_t>(model_.control_points));
    out.f64(state_.time);
    out.f64s(state_.q.data(), state_.q.size());
    out.f64s(state_.v.data(), state_.v.size());
    out.u64(stats_.steps);
    out.u64(stats_.substeps);
    out.u64(guard_.rollbacks());
    const mechanics::Dynamics::Energies& reference = guard_.reference();
    out.f64(reference.kinetic);
    out.f64(reference.potential);
    out.f64(reference.deformation);
    out.end_section();
    frames_.save_state(out);
    dynamics_.save_state(out);
    integrator_->save_state(out);
}

std::size_t Scene::save_state(void* buffer, std::size_t capacity) const {
    StateWriter out(buffer, capacity, fingerprint());
    save_sections(out);
    return out.finish();
}

void Scene::restore_sections(StateReader& in) {
    const uint32_t version = in.begin_section("scene", 2);
    if (in.u32("control points") != model_.control_points) in.fail("saved with another number of control points");
    const double time = in.f64("time");
    in.f64s("control point positions", state_.q.size(), in.checking() ? nullptr : state_.q.data());
    in.f64s("control point velocities", state_.v.size(), in.checking() ? nullptr : state_.v.data());
    const uint64_t steps = in.u64("steps"), substeps = in.u64("substeps"), rollbacks = in.u64("rollbacks");
    if (version < 2) in.u64("last step wall time");  // version 1: dropped
    mechanics::Dynamics::Energies reference;
    reference.kinetic = in.f64("kinetic energy");
    reference.potential = in.f64("potential energy");
    reference.deformation = in.f64("deformation energy");
    in.end_section();
    if (!in.checking()) {
        state_.time = time;
        stats_.steps = steps;
        stats_.substeps = substeps;
        guard_.set_rollbacks(rollbacks);
        guard_.set_reference(reference);
    }
    frames_.restore_state(in);
    dynamics_.restore_state(in, frames_);
    integrator_->restore_state(in);
}

void Scene::restore_state(const void* data, std::size_t size) {
    StateReader in(data, size);
    const uint64_t expected = fingerprint();
    if (in.fingerprint() != expected) {
        char message[320];
        std::snprintf(message, sizeof message,
                      "state: saved from another scene (fingerprint %016llx, this scene's %016llx): a state restores "
                      "only into a scene made from the same description, with the same obstacles and tools added in "
                      "the same order",
                      static_cast<unsigned long long>(in.fingerprint()), static_cast<unsigned long long>(expected));
        throw Error(ErrorCode::invalid_argument, message);
    }
    // Check every section, then apply them: a bad image throws before anything changed.
    restore_sections(in);
    in.finish();
    in.start_applying();
    restore_sections(in);
    // The spheres are placed again for the restored control points, and every cache keyed
    // on a placement with them (the same bits: a placement depends on the points only).
    if (spheres_) spheres_->forget_placement();
    // The stability bounds follow the restored obstacles' friction and gravity (the same
    // bits when they did not change); the guard keeps the saved reference.
    const mechanics::Dynamics::Energies reference = guard_.reference();
    refinalize();
    guard_.set_reference(reference);
    publish();
}

}  // namespace enteron::scene
