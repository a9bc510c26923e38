// SPDX-License-Identifier: Apache-2.0
// Clamped ends (lib/mechanics/clamped_ends.h): the end tangent of the quadratic end
// treatment is a parabola's exact tangent; a folded end has no direction and is refused;
// the reduced solve (reduce, reduce_rhs, factor, solve, expand) gives the solution of the
// constrained system, checked against a dense KKT solve [A C^T; C 0] with the pins and the
// clamps' two rows per end; its velocity then holds the constraint whatever the velocity
// it starts from; an end attached to a turning frame turns with it, at a bounded rate; the
// attachments survive a saved state and a damaged one is refused.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "base/error.h"
#include "base/saved_image.h"
#include "base/state_io.h"
#include "mechanics/clamped_ends.h"
#include "saved_state_image.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kClampedEndsPoints = 9, kClampedEndsCoordinates = 3 * kClampedEndsPoints;

// Control points along a gentle 3-D curve.
std::vector<double> curve() {
    std::vector<double> q;
    for (std::size_t i = 0; i < kClampedEndsPoints; ++i) {
        const double s = 0.05 * double(i);
        q.insert(q.end(), {s, 0.3 * s * s, 0.1 * std::sin(4.0 * s)});
    }
    return q;
}

TEST(ClampedEnds, TheEndTangentIsAParabolasTangent) {
    // q_i = (i, i^2, 0): the parabola (t, t^2) with P'(0) = (1, 0), P'(n-1) = (1, 2 (n-1)).
    std::vector<double> q;
    for (std::size_t i = 0; i < kClampedEndsPoints; ++i) q.insert(q.end(), {double(i), double(i * i), 0.0});
    EXPECT_LT((clamped_end_tangent(q.data(), kClampedEndsPoints, true) - Vec3(1, 0, 0)).norm(), 1e-14);
    EXPECT_LT((clamped_end_tangent(q.data(), kClampedEndsPoints, false) - Vec3(1, 2.0 * (kClampedEndsPoints - 1), 0)).norm(), 1e-12);
    EXPECT_FALSE(clamped_end_is_degenerate(q.data(), kClampedEndsPoints, true));
    // Folded back: q_2 = 4 q_1 - 3 q_0 gives a zero tangent although the points differ.
    std::vector<double> folded = q;
    point_at(folded.data(), 2) = 4.0 * point_at(folded.data(), 1) - 3.0 * point_at(folded.data(), 0);
    EXPECT_TRUE(clamped_end_is_degenerate(folded.data(), kClampedEndsPoints, true));
    EXPECT_THROW(ClampedEnds(true, false, folded.data(), kClampedEndsPoints), Error);
    EXPECT_THROW(ClampedEnds(true, true, q.data(), 5), Error) << "both ends need 6 points";
    EXPECT_THROW(ClampedEnds(true, false, q.data(), 3), Error);
}

TEST(ClampedEnds, ItClampsWhatItIsAskedAndKnowsTheNearPoints) {
    const std::vector<double> q = curve();
    const ClampedEnds last(false, true, q.data(), kClampedEndsPoints);
    EXPECT_FALSE(last.clamped(true));
    EXPECT_TRUE(last.clamped(false));
    EXPECT_EQ(last.direction(true), Vec3::Zero());
    EXPECT_LT((last.direction(false) - clamped_end_tangent(q.data(), kClampedEndsPoints, false).normalized()).norm(), 1e-15);
    EXPECT_TRUE(last.constrains(kClampedEndsPoints - 2) && last.constrains(kClampedEndsPoints - 3));
    EXPECT_FALSE(last.constrains(kClampedEndsPoints - 1) || last.constrains(1));
}

// A random symmetric positive definite system over the 3n coordinates with the pattern of
// the spline's: control points more than 3 apart share no segment (a zero block).
Eigen::MatrixXd random_system(uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(kClampedEndsCoordinates, kClampedEndsCoordinates);
    for (std::size_t i = 0; i < kClampedEndsCoordinates; ++i)
        for (std::size_t j = 0; j <= i; ++j)
            if (i / 3 - j / 3 <= 3) a(i, j) = a(j, i) = i == j ? 20.0 + u(random) : u(random);
    return a;
}

