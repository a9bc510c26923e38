#include "mechanics/system_matrix.h"

namespace enteron::mechanics {

void add_axial_block(SystemMatrix& system, const spline::SegmentWeights& weights, const double u[3],
                     double a, double b, double scale) {
    const std::size_t base = 3 * weights.first;
    double g[12];
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) g[3 * k + c] = weights.w[k] * u[c];
    const double sa = scale * a, sb = scale * b;
    for (int r = 0; r < 12; ++r) {
        double* row = &system.lower(base + r, base);  // columns base .. base + r
        const double gr = sa * g[r];
        for (int c = 0; c <= r; ++c) row[c] += gr * g[c];
        if (sb != 0.0) {
            const double wr = sb * weights.w[r / 3];
            for (int c = r % 3; c <= r; c += 3) row[c] += wr * weights.w[c / 3];
        }
    }
}

}  // namespace enteron::mechanics

namespace enteron::mechanics {

void add_per_coordinate(const spline::ScalarBandMatrix& b, double scale, SystemMatrix& system) {
    for (std::size_t i = 0; i < b.size(); ++i) {
        const std::size_t j0 = i >= 3 ? i - 3 : 0;
        for (std::size_t j = j0; j <= i; ++j) {
            const double v = scale * b.lower(i, j);
            for (std::size_t c = 0; c < 3; ++c) system.lower(3 * i + c, 3 * j + c) += v;
        }
    }
}

void add_per_coordinate_product(const spline::ScalarBandMatrix& b, const double* x, double scale,
                                double* out) {
    const std::size_t n = b.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j0 = i >= 3 ? i - 3 : 0;
        for (std::size_t j = j0; j < i; ++j) {
            const double a = scale * b.lower(i, j);
            for (std::size_t c = 0; c < 3; ++c) {
                out[3 * i + c] += a * x[3 * j + c];
                out[3 * j + c] += a * x[3 * i + c];
            }
        }
        const double d = scale * b.lower(i, i);
        for (std::size_t c = 0; c < 3; ++c) out[3 * i + c] += d * x[3 * i + c];
    }
}

}  // namespace enteron::mechanics
