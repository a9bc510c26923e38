#include "mechanics/damping_force.h"

#include <cmath>

namespace enteron::mechanics {

namespace {
constexpr std::size_t kNodesPerSegment = 2;  // see stretch_force.h
}

DampingForce::DampingForce(const AxisModel& model, const DampingCoefficients& coefficients,
                           std::pmr::memory_resource* memory)
    : model_(model),
      coefficients_(coefficients),
      constant_(memory),
      nodes_(spline::segment_quadrature(model.control_points, spline::Derivative::first,
                                        kNodesPerSegment, memory)) {
    const std::size_t n = model.control_points;
    const double l0 = model.rest_segment_length;
    constant_.resize(n);
    spline::add_gram_matrix(n, spline::Derivative::value, coefficients.drag * l0, constant_);
    spline::add_gram_matrix(n, spline::Derivative::second, coefficients.bend / (l0 * l0 * l0), constant_);
}

void DampingForce::evaluate(const State& state, double* force, const Linearization* lin) {
    add_per_coordinate_product(constant_, state.v.data(), -1.0, force);

    const double l0 = model_.rest_segment_length;
    const double c = coefficients_.stretch;
    const double tiny = 1e-12 * l0;
    for (const spline::QuadratureNode& node : nodes_) {
        const spline::SegmentWeights& sw = node.weights;
        double d[3], rate[3];
        spline::evaluate(state.q.data(), sw, d);
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(len > tiny)) continue;
        const double u[3] = {d[0] / len, d[1] / len, d[2] / len};
        spline::evaluate(state.v.data(), sw, rate);
        const double strain_rate = (u[0] * rate[0] + u[1] * rate[1] + u[2] * rate[2]) / l0;
        const double scale = node.weight * c * strain_rate;
        const double f[3] = {-scale * u[0], -scale * u[1], -scale * u[2]};
        add_point_force(sw, f, force);
        if (lin != nullptr) add_axial_block(*lin->system, sw, u, c / l0, 0.0, lin->h * node.weight);
    }
}

void DampingForce::add_constant_linearization(double h, SystemMatrix& system) const {
    add_per_coordinate(constant_, h, system);
}

void DampingForce::add_damping_bound(spline::ScalarBandMatrix& bound) const {
    bound.add_scaled(constant_, 1.0);
    spline::add_gram_matrix(model_.control_points, spline::Derivative::first,
                            coefficients_.stretch / model_.rest_segment_length, bound);
}

}  // namespace enteron::mechanics
