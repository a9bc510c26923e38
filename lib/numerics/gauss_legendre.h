// SPDX-License-Identifier: Apache-2.0
// Gauss-Legendre quadrature on [0, 1]: an m-point rule integrates polynomials of degree
// up to 2m - 1 exactly.
#pragma once

#include <array>
#include <cstddef>

namespace enteron::numerics {

struct QuadraturePoint {
    double t;       // node in [0, 1]
    double weight;  // weights sum to 1
};

template <std::size_t M>
constexpr std::array<QuadraturePoint, M> gauss_legendre();

template <>
constexpr std::array<QuadraturePoint, 2> gauss_legendre<2>() {
    return {{{0.21132486540518713, 0.5}, {0.7886751345948129, 0.5}}};
}

template <>
constexpr std::array<QuadraturePoint, 3> gauss_legendre<3>() {
    return {{{0.1127016653792583, 5.0 / 18.0}, {0.5, 8.0 / 18.0}, {0.8872983346207417, 5.0 / 18.0}}};
}

template <>
constexpr std::array<QuadraturePoint, 4> gauss_legendre<4>() {
    return {{{0.06943184420297371, 0.17392742256872692},
             {0.33000947820757187, 0.32607257743127310},
             {0.66999052179242813, 0.32607257743127310},
             {0.93056815579702629, 0.17392742256872692}}};
}

template <>
constexpr std::array<QuadraturePoint, 5> gauss_legendre<5>() {
    return {{{0.04691007703066800, 0.11846344252809454},
             {0.23076534494715845, 0.23931433524968324},
             {0.5, 0.28444444444444444},
             {0.76923465505284155, 0.23931433524968324},
             {0.95308992296933200, 0.11846344252809454}}};
}

}  // namespace enteron::numerics
