// SPDX-License-Identifier: Apache-2.0
// Self-contact of the bowel (lib/collision/self_contact_force.h): folds closer than 2R push
// apart, neighbours along the axis never collide, and the kept list of near pairs finds what
// a fresh search finds.
#include "collision/self_contact_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory_resource>
#include <random>
#include <vector>

#include "collision/collision_fixtures.h"
#include "collision/collision_spheres.h"
#include "collision/sphere_loads.h"
#include "mechanics/state.h"

namespace {

using namespace collision_test;

std::vector<double> straight_line(std::size_t n, double spacing) {
    std::vector<double> points;
    for (std::size_t i = 0; i < n; ++i) points.insert(points.end(), {spacing * double(i), 0.0, 0.0});
    return points;
}

// A crumpled axis: 100 control points 1 cm apart, a random walk inside the cube of half
// edge `half_box` (m) centred on the origin.
std::vector<double> crumpled_points(std::mt19937& random, double half_box) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> points{0.0, 0.0, 0.0};
    for (int i = 1; i < 100; ++i) {
        double step[3], norm = 0.0;
        for (double& c : step) c = unit(random), norm += c * c;
        for (int c = 0; c < 3; ++c) {
            double next = points[3 * (i - 1) + c] + 0.01 * step[c] / std::sqrt(norm);
            if (std::fabs(next) > half_box) next = points[3 * (i - 1) + c] - 0.01 * step[c] / std::sqrt(norm);
            points.push_back(next);
        }
    }
    return points;
}

// The effect that lived through the moves gives the contacts and forces of a new one.
void expect_same_as_fresh(SelfContactForce& kept, SphereLoads& loads, const Axis& axis, int move) {
    std::vector<double> f_kept(axis.state.q.size(), 0.0), f_fresh;
    evaluate_with_loads(kept, loads, axis.state, f_kept.data(), nullptr);
    ContactSummary with_kept;
    kept.add_contacts(with_kept);
    const ContactSummary fresh = axis.contacts(&f_fresh);
    ASSERT_GT(fresh.count, 20u);
    ASSERT_EQ(with_kept.count, fresh.count) << "move " << move;
    EXPECT_EQ(with_kept.max_penetration, fresh.max_penetration);
    for (std::size_t i = 0; i < f_fresh.size(); ++i) EXPECT_NEAR(f_kept[i], f_fresh[i], 1e-12) << "move " << move;
}

// A crumpled axis (a random walk of 1 cm steps in a box of the given half size) and a
// self-contact effect that lives through the moves a test makes.
struct Crumpled {
    Crumpled(unsigned seed, double half_box)
        : random(seed),
          axis(crumpled_points(random, half_box)),
          spheres(axis.make_spheres()),
          loads(spheres, std::pmr::new_delete_resource()),
          kept(spheres, ContactParameters{}, axis.state, std::pmr::new_delete_resource(), loads) {}
    std::mt19937 random;
    Axis axis;
    CollisionSpheres spheres;
    SphereLoads loads;
    SelfContactForce kept;
};

TEST(SelfContact, NeighboursAlongAStraightAxisNeverCollide) {
    const Axis axis(straight_line(40, 0.01));
    EXPECT_EQ(axis.contacts().count, 0u);
}

TEST(SelfContact, ATightestBendMakesNoContact) {
    // A half circle of radius R: as tight as a tube can bend without overlapping itself.
    std::vector<double> points;
    for (int i = 0; i <= 30; ++i) {
        const double angle = 3.14159265358979 * i / 30.0;
        points.insert(points.end(), {kRadius * std::cos(angle), kRadius * std::sin(angle), 0.0});
    }
    const Axis axis(points);
    const ContactSummary summary = axis.contacts();
    EXPECT_LT(summary.max_penetration, 0.02 * kRadius);
}

