// SPDX-License-Identifier: Apache-2.0
// The direct tool's contact law (tool.h, docs/haptics.md): the capsule is at the commanded
// pose, its velocity (for contact damping and friction) the pose change over the step. Every
// collision sphere touching it gets the penalty law of contact_model.h at its velocity
// relative to the shaft's point, and a grasp its spring (tool_grasp.h). Action = reaction
// within the bound: the tool's forces on the bowel share one scale, so that the sum of
// their magnitudes stays within max_force (the sum bounds the net force and, unlike the net
// force, does not jump when contacts on opposite sides start to cancel). A grasp whose
// spring alone would need more than max_force slips (let go when the step is accepted).
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/tool_contacts.h"
#include "collision/tool_motion.h"
#include "collision/tool_state.h"
#include "mechanics/state.h"

namespace enteron::collision {

class DirectContacts {
public:
    explicit DirectContacts(std::pmr::memory_resource* memory) : hits_(memory) {}
    // Room for contacts with `spheres` spheres. Allocates.
    void reserve(std::size_t spheres) { hits_.reserve(spheres); }

    // The contacts and the grasp of `tool`, its shaft commanded at `shaft` at time t and its
    // grasp's rest length `grasp_rest`, with the bowel at `state` (its spheres placed):
    // added to `contacts`; the evaluation (where the tool rests, its counts and stiffness) in
    // tool.evaluation, a slip in tool.grasp.
    void evaluate(ToolState& tool, const ShaftAt& shaft, double t, double grasp_rest, const mechanics::State& state,
                  const CollisionSpheres& spheres, ToolContacts& contacts);

private:
    // A sphere touching the tool, before the bound's scale is known.
    struct Hit {
        std::size_t sphere;
        ContactForce force;  // on the bowel
        Vec3 normal;
        double depth;   // m
        Vec3 velocity;  // of the sphere's centre, m/s
        Vec3 arm;       // from the tip to the contact point on the tool's surface, m
    };
    std::pmr::vector<Hit> hits_;
};

}  // namespace enteron::collision
