// SPDX-License-Identifier: Apache-2.0
// The contact loads the contact effects share (lib/collision/sphere_loads.h): gathered per
// sphere and applied once, they equal each effect applying its own.
#include "collision/sphere_loads.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <random>
#include <vector>

#include "base/memory.h"
#include "collision/collision_fixtures.h"
#include "collision/environment_force.h"
#include "collision/self_contact_force.h"
#include "mechanics/dynamics.h"
#include "mechanics/rigid_frames.h"
#include "mechanics/state.h"

namespace {

using namespace collision_test;

TEST(SphereLoads, SharedByTheContactEffectsEqualsEachApplyingItsOwn) {
    // A U-turn whose legs touch, lying 0.4 R deep in a floor and moving: self-contact and
    // floor contacts on the same spheres, with damping and friction. The scene gives both
    // effects one set of sphere loads, which Dynamics applies once after them; that must
    // give the forces, H v and system of each effect applying its own, up to rounding.
    namespace mech = enteron::mechanics;
    using enteron::collision::EnvironmentForce;
    using enteron::collision::Obstacle;
    using enteron::collision::ObstacleKind;
    auto* memory = std::pmr::new_delete_resource();
    Axis axis(u_turn(1.8 * kRadius));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> speed(-0.05, 0.05);
    for (double& v : axis.state.v) v = speed(random);
    Obstacle floor;
    floor.kind = ObstacleKind::plane;
    floor.center = {0.0, 0.0, -0.6 * kRadius};
    floor.extent = {0.0, 0.0, 1.0};
    mech::RigidFrames frames(memory);  // the floor's, at rest
    ContactParameters contact;
    contact.damping_depth = 0.1 * kRadius;
    const std::size_t m = axis.state.q.size();
    const double h = 1e-3;
    struct Result {
        mech::SystemMatrix system;
        std::vector<double> force, hv;
    };
    const auto fresh = [&] {
        Result r{mech::SystemMatrix(memory), std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
        r.system.resize(m);
        return r;
    };

    // Each effect with loads of its own, applied after it.
    CollisionSpheres spheres_apart = axis.make_spheres();
    SphereLoads floor_loads(spheres_apart, memory), self_loads(spheres_apart, memory);
    EnvironmentForce floor_apart(spheres_apart, contact, frames, axis.state, memory, floor_loads);
    floor_apart.add_obstacle(floor);
    SelfContactForce self_apart(spheres_apart, contact, axis.state, memory, self_loads);
    Result apart = fresh();
    mech::Linearization lin_apart{&apart.system, h, apart.hv.data()};
    evaluate_with_loads(floor_apart, floor_loads, axis.state, apart.force.data(), &lin_apart);
    evaluate_with_loads(self_apart, self_loads, axis.state, apart.force.data(), &lin_apart);
    ContactSummary contacts;
    floor_apart.add_contacts(contacts);
    self_apart.add_contacts(contacts);
    ASSERT_GT(contacts.count, 20u);

    // Both into one set of loads: nothing reaches the forces until the loads are applied.
    CollisionSpheres spheres_shared = axis.make_spheres();
    SphereLoads loads(spheres_shared, memory);
    EnvironmentForce floor_shared(spheres_shared, contact, frames, axis.state, memory, loads);
    floor_shared.add_obstacle(floor);
    SelfContactForce self_shared(spheres_shared, contact, axis.state, memory, loads);
    Result shared = fresh();
    mech::Linearization lin_shared{&shared.system, h, shared.hv.data()};
    loads.clear();
    floor_shared.evaluate(axis.state, shared.force.data(), &lin_shared);
    self_shared.evaluate(axis.state, shared.force.data(), &lin_shared);
    for (double f : shared.force) ASSERT_EQ(f, 0.0);
    loads.apply(shared.force.data(), &lin_shared);

    // The same through Dynamics, which clears the loads before the effects and applies them after.
    CollisionSpheres spheres_dynamics = axis.make_spheres();
    SphereLoads dynamics_loads(spheres_dynamics, memory);
    mech::Dynamics dynamics(axis.model, memory);
    auto floor_dynamics = enteron::make_owned<EnvironmentForce>(memory, spheres_dynamics, contact, frames, axis.state,
                                                                memory, dynamics_loads);
    floor_dynamics->add_obstacle(floor);
    dynamics.add_effect(std::move(floor_dynamics));
    dynamics.add_effect(enteron::make_owned<SelfContactForce>(memory, spheres_dynamics, contact, axis.state, memory,
                                                              dynamics_loads));
    dynamics.add_shared_loads(&dynamics_loads, enteron::mechanics::EffectId::self_collision);
    dynamics.finalize();
    Result through = fresh();
    mech::Linearization lin_through{&through.system, h, through.hv.data()};
    for (int round = 0; round < 2; ++round) {  // a second evaluation must not keep the first's loads
        std::fill(through.force.begin(), through.force.end(), 0.0);
        through.system.set_zero();
        dynamics.forces(axis.state, through.force.data(), &lin_through);
    }

    double force_scale = 0.0, hv_scale = 0.0, system_scale = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
        force_scale = std::max(force_scale, std::fabs(apart.force[k]));
        hv_scale = std::max(hv_scale, std::fabs(apart.hv[k]));
        for (std::size_t j = 0; j < m; ++j) system_scale = std::max(system_scale, std::fabs(apart.system.at(k, j)));
    }
    ASSERT_GT(force_scale, 0.0);
    ASSERT_GT(hv_scale, 0.0);
    ASSERT_GT(system_scale, 0.0);
    for (const Result* other : {&shared, &through})
        for (std::size_t k = 0; k < m; ++k) {
            EXPECT_NEAR(other->force[k], apart.force[k], 1e-12 * force_scale) << k;
            EXPECT_NEAR(other->hv[k], apart.hv[k], 1e-12 * hv_scale) << k;
            for (std::size_t j = k >= 11 ? k - 11 : 0; j <= k; ++j)
                EXPECT_NEAR(other->system.at(k, j), apart.system.at(k, j), 1e-12 * system_scale) << k << ", " << j;
        }
    // The loads' time counts as the self-contact's.
    EXPECT_EQ(dynamics.counters(enteron::mechanics::EffectId::self_collision).calls, 2u);
    EXPECT_GT(dynamics.counters(enteron::mechanics::EffectId::self_collision).total_time_ns, 0u);
}

}  // namespace
