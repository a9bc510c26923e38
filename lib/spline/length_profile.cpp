// SPDX-License-Identifier: Apache-2.0
#include "spline/length_profile.h"

#include <algorithm>
#include <cmath>

namespace enteron::spline {

namespace {

// The integral of 1 / r over a run of `length` where r goes linearly from r0 to r1:
// length ln(r1 / r0) / (r1 - r0), or length / r0 where r barely changes.
double reciprocal_over(double length, double r0, double r1) {
    const double change = r1 - r0;
    if (std::abs(change) <= 1e-12 * r0) return length / r0;
    return length * std::log(r1 / r0) / change;
}

// Where, within a run of `length` from r0 to r1, the integral of 1 / r reaches u: the
// inverse of reciprocal_over (r(x) = r0 exp(u (r1 - r0) / length)).
double reciprocal_inverse(double u, double length, double r0, double r1) {
    const double change = r1 - r0;
    if (std::abs(change) <= 1e-12 * r0) return u * r0;
    const double r = r0 * std::exp(u * change / length);
    return (r - r0) * length / change;
}

}  // namespace

LengthProfile::LengthProfile(const std::vector<double>& pairs, std::pmr::memory_resource* memory)
    : s_(memory), values_(memory) {
    s_.reserve(pairs.size() / 2);
    values_.reserve(pairs.size() / 2);
    for (std::size_t k = 0; k + 1 < pairs.size(); k += 2) {
        s_.push_back(pairs[k]);
        values_.push_back(pairs[k + 1]);
    }
}

double LengthProfile::at(double s) const {
    if (s <= s_.front()) return values_.front();
    if (s >= s_.back()) return values_.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
    const double t = (s - s_[k]) / (s_[k + 1] - s_[k]);
    return (1.0 - t) * values_[k] + t * values_[k + 1];
}

double LengthProfile::largest() const { return *std::max_element(values_.begin(), values_.end()); }
double LengthProfile::smallest() const { return *std::min_element(values_.begin(), values_.end()); }

template <class Run>
double LengthProfile::sum_over_runs(double length, Run run) const {
    // The knots clipped to [0, length] cut it into runs where the value is linear (the ends
    // of [0, length] are run ends too).
    double total = 0.0;
    double from = 0.0, value = at(0.0);
    for (std::size_t k = 0; k <= s_.size(); ++k) {
        const double to = k < s_.size() ? std::min(s_[k], length) : length;
        if (to <= from) continue;
        const double next = at(to);
        total += run(to - from, value, next);
        from = to, value = next;
    }
    return total;
}

double LengthProfile::integral(double length) const {
    return sum_over_runs(length, [](double run, double v0, double v1) { return 0.5 * (v0 + v1) * run; });
}

double LengthProfile::reciprocal_integral(double s) const { return sum_over_runs(s, reciprocal_over); }

double LengthProfile::where_reciprocal_integral_is(double u) const {
    double from = 0.0, value = at(0.0), total = 0.0;
    for (std::size_t k = 0; k < s_.size(); ++k) {
        const double to = s_[k];
        if (to <= from) continue;
        const double next = values_[k];
        const double run = reciprocal_over(to - from, value, next);
        if (total + run >= u) return from + reciprocal_inverse(u - total, to - from, value, next);
        total += run;
        from = to, value = next;
    }
    return from + (u - total) * value;  // past the last knot the value is constant
}

}  // namespace enteron::spline
