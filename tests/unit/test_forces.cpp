// The effects of lib/mechanics checked against their energies and against finite
// differences: every conservative force must be minus the gradient of its potential energy,
// and the linearisation handed to the implicit integrator (H = -dF/dq, C = -dF/dv, H v) must
// be the derivative of the force it linearises. A wrong sign or a missing term here makes the
// implicit integrator converge slowly or gain energy, which the C API tests would only show
// indirectly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory_resource>
#include <random>
#include <vector>

#include "mechanics/axial_blocks.h"
#include "mechanics/axis_model.h"
#include "mechanics/bend_force.h"
#include "mechanics/damping_force.h"
#include "mechanics/gravity_force.h"
#include "mechanics/mesentery_force.h"
#include "mechanics/state.h"
#include "mechanics/stretch_force.h"
#include "mechanics/system_matrix.h"

namespace {

namespace mech = enteron::mechanics;

constexpr std::size_t kPoints = 10;
constexpr double kLength = 1.0;
constexpr double kDensity = 0.3;

mech::AxisModel model() {
    mech::AxisModel m;
    m.control_points = kPoints;
    m.rest_segment_length = kLength / double(kPoints - 1);
    m.linear_density = kDensity;
    return m;
}

// A bent axis stretched by about 10 % everywhere (so no stretch node is compressed and the
// stretch Hessian needs no clamping), with random velocities.
mech::State stretched_state(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    mech::State s;
    s.resize(kPoints);
    const double l0 = model().rest_segment_length;
    for (std::size_t i = 0; i < kPoints; ++i) {
        s.q[3 * i + 0] = 1.1 * l0 * double(i);
        s.q[3 * i + 1] = 0.02 * std::sin(double(i)) + 0.002 * u(rng);
        s.q[3 * i + 2] = 0.01 * std::cos(2.0 * double(i)) + 0.002 * u(rng);
    }
    for (double& v : s.v) v = 0.3 * u(rng);
    return s;
}

std::vector<double> force_of(mech::Effect& effect, const mech::State& state) {
    std::vector<double> f(3 * kPoints, 0.0);
    effect.evaluate(state, f.data(), nullptr);
    return f;
}

double max_abs(const std::vector<double>& x) {
    double m = 0.0;
    for (double v : x) m = std::max(m, std::fabs(v));
    return m;
}

// F_k versus -dE/dq_k by central differences.
void expect_force_is_minus_gradient(mech::Effect& effect, const mech::State& state, double rel_tol) {
    const auto f = force_of(effect, state);
    const double scale = max_abs(f);
    ASSERT_GT(scale, 0.0) << "the state must load this effect";
    const double delta = 1e-6;
    for (std::size_t k = 0; k < f.size(); ++k) {
        mech::State plus = state, minus = state;
        plus.q[k] += delta;
        minus.q[k] -= delta;
        const double gradient = (effect.potential_energy(plus) - effect.potential_energy(minus)) / (2 * delta);
        EXPECT_NEAR(f[k], -gradient, rel_tol * scale) << "coordinate " << k;
    }
}

// The full 3n x 3n matrix -dF/dx by central differences, x = q or v.
std::vector<std::vector<double>> minus_jacobian(mech::Effect& effect, const mech::State& state, bool of_velocity) {
    const std::size_t m = 3 * kPoints;
    std::vector<std::vector<double>> j(m, std::vector<double>(m, 0.0));
    const double delta = 1e-6;
    for (std::size_t col = 0; col < m; ++col) {
        mech::State plus = state, minus = state;
        (of_velocity ? plus.v : plus.q)[col] += delta;
        (of_velocity ? minus.v : minus.q)[col] -= delta;
        const auto fp = force_of(effect, plus);
        const auto fm = force_of(effect, minus);
        for (std::size_t row = 0; row < m; ++row) j[row][col] = -(fp[row] - fm[row]) / (2 * delta);
    }
    return j;
}

void expect_matrix_matches(const mech::SystemMatrix& system, const std::vector<std::vector<double>>& expected,
                           double rel_tol) {
    double scale = 0.0;
    for (const auto& row : expected)
        for (double v : row) scale = std::max(scale, std::fabs(v));
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < expected.size(); ++i)
        for (std::size_t j = 0; j < expected.size(); ++j)
            EXPECT_NEAR(system.at(i, j), expected[i][j], rel_tol * scale) << "(" << i << ", " << j << ")";
}

