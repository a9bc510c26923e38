// SPDX-License-Identifier: Apache-2.0
// The mesentery that fans out (docs/anatomy.md, docs/scene-json.md mesentery.root): a bowel
// whose start shape lies flat on the fan around a 15 cm root polyline settles back to it
// after a push; a root on an obstacle carries the bowel when the obstacle moves; a span of
// the bowel pinned on an obstacle rides with it. Through the C API.
#include <enteron/enteron.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "capi_test_support.h"

namespace {

using capi_test::ScenePtr;

// A 1 m bowel (41 control points) laid on a half circle of radius 1/pi around the origin in
// the plane z = 0, and the root: a 15 cm polyline (two segments of 7.5 cm) bowed toward the
// bowel. 20 attachments at fractions (k + 1/2) / 20 sit on control points 2k + 1 (spline
// parameter (k + 1/2) / 20 x 40), which the Catmull-Rom spline passes through.
constexpr int kFanPoints = 41;
constexpr int kFanAttachments = 20;

std::string fan_points_json() {
    const double radius = 1.0 / M_PI;
    std::string points;
    for (int i = 0; i < kFanPoints; ++i) {
        const double angle = M_PI * (1.0 - double(i) / (kFanPoints - 1));
        char point[96];
        std::snprintf(point, sizeof point, "%s[%.17g, %.17g, 0]", i == 0 ? "" : ", ", radius * std::cos(angle),
                      radius * std::sin(angle));
        points += point;
    }
    return "[" + points + "]";
}

// The fan: gravity present but zero (a push is a brief gravity), rest lengths from the start
// shape; `mesentery` extra keys, `environment` extra top-level keys. Without the mesentery:
// the same bowel, free.
std::string fan_json(bool with_mesentery, const std::string& mesentery = "", const std::string& environment = "") {
    std::string json = R"({"intestine": {"control_points": 41, "shape": {"kind": "points", "points": )" +
                       fan_points_json() + R"(}}, "gravity": [0, 0, 0], "damping": {})";
    if (with_mesentery)
        json += R"(, "mesentery": {"root": [[-0.072, 0, 0], [0, 0.021, 0], [0.072, 0, 0]], "attachments": 20,
                      "stiffness": 20)" + mesentery + "}";
    return json + environment + "}";
}

// Where attachment k is: control point 2k + 1.
std::array<double, 3> attachment(const std::vector<double>& q, int k) {
    const std::size_t i = 2 * std::size_t(k) + 1;
    return {q[3 * i], q[3 * i + 1], q[3 * i + 2]};
}

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The largest distance of an attachment from where it started, moved by `shift`.
double farthest_attachment(const std::vector<double>& q, const std::vector<double>& start,
                           const std::array<double, 3>& shift = {0, 0, 0}) {
    double farthest = 0.0;
    for (int k = 0; k < kFanAttachments; ++k) {
        std::array<double, 3> home = attachment(start, k);
        for (int c = 0; c < 3; ++c) home[c] += shift[c];
        farthest = std::max(farthest, distance(attachment(q, k), home));
    }
    return farthest;
}

// Released from the flat fan, pushed in its plane (toward the root and sideways: the push
// slackens some springs) for 0.15 s and let go, the bowel settles back onto the fan: every
// attachment within a few millimetres of where it started after 3 s, from a push that moved
// them by centimetres. Without the mesentery the same push carries the bowel away.
TEST(FanMesentery, ABowelPushedOffItsFlatFanSettlesBackToIt) {
    for (const bool with_mesentery : {true, false}) {
        ScenePtr scene = capi_test::create_json(fan_json(with_mesentery));
        ASSERT_TRUE(scene);
        const std::vector<double> start = capi_test::control_points(scene.get());
        const double push[3] = {1.0, -2.0, 0.0}, none[3] = {0.0, 0.0, 0.0};
        ASSERT_EQ(ent_scene_set_gravity(scene.get(), push), ENT_OK) << ent_last_error();
        ASSERT_TRUE(capi_test::step_n(scene.get(), 1e-3, 150));
        const double pushed = farthest_attachment(capi_test::control_points(scene.get()), start);
        ASSERT_EQ(ent_scene_set_gravity(scene.get(), none), ENT_OK) << ent_last_error();
        ASSERT_TRUE(capi_test::step_n(scene.get(), 1e-3, 3000));
        const double settled = farthest_attachment(capi_test::control_points(scene.get()), start);
        std::printf("[ fan %s ] pushed %.4f m, settled %.5f m\n", with_mesentery ? "held" : "free", pushed, settled);
        EXPECT_GT(pushed, 0.01);
        if (with_mesentery) {
            EXPECT_LT(settled, 0.003);
        } else {
            EXPECT_GT(settled, 0.02);
        }
    }
}

