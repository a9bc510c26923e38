// SPDX-License-Identifier: Apache-2.0
#include "mechanics/bordered_system.h"

#include <algorithm>
#include <cmath>

namespace enteron::mechanics {

namespace {

// Solves S e = b in place (S symmetric positive semi-definite, m x m, row-major; b in e) by
// L D L^T without pivoting. A pivot at or below `tolerance` times the largest diagonal entry
// is a direction S does not hold: its unknown is set to zero and its row and column take no
// part in the rest. S is overwritten.
void solve_semidefinite(double* s, double* e, std::size_t m) {
    double largest = 0.0;
    for (std::size_t i = 0; i < m; ++i) largest = std::max(largest, std::fabs(s[i * m + i]));
    const double tolerance = 1e-12 * largest;
    // Factor: s[i][j] (j < i) becomes L(i, j), s[i][i] D(i) (0 for a dropped direction).
    for (std::size_t j = 0; j < m; ++j) {
        double d = s[j * m + j];
        for (std::size_t k = 0; k < j; ++k) d -= s[j * m + k] * s[j * m + k] * s[k * m + k];
        const bool held = d > tolerance;
        s[j * m + j] = held ? d : 0.0;
        for (std::size_t i = j + 1; i < m; ++i) {
            double v = s[i * m + j];
            for (std::size_t k = 0; k < j; ++k) v -= s[i * m + k] * s[j * m + k] * s[k * m + k];
            s[i * m + j] = held ? v / d : 0.0;
        }
    }
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t k = 0; k < i; ++k) e[i] -= s[i * m + k] * e[k];
    for (std::size_t i = 0; i < m; ++i) e[i] = s[i * m + i] > 0.0 ? e[i] / s[i * m + i] : 0.0;
    for (std::size_t i = m; i-- > 0;)
        for (std::size_t k = i + 1; k < m; ++k) e[i] -= s[k * m + i] * e[k];
    // A dropped direction stays zero: its column of L is zero.
}

}  // namespace

BorderedSystem::BorderedSystem(std::pmr::memory_resource* memory)
    : body_(memory),
      columns_(memory),
      couplings_(memory),
      schur_(memory),
      solution_(memory),
      window_first_(memory),
      window_last_(memory) {}

void BorderedSystem::reserve(std::size_t bodies, std::size_t coordinates) {
    if (bodies <= capacity_ && coordinates == coordinates_) return;
    body_.resize(bodies);
    columns_.resize(bodies);
    couplings_.resize(bodies);
    for (std::size_t b = 0; b < bodies; ++b) {
        columns_[b].assign(3 * coordinates, 0.0);
        couplings_[b].assign(3 * coordinates, 0.0);
    }
    schur_.assign(9 * bodies * bodies, 0.0);
    solution_.assign(3 * bodies, 0.0);
    window_first_.assign(bodies, 0);
    window_last_.assign(bodies, 0);
    capacity_ = bodies;
    coordinates_ = coordinates;
    bodies_ = 0;
}

void BorderedSystem::clear() {
    // The columns are zeroed as they are used (solve), or here if an evaluation added a body
    // that was never solved (an explicit method, a failed factorisation).
    for (std::size_t b = 0; b < bodies_; ++b) {
        const Body& body = body_[b];
        if (body.first_row <= body.last_row)
            std::fill(columns_[b].begin() + 3 * body.first_row, columns_[b].begin() + 3 * (body.last_row + 1), 0.0);
    }
    bodies_ = 0;
}

std::size_t BorderedSystem::add_body(const Mat3& block, const Vec3& rhs) {
    Body& body = body_[bodies_];
    body.block = block;
    body.rhs = rhs;
    body.first_row = coordinates_;
    body.last_row = 0;
    return bodies_++;
}

void BorderedSystem::add_coupling(std::size_t b, const spline::SegmentWeights& weights, const Mat3& coupling) {
    Body& body = body_[b];
    double* column = columns_[b].data();
    const std::size_t first = 3 * weights.first;
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t c = 0; c < 3; ++c) {
            double* row = column + 3 * (first + 3 * k + c);
            for (std::size_t j = 0; j < 3; ++j) row[j] += weights.w[k] * coupling(c, j);
        }
    body.first_row = std::min(body.first_row, first);
    body.last_row = std::max(body.last_row, first + 11);
}

