// Self-contact of the bowel: the spatial hash finds exactly the pairs a brute-force search
// finds, folds closer than 2R push apart, and neighbours along the axis never collide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory_resource>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "base/memory.h"
#include "collision/environment_force.h"
#include "collision/self_contact_force.h"
#include "collision/spatial_hash.h"
#include "collision/sphere_loads.h"
#include "mechanics/dynamics.h"
#include "mechanics/state.h"

namespace {

using enteron::collision::CollisionSpheres;
using enteron::collision::ContactParameters;
using enteron::collision::SelfContactForce;
using enteron::collision::SpatialHash;
using enteron::collision::SphereLoads;
using enteron::mechanics::AxisModel;
using enteron::mechanics::ContactSummary;
using enteron::mechanics::State;

// What Dynamics does for a contact effect: clears the loads it shares, evaluates, applies them.
void evaluate_with_loads(enteron::mechanics::Effect& effect, SphereLoads& loads, const State& state, double* force,
                         const enteron::mechanics::Linearization* lin) {
    loads.clear();
    effect.evaluate(state, force, lin);
    loads.apply(force, lin);
}

TEST(SpatialHash, CandidatePairsCoverBruteForceAndRepeatNone) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 20; ++trial) {
        const std::size_t count = 50 + 40 * trial;
        const double cell = 0.025;
        std::uniform_real_distribution<double> coordinate(-0.1, 0.1);
        std::vector<double> points(3 * count);
        for (double& p : points) p = coordinate(random);
        SpatialHash grid(count, cell, std::pmr::new_delete_resource());
        grid.build(points.data(), count, 3);
        std::set<std::pair<std::size_t, std::size_t>> found;
        std::size_t visits = 0;
        grid.for_each_candidate_pair([&](std::size_t i, std::size_t j) {
            ++visits;
            found.insert({std::min(i, j), std::max(i, j)});
        });
        EXPECT_EQ(visits, found.size()) << "a pair was visited twice";
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t j = i + 1; j < count; ++j) {
                const double* a = &points[3 * i];
                const double* b = &points[3 * j];
                const double d2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                  (a[2] - b[2]) * (a[2] - b[2]);
                if (d2 < cell * cell) {
                    EXPECT_TRUE(found.count({i, j})) << "missed pair " << i << ", " << j;
                }
            }
    }
}

TEST(SpatialHash, PointsRefiledOneByOneFindTheSamePairsAsARebuild) {
    // The self-contact refiles only the spheres that moved; after any sequence of moves the
    // grid must answer as one built from scratch at the new places.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-0.1, 0.1), step(-0.03, 0.03);
    const std::size_t count = 400;
    const double cell = 0.025;
    std::vector<double> points(3 * count);
    for (double& p : points) p = coordinate(random);
    SpatialHash moved(count, cell, std::pmr::new_delete_resource());
    moved.build(points.data(), count, 3);
    for (int round = 0; round < 10; ++round) {
        for (std::size_t i = round % 3; i < count; i += 2) {  // some move a little, some across cells
            for (int c = 0; c < 3; ++c) points[3 * i + c] += (i % 5 == 0 ? 4.0 : 1.0) * step(random);
            moved.move(i, enteron::point_at(points.data(), i));
        }
        SpatialHash rebuilt(count, cell, std::pmr::new_delete_resource());
        rebuilt.build(points.data(), count, 3);
        // Sorted lists, not sets: a pair visited twice (a point filed twice) must show.
        auto pairs_of = [](const SpatialHash& grid) {
            std::vector<std::pair<std::size_t, std::size_t>> pairs;
            grid.for_each_candidate_pair(
                [&](std::size_t i, std::size_t j) { pairs.emplace_back(std::min(i, j), std::max(i, j)); });
            std::sort(pairs.begin(), pairs.end());
            return pairs;
        };
        EXPECT_EQ(pairs_of(moved), pairs_of(rebuilt)) << "round " << round;
        for (std::size_t i = 0; i < count; i += 37) {
            std::vector<std::size_t> a, b;
            moved.for_each_neighbour(i, [&](std::size_t j) { a.push_back(j); });
            rebuilt.for_each_neighbour(i, [&](std::size_t j) { b.push_back(j); });
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            EXPECT_EQ(a, b) << "round " << round << ", point " << i;
        }
    }
}

