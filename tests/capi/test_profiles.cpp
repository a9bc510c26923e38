// SPDX-License-Identifier: Apache-2.0
// Properties along the length (docs/scene-json.md, "Properties along the length").
//
// Hanging tube: a straight bowel of length L hangs from its pinned first end under gravity g.
// At rest the tension at s carries the weight below, T(s) = g m(s) with m(s) the integral of
// mu over [s, L], and the stretch law T = EA eps gives the tip's drop below its rest place
//     delta = integral over [0, L] of g m(s) / EA(s) ds,
// for mu = a + b s and a constant EA: (g / EA)(a L^2 / 2 + b L^3 / 3). The reference is that
// integral, taken here by Simpson's rule on 20000 intervals (independent of the library's
// quadrature); the library's own error is the spline's discretisation (N = 41).
// Measured: density profile 0.11445 m, relative error 6e-9 (a linear density and a constant
// EA: the strain is linear in s, which the spline holds exactly); stiffness profile (knots on
// segment ends) 0.070358 m, relative error 5.5e-6. The bounds are 1e-6 and 1e-4.
// Measured on the floor: the axis within 0.104 mm of R(s) (bound 0.5 mm).
//
// Floor: a tube whose radius falls linearly from 3.5 cm to 1.3 cm (the colon's caecum to its
// sigmoid) lies along a floor: each part rests on its own radius, so its axis rises like the
// profile, within the contact's sinking (mu g spacing / k, about 0.1 mm).
#include <cmath>
#include <functional>

#include "capi_test_support.h"

using namespace capi_test;

namespace {

constexpr double kProfilesLength = 1.0;
constexpr double kProfilesGravity = 9.81;
constexpr uint32_t kProfilesPoints = 41;

// Simpson's rule of f over [0, L].
double simpson(const std::function<double(double)>& f, double length) {
    constexpr int kIntervals = 20000;
    const double h = length / kIntervals;
    double sum = f(0.0) + f(length);
    for (int k = 1; k < kIntervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * f(k * h);
    return sum * h / 3.0;
}

struct Hanging {
    double drop = 0.0;  // m
    bool settled = false;
};

// Hangs the tube (its density and stiffness as profiles of pairs, or null) and settles it.
Hanging hang(const double* density, uint32_t density_pairs, const double* stiffness, uint32_t stiffness_pairs,
             double constant_density, double constant_stiffness) {
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) |
                   ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = kProfilesPoints;
    desc.length_m = kProfilesLength;
    desc.linear_density_kg_per_m = constant_density;
    desc.stretch_stiffness_N = constant_stiffness;
    desc.linear_density_profile_kg_per_m = density;
    desc.linear_density_profile_count = density_pairs;
    desc.stretch_stiffness_profile_N = stiffness;
    desc.stretch_stiffness_profile_count = stiffness_pairs;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_direction[0] = 0.0;
    desc.shape_direction[2] = -1.0;
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.timestep_s = 0.005;
    desc.gravity_m_per_s2[2] = -kProfilesGravity;
    desc.drag_N_s_per_m2 = 2.0;
    desc.stretch_damping_N_s = 0.5;
    desc.pinned_ends = ENT_PIN_FIRST;
    ScenePtr scene = create(desc);
    if (!scene) return {};
    const double rest_tip = control_points(scene.get())[3 * (kProfilesPoints - 1) + 2];
    double previous = rest_tip;
    for (int k = 1; k <= 40000; ++k) {
        if (ent_scene_step(scene.get(), 0.005) != ENT_OK) return {};
        const double tip = control_points(scene.get())[3 * (kProfilesPoints - 1) + 2];
        if (k > 200 && std::fabs(tip - previous) < 1e-12) return {rest_tip - tip, true};
        previous = tip;
    }
    return {rest_tip - previous, false};
}

}  // namespace