TEST(SelfContact, TheLegsOfATouchingUTurnCollideAndPushApart) {
    const Axis axis(u_turn(1.8 * kRadius));
    std::vector<double> force;
    const ContactSummary summary = axis.contacts(&force);
    EXPECT_GT(summary.count, 10u);
    EXPECT_NEAR(summary.max_penetration, 0.2 * kRadius, 0.05 * kRadius);
    // The legs are pushed apart: the first leg (y = 0) toward -y, the second toward +y.
    double first_leg = 0.0, second_leg = 0.0, total = 0.0;
    for (std::size_t i = 0; i < axis.state.count(); ++i) {
        const double x = axis.state.q[3 * i], y = axis.state.q[3 * i + 1];
        total += force[3 * i + 1];
        if (x < 0.05) continue;  // the turn
        (y < 0.5 * 1.8 * kRadius ? first_leg : second_leg) += force[3 * i + 1];
    }
    EXPECT_LT(first_leg, 0.0);
    EXPECT_GT(second_leg, 0.0);
    // Action and reaction: the contacts add no net force to the bowel.
    EXPECT_NEAR(total, 0.0, 1e-9 * std::fabs(first_leg));
}

TEST(SelfContact, LegsApartMakeNoContact) {
    const Axis axis(u_turn(2.2 * kRadius));
    EXPECT_EQ(axis.contacts().count, 0u);
}

TEST(SelfContact, TwoCrossingFoldsPushApart) {
    // One straight piece along x at z = 0, a second along y at z = 1.5 R above it, joined
    // far away so they are not neighbours along the axis.
    std::vector<double> points;
    for (int i = 0; i <= 20; ++i) points.insert(points.end(), {-0.1 + 0.01 * i, 0.0, 0.0});
    for (int i = 1; i <= 10; ++i) points.insert(points.end(), {0.1, 0.01 * i, 0.01 * i});
    for (int i = 1; i <= 20; ++i) points.insert(points.end(), {0.1 - 0.005 * i, 0.1 - 0.01 * i, 0.1});
    // Bring the last straight piece down so it crosses the first at z = 1.5 R.
    for (int i = 0; i < 20; ++i) points[3 * (31 + i) + 2] = 1.5 * kRadius;
    for (int i = 0; i < 20; ++i) points[3 * (31 + i) + 0] = 0.0;
    const Axis axis(points);
    std::vector<double> force;
    const ContactSummary summary = axis.contacts(&force);
    ASSERT_GT(summary.count, 0u);
    EXPECT_NEAR(summary.max_penetration, 0.5 * kRadius, 0.1 * kRadius);
    double lower = 0.0, upper = 0.0;
    for (std::size_t i = 0; i < axis.state.count(); ++i) (i <= 20 ? lower : upper) += force[3 * i + 2];
    EXPECT_LT(lower, 0.0);
    EXPECT_GT(upper, 0.0);
}

TEST(SelfContact, TheKeptListOfNearPairsFindsWhatAFreshSearchFinds) {
    // A crumpled axis (a random walk in a 16 cm box) that keeps moving a little: the effect
    // that lives through the moves (and searches its grid again only when a sphere has
    // moved R / 6) must give the same contacts and forces as a new effect each time.
    Crumpled crumpled(11, 0.08);
    auto& [random, axis, spheres, loads, kept] = crumpled;
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const int moves = 60;
    for (int move = 0; move < moves; ++move) {
        for (double& q : axis.state.q) q += 0.00015 * unit(random);  // up to 0.15 mm a move
        expect_same_as_fresh(kept, loads, axis, move);
        if (HasFatalFailure()) return;
    }
    // 60 moves of up to 0.15 mm per coordinate (which also change the length, and so slide
    // every sphere along the axis) drift some sphere past R / 6 often, but not at every move.
    std::cout << "[ near pairs ] " << kept.grid_searches() << " grid searches in " << moves << " moves\n";
    EXPECT_GT(kept.grid_searches(), 1u);
    EXPECT_LT(kept.grid_searches(), std::uint64_t(moves));
}