constexpr double kRadius = 0.0125;

// A bowel axis through the given control points, with the default contact law.
struct Axis {
    explicit Axis(const std::vector<double>& points) : state(std::pmr::new_delete_resource()) {
        const std::size_t n = points.size() / 3;
        state.resize(n);
        state.q.assign(points.begin(), points.end());
        length = 0.0;
        for (std::size_t i = 1; i < n; ++i) {
            const double* a = &points[3 * (i - 1)];
            const double* b = &points[3 * i];
            length += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                (a[2] - b[2]) * (a[2] - b[2]));
        }
        model.control_points = n;
        model.rest_segment_length = length / double(n - 1);
        model.linear_density = 0.3;
    }
    // Collision spheres at R / 2 along this axis.
    CollisionSpheres make_spheres() const {
        return CollisionSpheres(model.control_points, length, 0.5 * kRadius, kRadius, std::pmr::new_delete_resource());
    }
    // Contacts and generalised force of the self-contact effect on this axis.
    ContactSummary contacts(std::vector<double>* force = nullptr) const {
        CollisionSpheres spheres = make_spheres();
        SphereLoads loads(spheres, std::pmr::new_delete_resource());
        SelfContactForce effect(spheres, ContactParameters{}, state, std::pmr::new_delete_resource(), loads);
        std::vector<double> f(state.q.size(), 0.0);
        evaluate_with_loads(effect, loads, state, f.data(), nullptr);
        if (force != nullptr) *force = f;
        ContactSummary summary;
        effect.add_contacts(summary);
        return summary;
    }
    State state;
    AxisModel model;
    double length;
};

std::vector<double> straight_line(std::size_t n, double spacing) {
    std::vector<double> points;
    for (std::size_t i = 0; i < n; ++i) points.insert(points.end(), {spacing * double(i), 0.0, 0.0});
    return points;
}

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

