// SPDX-License-Identifier: Apache-2.0
// The rest length of a "points" shape (lib/scene/points_length.h): the length of the spline
// through the points, exact on a straight line and closer to a circle's arc than the
// polygon through the same points; a length given that differs by more than 1 %, and points
// spaced unevenly, are warned about with the keys the caller wrote.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/logger.h"
#include "scene/points_length.h"
#include "scene/scene_config.h"
#include "scene/validate.h"

namespace enteron::scene {
namespace {

SceneConfig points_scene(const std::vector<double>& points) {
    SceneConfig config;
    config.intestine.shape.kind = ShapeKind::points;
    config.intestine.shape.points = points;
    config.intestine.control_points = points.size() / 3;
    return config;
}

// n points on an arc of radius r from angle 0 to `angle`, evenly spaced.
std::vector<double> arc_points(std::size_t n, double r, double angle) {
    std::vector<double> points;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = angle * double(i) / double(n - 1);
        points.insert(points.end(), {r * std::cos(a), r * std::sin(a), 0.0});
    }
    return points;
}

std::vector<std::string> points_length_warnings_of(const SceneConfig& config) {
    std::vector<std::string> lines;
    const Logger logger(
        [](void* user, int32_t, const char* message) { static_cast<std::vector<std::string>*>(user)->push_back(message); },
        &lines);
    warn_points_length(config, json_field_names(), logger);
    return lines;
}

TEST(PointsLength, OnAStraightLineTheSplineIsThePolyline) {
    std::vector<double> points;
    for (int i = 0; i < 11; ++i) points.insert(points.end(), {0.03 * i, -0.01 * i, 0.002 * i});
    const double polyline = 10.0 * std::sqrt(0.03 * 0.03 + 0.01 * 0.01 + 0.002 * 0.002);
    EXPECT_NEAR(points_spline_length(points_scene(points)), polyline, 1e-12 * polyline);
}

TEST(PointsLength, OnACircleTheSplineIsCloserToTheArcThanThePolygon) {
    const double r = 0.1, angle = M_PI;
    const std::size_t n = 13;
    const double arc = r * angle;
    const double polygon = double(n - 1) * 2.0 * r * std::sin(angle / double(n - 1) / 2.0);
    const double spline = points_spline_length(points_scene(arc_points(n, r, angle)));
    EXPECT_LT(polygon, arc);
    EXPECT_LT(std::fabs(spline - arc), std::fabs(polygon - arc));
    EXPECT_LT(std::fabs(spline - arc), 2e-3 * arc);
}

TEST(PointsLength, ALengthGivenThatDisagreesBeyondOnePercentIsWarnedAbout) {
    SceneConfig config = points_scene(arc_points(13, 0.1, M_PI));
    const double spline = points_spline_length(config);
    config.intestine.length = spline;
    EXPECT_TRUE(points_length_warnings_of(config).empty());
    config.intestine.length = spline * (1.0 + 0.5 * kPointsLengthTolerance);
    EXPECT_TRUE(points_length_warnings_of(config).empty()) << "within the tolerance";
    config.intestine.length = spline / 1.05;  // the spline is 5 % longer than its rest length
    const std::vector<std::string> stretched = points_length_warnings_of(config);
    ASSERT_EQ(stretched.size(), 1u);
    EXPECT_NE(stretched[0].find("intestine.length"), std::string::npos) << stretched[0];
    EXPECT_NE(stretched[0].find("stretched by 5"), std::string::npos) << stretched[0];
    config.intestine.length = spline * 1.05;
    const std::vector<std::string> compressed = points_length_warnings_of(config);
    ASSERT_EQ(compressed.size(), 1u);
    EXPECT_NE(compressed[0].find("compressed"), std::string::npos) << compressed[0];
}

TEST(PointsLength, PointsSpacedUnevenlyAreWarnedAboutWhereTheyAre) {
    // A straight line whose points 4 and 5 are twice as far apart as the others.
    std::vector<double> points;
    double x = 0.0;
    for (int i = 0; i < 10; ++i) {
        points.insert(points.end(), {x, 0.0, 0.0});
        x += i == 4 ? 0.04 : 0.02;
    }
    SceneConfig config = points_scene(points);
    config.intestine.length = points_spline_length(config);
    const std::vector<std::string> lines = points_length_warnings_of(config);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NE(lines[0].find("spaced unevenly"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("points 4 and 5"), std::string::npos) << lines[0];
}

}  // namespace
}  // namespace enteron::scene
