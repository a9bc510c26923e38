// SPDX-License-Identifier: Apache-2.0
// Statics: a cantilever under its own weight, against Euler-Bernoulli beam theory.
//
// A straight horizontal bowel of length L = 0.5 m has its first two control points pinned (a
// clamped end: with the linear phantom point the end tangent is the chord q1 - q0, so pinning
// q0 and q1 fixes both the position and the slope at s = 0). Gravity loads it uniformly with
// w = mu g; the tip deflection of a clamped-free beam is w L^4 / (8 EI).
//
// Load: with the stiffnesses asked for (EA = 1e4 N, EI = 1e-2 N m^2) and mu = 0.3 kg/m under
// full gravity, w L^4 / (8 EI) would be 2.3 m, far outside small-deflection theory. The model is
// geometrically nonlinear, so gravity is scaled down to g = 0.01 m/s^2: deflection 2.3 mm,
// 0.5 % of L, where the nonlinear correction is ~(delta/L)^2 ~ 1e-5 of the deflection.
//
// Expected convergence: pinning q1 also pins the axis point at s = 1 (a distance l0 from the
// clamp), which the true beam does not have: there it has already sagged by about
// w''(0) l0^2 / 2. This extra support stiffens the root and makes the tip deflection too
// small by O(l0 / L), i.e. first order in 1/(N-1). A beam clamped at 0 and also pinned at l0
// has (the stub [0, l0] adds rotational stiffness 4 EI / l0 at the pin, loaded by the moment
// w L'^2 / 2 of the rest, L' = L - l0) the tip deflection
//     w L'^3 L / (8 EI) = (1 - l0/L)^3 w L^4 / (8 EI),
// i.e. a relative error of about 3 l0 / L; what remains is the spline's own discretisation
// error, also first order here (the free end's phantom point makes its end tangent the end
// chord).
//
// Measured (N = 10, 20, 40):
//   tip 1.5674e-3, 1.9457e-3, 2.1426e-3 m vs 2.34375e-3 m analytic;
//   relative error 0.3313, 0.1698, 0.0858 (ratios 1.95, 1.98: first order);
//   relative error against the clamped-and-pinned-at-l0 beam 0.047, 0.023, 0.012.
// The bounds are twice those, and each doubling of N must divide the error by at least 1.6.
//
// Settling: implicit Euler with a 20 ms substep and drag near critical for the first mode
// (omega_1 = 1.875^2 sqrt(EI / (mu L^4)) = 2.57 rad/s; drag 1.5 N s/m^2 gives zeta ~ 1); the
// higher modes are damped by the integrator itself (h omega >> 1). Stepped until the tip moves
// less than 1e-13 m per step.
#include "capi_test_support.h"

using namespace capi_test;

namespace {

constexpr double kStaticsLength = 0.5;
constexpr double kStaticsDensity = 0.3;
constexpr double kEA = 1e4;
constexpr double kEI = 1e-2;
constexpr double kStaticsGravity = 0.01;

struct Deflection {
    double tip;        // m, downward
    int steps;         // to settle
    bool settled;
};

Deflection settle_cantilever(uint32_t n) {
    // (Wall time: about 350 implicit steps per N, well under a second in all.)
    static const uint32_t clamp[2] = {0, 1};
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) | ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) |
                   ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = n;
    desc.length_m = kStaticsLength;
    desc.linear_density_kg_per_m = kStaticsDensity;
    desc.stretch_stiffness_N = kEA;
    desc.bend_stiffness_N_m2 = kEI;
    desc.shape = ENT_SHAPE_LINE;
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.timestep_s = 0.02;
    desc.gravity_m_per_s2[0] = 0.0;
    desc.gravity_m_per_s2[1] = 0.0;
    desc.gravity_m_per_s2[2] = -kStaticsGravity;
    desc.drag_N_s_per_m2 = 1.5;
    desc.stretch_damping_N_s = 0.5;
    desc.bend_damping_N_m2_s = 0.0;
    desc.pinned_points = clamp;
    desc.pinned_point_count = 2;
    ScenePtr scene = create(desc);
    if (!scene) return {0.0, 0, false};
    const double z0 = control_points(scene.get())[3 * (n - 1) + 2];
    double previous = z0;
    for (int k = 1; k <= 20000; ++k) {
        if (ent_scene_step(scene.get(), 0.02) != ENT_OK) {
            ADD_FAILURE() << "N " << n << " step " << k << ": " << ent_last_error();
            return {0.0, k, false};
        }
        const double z = control_points(scene.get())[3 * (n - 1) + 2];
        if (k > 50 && std::fabs(z - previous) < 1e-13) return {z0 - z, k, true};
        previous = z;
    }
    return {z0 - previous, 20000, false};
}

TEST(Statics, CantileverTipDeflectionConvergesToBeamTheory) {
    const double w = kStaticsDensity * kStaticsGravity;
    const double analytic = w * std::pow(kStaticsLength, 4) / (8.0 * kEI);
    const uint32_t counts[] = {10, 20, 40};
    const double bounds[] = {0.66, 0.34, 0.17};               // against the clamped beam
    const double pinned_root_bounds[] = {0.094, 0.046, 0.024};  // against clamp + pin at l0
    double previous_error = 0.0;
    for (int k = 0; k < 3; ++k) {
        const uint32_t n = counts[k];
        const Deflection d = settle_cantilever(n);
        ASSERT_TRUE(d.settled) << "N " << n << " did not settle in " << d.steps << " steps";
        const double error = std::fabs(d.tip - analytic) / analytic;
        const double l0 = kStaticsLength / double(n - 1);
        const double pinned_root = std::pow(1.0 - l0 / kStaticsLength, 3) * analytic;
        const double pinned_root_error = std::fabs(d.tip - pinned_root) / pinned_root;
        std::printf("N %u: tip %.6e m, analytic %.6e m, error %.4f, vs clamp + pin at l0 %.4f, %d steps\n", n,
                    d.tip, analytic, error, pinned_root_error, d.steps);
        EXPECT_GT(d.tip, 0.0) << "N " << n << ": it must sag";
        EXPECT_LT(d.tip, analytic) << "N " << n << ": the pinned root can only stiffen it";
        EXPECT_LT(error, bounds[k]) << "N " << n;
        EXPECT_LT(pinned_root_error, pinned_root_bounds[k]) << "N " << n;
        if (k > 0) {
            EXPECT_GT(previous_error / error, 1.6) << "N " << n << ": the error must fall like 1/N";
        }
        previous_error = error;
    }
}

}  // namespace
