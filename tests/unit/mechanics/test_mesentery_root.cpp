// SPDX-License-Identifier: Apache-2.0
// The root polyline (lib/mechanics/mesentery_root.h): the point at fraction t of its length,
// walked segment by segment; two points are the segment start + t (end - start).
#include "mechanics/mesentery_root.h"

#include <gtest/gtest.h>

#include <memory_resource>

namespace enteron::mechanics {
namespace {

TEST(MesenteryRoot, APointAtAFractionOfThePolylinesLength) {
    // 3 cm along x, then 4 cm along y: 7 cm.
    const std::pmr::vector<Vec3> root{Vec3(0, 0, 0), Vec3(0.03, 0, 0), Vec3(0.03, 0.04, 0)};
    EXPECT_LT((point_along_root(root, 0.0) - Vec3(0, 0, 0)).norm(), 1e-17);
    EXPECT_LT((point_along_root(root, 1.0 / 7.0) - Vec3(0.01, 0, 0)).norm(), 1e-17);
    EXPECT_LT((point_along_root(root, 3.0 / 7.0) - Vec3(0.03, 0, 0)).norm(), 1e-17);
    EXPECT_LT((point_along_root(root, 5.0 / 7.0) - Vec3(0.03, 0.02, 0)).norm(), 1e-17);
    EXPECT_LT((point_along_root(root, 1.0) - Vec3(0.03, 0.04, 0)).norm(), 1e-17);
}

TEST(MesenteryRoot, TwoPointsAreTheSegmentEvenOfNoLength) {
    const std::pmr::vector<Vec3> segment{Vec3(-0.075, 0.1, 0), Vec3(0.075, 0.2, 0.3)};
    EXPECT_EQ(point_along_root(segment, 0.3), segment[0] + 0.3 * (segment[1] - segment[0]));
    const std::pmr::vector<Vec3> point{Vec3(0.1, 0.2, 0.3), Vec3(0.1, 0.2, 0.3)};
    EXPECT_EQ(point_along_root(point, 0.7), point[0]);
}

}  // namespace
}  // namespace enteron::mechanics
