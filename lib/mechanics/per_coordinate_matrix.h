// SPDX-License-Identifier: Apache-2.0
// A constant band matrix B (n x n, half bandwidth 3) that acts the same on x, y and z, such
// as the mass, bending and drag matrices, and its products with 3n vectors: (B (x) I3) x.
// Stored by diagonals, each repeated for the three coordinates, so that entry k of a product
// is sum_d E_d[k] x[k + 3d] over d = -3 .. 3: one contiguous loop over the 3n coordinates,
// which vectorises (row by row, each entry met three coordinates spaced three apart). The
// terms are summed in the order of the band's own multiply (column by column), so both
// give the same bits.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

#include "spline/gram_matrix.h"

namespace enteron::mechanics {

class PerCoordinateMatrix {
public:
    explicit PerCoordinateMatrix(std::pmr::memory_resource* memory) : diagonals_(memory) {}

    // Takes the entries of b (allocates; call when the scene is made).
    void assign(const numerics::ScalarBandMatrix& b);

    std::size_t coordinates() const { return coordinates_; }

    // The products below take 3n values in each vector; an output must not overlap any
    // input or the other output.
    // y = (B (x) I3) x.
    void multiply(const double* x, double* y) const;
    // y += scale (B (x) I3) x.
    void multiply_add(const double* x, double scale, double* y) const;
    // y0 += scale0 (B (x) I3) x0 and y1 += scale1 (B (x) I3) x1 in one pass over B.
    void multiply_add(const double* x0, double scale0, double* y0, const double* x1, double scale1,
                      double* y1) const;

private:
    static constexpr int kHalfBandwidth = numerics::ScalarBandMatrix::kHalfBandwidth;
    static constexpr int kDiagonals = 2 * kHalfBandwidth + 1;

    std::size_t coordinates_ = 0;  // 3n
    // Diagonal d (from -3 to 3) at d + 3: E_d[3i + c] = B(i, i + d), zero where i + d is
    // outside the matrix.
    std::pmr::vector<double> diagonals_;
};

}  // namespace enteron::mechanics
