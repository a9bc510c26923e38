// SPDX-License-Identifier: Apache-2.0
// The bordered solve (lib/mechanics/bordered_system.h) against a dense solve of the whole
// system [A -B; -B^T P] [dv; e] = [r; r_p] (Eigen's LDL^T): bodies held by contact springs
// K_b at spline points, also pulled by a device spring D_b, so the whole matrix is positive
// definite; bodies on distant control points and two bodies on the same ones, solve after
// solve with one BorderedSystem; a body held
// in one direction only (a frictionless contact), whose unheld unknowns are set to zero,
// as the dense solve with them removed gives; a body that touches nothing; a pinned
// coordinate, which the bodies do not move.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "mechanics/bordered_system.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kBorderedSystemPoints = 16, kBorderedSystemCoordinates = 3 * kBorderedSystemPoints;

// A random symmetric positive definite band matrix (the bowel's system), as SystemMatrix
// and dense.
struct BowelSystem {
    explicit BowelSystem(uint64_t seed) : dense(Eigen::MatrixXd::Zero(kBorderedSystemCoordinates, kBorderedSystemCoordinates)) {
        std::mt19937_64 random(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        banded.resize(kBorderedSystemCoordinates);
        for (std::size_t i = 0; i < kBorderedSystemCoordinates; ++i)
            for (std::size_t j = i >= 11 ? i - 11 : 0; j <= i; ++j) {
                const double value = i == j ? 30.0 + 5.0 * u(random) : u(random);
                banded.add(i, j, value);
                dense(i, j) = dense(j, i) = value;
            }
    }
    // Adds (w w^T) (x) K at a spline point: a contact spring on the bowel's side.
    void add_spring(const spline::SegmentWeights& w, const Mat3& k) {
        for (std::size_t a = 0; a < 4; ++a)
            for (std::size_t b = 0; b < 4; ++b) {
                const std::size_t i = 3 * (w.first + a), j = 3 * (w.first + b);
                dense.block<3, 3>(i, j) += w.w[a] * w.w[b] * k;
                if (j <= i)
                    for (std::size_t r = 0; r < 3; ++r)
                        for (std::size_t c = 0; c < 3; ++c)
                            if (j + c <= i + r) banded.add(i + r, j + c, w.w[a] * w.w[b] * k(r, c));
            }
    }
    SystemMatrix banded;
    Eigen::MatrixXd dense;
};

struct Body {
    spline::SegmentWeights weights;
    Mat3 spring;  // K: the contact, between the body and the bowel's point
    Mat3 device;  // D: what else holds the body
    Vec3 rhs;
};

spline::SegmentWeights bordered_system_weights(std::size_t first, double t) {
    spline::SegmentWeights w;
    w.first = first;
    const std::array<double, 4> raw = spline::raw_weights(t, spline::Derivative::value);
    for (int k = 0; k < 4; ++k) w.w[k] = raw[k];
    return w;
}

Mat3 spd(std::mt19937_64& random, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = u(random);
    return scale * (a * a.transpose() + 0.5 * Mat3::Identity());
}

// The bordered solve's dv and e, and the dense solve's, of the same system. `held`: per
// body, the directions its unknowns may take (the dense solve keeps only those).
struct Solutions {
    Eigen::VectorXd bordered, dense;
};

Solutions solve_both(BowelSystem& bowel, const std::vector<Body>& bodies, const Eigen::VectorXd& r,
                     const std::vector<Mat3>& held_directions = {}, const std::vector<std::size_t>& pinned = {},
                     BorderedSystem* reused = nullptr) {
    for (const Body& b : bodies) bowel.add_spring(b.weights, b.spring);
    const std::size_t m = 3 * bodies.size();
    // Dense: [A -B; -B^T P], B = w (x) K, P = K + D; pinned rows and columns identity.
    Eigen::MatrixXd whole = Eigen::MatrixXd::Zero(kBorderedSystemCoordinates + m, kBorderedSystemCoordinates + m);
    whole.topLeftCorner(kBorderedSystemCoordinates, kBorderedSystemCoordinates) = bowel.dense;
    Eigen::VectorXd rhs(kBorderedSystemCoordinates + m);
    rhs.head(kBorderedSystemCoordinates) = r;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const Body& body = bodies[b];
        const std::size_t at = kBorderedSystemCoordinates + 3 * b;
        whole.block<3, 3>(at, at) = body.spring + body.device;
        for (std::size_t k = 0; k < 4; ++k) {
            const Mat3 coupling = body.weights.w[k] * body.spring;
            whole.block<3, 3>(3 * (body.weights.first + k), at) = -coupling;
            whole.block<3, 3>(at, 3 * (body.weights.first + k)) = -coupling.transpose();
        }
        rhs.segment<3>(at) = body.rhs;
    }
    Eigen::VectorXd r_pinned = r;
    for (std::size_t p : pinned) {
        whole.row(p).setZero();
        whole.col(p).setZero();
        whole(p, p) = 1.0;
        rhs[p] = 0.0;
        r_pinned[p] = 0.0;
        bowel.banded.make_identity_row(p);
    }
    // The unknowns the dense solve keeps: every bowel coordinate, each body's held directions.
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(kBorderedSystemCoordinates + m, kBorderedSystemCoordinates + m);
    basis.topLeftCorner(kBorderedSystemCoordinates, kBorderedSystemCoordinates).setIdentity();
    std::size_t columns = kBorderedSystemCoordinates;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const Mat3 held = held_directions.empty() ? Mat3::Identity() : held_directions[b];
        for (int c = 0; c < 3; ++c)
            if (held.col(c).squaredNorm() > 0.0) basis.block<3, 1>(kBorderedSystemCoordinates + 3 * b, columns++) = held.col(c);
    }
    const Eigen::MatrixXd t = basis.leftCols(columns);
    Solutions out;
    out.dense = t * (t.transpose() * whole * t).ldlt().solve(t.transpose() * rhs);

    BorderedSystem own(std::pmr::new_delete_resource());
    BorderedSystem& border = reused != nullptr ? *reused : own;
    border.clear();
    border.reserve(bodies.size(), kBorderedSystemCoordinates);
    for (const Body& body : bodies) {
        const std::size_t index = border.add_body(body.spring + body.device, body.rhs);
        border.add_coupling(index, body.weights, body.spring);
    }
    for (std::size_t p : pinned) border.zero_row(p);
    EXPECT_TRUE(bowel.banded.factor());
    Eigen::VectorXd dv = r_pinned;
    bowel.banded.solve(dv.data());
    border.solve(bowel.banded, dv.data());
    out.bordered.resize(kBorderedSystemCoordinates + m);
    out.bordered.head(kBorderedSystemCoordinates) = dv;
    for (std::size_t b = 0; b < bodies.size(); ++b) out.bordered.segment<3>(kBorderedSystemCoordinates + 3 * b) = border.solution(b);
    return out;
}

