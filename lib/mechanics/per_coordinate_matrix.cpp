// SPDX-License-Identifier: Apache-2.0
#include "mechanics/per_coordinate_matrix.h"

#include "base/hot_kernel.h"

namespace enteron::mechanics {

namespace {

constexpr int kP = numerics::ScalarBandMatrix::kHalfBandwidth;

// The rows away from the ends: one loop over k with the seven diagonals unrolled. The
// pointers are restrict (the outputs never overlap the inputs), so that it vectorises with
// no run-time overlap check. Entry k takes x[k + 3 (d - 3)], d = 0 .. 6.
template <int R, bool Accumulate>
[[gnu::always_inline]] inline void interior(const double* __restrict e, std::size_t m, std::size_t begin,
                                            std::size_t end, const double* __restrict x0, double scale0,
                                            double* __restrict y0, const double* __restrict x1, double scale1,
                                            double* __restrict y1) {
    for (std::size_t k = begin; k < end; ++k) {
        double s0 = 0.0, s1 = 0.0;
#pragma GCC unroll 7
        for (int d = 0; d <= 2 * kP; ++d) {
            const double entry = e[d * m + k];
            const std::size_t j = k + 3 * static_cast<std::size_t>(d) - 3 * kP;  // k >= 3 kP here
            s0 += entry * x0[j];
            if (R == 2) s1 += entry * x1[j];
        }
        y0[k] = (Accumulate ? y0[k] : 0.0) + scale0 * s0;
        if (R == 2) y1[k] = (Accumulate ? y1[k] : 0.0) + scale1 * s1;
    }
}

// y_r = (Accumulate ? y_r : 0) + scale_r sum_d E_d x_r[k + 3d] for R vectors at once. Every
// sum starts from zero and takes its terms in increasing d, as the band's multiply does.
template <int R, bool Accumulate>
[[gnu::always_inline]] inline void products(const double* __restrict diagonals, std::size_t m,
                                            const double* const x[R], const double scale[R], double* const y[R]) {
    const std::size_t points = m / 3;
    // Entry k of point i = k / 3 takes diagonal d only where i + d is a point.
    const auto edge = [&](std::size_t k) {
        const std::size_t i = k / 3;
        double s[R] = {};
        for (int d = -kP; d <= kP; ++d) {
            if (static_cast<std::ptrdiff_t>(i) + d < 0 || i + d >= points) continue;
            const double e = diagonals[(d + kP) * m + k];
            for (int r = 0; r < R; ++r) s[r] += e * x[r][k + 3 * d];
        }
        for (int r = 0; r < R; ++r) y[r][k] = (Accumulate ? y[r][k] : 0.0) + scale[r] * s[r];
    };
    // The first and last kP points have a shorter band.
    const std::size_t margin = 3 * static_cast<std::size_t>(kP);
    if (m <= 2 * margin) {
        for (std::size_t k = 0; k < m; ++k) edge(k);
        return;
    }
    for (std::size_t k = 0; k < margin; ++k) edge(k);
    interior<R, Accumulate>(diagonals, m, margin, m - margin, x[0], scale[0], y[0], R == 2 ? x[R - 1] : nullptr,
                            scale[R - 1], R == 2 ? y[R - 1] : nullptr);
    for (std::size_t k = m - margin; k < m; ++k) edge(k);
}

ENTERON_HOT_KERNEL void product_one(const double* diagonals, std::size_t m, const double* x, double scale,
                                    double* y, bool accumulate) {
    const double* const xs[1] = {x};
    const double scales[1] = {scale};
    double* const ys[1] = {y};
    if (accumulate)
        products<1, true>(diagonals, m, xs, scales, ys);
    else
        products<1, false>(diagonals, m, xs, scales, ys);
}

ENTERON_HOT_KERNEL void product_two(const double* diagonals, std::size_t m, const double* x0, double scale0,
                                    double* y0, const double* x1, double scale1, double* y1) {
    const double* const xs[2] = {x0, x1};
    const double scales[2] = {scale0, scale1};
    double* const ys[2] = {y0, y1};
    products<2, true>(diagonals, m, xs, scales, ys);
}

}  // namespace

void PerCoordinateMatrix::assign(const numerics::ScalarBandMatrix& b) {
    const std::size_t n = b.size();
    coordinates_ = 3 * n;
    diagonals_.assign(kDiagonals * coordinates_, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (int d = -kP; d <= kP; ++d) {
            if (static_cast<std::ptrdiff_t>(i) + d < 0 || i + d >= n) continue;
            const double entry = b.at(i, i + d);
            for (std::size_t c = 0; c < 3; ++c) diagonals_[(d + kP) * coordinates_ + 3 * i + c] = entry;
        }
}

void PerCoordinateMatrix::multiply(const double* x, double* y) const {
    product_one(diagonals_.data(), coordinates_, x, 1.0, y, false);
}

void PerCoordinateMatrix::multiply_add(const double* x, double scale, double* y) const {
    product_one(diagonals_.data(), coordinates_, x, scale, y, true);
}

void PerCoordinateMatrix::multiply_add(const double* x0, double scale0, double* y0, const double* x1,
                                       double scale1, double* y1) const {
    product_two(diagonals_.data(), coordinates_, x0, scale0, y0, x1, scale1, y1);
}

}  // namespace enteron::mechanics
