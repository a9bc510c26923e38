// A symmetric positive definite band matrix with half bandwidth P (entries with
// |i - j| > P are zero), stored as its lower band row by row, and its in-place Cholesky
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

namespace enteron::numerics {

// a . b with four independent partial sums: the band loops are short dot products, and a
// single running sum would wait on each multiply-add's latency.
inline double dot(const double* a, const double* b, std::size_t n) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    std::size_t m = 0;
    for (; m + 4 <= n; m += 4) {
        s0 += a[m] * b[m];
        s1 += a[m + 1] * b[m + 1];
        s2 += a[m + 2] * b[m + 2];
        s3 += a[m + 3] * b[m + 3];
    }
    for (; m < n; ++m) s0 += a[m] * b[m];
    return (s0 + s1) + (s2 + s3);
}

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
        for (std::size_t i = 0; i < n_; ++i)
            for (std::size_t c = 0; c < columns; ++c) y[i * stride + c] = 0.0;
        for (std::size_t i = 0; i < n_; ++i) {
            const double* row = &band_[i * kRowStride];
            const std::size_t j0 = i >= static_cast<std::size_t>(P) ? i - P : 0;
            for (std::size_t j = j0; j < i; ++j) {
                const double a = row[j + P - i];
                for (std::size_t c = 0; c < columns; ++c) {
                    y[i * stride + c] += a * x[j * stride + c];
                    y[j * stride + c] += a * x[i * stride + c];
                }
            }
            for (std::size_t c = 0; c < columns; ++c) y[i * stride + c] += row[P] * x[i * stride + c];
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

    // Cholesky factorisation A = L L^T in place. Returns false, leaving the matrix
    // unusable for solve, if A is not numerically positive definite.
    //
    // Right-looking: column k is scaled, then the trailing P x P window takes the rank-one
    // update -l l^T. The window has a fixed size and each of its rows is contiguous in the
    // band storage, so the inner loop is short, branch-free and vectorisable.
    bool factor() {
        factored_ = false;
        double column[P];
        for (std::size_t k = 0; k < n_; ++k) {
            double* rk = &band_[k * kRowStride];
            const double pivot = rk[P];
            if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
            const double d = std::sqrt(pivot);
            const double inv = 1.0 / d;
            rk[P] = d;
            inverse_diagonal_[k] = inv;
            const std::size_t below = std::min<std::size_t>(P, n_ - 1 - k);
            // L(k+t, k) sits in row k+t at offset P - t.
            for (std::size_t t = 1; t <= below; ++t) {
                double& entry = band_[(k + t) * kRowStride + (P - t)];
                entry *= inv;
                column[t - 1] = entry;
            }
            for (std::size_t t = 1; t <= below; ++t) {
                // Row k+t, columns k+1 .. k+t, at offsets P - t + 1 .. P.
                double* row = &band_[(k + t) * kRowStride + (P - t)];
                const double lt = column[t - 1];
                for (std::size_t u = 1; u <= t; ++u) row[u] -= lt * column[u - 1];
            }
        }
        factored_ = true;
        return true;
    }

    // Solves A x = b in place after factor(); same layout as multiply.
    void solve(double* x, std::size_t stride = 1, std::size_t columns = 1) const {
        // L y = b
        for (std::size_t i = 0; i < n_; ++i) {
            const double* li = &band_[i * kRowStride];
            const std::size_t j0 = i >= static_cast<std::size_t>(P) ? i - P : 0;
            if (stride == 1) {
                x[i] = (x[i] - dot(li + (j0 + P - i), x + j0, i - j0)) * inverse_diagonal_[i];
                continue;
            }
            for (std::size_t c = 0; c < columns; ++c) {
                double s = x[i * stride + c];
                for (std::size_t k = j0; k < i; ++k) s -= li[k + P - i] * x[k * stride + c];
                x[i * stride + c] = s * inverse_diagonal_[i];
            }
        }
        // L^T x = y
        for (std::size_t ii = n_; ii-- > 0;) {
            const std::size_t last = std::min(n_ - 1, ii + P);
            for (std::size_t c = 0; c < columns; ++c) {
                double s = x[ii * stride + c];
                for (std::size_t k = ii + 1; k <= last; ++k) s -= lower(k, ii) * x[k * stride + c];
                x[ii * stride + c] = s * inverse_diagonal_[ii];
            }
        }
    }

private:
    std::size_t n_ = 0;
    std::pmr::vector<double> band_;
    std::pmr::vector<double> inverse_diagonal_;
    bool factored_ = false;
};

}  // namespace enteron::numerics