// The clamped system's solution dv of A dv = b, pins at the end points, by the library's
// reduction, and the dense KKT solution with the constraints e_k . (4 dv_1 - 3 dv_0 - dv_2)
// = -e_k . u(v) (dv_0 = 0 at a pinned end).
struct Both {
    Eigen::VectorXd reduced, kkt;
};
Both clamped_ends_solve_both(const ClampedEnds& clamps, const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& v,
                const std::vector<std::size_t>& pinned_points) {
    SystemMatrix system;
    system.resize(kClampedEndsCoordinates);
    for (std::size_t i = 0; i < kClampedEndsCoordinates; ++i)
        for (std::size_t j = i >= 11 ? i - 11 : 0; j <= i; ++j) system.add(i, j, a(i, j));
    Both out;
    out.reduced = b;
    for (std::size_t p : pinned_points)
        for (std::size_t c = 0; c < 3; ++c) {
            system.make_identity_row(3 * p + c);
            out.reduced[3 * p + c] = 0.0;
        }
    clamps.reduce(system);
    clamps.reduce_rhs(out.reduced.data(), v.data());
    EXPECT_TRUE(system.factor());
    system.solve(out.reduced.data());
    clamps.expand(out.reduced.data());

    std::vector<Eigen::RowVectorXd> rows;
    std::vector<double> values;
    for (std::size_t p : pinned_points)
        for (std::size_t c = 0; c < 3; ++c) {
            Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(kClampedEndsCoordinates);
            row[3 * p + c] = 1.0;
            rows.push_back(row);
            values.push_back(0.0);
        }
    for (const bool first : {true, false}) {
        if (!clamps.clamped(first)) continue;
        const std::size_t end = first ? 0 : kClampedEndsPoints - 1, near = first ? 1 : kClampedEndsPoints - 2, far = first ? 2 : kClampedEndsPoints - 3;
        const Vec3 d = clamps.direction(first);
        // Two unit vectors across d (any pair spans the same constraint).
        const Vec3 e1 = d.unitOrthogonal(), e2 = d.cross(e1);
        const Vec3 u = 4.0 * point_at(v.data(), near) - 3.0 * point_at(v.data(), end) - point_at(v.data(), far);
        for (const Vec3& e : {e1, e2}) {
            Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(kClampedEndsCoordinates);
            row.segment<3>(3 * near) = 4.0 * e.transpose();
            row.segment<3>(3 * end) = -3.0 * e.transpose();
            row.segment<3>(3 * far) = -e.transpose();
            rows.push_back(row);
            values.push_back(-e.dot(u));
        }
    }
    const Eigen::Index m = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(kClampedEndsCoordinates + m, kClampedEndsCoordinates + m);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(kClampedEndsCoordinates + m);
    kkt.topLeftCorner(kClampedEndsCoordinates, kClampedEndsCoordinates) = a;
    rhs.head(kClampedEndsCoordinates) = b;
    for (Eigen::Index r = 0; r < m; ++r) {
        kkt.block(kClampedEndsCoordinates + r, 0, 1, kClampedEndsCoordinates) = rows[r];
        kkt.block(0, kClampedEndsCoordinates + r, kClampedEndsCoordinates, 1) = rows[r].transpose();
        rhs[kClampedEndsCoordinates + r] = values[r];
    }
    out.kkt = kkt.fullPivLu().solve(rhs).head(kClampedEndsCoordinates);
    return out;
}

