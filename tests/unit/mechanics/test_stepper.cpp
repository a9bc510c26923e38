// SPDX-License-Identifier: Apache-2.0
// The step transaction (lib/mechanics/stepper.h) on a small elastic axis under gravity,
// for every integrator: its hooks run in the order of the step; a rejected attempt is retried
// from exactly the step's start with twice the substeps; a step that stays unstable leaves
// everything (the state, the integrator's history, the effects, the frames) as it was, so
// that the next step gives the bits it would have given without it; a bad dt is refused
// with nothing changed; a state set from outside restarts a multistep integrator; a saved
// stepper restored into another continues to the bit.
#include "mechanics/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory_resource>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/memory.h"
#include "base/state_io.h"
#include "mechanics/driven_effect.h"
#include "mechanics/gravity_force.h"
#include "mechanics/stretch_force.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kStepperPoints = 8;
constexpr double kLength = 0.4;  // m
constexpr double kDt = 1e-3;     // s

AxisModel stepper_model() {
    AxisModel m;
    m.control_points = kStepperPoints;
    m.rest_segment_length = kLength / double(kStepperPoints - 1);
    m.linear_density = 0.3;
    return m;
}

// An effect driven from outside that records the hooks it sees (a tool's, in miniature) and,
// while `kicks` is above zero, throws control point 3 with a force far past what the guard
// lets through, once per attempt: each attempt it spoils uses one kick.
class Kicker final : public DrivenEffect {
public:
    explicit Kicker(std::vector<std::string>& log) : log_(log) {}
    EffectId id() const override { return EffectId::tools; }
    void evaluate(const State&, double* force, const Linearization*) override {
        if (kicking_) force[3 * 3 + 2] += 1e6;  // N
    }
    bool take_commands(const State&, double) override {
        log_.push_back("take_commands");
        return false;
    }
    void begin_step(double) override { log_.push_back("begin_step"); }
    void begin_attempt() override {
        log_.push_back("begin_attempt");
        kicking_ = kicks > 0;
        if (kicking_) --kicks;
        evaluations = 0;
    }
    void evaluation_used(double, const State*) override { ++evaluations; }
    std::size_t border_bodies() const override { return 0; }
    void end_step(bool accepted) override { log_.push_back(accepted ? "accepted" : "failed"); }

    int kicks = 0;
    int evaluations = 0;  // used in the current attempt

private:
    std::vector<std::string>& log_;
    bool kicking_ = false;
};

// An axis hanging from nothing, stretched along x, falling: every integrator has work to do.
struct Bench {
    Bench(IntegratorKind integrator, double timestep = kDt)
        : memory(std::pmr::new_delete_resource()), frames(memory), dynamics(stepper_model(), memory),
          stepper(dynamics, frames, settings(integrator, timestep), Logger(), memory) {
        dynamics.add_effect(make_owned<StretchForce>(memory, stepper_model(), 100.0, memory));
        dynamics.add_effect(make_owned<GravityForce>(memory, stepper_model(), Vec3(0.0, 0.0, -9.81), memory));
        kicker = &dynamics.add_effect(make_owned<Kicker>(memory, log));
        State& state = stepper.state();
        for (std::size_t i = 0; i < kStepperPoints; ++i) state.q[3 * i] = 1.05 * stepper_model().rest_segment_length * double(i);
        frame = frames.add(RigidPose{});
        stepper.effects_changed();
    }

    static StepperSettings settings(IntegratorKind integrator, double timestep) {
        StepperSettings s;
        s.integrator = integrator;
        s.timestep = timestep;
        s.total_mass = 0.3 * kLength;
        return s;
    }

    std::pmr::memory_resource* memory;
    std::vector<std::string> log;
    RigidFrames frames;
    Dynamics dynamics;
    Stepper stepper;
    Kicker* kicker = nullptr;
    std::size_t frame = 0;
};

bool stepper_same_bits(const State& a, const State& b) {
    return a.time == b.time && std::memcmp(a.q.data(), b.q.data(), a.q.size() * sizeof(double)) == 0 &&
           std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(double)) == 0;
}

const IntegratorKind kIntegrators[] = {IntegratorKind::rk4, IntegratorKind::symplectic_euler,
                                       IntegratorKind::implicit_euler, IntegratorKind::bdf2};

const char* stepper_name(IntegratorKind kind) {
    switch (kind) {
        case IntegratorKind::rk4: return "rk4";
        case IntegratorKind::symplectic_euler: return "symplectic_euler";
        case IntegratorKind::implicit_euler: return "implicit_euler";
        case IntegratorKind::bdf2: return "bdf2";
    }
    return "?";
}