void BorderedSystem::zero_row(std::size_t coordinate) {
    for (std::size_t b = 0; b < bodies_; ++b) {
        const Body& body = body_[b];
        if (coordinate < body.first_row || coordinate > body.last_row) continue;
        std::fill(columns_[b].begin() + 3 * coordinate, columns_[b].begin() + 3 * coordinate + 3, 0.0);
    }
}

void BorderedSystem::solve(const SystemMatrix& factored, double* dv) {
    const std::size_t m = 3 * bodies_;
    if (m == 0) return;
    // X = A^-1 B on each body's window, B kept aside for B^T X; the Schur complement starts
    // as P, the right-hand side as r_p + B^T y.
    std::size_t* window_first = window_first_.data();
    std::size_t* window_last = window_last_.data();
    const std::size_t bodies = bodies_;
    // P is block-diagonal (bodies meet only through the bowel): the blocks between two
    // bodies start at zero, not at what the last solve's factorisation left there.
    std::fill(schur_.begin(), schur_.begin() + m * m, 0.0);
    for (std::size_t b = 0; b < bodies; ++b) {
        Body& body = body_[b];
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) schur_[(3 * b + i) * m + 3 * b + j] = body.block(i, j);
        Vec3 rhs = body.rhs;
        if (body.first_row > body.last_row) {  // touches nothing
            window_first[b] = 1;
            window_last[b] = 0;
            point_at(solution_.data(), b) = rhs;
            continue;
        }
        const double* column = columns_[b].data();
        double* kept = couplings_[b].data();
        for (std::size_t k = body.first_row; k <= body.last_row; ++k)
            for (std::size_t j = 0; j < 3; ++j) {
                kept[3 * k + j] = column[3 * k + j];
                rhs[j] += column[3 * k + j] * dv[k];
            }
        point_at(solution_.data(), b) = rhs;
        factored.solve_window<3>(columns_[b].data(), body.first_row, body.last_row, kWindowTolerance,
                                 &window_first[b], &window_last[b]);
    }
    // Schur complement: P - B_a^T X_b over the rows where both are non-zero.
    for (std::size_t a = 0; a < bodies; ++a) {
        const Body& body = body_[a];
        if (body.first_row > body.last_row) continue;
        const double* kept = couplings_[a].data();
        for (std::size_t b = 0; b < bodies; ++b) {
            const std::size_t first = std::max(body.first_row, window_first[b]);
            const std::size_t last = std::min(body.last_row, window_last[b]);
            const double* x = columns_[b].data();
            for (std::size_t k = first; k <= last && first <= last; ++k)
                for (std::size_t i = 0; i < 3; ++i)
                    for (std::size_t j = 0; j < 3; ++j)
                        schur_[(3 * a + i) * m + 3 * b + j] -= kept[3 * k + i] * x[3 * k + j];
        }
    }
    solve_semidefinite(schur_.data(), solution_.data(), m);
    // dv += X e; then the columns and the kept copy go back to zero.
    for (std::size_t b = 0; b < bodies; ++b) {
        Body& body = body_[b];
        if (body.first_row > body.last_row) continue;
        const Vec3 e = point_at(solution_.data(), b);
        double* x = columns_[b].data();
        for (std::size_t k = window_first[b]; k <= window_last[b]; ++k) {
            dv[k] += x[3 * k] * e[0] + x[3 * k + 1] * e[1] + x[3 * k + 2] * e[2];
            x[3 * k] = x[3 * k + 1] = x[3 * k + 2] = 0.0;
        }
        std::fill(couplings_[b].begin() + 3 * body.first_row, couplings_[b].begin() + 3 * (body.last_row + 1), 0.0);
        body.first_row = coordinates_;  // solved: clear() has nothing left to zero
        body.last_row = 0;
    }
}

}  // namespace enteron::mechanics