struct Linearized {
    mech::SystemMatrix system;
    std::vector<double> force;
    std::vector<double> stiffness_times_velocity;
};

// Runs evaluate with a linearisation at h = 1 (so the system holds C + H) on top of the
// constant part, from a zero system.
Linearized linearize(mech::Effect& effect, const mech::State& state) {
    Linearized out;
    out.system.resize(3 * kPoints);
    out.force.assign(3 * kPoints, 0.0);
    out.stiffness_times_velocity.assign(3 * kPoints, 0.0);
    effect.add_constant_linearization(1.0, out.system);
    mech::Linearization lin{&out.system, 1.0, out.stiffness_times_velocity.data()};
    effect.evaluate(state, out.force.data(), &lin);
    return out;
}

std::vector<double> times(const std::vector<std::vector<double>>& a, const std::vector<double>& x) {
    std::vector<double> y(x.size(), 0.0);
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j) y[i] += a[i][j] * x[j];
    return y;
}

TEST(StretchForce, ForceIsMinusTheGradientOfItsEnergy) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(stretch, stretched_state(31), 1e-6);
}

TEST(StretchForce, ZeroOnTheStraightLineAtRestLength) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    mech::State s;
    s.resize(kPoints);
    for (std::size_t i = 0; i < kPoints; ++i) s.q[3 * i] = model().rest_segment_length * double(i);
    EXPECT_LT(max_abs(force_of(stretch, s)), 1e-12);
    EXPECT_LT(stretch.potential_energy(s), 1e-24);
}

TEST(StretchForce, EnergyOfAUniformStretch) {
    // Straight, every segment stretched by 5 %: E = 1/2 EA eps^2 L.
    const double ea = 100.0, eps = 0.05;
    mech::StretchForce stretch(model(), ea, std::pmr::get_default_resource());
    mech::State s;
    s.resize(kPoints);
    for (std::size_t i = 0; i < kPoints; ++i) s.q[3 * i] = (1 + eps) * model().rest_segment_length * double(i);
    EXPECT_NEAR(stretch.potential_energy(s), 0.5 * ea * eps * eps * kLength, 1e-12);
}

TEST(StretchForce, LinearizationIsTheJacobianWhenStretched) {
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    const mech::State s = stretched_state(32);
    const Linearized lin = linearize(stretch, s);
    const auto h = minus_jacobian(stretch, s, false);
    expect_matrix_matches(lin.system, h, 1e-6);
    const auto hv = times(h, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t k = 0; k < hv.size(); ++k)
        EXPECT_NEAR(lin.stiffness_times_velocity[k], hv[k], 1e-6 * max_abs(hv)) << k;
    const auto plain = force_of(stretch, s);
    for (std::size_t k = 0; k < plain.size(); ++k) EXPECT_EQ(lin.force[k], plain[k]);
}