TEST(ClampedEnds, TheReducedSolveIsTheConstrainedSolution) {
    const std::vector<double> q = curve();
    std::mt19937_64 random(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd b(kClampedEndsCoordinates), v(kClampedEndsCoordinates);
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = u(random);
    // A velocity on the constraint (what the integrators keep): the reduced system is then
    // exactly the constrained one.
    const ClampedEnds both(true, true, q.data(), kClampedEndsPoints);
    v.setZero();
    for (std::size_t i = 3; i + 3 < kClampedEndsPoints; ++i) point_at(v.data(), i) = Vec3(u(random), u(random), u(random));
    const Both s = clamped_ends_solve_both(both, random_system(3), b, v, {0, kClampedEndsPoints - 1});
    EXPECT_LT((s.reduced - s.kkt).cwiseAbs().maxCoeff(), 1e-12 * s.kkt.cwiseAbs().maxCoeff());
    const ClampedEnds first(true, false, q.data(), kClampedEndsPoints);
    const Both f = clamped_ends_solve_both(first, random_system(4), b, v, {0});
    EXPECT_LT((f.reduced - f.kkt).cwiseAbs().maxCoeff(), 1e-12 * f.kkt.cwiseAbs().maxCoeff());
}

TEST(ClampedEnds, TheVelocityComesBackOntoTheConstraint) {
    // From a velocity off the constraint (round-off drift, a pin released) the solution
    // brings v + dv back onto it exactly.
    const std::vector<double> q = curve();
    const ClampedEnds both(true, true, q.data(), kClampedEndsPoints);
    std::mt19937_64 random(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd b(kClampedEndsCoordinates), v(kClampedEndsCoordinates);
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = u(random), v[i] = u(random);
    for (std::size_t c = 0; c < 3; ++c) v[c] = v[3 * (kClampedEndsPoints - 1) + c] = 0.0;  // the pinned ends rest
    const Both s = clamped_ends_solve_both(both, random_system(5), b, v, {0, kClampedEndsPoints - 1});
    const Eigen::VectorXd after = v + s.reduced;
    for (const bool first : {true, false}) {
        const Vec3 tangent = clamped_end_tangent(after.data(), kClampedEndsPoints, first);
        const Vec3 d = both.direction(first);
        EXPECT_LT((tangent - tangent.dot(d) * d).norm(), 1e-12) << "its rate stays along the clamp";
    }
}

TEST(ClampedEnds, AnEndAttachedToATurningFrameTurnsWithIt) {
    const std::vector<double> q = curve();
    ClampedEnds clamps(true, false, q.data(), kClampedEndsPoints);
    RigidFrames frames(std::pmr::new_delete_resource());
    const std::size_t frame = frames.add(RigidPose{});
    clamps.attach(true, frames, frame, 0.0);
    const Vec3 before = clamps.direction(true);
    State state;
    state.resize(kClampedEndsPoints);
    std::copy(q.begin(), q.end(), state.q.begin());
    // The frame turns 2 degrees about z in a step of 10 ms.
    RigidPose turned;
    const double angle = 2.0 * kPi / 180.0;
    turned.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
    frames.set_target(frame, turned);
    const double dt = 0.01;
    frames.begin_step(0.0, dt);
    EXPECT_TRUE(clamps.prescribe(state, dt, 10.0));
    EXPECT_LT((clamps.direction(true) - turned.orientation * before).norm(), 1e-14);
    // The tangent's rate across the new direction brings u = 2 P'(0) onto it in the step.
    const Vec3 d = clamps.direction(true);
    const Vec3 u = 2.0 * clamped_end_tangent(state.q.data(), kClampedEndsPoints, true);
    const Vec3 rate = 2.0 * clamped_end_tangent(state.v.data(), kClampedEndsPoints, true);
    const Vec3 across = (u + dt * rate) - (u + dt * rate).dot(d) * d;
    EXPECT_LT(across.norm(), 1e-12 * u.norm());
    // With a tight speed limit the turn is spread over more steps.
    ClampedEnds slow(true, false, q.data(), kClampedEndsPoints);
    slow.attach(true, frames, frame, 0.0);
    State rest;
    rest.resize(kClampedEndsPoints);
    std::copy(q.begin(), q.end(), rest.q.begin());
    slow.prescribe(rest, dt, 1e-4);
    EXPECT_NEAR(point_at(rest.v.data(), 1).norm(), 1e-4, 1e-12) << "the near point's change at the limit";
    frames.end_step(true);
    // Back in the world: it holds its direction again.
    clamps.attach(true, frames, ClampedEnds::kWorld, dt);
    frames.begin_step(dt, dt);
    EXPECT_FALSE(clamps.prescribe(state, dt, 10.0));
}

TEST(ClampedEnds, TheAttachmentsSurviveASavedStateAndADamagedOneIsRefused) {
    const std::vector<double> q = curve();
    RigidFrames frames(std::pmr::new_delete_resource());
    const std::size_t frame = frames.add(RigidPose{});
    ClampedEnds saved(true, true, q.data(), kClampedEndsPoints);
    saved.attach(false, frames, frame, 0.0);
    const auto image = [](const ClampedEnds& clamps) {
        return state_test::saved_image([&](StateWriter& out) {
            out.begin_section("clamps", 1);
            clamps.save_attachments(out);
            out.end_section();
        });
    };
    const auto restore = [&](ClampedEnds& clamps, const std::vector<unsigned char>& bytes) {
        StateReader in(bytes.data(), bytes.size());
        for (int pass = 0; pass < 2; ++pass) {
            in.begin_section("clamps", 1);
            clamps.restore_attachments(in, frames);
            in.end_section();
            in.finish();
            if (pass == 0) in.start_applying();
        }
    };
    const std::vector<unsigned char> bytes = image(saved);
    ClampedEnds restored(true, true, q.data(), kClampedEndsPoints);
    restore(restored, bytes);
    EXPECT_EQ(image(restored), bytes);
    ClampedEnds one_end(true, false, q.data(), kClampedEndsPoints);
    try {
        restore(one_end, bytes);
        ADD_FAILURE() << "restored the clamps of another scene";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()), "state: section 'clamps': the saved scene clamps other ends");
    }
    // A direction that is no longer a unit vector (the checksum sealed again).
    std::vector<unsigned char> damaged = bytes;
    const double bent = 0.5;
    std::memcpy(damaged.data() + StateWriter::kHeaderSize + StateWriter::kSectionHeaderSize + 8, &bent, sizeof bent);
    saved_state_image::seal_checksum(damaged.data(), damaged.size());
    ClampedEnds untouched(true, true, q.data(), kClampedEndsPoints);
    const Vec3 direction = untouched.direction(true);
    try {
        restore(untouched, damaged);
        ADD_FAILURE() << "restored a bent frame";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()), "state: section 'clamps': a clamped end's directions are not orthonormal");
    }
    EXPECT_EQ(untouched.direction(true), direction);
}

}  // namespace
}  // namespace enteron::mechanics