// The root on an obstacle's frame (mesentery.obstacle): the obstacle moves 6 cm and turns
// 30 degrees about z over 0.5 s (ent_obstacle_set_pose every step) and rests; the bowel's
// attachments follow the frame: each within a few millimetres of where the frame takes its
// start after 2 s more, and far from it when the root stays in the world.
TEST(FanMesentery, ARootOnAMovingObstacleCarriesTheBowel) {
    const std::string environment =
        R"(, "environment": [{"type": "sphere", "center": [0, 0, -0.5], "radius": 0.02}])";
    for (const bool attached : {true, false}) {
        ScenePtr scene = capi_test::create_json(fan_json(true, attached ? R"(, "obstacle": 0)" : "", environment));
        ASSERT_TRUE(scene);
        const std::vector<double> start = capi_test::control_points(scene.get());
        const double turn = 30.0 * M_PI / 180.0, shift[3] = {0.06, 0.03, 0.0};
        for (int i = 1; i <= 2500; ++i) {
            const double s = std::min(1.0, i / 500.0), ramp = s * s * (3.0 - 2.0 * s);
            const double position[3] = {shift[0] * ramp, shift[1] * ramp, 0.0};
            const double orientation[4] = {std::cos(turn * ramp / 2), 0.0, 0.0, std::sin(turn * ramp / 2)};
            ASSERT_EQ(ent_obstacle_set_pose(scene.get(), 0, position, orientation), ENT_OK) << ent_last_error();
            ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        }
        // Where the frame takes each attachment: turned about z through the origin, then shifted.
        const std::vector<double> q = capi_test::control_points(scene.get());
        double farthest = 0.0;
        for (int k = 0; k < kFanAttachments; ++k) {
            const std::array<double, 3> a = attachment(start, k);
            const std::array<double, 3> carried = {std::cos(turn) * a[0] - std::sin(turn) * a[1] + shift[0],
                                                   std::sin(turn) * a[0] + std::cos(turn) * a[1] + shift[1], a[2]};
            farthest = std::max(farthest, distance(attachment(q, k), carried));
        }
        std::printf("[ fan on an obstacle %s ] farthest attachment from the carried fan %.5f m\n",
                    attached ? "attached" : "in the world", farthest);
        if (attached) {
            EXPECT_LT(farthest, 0.004);
        } else {
            EXPECT_GT(farthest, 0.03);
        }
    }
}

// A span of the bowel pinned on an obstacle (pinned.spans with an obstacle: the
// retroperitoneal colon on the posterior wall) rides with it exactly, and a span pinned in
// the world stays: every control point in [0.19, 0.41] m of the 1 m bowel on the obstacle, in [0.69, 0.81] in
// the world.
TEST(FanMesentery, ASpanPinnedOnAnObstacleRidesWithIt) {
    const std::string environment =
        R"(, "environment": [{"type": "sphere", "center": [0, 0, -0.5], "radius": 0.02}],
        "pinned": {"spans": [{"from": 0.19, "to": 0.41, "obstacle": 0}, {"from": 0.69, "to": 0.81}]})";
    ScenePtr scene = capi_test::create_json(fan_json(false, "", environment));
    ASSERT_TRUE(scene);
    const std::vector<double> start = capi_test::control_points(scene.get());
    const double position[3] = {0.0, 0.0, 0.02}, orientation[4] = {1, 0, 0, 0};
    for (int i = 1; i <= 300; ++i) {
        const double lift[3] = {0.0, 0.0, position[2] * std::min(1.0, i / 200.0)};
        ASSERT_EQ(ent_obstacle_set_pose(scene.get(), 0, lift, orientation), ENT_OK) << ent_last_error();
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
    }
    const std::vector<double> q = capi_test::control_points(scene.get());
    // Control points every 2.5 cm: 8 .. 16 on the obstacle, 28 .. 32 in the world.
    for (int i = 0; i < kFanPoints; ++i) {
        const bool on_obstacle = i >= 8 && i <= 16, in_world = i >= 28 && i <= 32;
        for (int c = 0; c < 3; ++c) {
            const double expected = start[3 * i + c] + (on_obstacle && c == 2 ? position[2] : 0.0);
            if (on_obstacle || in_world) EXPECT_NEAR(q[3 * i + c], expected, 1e-12) << "point " << i << " coordinate " << c;
        }
    }
    // Its neighbours outside the spans are free: the lifted span pulled them up.
    EXPECT_GT(q[3 * 7 + 2], start[3 * 7 + 2] + 1e-3);
    EXPECT_GT(q[3 * 17 + 2], start[3 * 17 + 2] + 1e-3);
}

}  // namespace
