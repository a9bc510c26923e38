// SPDX-License-Identifier: Apache-2.0
// Several tubes in one state (lib/mechanics/axis_model.h): their points back to back, each
// tube its own spline, profiles and l0, no coupling between them. Two tubes stepped together
// move exactly as each stepped alone, with every integrator (the block-banded solve adds
// nothing across the blocks), and their energies add up.
#include "mechanics/axis_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory_resource>
#include <vector>

#include "base/memory.h"
#include "mechanics/bend_force.h"
#include "mechanics/damping_force.h"
#include "mechanics/dynamics.h"
#include "mechanics/gravity_force.h"
#include "mechanics/integrator.h"
#include "mechanics/state.h"
#include "mechanics/stretch_force.h"
#include "spline/length_profile.h"

namespace enteron::mechanics {
namespace {

std::pmr::memory_resource* tubes_memory() { return std::pmr::new_delete_resource(); }

// Two unlike tubes: 9 points over 0.4 m with a stretch stiffness profile, and 7 points over
// 0.3 m with a density profile, a quadratic first end and its own EA and EI.
struct TwoTubes {
    spline::LengthProfile stiffness{{0.0, 150.0, 0.4, 60.0}, tubes_memory()};
    spline::LengthProfile density{{0.0, 0.5, 0.3, 0.2}, tubes_memory()};
    TubeModel a{0, 9, 0.4 / 8.0, 0.3, {}, nullptr, &stiffness, nullptr};
    TubeModel b{9,       7,       0.3 / 6.0, 0.5, {spline::EndTreatment::quadratic, spline::EndTreatment::linear},
                &density, nullptr, nullptr,   80.0, 1e-3};

    // The axis of a alone (which = 0), of b alone (1) or of both (2).
    AxisModel axis(int which) const {
        AxisModel model;
        if (which == 0) model.tubes = {a};
        if (which == 1) model.tubes = {b};
        if (which == 2) model.tubes = {a, b};
        if (which == 1) model.tubes[0].first = 0;
        for (const TubeModel& tube : model.tubes) model.control_points += tube.control_points;
        return model;
    }
};

// A bent, moving start for tube `which` of TwoTubes (its own points only).
std::vector<double> tube_start(const TubeModel& tube, double phase, std::vector<double>* velocity) {
    std::vector<double> q;
    for (std::size_t i = 0; i < tube.control_points; ++i) {
        const double s = tube.rest_segment_length * double(i);
        q.insert(q.end(), {0.9 * s, 0.05 * std::sin(8.0 * s + phase), 0.02 * std::cos(5.0 * s) + phase});
        velocity->insert(velocity->end(), {0.1 * std::cos(3.0 * s), -0.2 * s, 0.05});
    }
    return q;
}

// Every effect of the tube laws on `model`, stepped `steps` times by `kind` from `state`.
void step_tubes(const AxisModel& model, IntegratorKind kind, State& state, int steps) {
    Dynamics dynamics(model, tubes_memory());
    dynamics.add_effect(make_owned<StretchForce>(tubes_memory(), model, 150.0, tubes_memory()));
    dynamics.add_effect(make_owned<BendForce>(tubes_memory(), model, 2.5e-3, tubes_memory()));
    dynamics.add_effect(
        make_owned<DampingForce>(tubes_memory(), model, DampingCoefficients{0.05, 0.05, 1e-5}, tubes_memory()));
    dynamics.add_effect(make_owned<GravityForce>(tubes_memory(), model, Vec3(0.0, 0.0, -9.81), tubes_memory()));
    dynamics.finalize();
    Owned<Integrator> integrator = make_integrator(kind, model, tubes_memory());
    for (int k = 0; k < steps; ++k) ASSERT_TRUE(integrator->step(dynamics, state, 1e-4));
}

class TwoTubesInOneState : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(TwoTubesInOneState, MoveExactlyAsEachTubeAlone) {
    const TwoTubes tubes;
    std::vector<double> va, vb;
    const std::vector<double> qa = tube_start(tubes.a, 0.0, &va), qb = tube_start(tubes.b, 0.1, &vb);
    State alone_a(tubes_memory()), alone_b(tubes_memory()), both(tubes_memory());
    alone_a.resize(tubes.a.control_points);
    alone_b.resize(tubes.b.control_points);
    both.resize(tubes.a.control_points + tubes.b.control_points);
    alone_a.q.assign(qa.begin(), qa.end());
    alone_a.v.assign(va.begin(), va.end());
    alone_b.q.assign(qb.begin(), qb.end());
    alone_b.v.assign(vb.begin(), vb.end());
    std::copy(qa.begin(), qa.end(), both.q.begin());
    std::copy(qb.begin(), qb.end(), both.q.begin() + qa.size());
    std::copy(va.begin(), va.end(), both.v.begin());
    std::copy(vb.begin(), vb.end(), both.v.begin() + va.size());

