// SPDX-License-Identifier: Apache-2.0
// A symmetric positive definite band matrix with half bandwidth P (entries with
// |i - j| > P are zero), stored as its lower band row by row, and its in-place L D L^T
// factorisation. Factor and solve cost O(n P^2) and O(n P): linear in n. P is a template
// parameter so the inner loops have a fixed maximum length.
//
// Two uses: the scalar mass matrix of the spline (P = 3, one row per control point, the
// same for x, y and z) and the implicit integrator's system over the 3n coupled
// coordinates ordered x0 y0 z0 x1 ... (P = 3*3 + 2 = 11).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <memory_resource>
#include <vector>

#include "base/hot_kernel.h"

namespace enteron::numerics {

// Two doubles that the compiler keeps in one SIMD register where there is one (GCC/Clang
// vector extension; elsewhere it lowers to scalar code).
typedef double Pair __attribute__((vector_size(2 * sizeof(double))));
typedef double Quad __attribute__((vector_size(4 * sizeof(double))));

template <int P>
class BandedSpdMatrix {
public:
    static constexpr int kHalfBandwidth = P;
    static constexpr std::size_t kRowStride = P + 1;

    explicit BandedSpdMatrix(std::pmr::memory_resource* memory = std::pmr::get_default_resource())
        : band_(memory), inverse_diagonal_(memory) {}

    // Sets the size to n x n and every entry to zero.
    void resize(std::size_t n) {
        n_ = n;
        band_.assign(n * kRowStride, 0.0);
        inverse_diagonal_.assign(n, 0.0);
        factored_ = false;
    }

    std::size_t size() const { return n_; }
    bool factored() const { return factored_; }

    void set_zero() {
        std::fill(band_.begin(), band_.end(), 0.0);
        factored_ = false;
    }

    // Copies another matrix of the same size without allocating.
    void assign(const BandedSpdMatrix& other) {
        std::copy(other.band_.begin(), other.band_.end(), band_.begin());
        if (other.factored_)  // otherwise not yet meaningful
            std::copy(other.inverse_diagonal_.begin(), other.inverse_diagonal_.end(),
                      inverse_diagonal_.begin());
        factored_ = other.factored_;
    }

    // this += scale * other (same size, both unfactored).
    void add_scaled(const BandedSpdMatrix& other, double scale) {
        for (std::size_t k = 0; k < band_.size(); ++k) band_[k] += scale * other.band_[k];
    }

    // Entry (i, j) of the lower band: requires j <= i and i - j <= P.
    double& lower(std::size_t i, std::size_t j) { return band_[i * kRowStride + (j + P - i)]; }
    double lower(std::size_t i, std::size_t j) const { return band_[i * kRowStride + (j + P - i)]; }

    // Entry (i, j) of the whole symmetric matrix (zero outside the band).
    double at(std::size_t i, std::size_t j) const {
        if (j > i) std::swap(i, j);
        return i - j > static_cast<std::size_t>(P) ? 0.0 : lower(i, j);
    }

    // Adds v to (i, j) and, implicitly, to (j, i). The pair must lie within the band.
    void add(std::size_t i, std::size_t j, double v) {
        if (j > i) std::swap(i, j);
        lower(i, j) += v;
    }

    // y = A x (before factorisation). x and y hold n values spaced by stride, `columns`
    // interleaved right-hand sides: x[i * stride + c].
    void multiply(const double* x, double* y, std::size_t stride = 1, std::size_t columns = 1) const {
        if (columns == 1)
            multiply_add<1>(x, 1.0, y, stride, false);
        else if (columns == 3)
            multiply_add<3>(x, 1.0, y, stride, false);
        else
            for (std::size_t c = 0; c < columns; ++c) multiply_add<1>(x + c, 1.0, y + c, stride, false);
    }

    // y += scale * A x for C interleaved right-hand sides (x[i * stride + c]), or y = A x
    // when accumulate is false. Row by row, the terms in column order: each y_i is one
    // running sum, written once.
    template <std::size_t C>
    void multiply_add(const double* x, double scale, double* y, std::size_t stride, bool accumulate) const {
        const std::size_t p = static_cast<std::size_t>(P);
        const bool scaled = accumulate;  // y = A x multiplies by the entries as they are
        for (std::size_t i = 0; i < n_; ++i) {
            const double* row = &band_[i * kRowStride];
            const std::size_t j0 = i >= p ? i - p : 0;
            const std::size_t j1 = std::min(n_ - 1, i + p);
            double s[C];
            for (std::size_t c = 0; c < C; ++c) s[c] = accumulate ? y[i * stride + c] : 0.0;
            for (std::size_t j = j0; j <= i; ++j) {  // row i of the lower band
                const double a = scaled ? scale * row[j + p - i] : row[j + p - i];
                for (std::size_t c = 0; c < C; ++c) s[c] += a * x[j * stride + c];
            }
            for (std::size_t j = i + 1; j <= j1; ++j) {  // column i of the lower band
                const double entry = band_[j * kRowStride + (i + p - j)];
                const double a = scaled ? scale * entry : entry;
                for (std::size_t c = 0; c < C; ++c) s[c] += a * x[j * stride + c];
            }
            for (std::size_t c = 0; c < C; ++c) y[i * stride + c] = s[c];
        }
    }

