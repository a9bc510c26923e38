// SPDX-License-Identifier: Apache-2.0
// The start shape (lib/scene/shape_builder.h): every shape's consecutive points are one rest
// segment length l0 = length / (count - 1) apart in a straight line (a bowel that starts at
// rest); a line runs from its centre along its direction, normalised; a helix's points lie
// on its cylinder and rise by its pitch per turn; a serpentine lies in its plane, centred
// on its centre, its legs leg_spacing apart; a points shape is copied.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/shape_builder.h"

namespace enteron::scene {
namespace {

std::vector<double> build(const ShapeConfig& shape, double length, std::size_t count) {
    std::vector<double> xyz(3 * count, std::nan(""));
    build_shape(shape, length, count, xyz.data());
    return xyz;
}

void expect_rest_chords(const std::vector<double>& xyz, double chord) {
    for (std::size_t i = 1; i < xyz.size() / 3; ++i)
        ASSERT_NEAR((point_at(xyz.data(), i) - point_at(xyz.data(), i - 1)).norm(), chord, 1e-12 * chord + 1e-15)
            << "segment " << i;
}

TEST(ShapeBuilder, ALineRunsFromItsCentreAlongItsDirection) {
    ShapeConfig line;
    line.kind = ShapeKind::line;
    line.center = Vec3(0.1, -0.2, 0.3);
    line.direction = Vec3(0.0, 3.0, 4.0);  // normalised when built
    const std::vector<double> xyz = build(line, 1.0, 11);
    expect_rest_chords(xyz, 0.1);
    EXPECT_EQ(point_at(xyz.data(), 0), line.center);
    EXPECT_LT((point_at(xyz.data(), 10) - (line.center + Vec3(0.0, 0.6, 0.8))).norm(), 1e-15);
}

TEST(ShapeBuilder, AHelixLiesOnItsCylinderAndRisesByItsPitch) {
    ShapeConfig helix;
    helix.kind = ShapeKind::helix;
    helix.center = Vec3(0.0, 0.0, 0.1);
    helix.helix_radius = 0.08;
    helix.helix_pitch = 0.03;
    const double length = 6.0;
    const std::size_t count = 240;
    const std::vector<double> xyz = build(helix, length, count);
    expect_rest_chords(xyz, length / (count - 1));
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 p = point_at(xyz.data(), i) - helix.center;
        ASSERT_NEAR(std::hypot(p.x(), p.y()), helix.helix_radius, 1e-12) << "on the cylinder, point " << i;
    }
    // Its height climbs one pitch per turn: z / (pitch / 2 pi) is the angle turned.
    const Vec3 last = point_at(xyz.data(), count - 1) - helix.center;
    const double turned = last.z() / (helix.helix_pitch / (2.0 * kPi));
    EXPECT_NEAR(std::cos(turned), last.x() / helix.helix_radius, 1e-9);
    EXPECT_NEAR(std::sin(turned), last.y() / helix.helix_radius, 1e-9);
    // Each chord spans the angle phi with chord^2 = (2 r sin(phi / 2))^2 + (rise phi)^2
    // (the chords cut the corners: the arc walked is a little longer than the length).
    const double chord = length / (count - 1), rise = helix.helix_pitch / (2.0 * kPi);
    double lo = 0.0, hi = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double phi = 0.5 * (lo + hi);
        (std::hypot(2.0 * helix.helix_radius * std::sin(0.5 * phi), rise * phi) < chord ? lo : hi) = phi;
    }
    EXPECT_NEAR(turned, (count - 1) * lo, 1e-8);
    EXPECT_GT(turned * std::hypot(helix.helix_radius, rise), length);
}

TEST(ShapeBuilder, ASerpentineLiesInItsPlaneCentredWithItsLegsApart) {
    ShapeConfig serpentine;
    serpentine.kind = ShapeKind::serpentine;
    serpentine.center = Vec3(0.01, 0.02, 0.05);
    serpentine.leg_length = 0.3;
    serpentine.leg_spacing = 0.05;
    const std::size_t count = 120;
    const std::vector<double> xyz = build(serpentine, 3.0, count);
    expect_rest_chords(xyz, 3.0 / (count - 1));
    Vec3 low = Vec3::Constant(1e9), high = -low;
    std::vector<double> ys;
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 p = point_at(xyz.data(), i);
        EXPECT_EQ(p.z(), serpentine.center.z()) << "in its plane";
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    EXPECT_LT((0.5 * (low + high) - serpentine.center).norm(), 1e-12) << "its bounding box centred on the centre";
    // The straight parts of the legs: points whose neighbours share their y.
    for (std::size_t i = 1; i + 1 < count; ++i) {
        const double y = xyz[3 * i + 1];
        if (xyz[3 * (i - 1) + 1] == y && xyz[3 * (i + 1) + 1] == y) ys.push_back(y);
    }
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    ASSERT_GE(ys.size(), 3u);
    for (std::size_t k = 1; k < ys.size(); ++k) EXPECT_NEAR(ys[k] - ys[k - 1], serpentine.leg_spacing, 1e-12);
}

TEST(ShapeBuilder, APointsShapeIsCopied) {
    ShapeConfig points;
    points.kind = ShapeKind::points;
    points.points = {0, 0, 0, 0.1, 0, 0, 0.2, 0.05, 0, 0.3, 0.05, 0.01};
    EXPECT_EQ(build(points, 0.5, 4), points.points);
}

}  // namespace
}  // namespace enteron::scene
