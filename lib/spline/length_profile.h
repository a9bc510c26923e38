// SPDX-License-Identifier: Apache-2.0
// A property of the bowel that changes along its length (a radius, a mass per metre, a
// stiffness): piecewise linear in s, the arc length from the first end at rest, through
// knots (s_k, value_k) with s strictly increasing, constant past the first and last knots.
// The mechanics read it at the Gauss nodes of each segment, where they integrate
// (s = l0 (segment + t): at rest the parameter maps to arc length as ds = l0 dt), so the
// mass and stiffness matrices stay constant and banded.
#pragma once

#include <cstddef>
#include <memory_resource>
#include <vector>

namespace enteron::spline {

class LengthProfile {
public:
    explicit LengthProfile(std::pmr::memory_resource* memory = std::pmr::get_default_resource())
        : s_(memory), values_(memory) {}
    // From pairs s_0, value_0, s_1, value_1, ... (the layout of the JSON [[s, v], ...] and of
    // the C arrays); the knots must be valid (scene/validate.cpp checks them).
    LengthProfile(const std::vector<double>& pairs, std::pmr::memory_resource* memory);

    bool empty() const { return s_.empty(); }
    // The value at arc length s, linear between knots.
    double at(double s) const;
    double largest() const;
    double smallest() const;
    // The integral of the value over [0, length] (exact: trapezoids between knots).
    double integral(double length) const;
    // The integral of 1 / value over [0, s] (exact for a piecewise linear value), and its
    // inverse: the arc length where that integral reaches u. For spacing that follows the
    // value (collision spheres spaced in proportion to the local radius).
    double reciprocal_integral(double s) const;
    double where_reciprocal_integral_is(double u) const;

private:
    // The sum of run(length of the run, value at its start, value at its end) over the runs
    // of [0, length] between knots.
    template <class Run>
    double sum_over_runs(double length, Run run) const;

    std::pmr::vector<double> s_;
    std::pmr::vector<double> values_;
};

}  // namespace enteron::spline