    // Replaces row and column i by those of the identity (a fixed coordinate).
    void make_identity_row(std::size_t i) {
        double* row = &band_[i * kRowStride];
        std::fill(row, row + P, 0.0);
        row[P] = 1.0;
        const std::size_t last = std::min(n_ - 1, i + P);
        for (std::size_t k = i + 1; k <= last; ++k) lower(k, i) = 0.0;
    }

    // Factorisation A = L D L^T in place (L unit lower triangular, D diagonal). Returns
    // false, leaving the matrix unusable for solve, if A is not numerically positive
    // definite (a pivot of D that is not finite and > 0).
    //
    // Root-free on purpose: the factorisation is a chain over the columns (each pivot waits
    // for the previous column's update), and a square root followed by a division on that
    // chain costs about twice a division alone. Right-looking: column k is scaled, then the
    // trailing P x P window takes the rank-one update -l c^T, c the column before scaling.
    // The window has a fixed size and each of its rows is contiguous in the band storage, so
    // away from the last P columns the loops have constant trip counts and unroll.
    ENTERON_HOT_KERNEL bool factor() {
        factored_ = false;
        std::size_t k = 0;
        const std::size_t interior = n_ > static_cast<std::size_t>(P) ? n_ - P : 0;
        for (; k < interior; ++k)
            if (!eliminate_interior(k)) return false;
        for (; k < n_; ++k)
            if (!eliminate_tail(k, n_ - 1 - k)) return false;
        factored_ = true;
        return true;
    }

    // Solves A x = b in place after factor(); same layout as multiply.
    ENTERON_HOT_KERNEL void solve(double* x, std::size_t stride = 1, std::size_t columns = 1) const {
        if (columns == 1)
            solve_columns<1>(x, stride);
        else if (columns == 3)
            solve_columns<3>(x, stride);
        else
            for (std::size_t c = 0; c < columns; ++c) solve_columns<1>(x + c, stride);
    }

    // Solves A x = b in place after factor() for C interleaved right-hand sides (layout of
    // solve) that are zero outside rows [first, last], on a window: A^-1 of a local load
    // decays away from it (each row of the sweeps is a weighted sum of the P rows before),
    // so the forward sweep stops below `last` and the backward sweep above `first` once P
    // rows in a row have fallen below `tolerance` times the largest magnitude so far. The
    // rows outside [*window_first, *window_last] are left as they were (zero): they hold
    // less than that tolerance of the solution. With tolerance 0 the sweeps run to the
    // ends: an exact solve.
    template <std::size_t C>
    void solve_window(double* x, std::size_t first, std::size_t last, double tolerance, std::size_t* window_first,
                      std::size_t* window_last) const {
        const std::size_t p = static_cast<std::size_t>(P);
        // Forward: y_i = b_i - sum_{j<i} L(i, j) y_j, with y_j = 0 below `first`.
        double largest = 0.0;
        std::size_t quiet = 0;  // rows in a row below the tolerance, past `last`
        std::size_t end = n_;   // one past the last row swept
        for (std::size_t i = first; i < n_; ++i) {
            const double* li = &band_[i * kRowStride];
            const std::size_t j0 = std::max(first, i >= p ? i - p : 0);
            double s[C];
            for (std::size_t c = 0; c < C; ++c) s[c] = x[i * C + c];
            for (std::size_t j = j0; j < i; ++j) {
                const double l = li[j + p - i];
                for (std::size_t c = 0; c < C; ++c) s[c] -= l * x[j * C + c];
            }
            double row = 0.0;
            for (std::size_t c = 0; c < C; ++c) {
                x[i * C + c] = s[c];
                row = std::max(row, std::fabs(s[c]));
            }
            largest = std::max(largest, row);
            quiet = i > last && row <= tolerance * largest ? quiet + 1 : 0;
            if (quiet == p) {
                end = i + 1;
                break;
            }
        }
        for (std::size_t i = first; i < end; ++i)
            for (std::size_t c = 0; c < C; ++c) x[i * C + c] *= inverse_diagonal_[i];
        // Backward: x_i = y_i / d_i - sum_{k>i} L(k, i) x_k, with x_k = 0 from `end` on.
        largest = 0.0;
        quiet = 0;
        std::size_t begin = 0;
        for (std::size_t i = end; i-- > 0;) {
            const std::size_t k1 = std::min(end - 1, i + p);
            double s[C];
            for (std::size_t c = 0; c < C; ++c) s[c] = x[i * C + c];
            for (std::size_t k = k1; k > i; --k) {
                const double l = band_[k * kRowStride + (i + p - k)];
                for (std::size_t c = 0; c < C; ++c) s[c] -= l * x[k * C + c];
            }
            double row = 0.0;
            for (std::size_t c = 0; c < C; ++c) {
                x[i * C + c] = s[c];
                row = std::max(row, std::fabs(s[c]));
            }
            largest = std::max(largest, row);
            quiet = i < first && row <= tolerance * largest ? quiet + 1 : 0;
            if (quiet == p) {
                begin = i;
                break;
            }
        }
        *window_first = begin;
        *window_last = end - 1;
    }

private:
    // Column k of the elimination with `below` rows under the pivot (below <= P).
    template <int Below>
    bool eliminate(std::size_t k) {
        double* base = &band_[k * kRowStride + P];  // the pivot
        const double pivot = base[0];
        if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
        const double inv = 1.0 / pivot;
        inverse_diagonal_[k] = inv;
        // A(k+t, k) sits in row k+t at offset P - t: t (kRowStride - 1) after the pivot.
        double column[P];
        for (int t = 1; t <= Below; ++t) {
            double& entry = base[t * (kRowStride - 1)];
            column[t - 1] = entry;
            entry *= inv;
        }
        for (int t = 1; t <= Below; ++t) {
            // Row k+t, columns k+1 .. k+t, at offsets P - t + 1 .. P.
            double* row = base + t * (kRowStride - 1);
            const double lt = row[0];
            for (int u = 1; u <= t; ++u) row[u] -= lt * column[u - 1];
        }
        return true;
    }

