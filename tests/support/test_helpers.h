// SPDX-License-Identifier: Apache-2.0
// Small helpers the test files share (one definition: the test targets are unity builds, in
// which two files' helpers of one name would collide).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace enteron_test {

// The identity orientation as the C API takes it: w, x, y, z.
inline constexpr double kIdentity[4] = {1.0, 0.0, 0.0, 0.0};
inline const double kNaN = std::numeric_limits<double>::quiet_NaN();

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline double norm3(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

inline bool all_finite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace enteron_test
