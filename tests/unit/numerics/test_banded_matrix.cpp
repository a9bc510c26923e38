// SPDX-License-Identifier: Apache-2.0
// The banded SPD matrix of lib/numerics against a dense reference written here.
#include "numerics/banded_matrix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using enteron::numerics::BandedSpdMatrix;

using Dense = std::vector<std::vector<double>>;

// Gaussian elimination with partial pivoting: the reference solve.
std::vector<double> dense_solve(Dense a, std::vector<double> b) {
    const std::size_t n = b.size();
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::fabs(a[i][k]) > std::fabs(a[pivot][k])) pivot = i;
        std::swap(a[k], a[pivot]);
        std::swap(b[k], b[pivot]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = a[i][k] / a[k][k];
            for (std::size_t j = k; j < n; ++j) a[i][j] -= f * a[k][j];
            b[i] -= f * b[k];
        }
    }
    std::vector<double> x(n);
    for (std::size_t i = n; i-- > 0;) {
        double s = b[i];
        for (std::size_t j = i + 1; j < n; ++j) s -= a[i][j] * x[j];
        x[i] = s / a[i][i];
    }
    return x;
}

// A = L L^T with L lower triangular of half bandwidth P, positive diagonal: SPD, banded,
// well conditioned.
template <int P>
Dense random_spd_band(std::size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> off(-0.3, 0.3), diag(1.0, 2.0);
    Dense l(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i >= std::size_t(P) ? i - P : 0; j <= i; ++j) l[i][j] = i == j ? diag(rng) : off(rng);
    Dense a(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < n; ++k) a[i][j] += l[i][k] * l[j][k];
    return a;
}

template <int P>
BandedSpdMatrix<P> to_band(const Dense& a) {
    BandedSpdMatrix<P> m;
    m.resize(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = i >= std::size_t(P) ? i - P : 0; j <= i; ++j) m.lower(i, j) = a[i][j];
    return m;
}

double max_rel_diff(const std::vector<double>& x, const std::vector<double>& ref) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        num = std::max(num, std::fabs(x[i] - ref[i]));
        den = std::max(den, std::fabs(ref[i]));
    }
    return num / den;
}

template <int P>
void check_solve_matches_dense(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const Dense a = random_spd_band<P>(n, rng);
    BandedSpdMatrix<P> m = to_band<P>(a);
    std::uniform_real_distribution<double> u(-1.0, 1.0);

    // multiply agrees with the dense product before factorisation.
    std::vector<double> x(n), y(n);
    for (double& v : x) v = u(rng);
    m.multiply(x.data(), y.data());
    for (std::size_t i = 0; i < n; ++i) {
        double s = 0.0;
        for (std::size_t j = 0; j < n; ++j) s += a[i][j] * x[j];
        EXPECT_NEAR(y[i], s, 1e-13) << "row " << i;
    }

    ASSERT_TRUE(m.factor());
    EXPECT_TRUE(m.factored());
    std::vector<double> b(n);
    for (double& v : b) v = u(rng);
    auto solved = b;
    m.solve(solved.data());
    EXPECT_LT(max_rel_diff(solved, dense_solve(a, b)), 1e-12) << "P " << P << " n " << n;

    // Three interleaved right-hand sides (x y z layout, stride 3) in one call.
    std::vector<double> rhs(3 * n);
    for (double& v : rhs) v = u(rng);
    auto interleaved = rhs;
    m.solve(interleaved.data(), 3, 3);
    for (std::size_t c = 0; c < 3; ++c) {
        std::vector<double> column(n), got(n);
        for (std::size_t i = 0; i < n; ++i) {
            column[i] = rhs[3 * i + c];
            got[i] = interleaved[3 * i + c];
        }
        EXPECT_LT(max_rel_diff(got, dense_solve(a, column)), 1e-12) << "column " << c;
    }
}

