// SPDX-License-Identifier: Apache-2.0
// Gauss-Legendre rules on [0, 1] (lib/numerics/gauss_legendre.h): the m-point rule
// integrates every monomial t^k up to degree 2m - 1 exactly (1 / (k + 1)) and misses
// degree 2m; its nodes are symmetric about 1/2 and its weights sum to 1.
#include <gtest/gtest.h>

#include <cmath>

#include "numerics/gauss_legendre.h"

namespace enteron::numerics {
namespace {

template <std::size_t M>
void expect_exact_to_degree() {
    constexpr auto rule = gauss_legendre<M>();
    for (int degree = 0; degree <= int(2 * M); ++degree) {
        double sum = 0.0;
        for (const QuadraturePoint& p : rule) sum += p.weight * std::pow(p.t, degree);
        const double exact = 1.0 / (degree + 1);
        if (degree < int(2 * M)) {
            EXPECT_NEAR(sum, exact, 2e-16 * (degree + 1)) << M << " points, degree " << degree;
        } else {
            EXPECT_GT(std::fabs(sum - exact), 1e-6) << M << " points miss degree " << degree;
        }
    }
    for (std::size_t i = 0; i < M; ++i) {
        EXPECT_NEAR(rule[i].t + rule[M - 1 - i].t, 1.0, 1e-16) << M << " points: symmetric nodes";
        EXPECT_EQ(rule[i].weight, rule[M - 1 - i].weight);
        EXPECT_GT(rule[i].t, 0.0);
        EXPECT_LT(rule[i].t, 1.0);
        if (i > 0) {
            EXPECT_LT(rule[i - 1].t, rule[i].t);
        }
    }
}

TEST(GaussLegendre, AnMPointRuleIsExactUpToDegree2MMinus1) {
    expect_exact_to_degree<2>();
    expect_exact_to_degree<3>();
    expect_exact_to_degree<4>();
    expect_exact_to_degree<5>();
}

}  // namespace
}  // namespace enteron::numerics
