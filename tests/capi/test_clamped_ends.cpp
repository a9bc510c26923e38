// SPDX-License-Identifier: Apache-2.0
// Clamped ends (ent_scene_desc.clamped_ends, JSON pinned.clamped): an end held in place and
// in direction. The reference is the large-deflection cantilever under its own weight: a
// straight horizontal bowel, L = 0.5 m, mu = 0.3 kg/m, EA = 1e4 N, its first end clamped, with
// the load wL^3/EI = 1, 5, 20 (w = mu g). Its static shape is the extensible elastica
//   EI theta'' = (1 + eps) w (L - s) cos theta,   eps = -w (L - s) sin theta / EA,
//   theta(0) = 0 (the clamp), theta'(L) = 0 (no moment at the free end),
// solved here by shooting on theta'(0); the tip's drop is the integral of (1 + eps) sin theta.
// The library's bowel is settled to rest (implicit Euler with drag, which does not change
// the equilibrium) and its tip's drop compared.
//
// Measured (tip drop error, relative; control points N, segment L / (N - 1)):
//   N = 11 (5 cm)      -1.40 %  -2.58 %  -5.08 %    (load 1, 5, 20)
//   N = 21 (2.5 cm)    -0.35 %  -0.55 %  -0.93 %
//   N = 41 (1.25 cm)   -0.09 %  -0.13 %  -0.20 %
// Second order: the error falls about 4x per halving (observed orders 2.0 to 2.5). Pinning control points 0 and 1
// instead (the old workaround) is first order: -16 %, -12.6 %, -7.1 % at 2.5 cm.
#include "capi_test_support.h"

#include <cstdio>

using namespace capi_test;

namespace {

constexpr double kLength = 0.5;           // m
constexpr double kDensity = 0.3;          // kg/m
constexpr double kGravity = 9.81;         // m/s^2
constexpr double kStretchStiffness = 1e4; // EA, N
constexpr double kWeight = kDensity * kGravity;  // w, N/m

// The extensible elastica of the cantilever: the drop of its tip (m, > 0) for EI.
double elastica_tip_drop(double bend_stiffness) {
    constexpr int kSteps = 20000;
    const double h = kLength / kSteps;
    // theta'' as a function of s and theta.
    const auto curvature_rate = [&](double s, double theta) {
        const double axial = -kWeight * (kLength - s) * std::sin(theta);  // tension, N
        return (1.0 + axial / kStretchStiffness) * kWeight * (kLength - s) * std::cos(theta) / bend_stiffness;
    };
    const auto strain = [&](double s, double theta) {
        return -kWeight * (kLength - s) * std::sin(theta) / kStretchStiffness;
    };
    // Integrates (theta, theta', drop) from the clamp with theta'(0) = kappa0 (RK4).
    struct End {
        double rate;  // theta'(L)
        double drop;  // m
    };
    const auto shoot = [&](double kappa0) {
        double theta = 0.0, rate = kappa0, drop = 0.0;
        for (int i = 0; i < kSteps; ++i) {
            const double s = i * h;
            // y = (theta, rate, drop); y' = (rate, curvature_rate, -(1 + eps) sin theta).
            const auto slope = [&](double ss, double th, double r) {
                return std::array<double, 3>{r, curvature_rate(ss, th), -(1.0 + strain(ss, th)) * std::sin(th)};
            };
            const auto k1 = slope(s, theta, rate);
            const auto k2 = slope(s + h / 2, theta + h / 2 * k1[0], rate + h / 2 * k1[1]);
            const auto k3 = slope(s + h / 2, theta + h / 2 * k2[0], rate + h / 2 * k2[1]);
            const auto k4 = slope(s + h, theta + h * k3[0], rate + h * k3[1]);
            theta += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
            rate += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
            drop += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
        }
        return End{rate, drop};
    };
    // theta'(L) > 0 with no moment at the clamp; < 0 with twice the small-deflection one.
    const double load = kWeight * kLength * kLength * kLength / bend_stiffness;
    double low = -load / kLength, high = 0.0;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (low + high);
        (shoot(mid).rate > 0.0 ? high : low) = mid;
    }
    return shoot(0.5 * (low + high)).drop;
}