TEST(Profiles, AHangingTubeStretchesAsItsDensityProfileLoadsIt) {
    // mu = 0.2 + 0.4 s kg/m (the heavy end down), EA = 20 N.
    const double density[4] = {0.0, 0.2, kProfilesLength, 0.6};
    constexpr double kEA = 20.0;
    const double a = 0.2, b = 0.4;
    const double mass = a * kProfilesLength + 0.5 * b * kProfilesLength * kProfilesLength;
    const double reference = simpson([&](double s) { return kProfilesGravity * (mass - (a * s + 0.5 * b * s * s)) / kEA; },
                                     kProfilesLength);
    const double closed_form = kProfilesGravity / kEA * (a * kProfilesLength * kProfilesLength / 2 + b * kProfilesLength * kProfilesLength * kProfilesLength / 3);
    ASSERT_NEAR(reference, closed_form, 1e-9 * closed_form);
    const Hanging hung = hang(density, 2, nullptr, 0, 0.3, kEA);
    ASSERT_TRUE(hung.settled);
    const double error = std::fabs(hung.drop - reference) / reference;
    std::printf("[ density profile ] drop %.6g m, closed form %.6g m, relative error %.3g\n", hung.drop, reference,
                error);
    EXPECT_LT(error, 1e-6);
    // The same mass spread evenly drops 14 % less: the test tells the profile from its mean.
    const double even = kProfilesGravity * mass * kProfilesLength / (2 * kEA);
    EXPECT_GT(std::fabs(hung.drop - even) / reference, 0.1);
}

TEST(Profiles, AHangingTubeStretchesAsItsStiffnessProfileAllows) {
    // mu = 0.4 kg/m, EA = 40 N at the top down to 10 N at the tip (piecewise linear, 3 knots).
    const double stiffness[6] = {0.0, 40.0, 0.5, 25.0, kProfilesLength, 10.0};
    constexpr double kMu = 0.4;
    const auto ea = [&](double s) { return s < 0.5 ? 40.0 - 30.0 * s : 25.0 - 30.0 * (s - 0.5); };
    const double reference = simpson([&](double s) { return kProfilesGravity * kMu * (kProfilesLength - s) / ea(s); }, kProfilesLength);
    const Hanging hung = hang(nullptr, 0, stiffness, 3, kMu, 100.0);
    ASSERT_TRUE(hung.settled);
    const double error = std::fabs(hung.drop - reference) / reference;
    std::printf("[ stiffness profile ] drop %.6g m, integral %.6g m, relative error %.3g\n", hung.drop, reference,
                error);
    EXPECT_LT(error, 1e-4);
    // The largest stiffness everywhere (what the constant reads back as) drops far less.
    const double stiffest = kProfilesGravity * kMu * kProfilesLength * kProfilesLength / (2 * 40.0);
    EXPECT_GT(std::fabs(hung.drop - stiffest) / reference, 0.3);
}

TEST(Profiles, EachPartOfATubeOnAFloorRestsOnItsOwnRadius) {
    const double radius[4] = {0.0, 0.035, 1.5, 0.013};
    ent_scene_desc desc = default_desc();
    desc.control_points = 61;
    desc.length_m = 1.5;
    desc.radius_profile_m = radius;
    desc.radius_profile_count = 2;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[2] = 0.036;  // above the floor by the largest radius (and 1 mm)
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.drag_N_s_per_m2 = 1.0;
    ScenePtr scene = create(desc);
    ASSERT_TRUE(scene);
    ent_obstacle_desc floor;
    ent_obstacle_desc_default(&floor);
    floor.kind = ENT_OBSTACLE_PLANE;
    int32_t index = -1;
    ASSERT_EQ(ent_scene_add_obstacle(scene.get(), &floor, &index), ENT_OK) << ent_last_error();
    ASSERT_TRUE(step_n(scene.get(), 0.001, 1500));
    const std::vector<double> q = control_points(scene.get());
    const double l0 = 1.5 / 60.0;
    double worst = 0.0;
    for (uint32_t j = 2; j + 2 < 61; ++j) {
        const double s = l0 * j;
        const double expected = 0.035 + (0.013 - 0.035) * s / 1.5;
        worst = std::max(worst, std::fabs(q[3 * j + 2] - expected));
    }
    std::printf("[ floor ] largest |z - R(s)| %.3g mm\n", 1e3 * worst);
    // Within 0.5 mm; a constant radius (of the largest, 3.5 cm) would be 2 cm off at the tip.
    EXPECT_LT(worst, 5e-4);
    // The description reads back the largest radius, without the arrays.
    ent_scene_desc read = default_desc();
    ASSERT_EQ(ent_scene_read_desc(scene.get(), &read), ENT_OK) << ent_last_error();
    EXPECT_EQ(read.radius_m, 0.035);
    EXPECT_EQ(read.radius_profile_m, nullptr);
    EXPECT_EQ(read.radius_profile_count, 0u);
}