    constexpr int kSteps = 40;
    step_tubes(tubes.axis(0), GetParam(), alone_a, kSteps);
    step_tubes(tubes.axis(1), GetParam(), alone_b, kSteps);
    step_tubes(tubes.axis(2), GetParam(), both, kSteps);

    // The tubes moved (the comparison is not of two resting states) ...
    EXPECT_GT(std::fabs(alone_a.q[2] - qa[2]), 1e-6);
    // ... and to the bit as alone: no term couples them.
    for (std::size_t k = 0; k < qa.size(); ++k) {
        ASSERT_EQ(both.q[k], alone_a.q[k]) << "tube 0, coordinate " << k;
        ASSERT_EQ(both.v[k], alone_a.v[k]) << "tube 0, coordinate " << k;
    }
    for (std::size_t k = 0; k < qb.size(); ++k) {
        ASSERT_EQ(both.q[qa.size() + k], alone_b.q[k]) << "tube 1, coordinate " << k;
        ASSERT_EQ(both.v[qa.size() + k], alone_b.v[k]) << "tube 1, coordinate " << k;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, TwoTubesInOneState,
                         ::testing::Values(IntegratorKind::implicit_euler, IntegratorKind::rk4,
                                           IntegratorKind::symplectic_euler, IntegratorKind::bdf2));

TEST(AxisModel, TheEnergiesAndTheMassOfTwoTubesAreEachTubesSummed) {
    const TwoTubes tubes;
    std::vector<double> va, vb;
    const std::vector<double> qa = tube_start(tubes.a, 0.0, &va), qb = tube_start(tubes.b, 0.1, &vb);
    auto energies = [&](int which, const std::vector<double>& q, const std::vector<double>& v) {
        const AxisModel model = tubes.axis(which);
        Dynamics dynamics(model, tubes_memory());
        dynamics.add_effect(make_owned<StretchForce>(tubes_memory(), model, 150.0, tubes_memory()));
        dynamics.add_effect(make_owned<BendForce>(tubes_memory(), model, 2.5e-3, tubes_memory()));
        dynamics.add_effect(make_owned<GravityForce>(tubes_memory(), model, Vec3(0.0, 0.0, -9.81), tubes_memory()));
        dynamics.finalize();
        State state(tubes_memory());
        state.resize(model.control_points);
        state.q.assign(q.begin(), q.end());
        state.v.assign(v.begin(), v.end());
        return dynamics.energies(state);
    };
    std::vector<double> q = qa, v = va;
    q.insert(q.end(), qb.begin(), qb.end());
    v.insert(v.end(), vb.begin(), vb.end());
    const Dynamics::Energies a = energies(0, qa, va), b = energies(1, qb, vb), both = energies(2, q, v);
    EXPECT_NEAR(both.kinetic, a.kinetic + b.kinetic, 1e-12 * both.kinetic);
    EXPECT_NEAR(both.potential, a.potential + b.potential, 1e-12 * std::fabs(both.potential));
    EXPECT_NEAR(both.deformation, a.deformation + b.deformation, 1e-12 * both.deformation);
    EXPECT_GT(a.deformation, 0.0);
    EXPECT_GT(b.deformation, 0.0);

    // The mass matrix is block diagonal: each tube's total mass from its own density.
    const AxisModel model = tubes.axis(2);
    numerics::ScalarBandMatrix mass(tubes_memory());
    mass.resize(model.control_points);
    add_mass_matrix(model, mass);
    std::vector<double> ones_a(model.control_points, 0.0), product(model.control_points, 0.0);
    for (std::size_t i = 0; i < tubes.a.control_points; ++i) ones_a[i] = 1.0;
    mass.multiply(ones_a.data(), product.data());
    double mass_a = 0.0, leak = 0.0;
    for (std::size_t i = 0; i < model.control_points; ++i) {
        if (i < tubes.a.control_points) mass_a += product[i];
        else leak += std::fabs(product[i]);
    }
    EXPECT_NEAR(mass_a, 0.3 * 0.4, 1e-12);  // mu L of tube 0
    EXPECT_EQ(leak, 0.0);                    // nothing of tube 0 reaches tube 1
}

}  // namespace
}  // namespace enteron::mechanics