// The bowel of the cantilever, first end clamped, settled at rest: its tip's drop (m).
double settled_tip_drop(uint32_t points, double load) {
    const double bend_stiffness = kWeight * kLength * kLength * kLength / load;
    ent_scene_desc desc = default_desc();
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_STRETCH) | ENT_EFFECT_BIT(ENT_EFFECT_BEND) |
                   ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY) | ENT_EFFECT_BIT(ENT_EFFECT_DAMPING) |
                   ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = points;
    desc.length_m = kLength;
    desc.linear_density_kg_per_m = kDensity;
    desc.stretch_stiffness_N = kStretchStiffness;
    desc.bend_stiffness_N_m2 = bend_stiffness;
    desc.shape = ENT_SHAPE_LINE;
    desc.clamped_ends = ENT_PIN_FIRST;
    desc.gravity_m_per_s2[0] = 0.0;
    desc.gravity_m_per_s2[1] = 0.0;
    desc.gravity_m_per_s2[2] = -kGravity;
    // About critical damping of the first mode (omega_1 = 3.52 sqrt(EI / (mu L^4))).
    desc.drag_N_s_per_m2 = 2.0 * kDensity * 3.52 * std::sqrt(bend_stiffness / (kDensity * std::pow(kLength, 4)));
    desc.integrator = ENT_INTEGRATOR_IMPLICIT_EULER;
    desc.timestep_s = 0.01;
    ScenePtr scene = create(desc);
    if (!scene) return NAN;
    double previous = 0.0;
    for (int step = 0; step < 5000; ++step) {
        if (ent_scene_step(scene.get(), 0.01) != ENT_OK) {
            ADD_FAILURE() << "N " << points << " load " << load << ": " << ent_last_error();
            return NAN;
        }
        const std::vector<double> q = control_points(scene.get());
        const double drop = -q[3 * (points - 1) + 2];
        if (step > 100 && std::fabs(drop - previous) < 1e-13) return drop;
        previous = drop;
    }
    ADD_FAILURE() << "N " << points << " load " << load << " did not settle";
    return previous;
}

TEST(ClampedEnds, LargeDeflectionCantileverConvergesAtSecondOrderToTheElastica) {
    const double loads[3] = {1.0, 5.0, 20.0};
    const uint32_t counts[3] = {11, 21, 41};  // segments of 5, 2.5, 1.25 cm
    for (const double load : loads) {
        const double exact = elastica_tip_drop(kWeight * kLength * kLength * kLength / load);
        double errors[3];
        for (int k = 0; k < 3; ++k) {
            errors[k] = settled_tip_drop(counts[k], load) / exact - 1.0;
            std::printf("load %4.0f  N %3u  drop %.6f m (elastica %.6f m)  error %+.4f %%\n", load, counts[k],
                        exact * (1.0 + errors[k]), exact, 100.0 * errors[k]);
        }
        const double order1 = std::log2(std::fabs(errors[0] / errors[1]));
        const double order2 = std::log2(std::fabs(errors[1] / errors[2]));
        std::printf("load %4.0f  orders %.2f %.2f\n", load, order1, order2);
        // At the default resolution (2.5 cm segments, 240 points over 6 m): within 1 %.
        EXPECT_LT(std::fabs(errors[1]), 0.01) << "load " << load;
        EXPECT_GT(order1, 1.7) << "load " << load;
        EXPECT_GT(order2, 1.7) << "load " << load;
    }
}

}  // namespace