TEST(SelfContact, AStateThatIsNotFiniteLeavesNoContactBehind) {
    // An explicit stage that blew up (a NaN control point: the spheres' arc lengths are
    // NaN from there on) is evaluated and then rolled back: the spheres must search again at the finite state,
    // with the contacts and forces of a fresh search, however the NaN state was filed.
    Crumpled crumpled(17, 0.1);
    auto& [random, axis, spheres, loads, kept] = crumpled;
    expect_same_as_fresh(kept, loads, axis, 0);
    const State finite = axis.state;
    State blown = finite;
    blown.q[3 * 50] = std::numeric_limits<double>::quiet_NaN();
    kept.potential_energy(blown);
    std::vector<double> f(blown.q.size(), 0.0);
    evaluate_with_loads(kept, loads, blown, f.data(), nullptr);
    axis.state = finite;
    expect_same_as_fresh(kept, loads, axis, 1);
    // And after a small move from there.
    for (double& q : axis.state.q) q += 1e-4;
    expect_same_as_fresh(kept, loads, axis, 2);
}

TEST(SelfContact, OnlyTheSpheresThatMovedSearchAgainAndNoContactIsMissed) {
    // A crumpled axis (a random walk in a 20 cm box: sparser than a pile, so that the list
    // of near pairs never overflows) at rest but for its last 16 control points, which
    // turn as one piece about the one before them (lengths nearly kept; the spheres are
    // spread by arc length, so a change of length would slide them all) and sweep
    // through the others by up to a few mm a move: those spheres search the grid again on
    // their own, the rest keep their pairs, and the contacts and forces must equal a fresh
    // search at every move.
    Crumpled crumpled(5, 0.1);
    auto& [random, axis, spheres, loads, kept] = crumpled;
    const double angle = 0.02;  // rad a move, about z through control point 83
    const double pivot[2] = {axis.state.q[3 * 83], axis.state.q[3 * 83 + 1]};
    const int moves = 40;
    for (int move = 0; move < moves; ++move) {
        for (std::size_t i = 84; i < 100; ++i) {
            const double x = axis.state.q[3 * i] - pivot[0], y = axis.state.q[3 * i + 1] - pivot[1];
            axis.state.q[3 * i] = pivot[0] + std::cos(angle) * x - std::sin(angle) * y;
            axis.state.q[3 * i + 1] = pivot[1] + std::sin(angle) * x + std::cos(angle) * y;
        }
        expect_same_as_fresh(kept, loads, axis, move);
        if (HasFatalFailure()) return;
    }
    std::cout << "[ near pairs ] " << kept.moved_sphere_searches() << " searches of moved spheres, "
              << kept.grid_searches() << " in all, in " << moves << " moves\n";
    EXPECT_GT(kept.moved_sphere_searches(), 5u);
}

// Two tubes end to end along x, the second's first sphere on the first's last (the next
// index): neighbours by index, but of two tubes, so they touch; each tube alone, straight,
// touches nothing.
TEST(SelfContact, TheWindowOfNeighboursHoldsWithinATubeOnly) {
    const std::vector<double> a = straight_line(21, 0.01);
    std::vector<double> both = a;
    for (std::size_t i = 0; i < 21; ++i) both.insert(both.end(), {0.2 + 0.5 * kRadius + 0.01 * double(i), 0.0, 0.0});
    State state(std::pmr::new_delete_resource());
    state.resize(42);
    state.q.assign(both.begin(), both.end());
    CollisionSpheres spheres({{0, 21, 0.2, 0.5 * kRadius, kRadius, {}, nullptr}, {21, 21, 0.2, 0.5 * kRadius, kRadius, {}, nullptr}},
                             42, std::pmr::new_delete_resource());
    SphereLoads loads(spheres, std::pmr::new_delete_resource());
    SelfContactForce effect(spheres, ContactParameters{}, state, std::pmr::new_delete_resource(), loads);
    std::vector<double> force(state.q.size(), 0.0);
    evaluate_with_loads(effect, loads, state, force.data(), nullptr);
    ContactSummary summary;
    effect.add_contacts(summary);
    // The ends overlap by 1.5 R: the few spheres within 2R of the other tube's end touch it.
    EXPECT_GE(summary.count, 1u);
    EXPECT_NEAR(summary.max_penetration, 1.5 * kRadius, 1e-9);
    // They push apart along x: the first tube's last point backwards, the second's first forwards.
    EXPECT_LT(force[3 * 20], 0.0);
    EXPECT_GT(force[3 * 21], 0.0);
    EXPECT_EQ(Axis(a).contacts().count, 0u);
}

}  // namespace