    // Column k with all P rows below it. The update of row k+t touches its last t entries
    // (columns k+1 .. k+t, the diagonal last), taken in groups of four from the diagonal
    // end, then a pair, then one: the groups sit at the same offsets from the diagonal for
    // every column k, so each group loads what the previous column stored as one group (no
    // store forwarding across two stores), and the lanes share each multiply and subtraction.
    bool eliminate_interior(std::size_t k) {
        double* pivot_entry = &band_[k * kRowStride + P];
        const double pivot = pivot_entry[0];
        if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
        const double inv = 1.0 / pivot;
        inverse_diagonal_[k] = inv;
        double column[P];  // A(k+t, k), t = 1 .. P, before scaling
#pragma GCC unroll 16
        for (int t = 1; t <= P; ++t) {
            double& entry = pivot_entry[t * P];  // row k+t at offset P - t
            column[t - 1] = entry;
            entry *= inv;
        }
#pragma GCC unroll 16
        for (int t = 1; t <= P; ++t) {
            double* row = pivot_entry + t * P;  // row[u]: column k+u, u = 1 .. t
            const double lt = row[0];
            const Pair l = {lt, lt};
            int u = t - 3;
            const Quad l4 = {lt, lt, lt, lt};
#pragma GCC unroll 16
            for (; u >= 1; u -= 4) {
                const Quad c = {column[u - 1], column[u], column[u + 1], column[u + 2]};
                Quad x;
                std::memcpy(&x, row + u, sizeof x);
                x -= l4 * c;
                std::memcpy(row + u, &x, sizeof x);
            }
            u += 2;  // the last element of what is left
#pragma GCC unroll 16
            for (; u >= 1; u -= 2) {
                const Pair c = {column[u - 1], column[u]};
                Pair x;
                std::memcpy(&x, row + u, sizeof x);
                x -= l * c;
                std::memcpy(row + u, &x, sizeof x);
            }
            if (u == 0) row[1] -= lt * column[0];
        }
        return true;
    }

    bool eliminate_tail(std::size_t k, std::size_t below) {
        switch (below) {
            case 0: return eliminate<0>(k);
            case 1: return eliminate<(P >= 1 ? 1 : 0)>(k);
            case 2: return eliminate<(P >= 2 ? 2 : 0)>(k);
            case 3: return eliminate<(P >= 3 ? 3 : 0)>(k);
            default: return eliminate_generic(k, below);
        }
    }

