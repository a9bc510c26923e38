// SPDX-License-Identifier: Apache-2.0
// The environment effect (lib/collision/environment_force.h): the contact law of every
// sphere against the obstacles, mapped to the control points.
#include "collision/environment_force.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory_resource>
#include <vector>

#include "collision/collision_fixtures.h"
#include "collision/collision_spheres.h"
#include "collision/contact_model.h"
#include "collision/obstacle.h"
#include "collision/sphere_loads.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/state.h"

namespace {

using namespace collision_test;
using enteron::collision::CollisionSpheres;
using enteron::collision::ContactParameters;
using enteron::collision::EnvironmentForce;
using enteron::collision::Obstacle;
using enteron::collision::ObstacleKind;
using enteron::collision::SphereLoads;
using enteron::mechanics::AxisModel;
using enteron::mechanics::ContactSummary;
using enteron::mechanics::RigidFrames;
using enteron::mechanics::State;

TEST(EnvironmentForce, AStraightAxisPressedIntoAPlaneGetsTheSumOfItsSpheresForces) {
    // A straight axis along x at height R - d above the plane z = 0: every sphere is d deep.
    const std::size_t n = 21;
    const double length = 0.4, d = 0.001;
    State state(std::pmr::new_delete_resource());
    state.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        state.q[3 * i] = length * double(i) / double(n - 1);
        state.q[3 * i + 2] = kRadius - d;
    }
    AxisModel model;
    model.control_points = n;
    model.rest_segment_length = length / double(n - 1);
    model.linear_density = 0.3;
    Obstacle plane;
    plane.kind = ObstacleKind::plane;
    plane.extent = {0.0, 0.0, 3.0};  // not unit: the effect normalises it
    const ContactParameters contact;
    CollisionSpheres axis_spheres(model.control_points, length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    SphereLoads loads(axis_spheres, std::pmr::new_delete_resource());
    RigidFrames frames(std::pmr::new_delete_resource());
    EnvironmentForce effect(axis_spheres, contact, frames, state, std::pmr::new_delete_resource(), loads);
    effect.add_obstacle(plane);
    // What Dynamics does with the loads the contact effects share.
    const auto evaluate = [&](std::vector<double>& force) {
        loads.clear();
        effect.evaluate(state, force.data(), nullptr);
        loads.apply(force.data(), nullptr);
    };
    std::vector<double> force(3 * n, 0.0);
    evaluate(force);
    ContactSummary summary;
    effect.add_contacts(summary);
    const std::size_t spheres = 65;  // 0.4 / 0.00625 + 1
    EXPECT_EQ(summary.count, spheres);
    EXPECT_NEAR(summary.max_penetration, d, 1e-12);
    // The basis weights sum to one: the control points receive the spheres' total force.
    double fx = 0.0, fy = 0.0, fz = 0.0;
    for (std::size_t i = 0; i < n; ++i) fx += force[3 * i], fy += force[3 * i + 1], fz += force[3 * i + 2];
    EXPECT_NEAR(fz, double(spheres) * contact.stiffness * d, 1e-9);
    EXPECT_NEAR(fx, 0.0, 1e-12);
    EXPECT_NEAR(fy, 0.0, 1e-12);
    for (std::size_t i = 0; i < n; ++i) EXPECT_GT(force[3 * i + 2], 0.0) << "control point " << i;
    EXPECT_NEAR(effect.potential_energy(state), double(spheres) * 0.5 * contact.stiffness * d * d, 1e-12);

    // Lifted clear of the plane: no contact, no force, no energy.
    for (std::size_t i = 0; i < n; ++i) state.q[3 * i + 2] = kRadius + 1e-6;
    std::fill(force.begin(), force.end(), 0.0);
    evaluate(force);
    ContactSummary none;
    effect.add_contacts(none);
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(*std::max_element(force.begin(), force.end()), 0.0);
    EXPECT_EQ(*std::min_element(force.begin(), force.end()), 0.0);
    EXPECT_EQ(effect.potential_energy(state), 0.0);

    // An obstacle added between two evaluations of the same state counts at once (the
    // contacts found for that placement are not reused).
    Obstacle floor_above = plane;
    floor_above.center = {0.0, 0.0, 2e-6};
    effect.add_obstacle(floor_above);
    evaluate(force);
    ContactSummary after;
    effect.add_contacts(after);
    EXPECT_EQ(after.count, spheres);
    EXPECT_GT(effect.potential_energy(state), 0.0);
}

}  // namespace
