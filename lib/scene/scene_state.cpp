// SPDX-License-Identifier: Apache-2.0
// Save and restore of a scene (scene.h, docs/scoring-and-state.md): what the next step reads,
// in the stepper's sections (mechanics/stepper.h: the axis state, the counters, the guard's
// reference energies; the frames; the effects; the integrator's history).
//
// The continuation of a restored scene is bit-identical to the original's: everything the
// next steps read is either saved (the state, the tools, the near pairs of the self-contact
// with the grid's filing order, the guard's reference) or a pure function of the control
// points that is computed again (the collision spheres' placement and every cache keyed on
// it, which the restore drops).
#include <cstdio>

#include "base/error.h"
#include "scene/scene.h"

namespace enteron::scene {

uint64_t Scene::fingerprint() const {
    Fingerprint fingerprint = description_;
    dynamics_.add_layout(fingerprint);
    return fingerprint.value();
}

std::size_t Scene::save_state(void* buffer, std::size_t capacity) const {
    StateWriter out(buffer, capacity, fingerprint());
    stepper_.save_state(out);
    return out.finish();
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
    stepper_.restore_state(in);
    in.finish();
    in.start_applying();
    stepper_.restore_state(in);
    // The spheres are placed again for the restored control points, and every cache keyed
    // on a placement with them (the same bits: a placement depends on the points only).
    if (spheres_) spheres_->forget_placement();
    stepper_.restored();
    publish();
}

}  // namespace enteron::scene
