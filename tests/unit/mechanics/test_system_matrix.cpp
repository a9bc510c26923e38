// SPDX-License-Identifier: Apache-2.0
// The implicit system's assembly kernels (lib/mechanics/system_matrix.h) against dense
// products written from their formulas: an axial block adds scale (w w^T) (x) (a u u^T + b I)
// on the four points of a spline point; a pair of them is the sum of two; a SegmentBlock
// adds sum_m (w_m w_m^T) (x) S_m once; add_per_coordinate adds B (x) I3; a point force
// reaches the generalised forces as w_k f; axial_times is (a u u^T + b I) x.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "mechanics/system_matrix.h"

namespace enteron::mechanics {
namespace {

constexpr std::size_t kSystemMatrixPoints = 9, kSystemMatrixCoordinates = 3 * kSystemMatrixPoints;

Eigen::MatrixXd dense(const SystemMatrix& m) {
    Eigen::MatrixXd out(kSystemMatrixCoordinates, kSystemMatrixCoordinates);
    for (std::size_t i = 0; i < kSystemMatrixCoordinates; ++i)
        for (std::size_t j = 0; j < kSystemMatrixCoordinates; ++j) out(i, j) = m.at(i, j);
    return out;
}

// (w w^T) (x) S on points first .. first+3, dense.
Eigen::MatrixXd kron(const spline::SegmentWeights& w, const Mat3& s) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(kSystemMatrixCoordinates, kSystemMatrixCoordinates);
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = 0; b < 4; ++b) out.block<3, 3>(3 * (w.first + a), 3 * (w.first + b)) = w.w[a] * w.w[b] * s;
    return out;
}

spline::SegmentWeights system_matrix_weights(std::size_t segment, double t) {
    return spline::segment_weights(kSystemMatrixPoints, segment, t, spline::Derivative::first);
}

SystemMatrix zero_system() {
    SystemMatrix m;
    m.resize(kSystemMatrixCoordinates);
    return m;
}

TEST(SystemMatrix, AnAxialBlockIsTheKroneckerProductOfItsLaw) {
    const Vec3 u = Vec3(0.2, -0.6, 0.7).normalized();
    for (std::size_t segment : {0u, 3u, 7u}) {
        SystemMatrix m = zero_system();
        const spline::SegmentWeights w = system_matrix_weights(segment, 0.3);
        add_axial_block(m, w, u, 50.0, 2.0, 0.01);
        const Mat3 law = 50.0 * u * u.transpose() + 2.0 * Mat3::Identity();
        EXPECT_LT((dense(m) - 0.01 * kron(w, law)).cwiseAbs().maxCoeff(), 1e-14) << "segment " << segment;
        const Vec3 x(0.3, 0.1, -0.4);
        EXPECT_LT((axial_times(u, 50.0, 2.0, x) - law * x).norm(), 1e-13);
    }
}

TEST(SystemMatrix, APairOfAxialBlocksIsTheSumOfTwo) {
    const spline::SegmentWeights w0 = system_matrix_weights(4, 0.21), w1 = system_matrix_weights(4, 0.79);
    const Vec3 u0 = Vec3(1, 2, 3).normalized(), d1(0.5, -1.0, 0.25);  // d1 need not be a unit vector when b = 0
    SystemMatrix pair = zero_system(), single = zero_system();
    add_axial_block_pair(pair, w0, u0, 3.0, 0.5, w1, d1, 7.0 / d1.squaredNorm(), 0.0);
    add_axial_block(single, w0, u0, 3.0, 0.5, 1.0);
    add_axial_block(single, w1, d1.normalized(), 7.0, 0.0, 1.0);
    EXPECT_LT((dense(pair) - dense(single)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(SystemMatrix, ASegmentBlockAddsItsSumOnce) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    SegmentBlock block;
    block.reset(2);
    EXPECT_EQ(block.first(), 2u);
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(kSystemMatrixCoordinates, kSystemMatrixCoordinates);
    for (const double t : {0.1, 0.5, 0.9}) {
        spline::SegmentWeights w = spline::segment_weights(kSystemMatrixPoints, 3, t, spline::Derivative::value);
        Mat3 a;
        for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = uniform(random);
        const Mat3 s = a + a.transpose();
        const double lower[6] = {s(0, 0), s(1, 0), s(1, 1), s(2, 0), s(2, 1), s(2, 2)};
        block.add(w, lower);
        expected += kron(w, s);
    }
    SystemMatrix m = zero_system();
    block.add_to(m);
    EXPECT_LT((dense(m) - expected).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(SystemMatrix, APerCoordinateMatrixIsAddedToXYAndZ) {
    numerics::ScalarBandMatrix b;
    b.resize(kSystemMatrixPoints);
    for (std::size_t i = 0; i < kSystemMatrixPoints; ++i)
        for (std::size_t j = i >= 3 ? i - 3 : 0; j <= i; ++j) b.add(i, j, 1.0 + double(i) + 0.1 * double(j));
    SystemMatrix m = zero_system();
    add_per_coordinate(b, 2.0, m);
    for (std::size_t i = 0; i < kSystemMatrixCoordinates; ++i)
        for (std::size_t j = 0; j < kSystemMatrixCoordinates; ++j)
            EXPECT_EQ(m.at(i, j), i % 3 == j % 3 ? 2.0 * b.at(i / 3, j / 3) : 0.0) << i << ", " << j;
}

TEST(SystemMatrix, APointForceReachesItsFourControlPoints) {
    const spline::SegmentWeights w0 = spline::segment_weights(kSystemMatrixPoints, 5, 0.3, spline::Derivative::value);
    const spline::SegmentWeights w1 = spline::segment_weights(kSystemMatrixPoints, 5, 0.8, spline::Derivative::value);
    const Vec3 f0(1.0, -2.0, 0.5), f1(0.0, 3.0, -1.0);
    std::vector<double> single(kSystemMatrixCoordinates, 0.0), pair(kSystemMatrixCoordinates, 0.0), expected(kSystemMatrixCoordinates, 0.0);
    add_point_force(w0, f0, single.data());
    add_point_force(w1, f1, single.data());
    add_point_force_pair(w0, f0, w1, f1, pair.data());
    for (std::size_t k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) expected[3 * (w0.first + k) + c] = w0.w[k] * f0[c] + w1.w[k] * f1[c];
    for (std::size_t i = 0; i < kSystemMatrixCoordinates; ++i) {
        EXPECT_NEAR(single[i], expected[i], 1e-15);
        EXPECT_NEAR(pair[i], expected[i], 1e-15);
    }
    // The total force is kept (the value weights sum to one).
    Vec3 total = Vec3::Zero();
    for (std::size_t i = 0; i < kSystemMatrixPoints; ++i) total += point_at(pair.data(), i);
    EXPECT_LT((total - f0 - f1).norm(), 1e-14);
}

}  // namespace
}  // namespace enteron::mechanics
