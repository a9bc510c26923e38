// SPDX-License-Identifier: Apache-2.0
// The geometry vocabulary (lib/base/geometry.h): normalized_or multiplies by the inverse
// norm (the bits the force laws were written with) and falls back for a vector too short
// to have a direction; point_at views point i of a packed x y z array, for reading and for
// writing, without copying.
#include <gtest/gtest.h>

#include <vector>

#include "base/geometry.h"

namespace enteron {
namespace {

TEST(Geometry, NormalizedOrMultipliesByTheInverseNormOrFallsBack) {
    const Vec3 a(3.0, -4.0, 12.0);
    const Vec3 unit = normalized_or(a, Vec3::UnitX());
    const double inverse = 1.0 / 13.0;
    EXPECT_EQ(unit, Vec3(3.0 * inverse, -4.0 * inverse, 12.0 * inverse)) << "times 1/|a|, bit for bit";
    EXPECT_EQ(normalized_or(Vec3::Zero(), Vec3::UnitZ()), Vec3::UnitZ());
    EXPECT_NEAR(normalized_or(Vec3(1e-150, 0, 0), Vec3::UnitY()).x(), 1.0, 1e-15);
    // Shorter than about 1e-154 m its squared norm underflows: no direction either.
    EXPECT_EQ(normalized_or(Vec3(1e-170, 0, 0), Vec3::UnitY()), Vec3::UnitY());
}

TEST(Geometry, PointAtViewsAPackedArray) {
    std::vector<double> xyz = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    EXPECT_EQ(point_at(static_cast<const double*>(xyz.data()), 2), Vec3(6, 7, 8));
    point_at(xyz.data(), 1) = Vec3(-1, -2, -3);
    EXPECT_EQ(xyz, (std::vector<double>{0, 1, 2, -1, -2, -3, 6, 7, 8}));
    point_at(xyz.data(), 0) += Vec3(1, 1, 1);
    EXPECT_EQ(xyz[0], 1.0);
    EXPECT_EQ(point_at(xyz.data(), 0).data(), xyz.data()) << "a view, not a copy";
}

}  // namespace
}  // namespace enteron
