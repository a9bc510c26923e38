// SPDX-License-Identifier: Apache-2.0
// The bdf2 integrator's history and order reduction (lib/mechanics/bdf2.h): a rolled-back
// step is retried with implicit Euler steps from the history it had; the first substep, a
// restart, a substep grown beyond the zero-stable ratio and the substep after a change of
// the contacts are implicit Euler steps, to the bit.
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

AxisModel bdf2_model() {
    AxisModel m;
    m.control_points = kPoints;
    m.rest_segment_length = 0.05;
    m.linear_density = 0.3;
    return m;
}

// A horizontal elastic bowel under gravity (it bends and stretches: every term of the
// method is exercised).
struct Bowel {
    explicit Bowel(std::pmr::memory_resource* memory) : dynamics(bdf2_model(), memory), state(memory) {
        dynamics.add_effect(make_owned<StretchForce>(memory, bdf2_model(), 100.0, memory));
        dynamics.add_effect(make_owned<BendForce>(memory, bdf2_model(), 2.5e-3, memory));
        dynamics.add_effect(make_owned<GravityForce>(memory, bdf2_model(), Vec3(0.0, 0.0, -9.81), memory));
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

// A stand-in for the contact effects: no force, and as many contacts as it is told.
class Contacts final : public Effect {
public:
    EffectId id() const override { return EffectId::environment; }
    void evaluate(const State&, double*, const Linearization*) override {}
    void add_contacts(ContactSummary& summary) const override { summary.count += count; }
    uint32_t count = 0;
};

// The bowel, and a second one to take implicit Euler steps from the same state.
struct Pair {
    explicit Pair(std::pmr::memory_resource* memory)
        : a(memory), b(memory), method(bdf2_model(), memory), euler(bdf2_model(), memory) {}
    // Both bowels at a's state; then one substep of h each, bdf2 on a, implicit Euler on b.
    void step_both(double h) {
        b.state.assign(a.state);
        ASSERT_TRUE(method.step(a.dynamics, a.state, h));
        ASSERT_TRUE(euler.step(b.dynamics, b.state, h));
    }
    Bowel a, b;
    Bdf2 method;
    ImplicitEuler euler;
};

TEST(Bdf2, TheFirstStepAndARestartAreImplicitEulerSteps) {
    Pair p(std::pmr::new_delete_resource());
    const double h = 1e-3;
    p.step_both(h);
    EXPECT_TRUE(same_bits(p.a.state, p.b.state));
    for (int k = 0; k < 20; ++k) ASSERT_TRUE(p.method.step(p.a.dynamics, p.a.state, h));
    p.step_both(h);  // second order: not implicit Euler
    EXPECT_FALSE(same_bits(p.a.state, p.b.state));
    p.method.restart();
    EXPECT_FALSE(p.method.second_order_next(h));
    p.step_both(h);
    EXPECT_TRUE(same_bits(p.a.state, p.b.state));
}

TEST(Bdf2, ARolledBackStepIsRetriedAtFirstOrderFromTheHistoryItHad) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Pair plain(memory), rolled(memory);
    const double h = 1e-3;
    for (int k = 0; k < 5; ++k) {
        plain.method.save_history();
        rolled.method.save_history();
        ASSERT_TRUE(plain.method.step(plain.a.dynamics, plain.a.state, h));
        ASSERT_TRUE(rolled.method.step(rolled.a.dynamics, rolled.a.state, h));
    }
    // A step of the scene that the guard rejects: two substeps of another length, then the
    // state and the history as they were.
    State backup(memory);
    backup.resize(kPoints);
    backup.assign(rolled.a.state);
    rolled.method.save_history();
    ASSERT_TRUE(rolled.method.step(rolled.a.dynamics, rolled.a.state, 3e-3));
    ASSERT_TRUE(rolled.method.step(rolled.a.dynamics, rolled.a.state, 3e-3));
    rolled.a.state.assign(backup);
    rolled.method.restore_history();
    // The retry (its two halved substeps) is implicit Euler's, to the bit.
    EXPECT_FALSE(rolled.method.second_order_next(h / 2));
    for (int k = 0; k < 2; ++k) {
        rolled.step_both(h / 2);
        EXPECT_TRUE(same_bits(rolled.a.state, rolled.b.state));
    }
    // The restored history is the one before the rejected step: taken up again (the scene's
    // next step), it gives the steps the method would have taken without the rejection.
    rolled.a.state.assign(backup);
    rolled.method.restore_history();
    rolled.method.save_history();
    for (int k = 0; k < 5; ++k) {
        plain.method.save_history();
        rolled.method.save_history();
        ASSERT_TRUE(plain.method.step(plain.a.dynamics, plain.a.state, h));
        ASSERT_TRUE(rolled.method.step(rolled.a.dynamics, rolled.a.state, h));
    }
    EXPECT_TRUE(same_bits(plain.a.state, rolled.a.state));
}

TEST(Bdf2, ASubstepGrowingBeyondTheZeroStableRatioIsFirstOrder) {
    Pair p(std::pmr::new_delete_resource());
    const double h = 1e-3;
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(p.method.step(p.a.dynamics, p.a.state, h));
    EXPECT_TRUE(p.method.second_order_next(2.4 * h));
    EXPECT_TRUE(p.method.second_order_next(0.25 * h));
    EXPECT_FALSE(p.method.second_order_next(2.5 * h));
    p.step_both(2.5 * h);
    EXPECT_TRUE(same_bits(p.a.state, p.b.state));
    // From there on, at a constant substep, second order again.
    EXPECT_TRUE(p.method.second_order_next(2.5 * h));
}

TEST(Bdf2, TheSubstepAfterAContactBeganOrEndedIsFirstOrder) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    Pair p(memory);
    Contacts* contacts[2];
    Bowel* bowels[2] = {&p.a, &p.b};
    for (int k = 0; k < 2; ++k) {
        auto effect = make_owned<Contacts>(memory);
        contacts[k] = effect.get();
        bowels[k]->dynamics.add_effect(std::move(effect));
        bowels[k]->dynamics.finalize();
    }
    const double h = 1e-3;
    // The bowel starts in contact: the first substep is implicit Euler's, and so is the
    // second (its history reaches back to before the contact, where there was none).
    contacts[0]->count = contacts[1]->count = 1;
    for (int k = 0; k < 2; ++k) {
        EXPECT_FALSE(p.method.second_order_next(h));
        p.step_both(h);
        EXPECT_TRUE(same_bits(p.a.state, p.b.state));
    }
    EXPECT_TRUE(p.method.second_order_next(h));
    for (const uint32_t count : {0u, 1u}) {  // the contact ends, then begins again
        contacts[0]->count = contacts[1]->count = count;
        p.step_both(h);  // its evaluation finds the change: still second order
        EXPECT_FALSE(same_bits(p.a.state, p.b.state));
        EXPECT_FALSE(p.method.second_order_next(h));
        p.step_both(h);
        EXPECT_TRUE(same_bits(p.a.state, p.b.state));
        EXPECT_TRUE(p.method.second_order_next(h));
    }
}

}  // namespace
}  // namespace enteron::mechanics
