// SPDX-License-Identifier: Apache-2.0
// The proxy tool's contacts (tool.h, docs/haptics.md): the capsule the bowel meets is the
// tool's proxy (tool_proxy.h), solved at each evaluation from where it was, with the bowel as
// it is, among the spheres it may meet on its way to the device. The bowel receives the
// proxy's contacts and its grasp, which balance the coupling force. A grasp slips when the
// coupling has to pull harder than max_force to hold it.
//
// In an implicit evaluation the proxy then moves with the bowel through the substep: its
// three unknowns join the implicit system's border (bordered_system.h) as one body whose
// balance at the substep's end is
//
//   h sum E_i e - B^T dv = h (F_c - sum g-hat_i),   B = h sum W_i^T E_i
//
// with E_i = h H_i + C_i each contact's blocks, W_i its weights and g-hat_i its force less
// h H_i v: the bowel receives exactly the coupling force of the evaluation, spread over the
// contacts as the proxy's balance spreads it. Explicit evaluations take the contacts' forces
// as they are (scaled to the bound should the balance be a rounding off).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "collision/collision_spheres.h"
#include "collision/tool_contacts.h"
#include "collision/tool_motion.h"
#include "collision/tool_proxy.h"
#include "collision/tool_state.h"
#include "mechanics/state.h"

namespace enteron::collision {

class ProxyContacts {
public:
    explicit ProxyContacts(std::pmr::memory_resource* memory) : candidates_(memory), proxy_(memory) {}
    // Room for contacts with `spheres` spheres. Allocates.
    void reserve(std::size_t spheres);

    // The contacts and the grasp of `tool`'s proxy at time t, the device commanded at
    // `shaft` and the grasp's rest length `grasp_rest`, with the bowel at `state` (its
    // spheres placed): added to `contacts` (and, implicit, the proxy's body to the border);
    // the evaluation (where the proxy rests, its counts, stiffness and body) in
    // tool.evaluation, a slip in tool.grasp.
    void evaluate(ToolState& tool, const ShaftAt& shaft, double t, double grasp_rest, const mechanics::State& state,
                  const CollisionSpheres& spheres, ToolContacts& contacts);

private:
    std::pmr::vector<ProxyCandidate> candidates_;  // spheres near the proxy
    ToolProxy proxy_;
};

}  // namespace enteron::collision
