// SPDX-License-Identifier: Apache-2.0
// numerics/lanes.h: add_two_products in lanes gives, for every length, the bits of the scalar
// loop out[c] += x0 a[c] + x1 b[c] it replaces (the promise the step's kernels rely on: the
// same trajectories), and touches nothing past its length.
#include "numerics/lanes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <utility>

namespace {

using enteron::numerics::add_two_products;

template <int Count>
void expect_scalar_bits(std::mt19937_64& random) {
    std::uniform_real_distribution<double> value(-1e3, 1e3);
    double a[16], b[16], lanes[16], scalar[16];
    for (int trial = 0; trial < 200; ++trial) {
        for (int c = 0; c < 16; ++c) {
            a[c] = value(random);
            b[c] = value(random) * 1e-7;  // different magnitudes: the rounding of each sum shows
            lanes[c] = scalar[c] = value(random);
        }
        const double x0 = value(random), x1 = value(random);
        add_two_products<Count>(lanes, x0, a, x1, b);
        for (int c = 0; c < Count; ++c) scalar[c] += x0 * a[c] + x1 * b[c];
        ASSERT_EQ(std::memcmp(lanes, scalar, sizeof lanes), 0) << "length " << Count << ", trial " << trial;
    }
}

template <int... Counts>
void expect_every_length(std::mt19937_64& random, std::integer_sequence<int, Counts...>) {
    (expect_scalar_bits<Counts + 1>(random), ...);
}

TEST(Lanes, AddTwoProductsGivesTheScalarBitsForEveryLength) {
    std::mt19937_64 random(31);
    expect_every_length(random, std::make_integer_sequence<int, 12>{});
}

}  // namespace
