// SPDX-License-Identifier: Apache-2.0
// The products of lib/mechanics/per_coordinate_matrix.h by diagonals against the band
// matrix's own row-by-row multiply: the same terms in the same order, so the same bits, at
// every size (bands shorter than 7 points run only the edge rows).
#include "mechanics/per_coordinate_matrix.h"

#include <gtest/gtest.h>

#include <memory_resource>
#include <random>
#include <vector>

#include "spline/gram_matrix.h"

namespace {

using enteron::mechanics::PerCoordinateMatrix;
using enteron::numerics::ScalarBandMatrix;

ScalarBandMatrix random_band(std::size_t n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ScalarBandMatrix b;
    b.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i >= 3 ? i - 3 : 0; j <= i; ++j) b.lower(i, j) = u(rng);
    return b;
}

std::vector<double> per_coordinate_matrix_random_vector(std::size_t size, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> v(size);
    for (double& x : v) x = u(rng);
    return v;
}

TEST(PerCoordinateMatrix, ProductsAreTheBandsOwnBitForBit) {
    std::mt19937_64 rng(7);
    for (const std::size_t n : {1, 2, 4, 6, 7, 8, 13, 240}) {
        const ScalarBandMatrix b = random_band(n, rng);
        PerCoordinateMatrix m(std::pmr::new_delete_resource());
        m.assign(b);
        ASSERT_EQ(m.coordinates(), 3 * n);
        const std::vector<double> x = per_coordinate_matrix_random_vector(3 * n, rng), v = per_coordinate_matrix_random_vector(3 * n, rng);
        // The reference: (B (x) I3) x by the band's multiply on the interleaved x y z.
        std::vector<double> bx(3 * n), bv(3 * n);
        b.multiply(x.data(), bx.data(), 3, 3);
        b.multiply(v.data(), bv.data(), 3, 3);

        std::vector<double> y(3 * n, -5.0);
        m.multiply(x.data(), y.data());
        for (std::size_t k = 0; k < 3 * n; ++k) EXPECT_EQ(y[k], bx[k]) << "n " << n << ", k " << k;

        const std::vector<double> start0 = per_coordinate_matrix_random_vector(3 * n, rng), start1 = per_coordinate_matrix_random_vector(3 * n, rng);
        std::vector<double> y0 = start0, y1 = start1;
        m.multiply_add(x.data(), -0.7, y0.data());
        for (std::size_t k = 0; k < 3 * n; ++k) EXPECT_EQ(y0[k], start0[k] + -0.7 * bx[k]) << "n " << n << ", k " << k;

        y0 = start0;
        m.multiply_add(x.data(), 2.5, y0.data(), v.data(), -1.5, y1.data());
        for (std::size_t k = 0; k < 3 * n; ++k) {
            EXPECT_EQ(y0[k], start0[k] + 2.5 * bx[k]) << "n " << n << ", k " << k;
            EXPECT_EQ(y1[k], start1[k] + -1.5 * bv[k]) << "n " << n << ", k " << k;
        }
    }
}

}  // namespace
