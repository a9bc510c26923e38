// SPDX-License-Identifier: Apache-2.0
// Dynamics around the step (lib/mechanics/dynamics.h): the effects' step hooks run in order,
// the driven effects' (driven_effect.h) only for them, the border is sized for their bodies,
// and the guard's report finds the effect behind a failure.
#include <gtest/gtest.h>

#include <memory_resource>
#include <string>
#include <vector>

#include "base/memory.h"
#include "mechanics/dynamics.h"
#include "mechanics/gravity_force.h"
#include "mechanics/state.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kDynamicsPoints = 5;

AxisModel dynamics_model() {
    AxisModel m;
    m.control_points = kDynamicsPoints;
    m.rest_segment_length = 0.1;
    m.linear_density = 0.3;
    return m;
}

// Records its hook calls in a shared log; pushes control point `point` with `force` (N) and
// stores `energy` per metre the point has moved along +x.
class Recorder : public Effect {
public:
    Recorder(EffectId id, std::vector<std::string>& log, std::size_t point = 0, double force = 0.0,
             double energy_per_m = 0.0)
        : id_(id), log_(log), point_(point), force_(force), energy_per_m_(energy_per_m) {}
    EffectId id() const override { return id_; }
    void evaluate(const State&, double* force, const Linearization*) override { force[3 * point_] += force_; }
    double potential_energy(const State& state) const override { return energy_per_m_ * state.q[3 * point_]; }
    void begin_step(double dt) override { log_.push_back(dynamics_name() + " begin_step " + std::to_string(dt)); }
    void begin_attempt() override { log_.push_back(dynamics_name() + " begin_attempt"); }

protected:
    std::string dynamics_name() const { return effect_name(id_); }
    EffectId id_;
    std::vector<std::string>& log_;
    std::size_t point_;
    double force_;
    double energy_per_m_;
};

// An effect driven from outside (driven_effect.h) that records its own hooks too.
class DrivenRecorder final : public DrivenEffect {
public:
    DrivenRecorder(EffectId id, std::vector<std::string>& log, bool changes_energy, std::size_t bodies = 0)
        : recorder_(id, log), log_(log), changes_energy_(changes_energy), bodies_(bodies) {}
    EffectId id() const override { return recorder_.id(); }
    void evaluate(const State& state, double* force, const Linearization* lin) override {
        recorder_.evaluate(state, force, lin);
    }
    void begin_step(double dt) override { recorder_.begin_step(dt); }
    void begin_attempt() override { recorder_.begin_attempt(); }
    bool take_commands(const State&, double dt) override {
        log_.push_back(dynamics_name() + " take_commands " + std::to_string(dt));
        return changes_energy_;
    }
    void evaluation_used(double duration, const State* after) override {
        log_.push_back(dynamics_name() + " used " + std::to_string(duration) + (after != nullptr ? " implicit" : " explicit"));
    }
    std::size_t border_bodies() const override { return bodies_; }
    void end_step(bool accepted) override { log_.push_back(dynamics_name() + (accepted ? " accepted" : " aborted")); }

private:
    std::string dynamics_name() const { return effect_name(recorder_.id()); }
    Recorder recorder_;
    std::vector<std::string>& log_;
    bool changes_energy_;
    std::size_t bodies_;
};

TEST(Dynamics, StepHooksRunForEveryEffectInOrderAndTheDrivenOnesOnlyForTheDrivenEffects) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    std::vector<std::string> log;
    Dynamics dynamics(dynamics_model(), memory);
    DrivenRecorder& tools = dynamics.add_effect(make_owned<DrivenRecorder>(memory, EffectId::tools, log, false));
    Recorder& environment = dynamics.add_effect(make_owned<Recorder>(memory, EffectId::environment, log));
    EXPECT_EQ(tools.id(), EffectId::tools) << "add_effect hands back the effect added, typed";
    EXPECT_EQ(environment.id(), EffectId::environment);
    dynamics.finalize();
    State state;
    state.resize(kDynamicsPoints);

    EXPECT_FALSE(dynamics.take_commands(state, 0.5)) << "no effect changed its energy";
    dynamics.begin_step(0.5);
    dynamics.begin_attempt();
    dynamics.evaluation_used(0.25, nullptr);
    dynamics.begin_attempt();
    dynamics.evaluation_used(0.5, &state);
    dynamics.end_step(false);
    dynamics.end_step(true);
    const std::vector<std::string> expected = {
        "tools take_commands 0.500000", "tools begin_step 0.500000", "environment begin_step 0.500000",
        "tools begin_attempt",          "environment begin_attempt", "tools used 0.250000 explicit",
        "tools begin_attempt",          "environment begin_attempt", "tools used 0.500000 implicit",
        "tools aborted",                "tools accepted"};
    EXPECT_EQ(log, expected);
}