TEST(BandedSpdMatrix, SolveMatchesDenseSolveHalfBandwidth3) {
    check_solve_matches_dense<3>(4, 21);
    check_solve_matches_dense<3>(5, 26);  // the first size whose backward sweep keeps a value in a register
    check_solve_matches_dense<3>(40, 22);
}

TEST(BandedSpdMatrix, SolveMatchesDenseSolveHalfBandwidth11) {
    check_solve_matches_dense<11>(12, 23);
    check_solve_matches_dense<11>(13, 27);
    check_solve_matches_dense<11>(90, 24);
}

TEST(BandedSpdMatrix, SmallerThanTheBandStillWorks) {
    check_solve_matches_dense<11>(5, 25);
}

TEST(BandedSpdMatrix, FactorRefusesAnIndefiniteMatrix) {
    // [[1 2] [2 1]] inside a larger identity: eigenvalues -1 and 3.
    BandedSpdMatrix<3> m;
    m.resize(6);
    for (std::size_t i = 0; i < 6; ++i) m.lower(i, i) = 1.0;
    m.add(3, 2, 2.0);
    EXPECT_FALSE(m.factor());
    EXPECT_FALSE(m.factored());
}

TEST(BandedSpdMatrix, FactorRefusesANegativeOrZeroDiagonal) {
    BandedSpdMatrix<3> negative;
    negative.resize(4);
    for (std::size_t i = 0; i < 4; ++i) negative.lower(i, i) = i == 2 ? -1.0 : 1.0;
    EXPECT_FALSE(negative.factor());

    BandedSpdMatrix<3> singular;
    singular.resize(4);
    for (std::size_t i = 0; i < 4; ++i) singular.lower(i, i) = i == 0 ? 0.0 : 1.0;
    EXPECT_FALSE(singular.factor());
}

TEST(BandedSpdMatrix, FactorRefusesNaN) {
    BandedSpdMatrix<3> m;
    m.resize(5);
    for (std::size_t i = 0; i < 5; ++i) m.lower(i, i) = 2.0;
    m.lower(3, 3) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(m.factor());
}

TEST(BandedSpdMatrix, AtAndAddAreSymmetric) {
    BandedSpdMatrix<3> m;
    m.resize(7);
    m.add(1, 4, 0.5);  // upper triangle: stored at (4, 1)
    m.add(4, 1, 0.25);
    EXPECT_EQ(m.at(4, 1), 0.75);
    EXPECT_EQ(m.at(1, 4), 0.75);
    EXPECT_EQ(m.at(6, 0), 0.0);  // outside the band
}

TEST(BandedSpdMatrix, IdentityRowFixesOneCoordinate) {
    std::mt19937_64 rng(26);
    const std::size_t n = 20, fixed = 7;
    Dense a = random_spd_band<3>(n, rng);
    BandedSpdMatrix<3> m = to_band<3>(a);
    m.make_identity_row(fixed);
    for (std::size_t j = 0; j < n; ++j) a[fixed][j] = a[j][fixed] = j == fixed ? 1.0 : 0.0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(m.at(i, j), a[i][j]) << i << " " << j;
    ASSERT_TRUE(m.factor());
    std::vector<double> b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = std::sin(double(i));
    auto x = b;
    m.solve(x.data());
    EXPECT_NEAR(x[fixed], b[fixed], 1e-15);
    EXPECT_LT(max_rel_diff(x, dense_solve(a, b)), 1e-12);
}

TEST(BandedSpdMatrix, AssignAndAddScaledWorkOnTheWholeBand) {
    std::mt19937_64 rng(27);
    const Dense a = random_spd_band<3>(10, rng);
    const BandedSpdMatrix<3> m = to_band<3>(a);
    BandedSpdMatrix<3> copy;
    copy.resize(10);
    copy.assign(m);
    copy.add_scaled(m, 2.0);
    for (std::size_t i = 0; i < 10; ++i)
        for (std::size_t j = 0; j < 10; ++j) EXPECT_NEAR(copy.at(i, j), 3.0 * a[i][j], 1e-14);
}

}  // namespace
