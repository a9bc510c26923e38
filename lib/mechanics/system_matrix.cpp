// SPDX-License-Identifier: Apache-2.0
#include "mechanics/system_matrix.h"

#include "base/hot_kernel.h"

namespace enteron::mechanics {

namespace {

// Adds sum_m (w_m w_m^T) (x) (a_m u_m u_m^T + b_m I) over Count spline points with the same
// four control points, in one pass over the band (fixed trip counts, unrolled).
template <int Count>
void add_axial_blocks(SystemMatrix& system, std::size_t first, const spline::SegmentWeights* const weights[],
                      const Vec3* const u[], const double a[], const double b[]) {
    double g[Count][12];
    for (int m = 0; m < Count; ++m)
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) g[m][3 * k + c] = weights[m]->w[k] * (*u[m])[c];
    // Entry (r, c) of the block, c <= r, is 11 r + c after its first diagonal entry: band
    // rows are 12 long and each starts one column later than the one above.
    constexpr int kStep = static_cast<int>(SystemMatrix::kRowStride) - 1;
    double* block = &system.lower(3 * first, 3 * first);
    // Constant trip counts: the compiler unrolls and pairs the columns.
#pragma GCC unroll 12
    for (int r = 0; r < 12; ++r) {
        double* row = block + kStep * r;
        double x[Count];
        for (int m = 0; m < Count; ++m) x[m] = a[m] * g[m][r];
#pragma GCC unroll 12
        for (int c = 0; c <= r; ++c) {
            double sum = x[0] * g[0][c];
            for (int m = 1; m < Count; ++m) sum += x[m] * g[m][c];
            row[c] += sum;
        }
    }
    bool transverse = false;
    for (int m = 0; m < Count; ++m) transverse = transverse || b[m] != 0.0;
    if (!transverse) return;
    // b I on each coordinate: the 4 x 4 matrix sum_m b_m w_m w_m^T on the diagonals of the
    // 3 x 3 point blocks.
    for (int j = 0; j < 4; ++j) {
        double bj[Count];
        for (int m = 0; m < Count; ++m) bj[m] = b[m] * weights[m]->w[j];
        for (int k = 0; k <= j; ++k) {
            double d = bj[0] * weights[0]->w[k];
            for (int m = 1; m < Count; ++m) d += bj[m] * weights[m]->w[k];
            for (int c = 0; c < 3; ++c) block[kStep * (3 * j + c) + 3 * k + c] += d;
        }
    }
}

}  // namespace

ENTERON_HOT_KERNEL void add_axial_block(SystemMatrix& system, const spline::SegmentWeights& weights, const Vec3& u,
                                        double a, double b, double scale) {
    const spline::SegmentWeights* const w[1] = {&weights};
    const Vec3* const directions[1] = {&u};
    const double sa[1] = {scale * a}, sb[1] = {scale * b};
    add_axial_blocks<1>(system, weights.first, w, directions, sa, sb);
}

ENTERON_HOT_KERNEL void add_axial_block_pair(SystemMatrix& system, const spline::SegmentWeights& weights0,
                                             const Vec3& u0, double a0, double b0,
                                             const spline::SegmentWeights& weights1, const Vec3& u1, double a1,
                                             double b1) {
    // The same as add_axial_blocks<2>, written out: GCC pairs the columns of this form
    // better (about 15 % faster).
    double g0[12], g1[12];
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) {
            g0[3 * k + c] = weights0.w[k] * u0[c];
            g1[3 * k + c] = weights1.w[k] * u1[c];
        }
    constexpr int kStep = static_cast<int>(SystemMatrix::kRowStride) - 1;
    double* block = &system.lower(3 * weights0.first, 3 * weights0.first);
#pragma GCC unroll 12
    for (int r = 0; r < 12; ++r) {
        double* row = block + kStep * r;
        const double x0 = a0 * g0[r], x1 = a1 * g1[r];
#pragma GCC unroll 12
        for (int c = 0; c <= r; ++c) row[c] += x0 * g0[c] + x1 * g1[c];
    }
    if (b0 == 0.0 && b1 == 0.0) return;
    for (int j = 0; j < 4; ++j) {
        const double bj0 = b0 * weights0.w[j], bj1 = b1 * weights1.w[j];
        for (int k = 0; k <= j; ++k) {
            const double d = bj0 * weights0.w[k] + bj1 * weights1.w[k];
            for (int c = 0; c < 3; ++c) block[kStep * (3 * j + c) + 3 * k + c] += d;
        }
    }
}

void SegmentBlock::reset(std::size_t first) {
    first_ = first;
    for (auto& sum : sums_)
        for (double& v : sum) v = 0.0;
}

ENTERON_HOT_KERNEL void SegmentBlock::add(const spline::SegmentWeights& weights, const double s[6]) {
    // Local copies: the compiler need not assume that s or the weights alias the sums.
    const double w[4] = {weights.w[0], weights.w[1], weights.w[2], weights.w[3]};
    const double m[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
    int pair = 0;
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j)
#pragma GCC unroll 4
        for (int k = 0; k <= j; ++k, ++pair) {
            const double wjk = w[j] * w[k];
            for (int e = 0; e < 6; ++e) sums_[pair][e] += wjk * m[e];
        }
}

ENTERON_HOT_KERNEL void SegmentBlock::add_to(SystemMatrix& system) const {
    // Index into the packed lower triangle of a symmetric 3 x 3 for row r, column c.
    static constexpr int kPacked[3][3] = {{0, 1, 3}, {1, 2, 4}, {3, 4, 5}};
    constexpr int kStep = static_cast<int>(SystemMatrix::kRowStride) - 1;
    double* block = &system.lower(3 * first_, 3 * first_);
    // Constant trip counts, unrolled: every offset and packed index is known at compile time.
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j)
#pragma GCC unroll 4
        for (int k = 0; k <= j; ++k) {
            const double* sum = sums_[j * (j + 1) / 2 + k];
#pragma GCC unroll 3
            for (int r = 0; r < 3; ++r) {
                double* row = block + kStep * (3 * j + r) + 3 * k;
                // The diagonal point block is stored only up to its own diagonal.
#pragma GCC unroll 3
                for (int c = 0; c < 3; ++c)
                    if (j != k || c <= r) row[c] += sum[kPacked[r][c]];
            }
        }
}

}  // namespace enteron::mechanics

namespace enteron::mechanics {

void add_per_coordinate(const numerics::ScalarBandMatrix& b, double scale, SystemMatrix& system) {
    for (std::size_t i = 0; i < b.size(); ++i) {
        const std::size_t j0 = i >= 3 ? i - 3 : 0;
        for (std::size_t j = j0; j <= i; ++j) {
            const double v = scale * b.lower(i, j);
            for (std::size_t c = 0; c < 3; ++c) system.lower(3 * i + c, 3 * j + c) += v;
        }
    }
}

}  // namespace enteron::mechanics