TEST(Dynamics, TakeCommandsReportsADrivenEffectThatChangedItsEnergy) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    std::vector<std::string> log;
    Dynamics dynamics(dynamics_model(), memory);
    dynamics.add_effect(make_owned<DrivenRecorder>(memory, EffectId::tools, log, true));
    dynamics.add_effect(make_owned<DrivenRecorder>(memory, EffectId::stretch, log, false));
    dynamics.finalize();
    State state;
    state.resize(kDynamicsPoints);
    EXPECT_TRUE(dynamics.take_commands(state, 1e-3));
    EXPECT_EQ(log.size(), 2u) << "every driven effect's hook runs, also after one reported a change";
}

TEST(Dynamics, TheBorderHoldsTheBodiesOfEveryDrivenEffect) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    std::vector<std::string> log;
    Dynamics dynamics(dynamics_model(), memory);
    dynamics.add_effect(make_owned<DrivenRecorder>(memory, EffectId::tools, log, false, 2));
    dynamics.add_effect(make_owned<DrivenRecorder>(memory, EffectId::environment, log, false, 1));
    dynamics.finalize();
    ASSERT_NE(dynamics.border(), nullptr);
    EXPECT_EQ(dynamics.border()->capacity(), 3u);
}

TEST(Dynamics, TheStrongestForceOnAPointAndTheLargestEnergyGainNameTheirEffects) {
    std::pmr::memory_resource* memory = std::pmr::new_delete_resource();
    std::vector<std::string> log;
    Dynamics dynamics(dynamics_model(), memory);
    dynamics.add_effect(make_owned<GravityForce>(memory, dynamics_model(), enteron::Vec3(0.0, 0.0, -9.81), memory));
    // Pushes point 3 with 100 N, far more than its weight (about 0.3 N); stores 5 J/m.
    dynamics.add_effect(make_owned<Recorder>(memory, EffectId::environment, log, 3, 100.0, 5.0));
    // Pushes point 1 with 0.01 N; stores 1 J/m of point 1's x.
    dynamics.add_effect(make_owned<Recorder>(memory, EffectId::mesentery, log, 1, 0.01, 1.0));
    dynamics.finalize();
    State before;
    before.resize(kDynamicsPoints);

    const Dynamics::Culprit at_3 = dynamics.strongest_force_at(before, 3);
    ASSERT_TRUE(at_3.found);
    EXPECT_EQ(at_3.effect, EffectId::environment);
    EXPECT_NEAR(at_3.amount, 100.0, 1e-12);
    const Dynamics::Culprit at_1 = dynamics.strongest_force_at(before, 1);
    ASSERT_TRUE(at_1.found);
    EXPECT_EQ(at_1.effect, EffectId::gravity) << "gravity's weight on point 1 beats 0.01 N";

    State after = before;
    after.q[3 * 3] = 0.1;  // environment: +0.5 J
    after.q[3 * 1] = 0.2;  // mesentery: +0.2 J
    const Dynamics::Culprit gain = dynamics.largest_energy_gain(before, after);
    ASSERT_TRUE(gain.found);
    EXPECT_EQ(gain.effect, EffectId::environment);
    EXPECT_NEAR(gain.amount, 0.5, 1e-12);
    EXPECT_FALSE(dynamics.largest_energy_gain(after, before).found) << "every effect lost energy";
}

}  // namespace
}  // namespace enteron::mechanics
