// SPDX-License-Identifier: Apache-2.0
// Rotation-minimising frames (lib/skinning/rotation_minimizing_frames.h) stay orthonormal
// and do not twist on a planar curve.
#include "skinning/rotation_minimizing_frames.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace enteron::skinning;
using enteron::normalized_or;
using enteron::Vec3;

TEST(RotationMinimizingFrames, StayOrthonormalAndDoNotTwistOnAPlanarCurve) {
    // A planar curve: the rotation-minimising normal that starts in the plane's normal
    // direction stays exactly there (no twist), whatever the bending.
    std::vector<Vec3> x, t;
    for (int i = 0; i <= 400; ++i) {
        const double a = 3.0 * std::sin(i * 0.03);
        x.push_back({std::cos(a) + 0.01 * i, std::sin(a), 0.0});
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        const Vec3 d = x[std::min(i + 1, x.size() - 1)] - x[i == 0 ? 0 : i - 1];
        t.push_back(normalized_or(d, Vec3{1, 0, 0}));
    }
    RotationMinimizingFrames frames;
    frames.build(x.data(), t.data(), x.size());
    // The first normal is arbitrary; rotate the test to its plane component.
    const double z0 = frames.normal(0).z();
    for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_NEAR(frames.normal(i).dot(t[i]), 0.0, 1e-12);
        EXPECT_NEAR(frames.normal(i).norm(), 1.0, 1e-12);
        EXPECT_NEAR(frames.normal(i).z(), z0, 1e-9) << "twist at sample " << i;
    }
}

}  // namespace
