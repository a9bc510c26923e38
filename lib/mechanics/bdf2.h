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
// h -> beta. Without history (the first substep, or after restart()) w = 0: a = 0,
// beta = h, one implicit Euler step. L-stable like implicit Euler, but second order, so it
// damps the slow modes far less (docs/accuracy.md).
//
// The history (q_{n-1}, v_{n-1}, h_{n-1}) is state: the scene saves it with each step's
// backup and restores it with a rolled-back state (save_history / restore_history).
#pragma once

#include "mechanics/axial_blocks.h"
#include "mechanics/integrator.h"

namespace enteron::mechanics {

class Bdf2 final : public Integrator {
public:
    Bdf2(const AxisModel& model, std::pmr::memory_resource* memory);
    bool step(Dynamics& dynamics, State& state, double h) override;
    double stability_interval() const override { return std::numeric_limits<double>::infinity(); }
    void save_history() override;
    void restore_history() override;
    void restart() override { history_.valid = false; }

private:
    // The substep before the current one: its start state and length.
    struct History {
        explicit History(std::size_t coordinates, std::pmr::memory_resource* memory)
            : q(coordinates, 0.0, memory), v(coordinates, 0.0, memory) {}
        void assign(const History& other);
        std::pmr::vector<double> q;  // q_{n-1}, m
        std::pmr::vector<double> v;  // v_{n-1}, m/s
        double h = 0.0;              // h_{n-1}, s
        bool valid = false;
    };

    SystemMatrix system_;
    AxialBlocks axial_;
    State predicted_;                                    // q*, v_n: where F and its linearisation are taken
    std::pmr::vector<double> rhs_;                       // F, then the right-hand side, then dv
    std::pmr::vector<double> velocity_difference_;       // v_n - v_{n-1}
    std::pmr::vector<double> history_momentum_;          // M (v_n - v_{n-1})
    std::pmr::vector<double> stiffness_times_velocity_;  // H v (asked of the effects; unused)
    History history_;
    History saved_history_;  // history_ at the start of the scene's step, for a rollback
};

}  // namespace enteron::mechanics
