// SPDX-License-Identifier: Apache-2.0
#include "collision/tool_contacts.h"

#include <algorithm>

#include "mechanics/system_matrix.h"

namespace enteron::collision {

using mechanics::add_axial_block;
using mechanics::add_point_force;

void ToolContacts::begin(double* force, const mechanics::Linearization* lin) {
    contacts_.clear();
    force_ = force;
    lin_ = lin;
    summary_ = {};
}

const ToolContact& ToolContacts::add(const ToolContact& contact, const ContactLinearization& blocks, double scale,
                                     const Vec3& stiffness_times_velocity) {
    add_point_force(contact.weights, contact.force, force_);
    if (lin_ != nullptr) {
        add_axial_block(*lin_->system, contact.weights, contact.normal, blocks.axial, blocks.transverse, scale);
        add_point_force(contact.weights, stiffness_times_velocity, lin_->stiffness_times_velocity);
    }
    contacts_.push_back(contact);
    return contacts_.back();
}

const ToolContact& ToolContacts::add_sphere(uint32_t sphere, const spline::SegmentWeights& weights, double depth,
                                            const ContactForce& law, const Vec3& normal, double scale,
                                            const Vec3& position, const Vec3& velocity, const Vec3& arm) {
    const Mat3 nn = outer(normal);
    ToolContact contact;
    contact.sphere = sphere;
    contact.depth = depth;
    contact.normal = normal;
    contact.weights = weights;
    contact.force = scale * law.force;
    contact.stiffness = (scale * law.stiffness) * nn;
    contact.damping = scale * (law.damping * nn + law.friction_damping * (Mat3::Identity() - nn));
    contact.position = position;
    contact.velocity = velocity;
    contact.arm = arm;
    summary_.count += 1;
    summary_.max_penetration = std::max(summary_.max_penetration, depth);
    // The implicit system's block, scaled with the force.
    return add(contact, contact_linearization(law, h()), scale,
               scale * law.stiffness * velocity.dot(normal) * normal);
}

const ToolContact& ToolContacts::add_grasp(const GraspSpring& spring, const GraspLaw& law,
                                           const spline::SegmentWeights& weights, double scale, const Vec3& position,
                                           const Vec3& velocity) {
    ToolContact contact;
    contact.normal = spring.direction;
    contact.weights = weights;
    contact.force = scale * spring.force;
    contact.stiffness = scale * grasp_stiffness(spring);
    contact.damping = (scale * law.damping) * Mat3::Identity();
    contact.position = position;
    contact.velocity = velocity;
    contact.arm = Vec3::Zero();
    return add(contact, grasp_linearization(spring, law, h()), scale, contact.stiffness * contact.velocity);
}

}  // namespace enteron::collision