Eigen::VectorXd random_rhs(std::mt19937_64& random) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd r(kBorderedSystemCoordinates);
    for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = u(random);
    return r;
}

TEST(BorderedSystem, MatchesADenseSolveOfTheWholeSystem) {
    std::mt19937_64 random(7);
    BowelSystem bowel(11);
    const std::vector<Body> bodies = {
        {bordered_system_weights(2, 0.3), spd(random, 40.0), spd(random, 5.0), Vec3(0.2, -0.1, 0.4)},
        {bordered_system_weights(2, 0.8), spd(random, 20.0), spd(random, 1.0), Vec3(-0.3, 0.0, 0.1)},  // the same points
        {bordered_system_weights(11, 0.5), spd(random, 60.0), spd(random, 2.0), Vec3(0.0, 0.5, -0.2)},  // far away
    };
    const Solutions s = solve_both(bowel, bodies, random_rhs(random));
    EXPECT_LT((s.bordered - s.dense).cwiseAbs().maxCoeff(), 1e-10 * s.dense.cwiseAbs().maxCoeff());
}

TEST(BorderedSystem, EverySolveOfTheSameBordersMatchesTheDenseSolve) {
    // One BorderedSystem solves step after step: nothing of a solve may leak into the next
    // (two proxies on distant folds each step: their Schur blocks couple them by nothing).
    std::mt19937_64 random(5);
    BorderedSystem border(std::pmr::new_delete_resource());
    for (int solve = 0; solve < 4; ++solve) {
        BowelSystem bowel(20 + solve);
        const std::vector<Body> bodies = {
            {bordered_system_weights(1, 0.4), spd(random, 40.0), spd(random, 5.0), Vec3(0.2, -0.1, 0.4)},
            {bordered_system_weights(12, 0.6), spd(random, 30.0), spd(random, 2.0), Vec3(-0.3, 0.2, 0.1)},
        };
        const Solutions s = solve_both(bowel, bodies, random_rhs(random), {}, {}, &border);
        EXPECT_LT((s.bordered - s.dense).cwiseAbs().maxCoeff(), 1e-10 * s.dense.cwiseAbs().maxCoeff())
            << "solve " << solve;
    }
}