    bool eliminate_generic(std::size_t k, std::size_t below) {
        double* base = &band_[k * kRowStride + P];  // the pivot
        const double pivot = base[0];
        if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
        const double inv = 1.0 / pivot;
        inverse_diagonal_[k] = inv;
        double column[P];
        for (std::size_t t = 1; t <= below; ++t) {
            double& entry = base[t * (kRowStride - 1)];
            column[t - 1] = entry;
            entry *= inv;
        }
        for (std::size_t t = 1; t <= below; ++t) {
            double* row = base + t * (kRowStride - 1);
            const double lt = row[0];
            for (std::size_t u = 1; u <= t; ++u) row[u] -= lt * column[u - 1];
        }
        return true;
    }

    // L y = b, then x = L^-T D^-1 y, for C interleaved right-hand sides at x[i*stride + c].
    // In both sweeps the value just computed enters the next row's sum last, so the chain
    // from row to row is one multiply and one subtraction, not the whole sum.
    template <std::size_t C>
    void solve_columns(double* x, std::size_t stride) const {
        const std::size_t p = static_cast<std::size_t>(P);
        // Forward: y_i = b_i - sum_{j<i} L(i, j) y_j (unit diagonal). The first P rows have a
        // shorter band; the others take a loop of constant length.
        const std::size_t head = std::min(p, n_);
        for (std::size_t i = 0; i < head; ++i) {
            const double* li = &band_[i * kRowStride];
            double s[C];
            for (std::size_t c = 0; c < C; ++c) s[c] = x[i * stride + c];
            for (std::size_t j = 0; j < i; ++j) {
                const double l = li[j + p - i];
                for (std::size_t c = 0; c < C; ++c) s[c] -= l * x[j * stride + c];
            }
            for (std::size_t c = 0; c < C; ++c) x[i * stride + c] = s[c];
        }
        if (C == 1 && head > 0) {
            // One right-hand side: the value just computed stays in a register for the next
            // row (reloading it from its store put a store-to-load delay on the chain).
            double last = x[(head - 1) * stride];
            for (std::size_t i = head; i < n_; ++i) {
                const double* li = &band_[i * kRowStride];
                const double* xj = x + (i - p) * stride;
                double s = x[i * stride];
                for (int j = 0; j + 1 < P; ++j) s -= li[j] * xj[j * stride];
                s -= li[P - 1] * last;
                x[i * stride] = s;
                last = s;
            }
        } else {
            for (std::size_t i = head; i < n_; ++i) {
                const double* li = &band_[i * kRowStride];
                const double* xj = x + (i - p) * stride;
                double s[C];
                for (std::size_t c = 0; c < C; ++c) s[c] = x[i * stride + c];
                for (int j = 0; j < P; ++j)
                    for (std::size_t c = 0; c < C; ++c) s[c] -= li[j] * xj[j * stride + c];
                for (std::size_t c = 0; c < C; ++c) x[i * stride + c] = s[c];
            }
        }
        for (std::size_t i = 0; i < n_; ++i)
            for (std::size_t c = 0; c < C; ++c) x[i * stride + c] *= inverse_diagonal_[i];
        // Backward: x_i = y_i / d_i - sum_{k>i} L(k, i) x_k, the farthest k first. With one
        // right-hand side, the rows with a full band keep x_{i+1} in a register, as above.
        std::size_t i = n_;
        if (C == 1 && n_ > p + 1) {
            for (; i > n_ - p; --i) backward_row<C>(x, stride, i - 1);
            double next = x[i * stride];
            for (; i-- > 0;) {
                double s = x[i * stride];
                for (std::size_t k = i + p; k > i + 1; --k) s -= band_[k * kRowStride + (i + p - k)] * x[k * stride];
                s -= band_[(i + 1) * kRowStride + (p - 1)] * next;
                x[i * stride] = s;
                next = s;
            }
            return;
        }
        for (; i-- > 0;) backward_row<C>(x, stride, i);
    }

    // Row i of the backward sweep (solve_columns), the farthest k first.
    template <std::size_t C>
    void backward_row(double* x, std::size_t stride, std::size_t i) const {
        const std::size_t p = static_cast<std::size_t>(P);
        const std::size_t last = std::min(n_ - 1, i + p);
        double s[C];
        for (std::size_t c = 0; c < C; ++c) s[c] = x[i * stride + c];
        for (std::size_t k = last; k > i; --k) {
            const double l = band_[k * kRowStride + (i + p - k)];
            for (std::size_t c = 0; c < C; ++c) s[c] -= l * x[k * stride + c];
        }
        for (std::size_t c = 0; c < C; ++c) x[i * stride + c] = s[c];
    }

    std::size_t n_ = 0;
    std::pmr::vector<double> band_;
    std::pmr::vector<double> inverse_diagonal_;
    bool factored_ = false;
};

// The per-coordinate matrices of the spline, one row per control point and the same for x,
// y and z (mass, bending, drag, the stability bounds): a segment couples four points.
using ScalarBandMatrix = BandedSpdMatrix<3>;

}  // namespace enteron::numerics
