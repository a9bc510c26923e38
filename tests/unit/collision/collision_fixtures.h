// SPDX-License-Identifier: Apache-2.0
// Shared by the collision tests: the default bowel radius, axes that touch themselves, and
// a contact effect evaluated the way Dynamics does.
#pragma once

#include <cmath>
#include <memory_resource>
#include <vector>

#include "base/geometry.h"
#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/self_contact_force.h"
#include "collision/sphere_loads.h"
#include "collision/tool_contacts.h"
#include "collision/tool_motion.h"
#include "collision/tool_state.h"
#include "mechanics/axis_model.h"
#include "mechanics/effect.h"
#include "mechanics/state.h"

namespace collision_test {

using enteron::collision::CollisionSpheres;
using enteron::collision::ContactParameters;
using enteron::collision::SelfContactForce;
using enteron::collision::SphereLoads;
using enteron::mechanics::AxisModel;
using enteron::mechanics::ContactSummary;
using enteron::mechanics::State;

// What Dynamics does for a contact effect: clears the loads it shares, evaluates, applies them.
inline void evaluate_with_loads(enteron::mechanics::Effect& effect, SphereLoads& loads, const State& state,
                                double* force, const enteron::mechanics::Linearization* lin) {
    loads.clear();
    effect.evaluate(state, force, lin);
    loads.apply(force, lin);
}

constexpr double kRadius = 0.0125;

// A bowel axis through the given control points, with the default contact law.
struct Axis {
    explicit Axis(const std::vector<double>& points) : state(std::pmr::new_delete_resource()) {
        const std::size_t n = points.size() / 3;
        state.resize(n);
        state.q.assign(points.begin(), points.end());
        length = 0.0;
        for (std::size_t i = 1; i < n; ++i) {
            length += (enteron::point_at(points.data(), i) - enteron::point_at(points.data(), i - 1)).norm();
        }
        model.control_points = n;
        model.rest_segment_length = length / double(n - 1);
        model.linear_density = 0.3;
    }
    // Collision spheres at R / 2 along this axis.
    CollisionSpheres make_spheres() const {
        return CollisionSpheres(model.control_points, length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    }
    // Contacts and generalised force of the self-contact effect on this axis.
    ContactSummary contacts(std::vector<double>* force = nullptr) const {
        CollisionSpheres spheres = make_spheres();
        SphereLoads loads(spheres, std::pmr::new_delete_resource());
        SelfContactForce effect(spheres, ContactParameters{}, state, std::pmr::new_delete_resource(), loads);
        std::vector<double> f(state.q.size(), 0.0);
        evaluate_with_loads(effect, loads, state, f.data(), nullptr);
        if (force != nullptr) *force = f;
        ContactSummary summary;
        effect.add_contacts(summary);
        return summary;
    }
    State state;
    AxisModel model;
    double length;
};

// A straight axis along +x from the origin: n control points `spacing` apart.
inline std::vector<double> straight(std::size_t n, double spacing) {
    std::vector<double> q;
    for (std::size_t i = 0; i < n; ++i) q.insert(q.end(), {spacing * double(i), 0.0, 0.0});
    return q;
}

// A tool's contact law (tool_direct_contacts.h, tool_proxy_contacts.h) on a straight bowel
// 0.4 m long, at rest, its spheres placed: evaluate() runs it for one tool into `contacts`.
template <class Law>
struct ToolLawBench {
    ToolLawBench() : axis(straight(21, 0.02)), spheres(axis.make_spheres()), force(axis.state.q.size(), 0.0) {
        spheres.update(axis.state.q.data());
        contacts.reserve(spheres.size() + 1);
        law.reserve(spheres.size());
    }
    // The tool's contacts 1 ms after its proxy was placed (its commanded pose at rest),
    // explicit without `lin`; the grasp's rest length `grasp_rest`.
    void evaluate(enteron::collision::ToolState& tool, const enteron::mechanics::Linearization* lin = nullptr,
                  double grasp_rest = 0.0) {
        const double t = 1e-3;
        contacts.begin(force.data(), lin);
        const enteron::collision::ShaftAt at = enteron::collision::commanded_shaft(
            tool.current, tool.target, tool.settings.length, enteron::collision::StepSpan{}, t);
        law.evaluate(tool, at, t, grasp_rest, axis.state, spheres, contacts);
    }
    Axis axis;
    CollisionSpheres spheres;
    std::vector<double> force;
    enteron::collision::ToolContacts contacts{std::pmr::new_delete_resource()};
    Law law{std::pmr::new_delete_resource()};
};

// A U-turn: two straight legs along x, `gap` apart axis to axis, joined by a half circle.
inline std::vector<double> u_turn(double gap) {
    std::vector<double> points;
    const double leg = 0.2, step = 0.005;
    for (double x = leg; x > 0.0; x -= step) points.insert(points.end(), {x, 0.0, 0.0});
    for (int i = 0; i <= 12; ++i) {
        const double angle = 3.14159265358979 * i / 12.0;
        points.insert(points.end(), {-0.5 * gap * std::sin(angle), 0.5 * gap * (1.0 - std::cos(angle)), 0.0});
    }
    for (double x = step; x <= leg; x += step) points.insert(points.end(), {x, gap, 0.0});
    return points;
}

}  // namespace collision_test
