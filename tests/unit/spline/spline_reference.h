// SPDX-License-Identifier: Apache-2.0
// Test-side reference of the spline of docs/architecture.md, written from the formula and
// not from lib/spline: the uniform Catmull-Rom segment on explicit phantom points
// q_{-1} = 2 q_0 - q_1 and q_n = 2 q_{n-1} - q_{n-2}, plus helpers shared by the unit tests.
#pragma once

#include <array>
#include <cstddef>
#include <random>
#include <vector>

namespace enteron_test {

// The raw Catmull-Rom polynomials of q_{i-1}, q_i, q_{i+1}, q_{i+2}, as printed in
// docs/architecture.md, and their first and second derivatives in t, derived by hand.
inline std::array<double, 4> design_weights(double t, int order) {
    const double t2 = t * t, t3 = t2 * t;
    switch (order) {
        case 0:
            return {0.5 * (-t3 + 2 * t2 - t), 0.5 * (3 * t3 - 5 * t2 + 2), 0.5 * (-3 * t3 + 4 * t2 + t),
                    0.5 * (t3 - t2)};
        case 1:
            return {0.5 * (-3 * t2 + 4 * t - 1), 0.5 * (9 * t2 - 10 * t), 0.5 * (-9 * t2 + 8 * t + 1),
                    0.5 * (3 * t2 - 2 * t)};
        default:
            return {0.5 * (-6 * t + 4), 0.5 * (18 * t - 10), 0.5 * (-18 * t + 8), 0.5 * (6 * t - 2)};
    }
}

// Points with `dim` coordinates each (dim = 1 for a scalar field over the control points,
// 3 for positions), extended with the two phantom points.
class ReferenceSpline {
public:
    ReferenceSpline(const std::vector<double>& points, std::size_t dim) : dim_(dim) {
        n_ = points.size() / dim;
        ext_.resize((n_ + 2) * dim);
        for (std::size_t i = 0; i < n_ * dim; ++i) ext_[dim + i] = points[i];
        for (std::size_t c = 0; c < dim; ++c) {
            ext_[c] = 2 * points[c] - points[dim + c];
            ext_[(n_ + 1) * dim + c] = 2 * points[(n_ - 1) * dim + c] - points[(n_ - 2) * dim + c];
        }
    }

    std::size_t count() const { return n_; }

    // Derivative `order` (in the segment parameter t) of the axis on `segment` at t, coordinate c.
    double at(std::size_t segment, double t, int order, std::size_t c) const {
        const auto w = design_weights(t, order);
        double sum = 0.0;
        // Extended index of q_{segment-1} is segment.
        for (std::size_t k = 0; k < 4; ++k) sum += w[k] * ext_[(segment + k) * dim_ + c];
        return sum;
    }

private:
    std::size_t dim_;
    std::size_t n_;
    std::vector<double> ext_;
};

// Composite Simpson rule of f over [0, 1] with `intervals` (even) subintervals: independent of
// the Gauss rules in the library, and with error ~ h^4 f''''/180, below 1e-13 for the degree
// six integrands of the Gram matrices at 2000 subintervals.
template <class F>
double simpson01(F&& f, int intervals = 2000) {
    const double h = 1.0 / intervals;
    double sum = f(0.0) + f(1.0);
    for (int k = 1; k < intervals; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * f(k * h);
    return sum * h / 3.0;
}

inline std::vector<double> random_vector(std::size_t size, std::mt19937_64& rng, double lo = -1.0,
                                         double hi = 1.0) {
    std::uniform_real_distribution<double> dist(lo, hi);
    std::vector<double> v(size);
    for (double& x : v) x = dist(rng);
    return v;
}

}  // namespace enteron_test
