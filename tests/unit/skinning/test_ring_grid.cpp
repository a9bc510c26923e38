// SPDX-License-Identifier: Apache-2.0
// The ring grid (lib/skinning/ring_grid.h): its vertex numbering (two poles, rows of
// `segments`), a closed manifold triangle list wound outwards, a layout rebuilt only when
// its shape changes, cap angles from the equator to the pole, v around the rings, and
// outward normals and unit tangents along the rows on a cylinder it is laid on.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "skinning/ring_grid.h"

namespace enteron::skinning {
namespace {

TEST(RingGrid, ItsTrianglesCloseATubeWoundOutwards) {
    RingGrid grid;
    std::vector<uint32_t> indices;
    EXPECT_TRUE(grid.layout(5, 8, 3, indices));
    EXPECT_EQ(grid.rows(), 5u + 2 * 3 + 2);
    EXPECT_EQ(grid.vertex_count(), 2u + (grid.rows() - 2) * 8);
    EXPECT_EQ(grid.vertex(0, 5), 0u);
    EXPECT_EQ(grid.vertex(grid.rows() - 1, 3), grid.vertex_count() - 1);
    EXPECT_EQ(grid.vertex(grid.body_row(0), 9), grid.vertex(grid.body_row(0), 1)) << "around the ring";
    EXPECT_EQ(grid.body_row(0), 4u);
    // Every edge is shared by two triangles that run along it in opposite directions.
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (std::size_t t = 0; t < indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) directed[{indices[t + k], indices[t + (k + 1) % 3]}] += 1;
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << edge.first << "-" << edge.second;
        EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "closed: " << edge.first << "-" << edge.second;
    }
    EXPECT_EQ(indices.size() / 3, 2 * 8 * (grid.rows() - 2) - 2 * 8 + 2 * 8) << "two per quad, one per pole fan";
    EXPECT_FALSE(grid.layout(5, 8, 3, indices)) << "the same shape: nothing rebuilt";
    EXPECT_TRUE(grid.layout(6, 8, 3, indices));
}

// Positions of the grid laid on the cylinder of radius r around +x, rows dx apart, with
// hemispherical caps; the caps' rows at their cap angles.
std::vector<float> cylinder(const RingGrid& grid, double r, double dx) {
    std::vector<float> positions(3 * grid.vertex_count());
    const double body_end = dx * double(grid.body_rings() - 1);
    for (std::size_t row = 0; row < grid.rows(); ++row) {
        const bool first_cap = row <= grid.cap_rings(), last_cap = row >= grid.body_row(grid.body_rings());
        const double angle = grid.cap_angle(row);
        double x = 0.0, radius = r;
        if (first_cap || last_cap) {
            x = (first_cap ? 0.0 : body_end) + r * std::sin(angle);
            radius = r * std::cos(angle);
        } else {
            x = dx * double(row - grid.body_row(0));
        }
        for (std::size_t j = 0; j < grid.segments(); ++j) {
            const std::size_t v = grid.vertex(row, j);
            positions[3 * v] = float(x);
            positions[3 * v + 1] = float(radius * grid.cosine(j));
            positions[3 * v + 2] = float(radius * grid.sine(j));
        }
    }
    return positions;
}

TEST(RingGrid, CapAnglesGoFromTheEquatorToThePoles) {
    RingGrid grid;
    std::vector<uint32_t> indices;
    grid.layout(4, 12, 4, indices);
    EXPECT_NEAR(grid.cap_angle(0), -0.5 * kPi, 1e-15) << "first pole, towards -t";
    EXPECT_NEAR(grid.cap_angle(grid.rows() - 1), 0.5 * kPi, 1e-15);
    EXPECT_EQ(grid.cap_angle(grid.body_row(2)), 0.0);
    for (std::size_t row = 1; row <= grid.cap_rings(); ++row) EXPECT_LT(grid.cap_angle(row - 1), grid.cap_angle(row));
    std::vector<float> v(grid.vertex_count());
    grid.around(v.data());
    EXPECT_EQ(v[0], 0.0f);
    EXPECT_FLOAT_EQ(v[grid.vertex(grid.body_row(1), 3)], 3.0f / 12.0f);
    EXPECT_NEAR(grid.cosine(3), std::cos(2.0 * kPi * 3 / 12), 1e-15);
    EXPECT_NEAR(grid.sine(3), std::sin(2.0 * kPi * 3 / 12), 1e-15);
}

TEST(RingGrid, GridNormalsPointOutOfACylinderAndTangentsAlongIt) {
    RingGrid grid;
    std::vector<uint32_t> indices;
    grid.layout(8, 16, 4, indices);
    const std::vector<float> positions = cylinder(grid, 0.0125, 0.006);
    std::vector<float> normals(positions.size()), tangents(positions.size());
    grid.grid_normals(positions.data(), Vec3::UnitX(), Vec3::UnitX(), normals.data(), tangents.data());  // the axis' end tangents
    for (std::size_t k = 1; k + 1 < grid.body_rings(); ++k)
        for (std::size_t j = 0; j < grid.segments(); ++j) {
            const std::size_t v = grid.vertex(grid.body_row(k), j);
            const Vec3 n(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
            const Vec3 t(tangents[3 * v], tangents[3 * v + 1], tangents[3 * v + 2]);
            const Vec3 radial(0.0, grid.cosine(j), grid.sine(j));
            EXPECT_GT(n.dot(radial), 0.999) << "body ring " << k << ", vertex " << j;
            EXPECT_NEAR(n.norm(), 1.0, 1e-6);
            EXPECT_GT(t.dot(Vec3::UnitX()), 0.999) << "towards the last pole";
            EXPECT_NEAR(t.dot(n), 0.0, 1e-6);
        }
    EXPECT_NEAR(normals[0], -1.0f, 1e-6) << "the first pole faces back along the axis";
    const std::size_t last = grid.vertex_count() - 1;
    EXPECT_NEAR(normals[3 * last], 1.0f, 1e-6);
}

}  // namespace
}  // namespace enteron::skinning