TEST(BendForce, ForceIsMinusTheGradientOfItsEnergy) {
    mech::BendForce bend(model(), 2.5e-3, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(bend, stretched_state(33), 1e-6);
}

TEST(BendForce, LinearizationIsTheJacobian) {
    mech::BendForce bend(model(), 2.5e-3, std::pmr::get_default_resource());
    const mech::State s = stretched_state(34);
    const Linearized lin = linearize(bend, s);
    const auto k = minus_jacobian(bend, s, false);
    expect_matrix_matches(lin.system, k, 1e-6);
    const auto kv = times(k, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t i = 0; i < kv.size(); ++i)
        EXPECT_NEAR(lin.stiffness_times_velocity[i], kv[i], 1e-6 * max_abs(kv)) << i;
}

TEST(GravityForce, ForceIsMinusTheGradientAndSumsToTheWeight) {
    const enteron::Vec3 g(0.5, -1.0, -9.81);
    mech::GravityForce gravity(model(), g, std::pmr::get_default_resource());
    const mech::State s = stretched_state(35);
    expect_force_is_minus_gradient(gravity, s, 1e-8);
    const auto f = force_of(gravity, s);
    for (int c = 0; c < 3; ++c) {
        double total = 0.0;
        for (std::size_t i = 0; i < kPoints; ++i) total += f[3 * i + c];
        EXPECT_NEAR(total, kDensity * kLength * g[c], 1e-12) << "coordinate " << c;
    }
}

TEST(DampingForce, LinearizationIsTheVelocityJacobianAndItDissipates) {
    const mech::DampingCoefficients coefficients{0.05, 0.05, 1e-3};
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    const mech::State s = stretched_state(36);
    const Linearized lin = linearize(damping, s);
    expect_matrix_matches(lin.system, minus_jacobian(damping, s, true), 1e-6);

    // Power of the damping force is never positive.
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        mech::State moving = s;
        for (double& v : moving.v) v = u(rng);
        const auto f = force_of(damping, moving);
        double power = 0.0;
        for (std::size_t k = 0; k < f.size(); ++k) power += f[k] * moving.v[k];
        EXPECT_LT(power, 0.0);
    }
}

TEST(AxialBlocks, SharedBlocksOfStretchAndDampingEqualEachAddingItsOwn) {
    // The implicit integrator lets the stretch and the axial damper sum their blocks per
    // node and adds them once; the result must be the two linearisations added apart, in
    // either order of the laws (the first one gives the tangent).
    const mech::DampingCoefficients coefficients{0.05, 0.05, 1e-3};
    mech::StretchForce stretch(model(), 100.0, std::pmr::get_default_resource());
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    const mech::State s = stretched_state(41);
    const double h = 1e-3;
    mech::SystemMatrix apart;
    apart.resize(3 * kPoints);
    std::vector<double> force_apart(3 * kPoints, 0.0), hv_apart(3 * kPoints, 0.0);
    mech::Linearization own{&apart, h, hv_apart.data()};
    stretch.evaluate(s, force_apart.data(), &own);
    damping.evaluate(s, force_apart.data(), &own);
    // One set of blocks through every round, as in the integrator: a round forgets the last.
    mech::AxialBlocks blocks(kPoints, std::pmr::get_default_resource());
    for (const bool stretch_first : {true, false}) {
        mech::SystemMatrix shared;
        shared.resize(3 * kPoints);
        std::vector<double> force(3 * kPoints, 0.0), hv(3 * kPoints, 0.0);
        blocks.clear();
        mech::Linearization lin{&shared, h, hv.data(), &blocks};
        mech::Effect* order[2] = {&stretch, &damping};
        if (!stretch_first) std::swap(order[0], order[1]);
        for (mech::Effect* effect : order) effect->evaluate(s, force.data(), &lin);
        // Nothing reaches the system until the integrator adds the blocks.
        EXPECT_EQ(shared.at(0, 0), 0.0);
        blocks.add_to(shared);
        double scale = 0.0;
        for (std::size_t i = 0; i < 3 * kPoints; ++i)
            for (std::size_t j = 0; j < 3 * kPoints; ++j) scale = std::max(scale, std::fabs(apart.at(i, j)));
        ASSERT_GT(scale, 0.0);
        for (std::size_t i = 0; i < 3 * kPoints; ++i) {
            for (std::size_t j = 0; j < 3 * kPoints; ++j)
                EXPECT_NEAR(shared.at(i, j), apart.at(i, j), 1e-12 * scale) << "(" << i << ", " << j << ")";
            // The forces too, up to the order of the two laws' sums.
            EXPECT_NEAR(force[i], force_apart[i], 1e-12 * (1.0 + std::fabs(force_apart[i])));
            EXPECT_NEAR(hv[i], hv_apart[i], 1e-12 * (1.0 + std::fabs(hv_apart[i])));
        }
    }
    // A last round with the damper alone, at another state: nothing of the stretch's blocks
    // (nor of their tangents) may stay.
    const mech::State other = stretched_state(42);
    mech::SystemMatrix alone, shared;
    alone.resize(3 * kPoints);
    shared.resize(3 * kPoints);
    std::vector<double> f(3 * kPoints, 0.0), hv(3 * kPoints, 0.0);
    mech::Linearization direct{&alone, h, hv.data()};
    damping.evaluate(other, f.data(), &direct);
    blocks.clear();
    mech::Linearization lin{&shared, h, hv.data(), &blocks};
    damping.evaluate(other, f.data(), &lin);
    blocks.add_to(shared);
    double scale = 0.0;
    for (std::size_t i = 0; i < 3 * kPoints; ++i)
        for (std::size_t j = 0; j < 3 * kPoints; ++j) scale = std::max(scale, std::fabs(alone.at(i, j)));
    ASSERT_GT(scale, 0.0);
    for (std::size_t i = 0; i < 3 * kPoints; ++i)
        for (std::size_t j = 0; j < 3 * kPoints; ++j)
            EXPECT_NEAR(shared.at(i, j), alone.at(i, j), 1e-12 * scale) << "(" << i << ", " << j << ")";
}