TEST(BorderedSystem, AnUnknownNoContactHoldsIsSetToZero) {
    std::mt19937_64 random(3);
    // Held along z only (a frictionless contact on a floor): its x and y unknowns are zero
    // pivots of P - B^T X, set to zero; a right-hand side along z has nothing in them.
    {
        BowelSystem bowel(5);
        const Vec3 z(0, 0, 1);
        Body frictionless{bordered_system_weights(6, 0.4), 80.0 * z * z.transpose(), Mat3::Zero(), 0.3 * z};
        const Solutions s = solve_both(bowel, {frictionless}, random_rhs(random), {z * z.transpose()});
        EXPECT_LT((s.bordered - s.dense).cwiseAbs().maxCoeff(), 1e-10 * s.dense.cwiseAbs().maxCoeff());
        EXPECT_EQ(s.bordered[kBorderedSystemCoordinates], 0.0);
        EXPECT_EQ(s.bordered[kBorderedSystemCoordinates + 1], 0.0);
        EXPECT_GT(std::fabs(s.bordered[kBorderedSystemCoordinates + 2]), 1e-6);
    }
    // Along a tilted normal the zero pivots are coordinates, not the directions across the
    // normal: the body's unknowns are a solution, not the smallest one, but what reaches
    // the bowel (K e, along the normal) and so dv are the dense solve's.
    {
        BowelSystem bowel(5);
        const Vec3 normal = Vec3(0.3, -0.2, 1.0).normalized();
        Body frictionless{bordered_system_weights(6, 0.4), 80.0 * normal * normal.transpose(), Mat3::Zero(), 0.3 * normal};
        const Solutions s = solve_both(bowel, {frictionless}, random_rhs(random), {normal * normal.transpose()});
        const double scale = s.dense.cwiseAbs().maxCoeff();
        EXPECT_LT((s.bordered.head(kBorderedSystemCoordinates) - s.dense.head(kBorderedSystemCoordinates)).cwiseAbs().maxCoeff(), 1e-10 * scale);
        EXPECT_NEAR(s.bordered.tail<3>().dot(normal), s.dense.tail<3>().dot(normal), 1e-10 * scale);
    }
}

TEST(BorderedSystem, ABodyTouchingNothingIsSolvedAlone) {
    std::mt19937_64 random(4);
    BowelSystem bowel(8);
    Body alone{bordered_system_weights(4, 0.5), Mat3::Zero(), spd(random, 3.0), Vec3(1.0, 2.0, -1.0)};
    const Eigen::VectorXd r = random_rhs(random);
    const Solutions s = solve_both(bowel, {alone}, r);
    EXPECT_LT((s.bordered - s.dense).cwiseAbs().maxCoeff(), 1e-12 * s.dense.cwiseAbs().maxCoeff());
    EXPECT_LT((s.bordered.tail<3>() - alone.device.inverse() * alone.rhs).norm(), 1e-12);
}

TEST(BorderedSystem, APinnedCoordinateIsNotMovedByTheBodies) {
    std::mt19937_64 random(9);
    BowelSystem bowel(2);
    const std::vector<Body> bodies = {{bordered_system_weights(5, 0.5), spd(random, 50.0), spd(random, 4.0), Vec3(0.5, 0.5, 0.5)}};
    const std::vector<std::size_t> pinned = {3 * 6 + 0, 3 * 6 + 1, 3 * 6 + 2, 3 * 7 + 2};
    const Solutions s = solve_both(bowel, bodies, random_rhs(random), {}, pinned);
    EXPECT_LT((s.bordered - s.dense).cwiseAbs().maxCoeff(), 1e-10 * s.dense.cwiseAbs().maxCoeff());
    for (std::size_t p : pinned) EXPECT_EQ(s.bordered[static_cast<Eigen::Index>(p)], 0.0) << p;
}

TEST(BorderedSystem, ClearForgetsTheBodiesAndTheirCouplings) {
    std::mt19937_64 random(12);
    BorderedSystem border(std::pmr::new_delete_resource());
    border.reserve(2, kBorderedSystemCoordinates);
    EXPECT_EQ(border.capacity(), 2u);
    const std::size_t a = border.add_body(spd(random, 1.0), Vec3(1, 0, 0));
    border.add_coupling(a, bordered_system_weights(3, 0.5), spd(random, 10.0));
    EXPECT_EQ(border.size(), 1u);
    border.clear();  // never solved: its coupling must go too
    EXPECT_EQ(border.size(), 0u);
    // Now a body that touches nothing: the old coupling must not reach its solution.
    BowelSystem bowel(1);
    ASSERT_TRUE(bowel.banded.factor());
    const Mat3 device = spd(random, 2.0);
    border.add_body(device, Vec3(0, 1, 0));
    std::vector<double> dv(kBorderedSystemCoordinates, 0.0);
    border.solve(bowel.banded, dv.data());
    EXPECT_LT((border.solution(0) - device.inverse() * Vec3(0, 1, 0)).norm(), 1e-12);
    for (double x : dv) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace enteron::mechanics