TEST(Stepper, TheHooksRunInTheOrderOfTheStep) {
    Bench bench(IntegratorKind::implicit_euler);
    bench.kicker->kicks = 1;  // the first attempt is rejected
    ASSERT_TRUE(bench.stepper.step(kDt));
    const std::vector<std::string> expected = {"take_commands", "begin_step", "begin_attempt", "begin_attempt",
                                               "accepted"};
    EXPECT_EQ(bench.log, expected);
    EXPECT_EQ(bench.kicker->evaluations, 2) << "the retry takes twice the substeps, each evaluation used once";
    EXPECT_EQ(bench.stepper.counters().steps, 1u);
    EXPECT_EQ(bench.stepper.counters().substeps, 3u) << "the rejected attempt's substep counts too";
    EXPECT_EQ(bench.stepper.guard().rollbacks(), 1u);
    // What the step did (ent_stats): two attempts, three substeps, one subdivided step.
    EXPECT_EQ(bench.stepper.counters().last_step_attempts, 2u);
    EXPECT_EQ(bench.stepper.counters().last_step_substeps, 3u);
    EXPECT_EQ(bench.stepper.counters().subdivided_steps, 1u);
    EXPECT_GE(bench.stepper.counters().max_step_ns, bench.stepper.counters().last_step_ns);
}

// A retry starts from the step's start: it gives the bits of a step that took its two
// substeps at once. bdf2 retries at first order (bdf2.h), which is implicit Euler's step.
TEST(Stepper, ARejectedAttemptIsRetriedFromTheStepsStartWithTwiceTheSubsteps) {
    for (IntegratorKind kind : kIntegrators) {
        Bench rolled(kind);
        rolled.kicker->kicks = 1;
        ASSERT_TRUE(rolled.stepper.step(kDt)) << stepper_name(kind);
        Bench twin(kind == IntegratorKind::bdf2 ? IntegratorKind::implicit_euler : kind, kDt / 2);
        ASSERT_TRUE(twin.stepper.step(kDt)) << stepper_name(kind);
        EXPECT_TRUE(stepper_same_bits(rolled.stepper.state(), twin.stepper.state())) << stepper_name(kind);
        EXPECT_EQ(rolled.stepper.guard().rollbacks(), 1u) << stepper_name(kind);
    }
}

// Every attempt rejected: step() says so with the state, the integrator's history (bdf2's),
// the effects and the frames as they were, and the next step gives the bits it would have
// given had the failed one never been tried.
TEST(Stepper, AStepThatStaysUnstableLeavesEverythingAsItWasForTheNextStep) {
    for (IntegratorKind kind : kIntegrators) {
        Bench failed(kind), twin(kind);
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(failed.stepper.step(kDt)) << stepper_name(kind);
            ASSERT_TRUE(twin.stepper.step(kDt)) << stepper_name(kind);
        }
        const State before = failed.stepper.state();
        const StepCounters counters = failed.stepper.counters();
        RigidPose moved;
        moved.position = Vec3(0.01, 0.0, 0.0);
        failed.frames.set_target(failed.frame, moved);
        twin.frames.set_target(twin.frame, moved);
        failed.log.clear();
        failed.kicker->kicks = 100;  // more than the attempts
        EXPECT_FALSE(failed.stepper.step(kDt)) << stepper_name(kind);
        EXPECT_TRUE(stepper_same_bits(failed.stepper.state(), before)) << stepper_name(kind);
        EXPECT_NE(failed.stepper.failure().find("stayed unstable after 4 subdivisions"), std::string::npos)
            << failed.stepper.failure();
        EXPECT_EQ(failed.stepper.counters().steps, counters.steps) << stepper_name(kind);
        EXPECT_EQ(failed.stepper.counters().substeps, counters.substeps + 1 + 2 + 4 + 8 + 16) << stepper_name(kind);
        EXPECT_EQ(failed.stepper.guard().rollbacks(), 5u) << stepper_name(kind);
        // The subdivision budget ran out: every attempt made, and counted as such.
        EXPECT_EQ(failed.stepper.counters().last_step_attempts, 5u) << stepper_name(kind);
        EXPECT_EQ(failed.stepper.counters().last_step_substeps, 1u + 2 + 4 + 8 + 16) << stepper_name(kind);
        EXPECT_EQ(failed.stepper.counters().subdivided_steps, counters.subdivided_steps) << stepper_name(kind);
        EXPECT_EQ(failed.log.back(), "failed");
        EXPECT_EQ(failed.frames.pose(failed.frame).position, Vec3::Zero()) << "the frame stays where it was";
        failed.kicker->kicks = 0;
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(failed.stepper.step(kDt)) << stepper_name(kind);
            ASSERT_TRUE(twin.stepper.step(kDt)) << stepper_name(kind);
            EXPECT_TRUE(stepper_same_bits(failed.stepper.state(), twin.stepper.state())) << stepper_name(kind) << " step " << k;
        }
        EXPECT_EQ(failed.frames.pose(failed.frame).position, moved.position) << "its target kept for the next step";
    }
}

