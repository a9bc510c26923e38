// SPDX-License-Identifier: Apache-2.0
// Second-order backward differentiation (BDF2) with the linearised Newton step and banded
// solve of implicit_euler.h. With the substep ratio w = h_n / h_{n-1} (variable-step BDF2,
// so a change of dt or a subdivided retry keeps second order) and
//   a = w^2 / (1 + 2w),   beta = h (1 + w) / (1 + 2w)        (w = 1: a = 1/3, beta = 2h/3)
// the method is
//   q_{n+1} = q_n + a (q_n - q_{n-1}) + beta v_{n+1}
//   M v_{n+1} = M (v_n + a (v_n - v_{n-1})) + beta F(q_{n+1}, v_{n+1}).
// One Newton step from the predictor q* = q_n + a (q_n - q_{n-1}) + beta v_n, v_n:
//   (M + beta C + beta^2 H) dv = beta F(q*, v_n) + a M (v_n - v_{n-1}),   v_{n+1} = v_n + dv
// with H, C the effects' linearisation at the predictor: the implicit Euler system with
// h -> beta. L-stable like implicit Euler, but second order, so it damps the slow modes far
// less (docs/accuracy.md).
//
// Order reduction, as variable-order BDF codes do (CVODE, DASSL): a substep is taken at
// first order, as an implicit Euler step (implicit_euler_step), when the history cannot
// be trusted to extrapolate:
//   - there is none (the first substep, or after restart(): the state was set from outside);
//   - the stepper retries a step the stability guard rejected (restore_history() until the
//     next save_history()): the retry is exactly implicit Euler's;
//   - the substep grew by more than kMaxStepRatio (variable-step BDF2 is zero-stable only
//     for w < 1 + sqrt(2)), as in the first step after a subdivided one;
//   - the previous substep's evaluation found a different number of contacts than the one
//     before it (none before the first): a contact began or ended between them, the motion
//     is not smooth there, and extrapolating the velocity from before the change drives
//     the folds deeper into each other (docs/accuracy.md#bdf2: without it a dense pile and
//     coincident spheres gain energy from nothing and 50 ms steps in the cavity fail).
//
// The history (q_{n-1}, v_{n-1}, h_{n-1}, the contacts) is state: the stepper keeps it with
// each step's start and brings it back with a rolled-back state (save_history /
// restore_history), and it is in a saved state (section "bdf2").
#pragma once

#include <cstdint>

#include "mechanics/implicit_euler.h"
#include "mechanics/integrator.h"

namespace enteron::mechanics {

class Bdf2 final : public Integrator {
public:
    // The largest substep ratio h_n / h_{n-1} taken at second order: 1 + sqrt(2), the
    // zero-stability bound of variable-step BDF2 (Grigorieff 1983).
    static constexpr double kMaxStepRatio = 2.414213562373095;

    Bdf2(const AxisModel& model, std::pmr::memory_resource* memory);
    bool step(Dynamics& dynamics, State& state, double h) override;
    double stability_interval() const override { return std::numeric_limits<double>::infinity(); }
    void save_history() override;
    void restore_history() override;
    // Forgets the history; the contacts before the next substep count as none.
    void restart() override {
        history_.valid = false;
        history_.contacts = 0;
    }
    // The history in a saved state (section "bdf2"): a restored scene continues with the
    // same steps.
    void save_state(StateWriter& out) const override;
    void restore_state(StateReader& in) override;

    // Whether the next substep of length h would be taken at second order (the rules above).
    bool second_order_next(double h) const;

private:
    // The substep before the current one: its start state and length, and the contacts its
    // evaluation found.
    struct History {
        explicit History(std::size_t coordinates, std::pmr::memory_resource* memory)
            : q(coordinates, 0.0, memory), v(coordinates, 0.0, memory) {}
        void assign(const History& other);
        std::pmr::vector<double> q;  // q_{n-1}, m
        std::pmr::vector<double> v;  // v_{n-1}, m/s
        double h = 0.0;              // h_{n-1}, s
        bool valid = false;
        uint32_t contacts = 0;        // contacts of the substep's evaluation
        bool contacts_kept = false;   // as many as the evaluation before it found
    };

    // The second-order substep (the formulas above); w = h / h_{n-1}.
    bool second_order_step(Dynamics& dynamics, State& state, double h, double w);

    ImplicitWork work_;  // shared by both orders (rhs: F, then the right-hand side, then dv)
    State predicted_;                                    // q*, v_n: where F and its linearisation are taken
    std::pmr::vector<double> velocity_difference_;       // v_n - v_{n-1}
    std::pmr::vector<double> history_momentum_;          // M (v_n - v_{n-1})
    History history_;
    History saved_history_;  // history_ at the start of the stepper's step, for a rollback
    bool retrying_ = false;  // restore_history() was called in this step of the scene
};

}  // namespace enteron::mechanics