// A U-turn: two straight legs along x, `gap` apart axis to axis, joined by a half circle.
std::vector<double> u_turn(double gap) {
    std::vector<double> points;
    const double leg = 0.2, step = 0.005;
    for (double x = leg; x > 0.0; x -= step) points.insert(points.end(), {x, 0.0, 0.0});
    for (int i = 0; i <= 12; ++i) {
        const double angle = 3.14159265358979 * i / 12.0;
        points.insert(points.end(), {-0.5 * gap * std::sin(angle), 0.5 * gap * (1.0 - std::cos(angle)), 0.0});
    }
    for (double x = step; x <= leg; x += step) points.insert(points.end(), {x, gap, 0.0});
    return points;
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

TEST(SphereLoads, SharedByTheContactEffectsEqualsEachApplyingItsOwn) {
    // A U-turn whose legs touch, lying 0.4 R deep in a floor and moving: self-contact and
    // floor contacts on the same spheres, with damping and friction. The scene gives both
    // effects one set of sphere loads, which Dynamics applies once after them; that must
    // give the forces, H v and system of each effect applying its own, up to rounding.
    namespace mech = enteron::mechanics;
    using enteron::collision::EnvironmentForce;
    using enteron::collision::Obstacle;
    using enteron::collision::ObstacleKind;
    auto* memory = std::pmr::new_delete_resource();
    Axis axis(u_turn(1.8 * kRadius));
    std::mt19937 random(5);
    std::uniform_real_distribution<double> speed(-0.05, 0.05);
    for (double& v : axis.state.v) v = speed(random);
    Obstacle floor;
    floor.kind = ObstacleKind::plane;
    floor.center = {0.0, 0.0, -0.6 * kRadius};
    floor.extent = {0.0, 0.0, 1.0};
    const std::vector<Obstacle> obstacles{floor};
    ContactParameters contact;
    contact.damping_depth = 0.1 * kRadius;
    const std::size_t m = axis.state.q.size();
    const double h = 1e-3;
    struct Result {
        mech::SystemMatrix system;
        std::vector<double> force, hv;
    };
    const auto fresh = [&] {
        Result r{mech::SystemMatrix(memory), std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
        r.system.resize(m);
        return r;
    };

    // Each effect with loads of its own, applied after it.
    CollisionSpheres spheres_apart = axis.make_spheres();
    SphereLoads floor_loads(spheres_apart, memory), self_loads(spheres_apart, memory);
    EnvironmentForce floor_apart(spheres_apart, contact, obstacles, axis.state, memory, floor_loads);
    SelfContactForce self_apart(spheres_apart, contact, axis.state, memory, self_loads);
    Result apart = fresh();
    mech::Linearization lin_apart{&apart.system, h, apart.hv.data()};
    evaluate_with_loads(floor_apart, floor_loads, axis.state, apart.force.data(), &lin_apart);
    evaluate_with_loads(self_apart, self_loads, axis.state, apart.force.data(), &lin_apart);
    ContactSummary contacts;
    floor_apart.add_contacts(contacts);
    self_apart.add_contacts(contacts);
    ASSERT_GT(contacts.count, 20u);

    // Both into one set of loads: nothing reaches the forces until the loads are applied.
    CollisionSpheres spheres_shared = axis.make_spheres();
    SphereLoads loads(spheres_shared, memory);
    EnvironmentForce floor_shared(spheres_shared, contact, obstacles, axis.state, memory, loads);
    SelfContactForce self_shared(spheres_shared, contact, axis.state, memory, loads);
    Result shared = fresh();
    mech::Linearization lin_shared{&shared.system, h, shared.hv.data()};
    loads.clear();
    floor_shared.evaluate(axis.state, shared.force.data(), &lin_shared);
    self_shared.evaluate(axis.state, shared.force.data(), &lin_shared);
    for (double f : shared.force) ASSERT_EQ(f, 0.0);
    loads.apply(shared.force.data(), &lin_shared);

    // The same through Dynamics, which clears the loads before the effects and applies them after.
    CollisionSpheres spheres_dynamics = axis.make_spheres();
    SphereLoads dynamics_loads(spheres_dynamics, memory);
    mech::Dynamics dynamics(axis.model, memory);
    dynamics.add_effect(enteron::make_owned<EnvironmentForce>(memory, spheres_dynamics, contact, obstacles,
                                                              axis.state, memory, dynamics_loads));
    dynamics.add_effect(enteron::make_owned<SelfContactForce>(memory, spheres_dynamics, contact, axis.state, memory,
                                                              dynamics_loads));
    dynamics.add_shared_loads(&dynamics_loads, enteron::EffectId::self_collision);
    dynamics.finalize();
    Result through = fresh();
    mech::Linearization lin_through{&through.system, h, through.hv.data()};
    for (int round = 0; round < 2; ++round) {  // a second evaluation must not keep the first's loads
        std::fill(through.force.begin(), through.force.end(), 0.0);
        through.system.set_zero();
        dynamics.forces(axis.state, through.force.data(), &lin_through);
    }

    double force_scale = 0.0, hv_scale = 0.0, system_scale = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
        force_scale = std::max(force_scale, std::fabs(apart.force[k]));
        hv_scale = std::max(hv_scale, std::fabs(apart.hv[k]));
        for (std::size_t j = 0; j < m; ++j) system_scale = std::max(system_scale, std::fabs(apart.system.at(k, j)));
    }
    ASSERT_GT(force_scale, 0.0);
    ASSERT_GT(hv_scale, 0.0);
    ASSERT_GT(system_scale, 0.0);
    for (const Result* other : {&shared, &through})
        for (std::size_t k = 0; k < m; ++k) {
            EXPECT_NEAR(other->force[k], apart.force[k], 1e-12 * force_scale) << k;
            EXPECT_NEAR(other->hv[k], apart.hv[k], 1e-12 * hv_scale) << k;
            for (std::size_t j = k >= 11 ? k - 11 : 0; j <= k; ++j)
                EXPECT_NEAR(other->system.at(k, j), apart.system.at(k, j), 1e-12 * system_scale) << k << ", " << j;
        }
    // The loads' time counts as the self-contact's.
    EXPECT_EQ(dynamics.counters(enteron::EffectId::self_collision).calls, 2u);
    EXPECT_GT(dynamics.counters(enteron::EffectId::self_collision).total_time_ns, 0u);
}

}  // namespace