TEST(Stepper, ABadDtIsRefusedWithNothingChanged) {
    Bench bench(IntegratorKind::implicit_euler);
    ASSERT_TRUE(bench.stepper.step(kDt));
    const State before = bench.stepper.state();
    bench.log.clear();
    // max_substeps (1000) substeps of 1 ms at most: 2 s is too long.
    for (double dt : {0.0, -1e-3, std::nan(""), HUGE_VAL, 2.0}) {
        try {
            bench.stepper.step(dt);
            ADD_FAILURE() << "dt " << dt << " was taken";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::invalid_argument) << dt;
            EXPECT_NE(std::string(e.what()).find("dt_s"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(stepper_same_bits(bench.stepper.state(), before));
    EXPECT_TRUE(bench.log.empty()) << "no hook ran";
    EXPECT_EQ(bench.stepper.counters().steps, 1u);
    EXPECT_EQ(bench.stepper.counters().substeps, 1u);
}

// A state set from outside (a pin stopped a point) restarts bdf2: its next step is implicit
// Euler's from that state, not an extrapolation of the motion before.
TEST(Stepper, AStateSetFromOutsideRestartsAMultistepIntegrator) {
    Bench restarted(IntegratorKind::bdf2), going_on(IntegratorKind::bdf2), euler(IntegratorKind::implicit_euler);
    for (int k = 0; k < 5; ++k) {
        ASSERT_TRUE(restarted.stepper.step(kDt));
        ASSERT_TRUE(going_on.stepper.step(kDt));
    }
    euler.stepper.state().assign(restarted.stepper.state());
    restarted.stepper.state_set_from_outside();
    ASSERT_TRUE(restarted.stepper.step(kDt));
    ASSERT_TRUE(going_on.stepper.step(kDt));
    ASSERT_TRUE(euler.stepper.step(kDt));
    EXPECT_TRUE(stepper_same_bits(restarted.stepper.state(), euler.stepper.state()));
    EXPECT_FALSE(stepper_same_bits(going_on.stepper.state(), euler.stepper.state())) << "bdf2 goes on at second order";
}

// What the next step reads, saved and restored into a stepper of the same scene: both go on
// with the same bits, and the counters and the guard's reference come along.
TEST(Stepper, ARestoredStepperContinuesToTheBit) {
    for (IntegratorKind kind : kIntegrators) {
        Bench saved(kind), restored(kind);
        for (int k = 0; k < 5; ++k) ASSERT_TRUE(saved.stepper.step(kDt)) << stepper_name(kind);
        std::vector<unsigned char> image(1 << 16);
        StateWriter out(image.data(), image.size(), 42);
        saved.stepper.save_state(out);
        image.resize(out.finish());
        ASSERT_LE(image.size(), std::size_t{1} << 16);
        StateReader in(image.data(), image.size());
        restored.stepper.restore_state(in);  // checking: nothing changes
        EXPECT_EQ(restored.stepper.counters().steps, 0u);
        in.finish();
        in.start_applying();
        restored.stepper.restore_state(in);
        restored.stepper.restored();
        EXPECT_EQ(restored.stepper.counters().steps, 5u);
        EXPECT_EQ(restored.stepper.guard().reference().kinetic, saved.stepper.guard().reference().kinetic);
        for (int k = 0; k < 5; ++k) {
            ASSERT_TRUE(saved.stepper.step(kDt)) << stepper_name(kind);
            ASSERT_TRUE(restored.stepper.step(kDt)) << stepper_name(kind);
        }
        EXPECT_TRUE(stepper_same_bits(saved.stepper.state(), restored.stepper.state())) << stepper_name(kind);
    }
}

}  // namespace
}  // namespace enteron::mechanics
