// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_direct_contacts.h"

#include <algorithm>

#include "collision/shaft_contact.h"
#include "collision/tool_shaft.h"

namespace enteron::collision {

void DirectContacts::evaluate(ToolState& tool, const ShaftAt& at, double t, double grasp_rest,
                              const mechanics::State& state, const CollisionSpheres& spheres,
                              ToolContacts& contacts) {
    ToolEvaluation& evaluation = tool.evaluation;
    const Shaft shaft(at.tip, at.tail, tool.settings.radius + spheres.radius(), {at.side, blade_share(tool.settings)});
    evaluation.rested = {at.tip, at.tip_velocity, t};
    // The contacts, first unscaled.
    hits_.clear();
    Vec3 total = Vec3::Zero();     // on the bowel
    double total_magnitude = 0.0;  // sum of the magnitudes of its parts
    // Their change as the tool moves rigidly by dx, velocities held (shaft_contact_rate): for the stiffness.
    Mat3 total_rate = Mat3::Zero();
    Eigen::RowVector3d magnitude_rate = Eigen::RowVector3d::Zero();
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        const Sphere& sphere = spheres[i];
        ShaftContact touch;
        if (!shaft_contact(shaft, sphere.center, &touch)) continue;
        touch.depth -= spheres.radius() - sphere.radius;  // the shaft reaches as far as the largest sphere
        if (!(touch.depth > 0.0)) continue;
        const double s = touch.at.s;
        Hit hit;
        hit.sphere = i;
        hit.depth = touch.depth;
        hit.normal = touch.normal;
        hit.velocity = spline::evaluate(state.v.data(), sphere.weights);
        Vec3 relative = hit.velocity - ((1.0 - s) * at.tip_velocity + s * at.tail_velocity);
        if (touch.at.w != 0.0) relative -= touch.at.w * at.side_velocity;
        hit.force = contact_force(tool.contact, hit.depth, hit.normal, relative);
        hit.arm = s * shaft.axis + tool.settings.radius * hit.normal;
        if (touch.at.w != 0.0) hit.arm += touch.at.w * at.side;
        total += hit.force.force;
        const double magnitude = hit.force.force.norm();
        total_magnitude += magnitude;
        const Mat3 rate = shaft_contact_rate(shaft_contact_jacobian(tool.contact, touch, hit.force, relative), touch,
                                             shaft, at.tail_velocity - at.tip_velocity, 0.0, at.side_velocity);
        total_rate += rate;
        if (magnitude > 0.0) magnitude_rate += (hit.force.force / magnitude).transpose() * rate;
        hits_.push_back(hit);
    }
    evaluation.sphere_contacts = static_cast<uint32_t>(hits_.size());

    // The grasp's spring, unless it slips.
    const GraspLaw& law = tool.grasp_law;
    Vec3 grasp = Vec3::Zero();  // on the bowel
    GraspSpring spring;
    Vec3 held = Vec3::Zero(), held_velocity = Vec3::Zero();
    const bool holding = tool.grasp.holding && !tool.grasp.slipped;
    if (holding) {
        held = spline::evaluate(state.q.data(), tool.grasp.point);
        held_velocity = spline::evaluate(state.v.data(), tool.grasp.point);
        spring = grasp_spring(law, grasp_rest, at.tip, at.tip_velocity, held, held_velocity);
        grasp = spring.force;
        if (grasp.norm() > tool.settings.max_force) {
            tool.grasp.slipped = true;  // let go when the step is accepted
            grasp = Vec3::Zero();
        }
        total += grasp;
        const double magnitude = grasp.norm();
        total_magnitude += magnitude;
        if (spring.taut && !tool.grasp.slipped) {
            const Mat3 h = grasp_stiffness(spring);
            total_rate += h;
            if (magnitude > 0.0) magnitude_rate += (grasp / magnitude).transpose() * h;
        }
    }

    // Action = reaction within the bound: every force of this tool shares one scale.
    const double max_force = tool.settings.max_force;
    const bool bounded = total_magnitude > max_force;
    const double scale = bounded ? max_force / total_magnitude : 1.0;
    evaluation.bounded = bounded;
    // The force on the tool is -scale total, the scale changing with the magnitudes.
    evaluation.stiffness =
        bounded ? Mat3(-scale * (total_rate - total * magnitude_rate / total_magnitude)) : Mat3(-total_rate);

    for (const Hit& hit : hits_)
        contacts.add_sphere(static_cast<uint32_t>(hit.sphere), spheres[hit.sphere].weights, hit.depth, hit.force,
                            hit.normal, scale, spheres[hit.sphere].center, hit.velocity, hit.arm);
    // A slack grasp spring pulls nothing.
    if (holding && !tool.grasp.slipped && spring.taut)
        contacts.add_grasp(spring, law, tool.grasp.point, scale, held, held_velocity);
}

}  // namespace enteron::collision