namespace {

// The tangent at an end with the clamp's quadratic end treatment (docs/c-api.md):
// (4 q1 - 3 q0 - q2) / 2 at the first end, (3 q[n-1] - 4 q[n-2] + q[n-3]) / 2 at the last.
std::array<double, 3> end_tangent(const std::vector<double>& q, bool first) {
    const std::size_t n = q.size() / 3;
    const std::size_t e = first ? 0 : n - 1, a = first ? 1 : n - 2, b = first ? 2 : n - 3;
    std::array<double, 3> t{};
    for (int c = 0; c < 3; ++c)
        t[c] = (first ? 1.0 : -1.0) * 0.5 * (4.0 * q[3 * a + c] - 3.0 * q[3 * e + c] - q[3 * b + c]);
    return t;
}

double angle_between(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    const std::array<double, 3> c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), dot);
}

}  // namespace

// Both ends of the default helix clamped, falling under gravity with every integrator for
// 2 s (the explicit ones through the clamped mass matrix, the implicit one through its
// system): each end stays where it was and points where it pointed, to round-off.
TEST(ClampedEnds, EndsKeepTheirPositionAndTangentWhileTheBowelMoves) {
    for (const int32_t integrator : kIntegrators) {
        ent_scene_desc desc = default_desc();
        desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
        desc.pinned_ends = ENT_PIN_NONE;
        desc.clamped_ends = ENT_PIN_BOTH;
        desc.integrator = integrator;
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene);
        const std::vector<double> start = control_points(scene.get());
        ASSERT_TRUE(step_n(scene.get(), 0.001, 2000)) << integrator_name(integrator);
        const std::vector<double> end = control_points(scene.get());
        const std::size_t n = start.size() / 3;
        EXPECT_GT(max_abs_difference(start, end), 0.01) << integrator_name(integrator) << ": the bowel did not move";
        for (const bool first : {true, false}) {
            const std::size_t e = first ? 0 : n - 1;
            for (int c = 0; c < 3; ++c) EXPECT_EQ(end[3 * e + c], start[3 * e + c]) << integrator_name(integrator);
            EXPECT_LT(angle_between(end_tangent(start, first), end_tangent(end, first)), 1e-9)
                << integrator_name(integrator) << (first ? " first" : " last") << " end";
        }
    }
}

TEST(ClampedEnds, BadClampsAreRefusedNamingTheInput) {
    const auto refused = [](const ent_scene_desc& desc, const std::string& expected) {
        ent_scene* scene = nullptr;
        EXPECT_EQ(ent_scene_create(&desc, &scene), ENT_ERROR_INVALID_ARGUMENT) << expected;
        EXPECT_EQ(scene, nullptr);
        EXPECT_NE(std::string(ent_last_error()).find(expected), std::string::npos) << ent_last_error();
    };
    ent_scene_desc desc = default_desc();
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.clamped_ends = 4;
    refused(desc, "clamped_ends must be <= 3, got 4");
    desc.clamped_ends = -1;
    refused(desc, "clamped_ends must be >= 0, got -1");
    desc.clamped_ends = ENT_PIN_BOTH;
    desc.control_points = 5;
    refused(desc, "clamped_ends clamps both ends, which needs at least 6 control points");
    desc = default_desc();
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.clamped_ends = ENT_PIN_LAST;
    const uint32_t pins[1] = {desc.control_points - 3};
    desc.pinned_points = pins;
    desc.pinned_point_count = 1;
    refused(desc, "pinned_points[0] is " + std::to_string(pins[0]) + ", a control point whose motion the clamped last end already constrains");
    // An end folding back on itself has no tangent to hold.
    ent_scene* scene = nullptr;
    const std::string json = R"({"intestine": {"control_points": 4, "length": 0.5, "shape": {"kind": "points",
        "points": [[0, 0, 0], [0.1, 0, 0], [0.4, 0, 0], [0.5, 0, 0]]}}, "pinned": {"clamped": "first"}})";
    EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), &scene), ENT_ERROR_INVALID_SCENE);
    EXPECT_EQ(scene, nullptr);
    EXPECT_NE(std::string(ent_last_error()).find("pinned.clamped clamps the first end, but the initial shape gives it "
                                                  "no direction to hold"),
              std::string::npos)
        << ent_last_error();
}
