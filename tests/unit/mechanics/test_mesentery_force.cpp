// SPDX-License-Identifier: Apache-2.0
// The mesentery (lib/mechanics/mesentery_force.h): tension-only springs, minus the gradient
// of their energy with a linearisation that is their Jacobian; slack springs pull nothing.
#include "mechanics/mesentery_force.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <vector>

#include "mechanics/axis_model.h"
#include "mechanics/effect_checks.h"
#include "mechanics/state.h"

namespace {

using namespace mechanics_test;

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

// The fan: attachment k (at s_k = (k + 1/2) / K of the bowel's length) is tied to the root
// polyline's point at the fraction t(s_k) of its length, t from the mapping's pairs (linear
// between them, held past the ends), or t = (k + 1/2) / K without one.
TEST(MesenteryForce, EachAttachmentIsTiedToTheRootPointTheMappingNames) {
    mech::MesenteryParameters p;
    // An L of 10 cm then 5 cm: fraction t of its 15 cm is at d = 0.15 t along it.
    p.root_points = {0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.1, 0.05, 0.0};
    p.attachments = 10;
    p.stiffness = 5.0;
    p.bowel_length = 2.0;
    const auto along_the_l = [](double t) {
        const double d = 0.15 * t;
        return d <= 0.1 ? enteron::Vec3(d, 0.0, 0.0) : enteron::Vec3(0.1, d - 0.1, 0.0);
    };
    const mech::State s = stretched_state(41);
    {
        mech::MesenteryForce even(model(), p, s, std::pmr::get_default_resource());
        ASSERT_EQ(even.springs(), 10u);
        for (std::size_t k = 0; k < 10; ++k)
            EXPECT_LT((even.root_point(k, 0.0) - along_the_l((k + 0.5) / 10.0)).norm(), 1e-15) << k;
    }
    // The first metre of bowel on the first fifth of the root, the second on the rest; before
    // s = 0.25 the first pair holds (t = 0.1).
    p.root_mapping = {0.25, 0.1, 1.0, 0.2, 2.0, 1.0};
    const auto t_of = [](double s) { return s <= 0.25 ? 0.1 : s <= 1.0 ? 0.1 + (s - 0.25) / 0.75 * 0.1 : 0.2 + (s - 1.0) * 0.8; };
    mech::MesenteryForce mapped(model(), p, s, std::pmr::get_default_resource());
    for (std::size_t k = 0; k < 10; ++k) {
        const double s_k = (k + 0.5) / 10.0 * 2.0;
        EXPECT_LT((mapped.root_point(k, 0.0) - along_the_l(t_of(s_k))).norm(), 1e-15) << k;
    }
    // The springs pull toward those points: with a rest length shorter than each, the force
    // on the bowel is minus the gradient of the energy of springs to the mapped points.
    p.rest_length = 0.01;
    mech::MesenteryForce pulling(model(), p, s, std::pmr::get_default_resource());
    expect_force_is_minus_gradient(pulling, s, 1e-6);
}

// Two root points: the segment start + t (end - start), as the root was before polylines.
TEST(MesenteryForce, ATwoPointRootIsTheSegment) {
    mech::MesenteryParameters segment;
    segment.root_start = {-0.075, -0.3, 0.01};
    segment.root_end = {0.075, -0.3, 0.02};
    segment.attachments = 7;
    segment.stiffness = 5.0;
    mech::MesenteryParameters polyline = segment;
    polyline.root_start = polyline.root_end = enteron::Vec3::Zero();
    polyline.root_points = {-0.075, -0.3, 0.01, 0.075, -0.3, 0.02};
    const mech::State s = stretched_state(42);
    mech::MesenteryForce a(model(), segment, s, std::pmr::get_default_resource());
    mech::MesenteryForce b(model(), polyline, s, std::pmr::get_default_resource());
    for (std::size_t k = 0; k < 7; ++k) {
        const double f = (k + 0.5) / 7.0;
        const enteron::Vec3 expected = segment.root_start + f * (segment.root_end - segment.root_start);
        EXPECT_EQ(a.root_point(k, 0.0), expected) << k;
        EXPECT_EQ(b.root_point(k, 0.0), expected) << k;
    }
}

}  // namespace
