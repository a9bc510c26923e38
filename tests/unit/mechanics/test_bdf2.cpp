// The bdf2 integrator's history (lib/mechanics/bdf2.h): a rolled-back step, restored with
// restore_history, leaves the method exactly where it was, and restart() starts it again with
// an implicit Euler step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory_resource>

#include "base/memory.h"
#include "mechanics/bdf2.h"
#include "mechanics/bend_force.h"
#include "mechanics/dynamics.h"
#include "mechanics/gravity_force.h"
#include "mechanics/implicit_euler.h"
#include "mechanics/stretch_force.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kPoints = 12;

AxisModel model() {
    AxisModel m;
    m.control_points = kPoints;
    m.rest_segment_length = 0.05;
    m.linear_density = 0.3;
    return m;
}

// A horizontal elastic bowel under gravity (it bends and stretches: every term of the
// method is exercised).
struct Bowel {
    explicit Bowel(std::pmr::memory_resource* memory) : dynamics(model(), memory), state(memory) {
        dynamics.add_effect(make_owned<StretchForce>(memory, model(), 100.0, memory));
        dynamics.add_effect(make_owned<BendForce>(memory, model(), 2.5e-3, memory));
        dynamics.add_effect(make_owned<GravityForce>(memory, model(), Vec3(0.0, 0.0, -9.81), memory));
        dynamics.finalize();
        state.resize(kPoints);
        for (std::size_t i = 0; i < kPoints; ++i) state.q[3 * i] = 0.05 * static_cast<double>(i);
    }
    Dynamics dynamics;
    State state;
};

bool same_bits(const State& a, const State& b) {
    return std::memcmp(a.q.data(), b.q.data(), a.q.size() * sizeof(double)) == 0 &&
           std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(double)) == 0;
}

TEST(Bdf2, ARolledBackStepLeavesTheMethodWhereItWas) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Bowel plain(memory), rolled(memory);
    Bdf2 plain_method(model(), memory), rolled_method(model(), memory);
    const double h = 1e-3;
    for (int k = 0; k < 5; ++k) {
        ASSERT_TRUE(plain_method.step(plain.dynamics, plain.state, h));
        ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, h));
    }
    // A step of the scene that is rejected: two substeps of another length, then the
    // state and the history as they were.
    State backup(memory);
    backup.resize(kPoints);
    backup.assign(rolled.state);
    rolled_method.save_history();
    ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, 3e-3));
    ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, 3e-3));
    rolled.state.assign(backup);
    rolled_method.restore_history();
    for (int k = 0; k < 5; ++k) {
        ASSERT_TRUE(plain_method.step(plain.dynamics, plain.state, h));
        ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, h));
    }
    EXPECT_TRUE(same_bits(plain.state, rolled.state));

    // Without restore_history the method would go on from the rejected substeps' history.
    rolled_method.save_history();
    backup.assign(rolled.state);
    ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, 3e-3));
    rolled.state.assign(backup);
    ASSERT_TRUE(plain_method.step(plain.dynamics, plain.state, h));
    ASSERT_TRUE(rolled_method.step(rolled.dynamics, rolled.state, h));
    EXPECT_FALSE(same_bits(plain.state, rolled.state));
}

TEST(Bdf2, TheFirstStepAndARestartAreImplicitEulerSteps) {
    // With no history BDF2 is implicit Euler, linearised at the predictor q + h v instead of
    // at q: the two agree to the linearisation's error, O(h^2 |v|^2 |F''|), far below a step's change.
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Bowel a(memory), b(memory);
    Bdf2 bdf2(model(), memory);
    ImplicitEuler euler(model(), memory);
    const double h = 1e-3;
    for (int k = 0; k < 20; ++k) ASSERT_TRUE(bdf2.step(a.dynamics, a.state, h));
    b.state.assign(a.state);
    const std::pmr::vector<double> before = a.state.v;
    bdf2.restart();
    ASSERT_TRUE(bdf2.step(a.dynamics, a.state, h));
    ASSERT_TRUE(euler.step(b.dynamics, b.state, h));
    double difference = 0.0, change = 0.0;
    for (std::size_t k = 0; k < a.state.v.size(); ++k) {
        difference = std::max(difference, std::fabs(a.state.v[k] - b.state.v[k]));
        change = std::max(change, std::fabs(b.state.v[k] - before[k]));
    }
    EXPECT_GT(change, 0.0);
    EXPECT_LT(difference, 1e-6 * change);
}

}  // namespace
}  // namespace enteron::mechanics