TEST(DampingForce, RigidTranslationFeelsOnlyDrag) {
    // Strain rate and curvature rate are zero, so only the drag acts: total -c_d L v.
    const mech::DampingCoefficients coefficients{0.05, 10.0, 10.0};
    mech::DampingForce damping(model(), coefficients, std::pmr::get_default_resource());
    mech::State s = stretched_state(38);
    const double v[3] = {0.3, -0.2, 0.1};
    for (std::size_t i = 0; i < kPoints; ++i)
        for (int c = 0; c < 3; ++c) s.v[3 * i + c] = v[c];
    const auto f = force_of(damping, s);
    for (int c = 0; c < 3; ++c) {
        double total = 0.0;
        for (std::size_t i = 0; i < kPoints; ++i) total += f[3 * i + c];
        // Had the stretch or bend damping (10 N s, 10 N m^2 s) acted on this motion, the sum
        // would be off by newtons; round-off of the bend damping matrix (entries ~ c_b / l0^3
        // = 7e3) times a constant vector leaves ~1e-10.
        EXPECT_NEAR(total, -coefficients.drag * kLength * v[c], 1e-9) << "coordinate " << c;
    }
}

TEST(MesenteryForce, ForceIsMinusTheGradientAndTheLinearizationItsJacobian) {
    mech::MesenteryParameters p;
    p.root_start = {-0.075, -0.3, 0.0};
    p.root_end = {0.075, -0.3, 0.0};
    p.attachments = 7;
    p.stiffness = 5.0;
    p.rest_length = 0.05;  // shorter than every spring: all pull
    const mech::State s = stretched_state(39);
    mech::MesenteryForce mesentery(model(), p, s, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(mesentery, s, 1e-6);
    const Linearized lin = linearize(mesentery, s);
    const auto h = minus_jacobian(mesentery, s, false);
    expect_matrix_matches(lin.system, h, 1e-6);
    const auto hv = times(h, std::vector<double>(s.v.begin(), s.v.end()));
    for (std::size_t k = 0; k < hv.size(); ++k)
        EXPECT_NEAR(lin.stiffness_times_velocity[k], hv[k], 1e-6 * max_abs(hv)) << k;
}

TEST(MesenteryForce, SlackSpringsPullNothing) {
    mech::MesenteryParameters p;
    p.root_start = {-0.075, -0.3, 0.0};
    p.root_end = {0.075, -0.3, 0.0};
    p.attachments = 7;
    p.stiffness = 5.0;
    p.rest_length = 0.0;  // each spring's initial length
    const mech::State s = stretched_state(40);
    mech::MesenteryForce mesentery(model(), p, s, std::pmr::get_default_resource());
    EXPECT_EQ(max_abs(force_of(mesentery, s)), 0.0);
    EXPECT_EQ(mesentery.potential_energy(s), 0.0);
    // Moving every point toward the root slackens every spring further.
    mech::State closer = s;
    for (std::size_t i = 0; i < kPoints; ++i) closer.q[3 * i + 1] -= 0.05;
    EXPECT_EQ(max_abs(force_of(mesentery, closer)), 0.0);
}

}  // namespace
