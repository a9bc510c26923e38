// SPDX-License-Identifier: Apache-2.0
// The marching cubes table (lib/skinning/marching_cubes_table.h): single-corner cases face
// away from the inside corner, and no triangle edge joins what a face leaves apart.
#include "skinning/marching_cubes_table.h"

#include <gtest/gtest.h>

#include <map>

#include "base/geometry.h"

namespace {

using namespace enteron::skinning;
using enteron::Vec3;

TEST(MarchingCubesTable, EverySingleCornerCaseFacesAwayFromTheInsideCorner) {
    const auto& table = marching_cubes_table();
    for (int c = 0; c < 8; ++c) {
        const MarchingCubesCase& entry = table[std::size_t(1 << c)];
        ASSERT_EQ(entry.triangle_count, 1);
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const auto& e = kEdgeCorners[entry.edges[std::size_t(k)]];
            const Vec3 a{double(e[0] & 1), double((e[0] >> 1) & 1), double((e[0] >> 2) & 1)};
            const Vec3 b{double(e[1] & 1), double((e[1] >> 1) & 1), double((e[1] >> 2) & 1)};
            p[k] = 0.5 * (a + b);
        }
        const Vec3 corner{double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)};
        EXPECT_LT((p[1] - p[0]).cross(p[2] - p[0]).dot(corner - p[0]), 0.0) << "case " << (1 << c);
    }
    // Complementary cases have the same number of crossing edges.
    for (int mask = 0; mask < 256; ++mask)
        EXPECT_EQ(table[std::size_t(mask)].triangle_count == 0, mask == 0 || mask == 255) << mask;
}

TEST(MarchingCubesTable, NoTriangleEdgeJoinsTwoVerticesOfAFaceThatTheFaceLeavesApart) {
    // A triangle edge inside a cell whose two vertices lie on one face of the cell, without
    // a face segment between them, crosses that face; the cell on the other side sees the
    // same two vertices, apart, on the same face and may draw the same edge: it would then
    // belong to four triangles (a non-manifold edge: the fan triangulation did this in 18
    // cases, where two folds touch).
    const auto& table = marching_cubes_table();
    auto on_face = [](int e, int axis, int side) {
        return ((kEdgeCorners[std::size_t(e)][0] >> axis) & 1) == side && ((kEdgeCorners[std::size_t(e)][1] >> axis) & 1) == side;
    };
    for (int mask = 0; mask < 256; ++mask) {
        const MarchingCubesCase& entry = table[std::size_t(mask)];
        std::map<std::pair<int, int>, int> uses;  // triangle edges of the case
        for (int t = 0; t < entry.triangle_count; ++t)
            for (int k = 0; k < 3; ++k) {
                const int a = entry.edges[std::size_t(3 * t + k)], b = entry.edges[std::size_t(3 * t + (k + 1) % 3)];
                ++uses[{std::min(a, b), std::max(a, b)}];
            }
        for (const auto& [edge, count] : uses) {
            if (count == 1) continue;  // on the loop: a face segment (or the cell's own edge)
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side)
                    EXPECT_FALSE(on_face(edge.first, axis, side) && on_face(edge.second, axis, side))
                        << "case " << mask << ": diagonal between edges " << edge.first << " and " << edge.second;
        }
    }
}

}  // namespace
