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

// A 1 m bowel (41 control points) laid flat in the plane z = 0 on five sixths of a circle
// (radius 0.191 m) around the root: a 15 cm polyline (two segments of 7.5 cm, bowed toward
// +y) through the circle's centre, the bowel's first end beside the root's first end, its
// springs fanning out in every direction but the sixth left open (a half fan would slide
// toward its root with every spring slack: tension-only springs at their rest length hold a
// fan only from all around). 20 attachments at fractions (k + 1/2) / 20 sit on control
// points 2k + 1 (spline parameter (k + 1/2) / 20 x 40), which the spline passes through.
constexpr int kFanPoints = 41;
constexpr int kFanAttachments = 20;

std::string fan_points_json() {
    const double sweep = 5.0 * M_PI / 3.0, radius = 1.0 / sweep;
    std::string points;
    for (int i = 0; i < kFanPoints; ++i) {
        const double angle = 4.0 * M_PI / 3.0 - sweep * double(i) / (kFanPoints - 1);
        char point[96];
        std::snprintf(point, sizeof point, "%s[%.17g, %.17g, 0]", i == 0 ? "" : ", ", radius * std::cos(angle),
                      radius * std::sin(angle));
        points += point;
    }
    return "[" + points + "]";
}

// The fan: gravity present but zero (a push is a brief gravity), rest lengths from the start
// shape, the drag of a bowel among others (1 N s/m^2: it settles in seconds); `mesentery`
// extra keys, `environment` extra top-level keys. Without the mesentery: the same bowel, free.
std::string fan_json(bool with_mesentery, const std::string& mesentery = "", const std::string& environment = "") {
    std::string json = R"({"intestine": {"control_points": 41, "shape": {"kind": "points", "points": )" +
                       fan_points_json() + R"(}}, "gravity": [0, 0, 0], "damping": {"drag": 1})";
    if (with_mesentery)
        json += R"(, "mesentery": {"root": [[-0.072, 0, 0], [0, 0.021, 0], [0.072, 0, 0]], "attachments": 20,
                      "stiffness": 20)" + mesentery + "}";
    return json + environment + "}";
}

// Where attachment k is: control point 2k + 1.
std::array<double, 3> fan_attachment(const std::vector<double>& q, int k) {
    const std::size_t i = 2 * std::size_t(k) + 1;
    return {q[3 * i], q[3 * i + 1], q[3 * i + 2]};
}

double fan_distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The largest distance of an attachment from where it started, moved by `shift`.
double fan_farthest_attachment(const std::vector<double>& q, const std::vector<double>& start,
                           const std::array<double, 3>& shift = {0, 0, 0}) {
    double farthest = 0.0;
    for (int k = 0; k < kFanAttachments; ++k) {
        std::array<double, 3> home = fan_attachment(start, k);
        for (int c = 0; c < 3; ++c) home[c] += shift[c];
        farthest = std::max(farthest, fan_distance(fan_attachment(q, k), home));
    }
    return farthest;
}

// Steps `steps` ms with gravity `push` (zero: none).
void fan_steps(ent_scene* scene, const double push[3], int steps) {
    ASSERT_EQ(ent_scene_set_gravity(scene, push), ENT_OK) << ent_last_error();
    ASSERT_TRUE(capi_test::step_n(scene, 1e-3, steps));
}

// Released from the flat fan, pushed in its plane (toward the root and sideways: the push
// slackens springs on one side) for 0.15 s and let go, the bowel settles back onto its fan:
// after 4 s every attachment is where the same fan left alone settles (within 1.5 mm; the
// bending stiffness, whose rest shape is straight, opens the fan's ends by up to a centimetre
// from the start shape, and the springs hold the rest within millimetres), from a push that
// moved them by centimetres. Without the mesentery the same push carries the bowel away.
TEST(FanMesentery, ABowelPushedOffItsFlatFanSettlesBackToIt) {
    const double none[3] = {0.0, 0.0, 0.0};
    ScenePtr alone = capi_test::create_json(fan_json(true));
    ASSERT_TRUE(alone);
    const std::vector<double> start = capi_test::control_points(alone.get());
    fan_steps(alone.get(), none, 4150);
    const std::vector<double> settled_alone = capi_test::control_points(alone.get());
    const double opened = fan_farthest_attachment(settled_alone, start);
    std::printf("[ fan ] left alone, the attachments settle within %.5f m of the start shape\n", opened);
    EXPECT_LT(opened, 0.012);
    for (const bool with_mesentery : {true, false}) {
        ScenePtr scene = capi_test::create_json(fan_json(with_mesentery));
        ASSERT_TRUE(scene);
        for (const double push : {1.0, -1.0}) {
            SCOPED_TRACE(push);
            const double sideways[3] = {push, -2.0, 0.0};
            fan_steps(scene.get(), sideways, 150);
            const double pushed = fan_farthest_attachment(capi_test::control_points(scene.get()), start);
            fan_steps(scene.get(), none, 4000);
            const double back = fan_farthest_attachment(capi_test::control_points(scene.get()), settled_alone);
            std::printf("[ fan %s, push %+g ] pushed %.4f m, then %.6f m from the fan left alone\n",
                        with_mesentery ? "held" : "free", push, pushed, back);
            EXPECT_GT(pushed, 0.015);
            if (with_mesentery) {
                EXPECT_LT(back, 1.5e-3);
            } else {
                EXPECT_GT(back, 0.05);
            }
        }
    }
}

// The root on an obstacle's frame (mesentery.obstacle): the obstacle moves 6.7 cm and turns
// 10 degrees about z over 0.5 s (ent_obstacle_set_pose every step) and rests; after 3.5 s
// more every attachment is within 5 mm of where the frame takes the same fan settled without
// the move (the fan turns back slowly: tension-only springs resist a turn weakly), and
// centimetres from it when the root stays in the world.
TEST(FanMesentery, ARootOnAMovingObstacleCarriesTheBowel) {
    const std::string environment =
        R"(, "environment": [{"type": "sphere", "center": [0, 0, -0.5], "radius": 0.02}])";
    ScenePtr still = capi_test::create_json(fan_json(true, R"(, "obstacle": 0)", environment));
    ASSERT_TRUE(still);
    ASSERT_TRUE(capi_test::step_n(still.get(), 1e-3, 4000));
    const std::vector<double> settled = capi_test::control_points(still.get());
    for (const bool attached : {true, false}) {
        ScenePtr scene = capi_test::create_json(fan_json(true, attached ? R"(, "obstacle": 0)" : "", environment));
        ASSERT_TRUE(scene);
        const double turn = 10.0 * M_PI / 180.0, shift[3] = {0.06, 0.03, 0.0};
        for (int i = 1; i <= 4000; ++i) {
            const double s = std::min(1.0, i / 500.0), ramp = s * s * (3.0 - 2.0 * s);
            const double position[3] = {shift[0] * ramp, shift[1] * ramp, 0.0};
            const double orientation[4] = {std::cos(turn * ramp / 2), 0.0, 0.0, std::sin(turn * ramp / 2)};
            ASSERT_EQ(ent_obstacle_set_pose(scene.get(), 0, position, orientation), ENT_OK) << ent_last_error();
            ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        }
        // Where the frame takes each settled attachment: turned about z through the origin, then shifted.
        const std::vector<double> q = capi_test::control_points(scene.get());
        double farthest = 0.0;
        for (int k = 0; k < kFanAttachments; ++k) {
            const std::array<double, 3> a = fan_attachment(settled, k);
            const std::array<double, 3> carried = {std::cos(turn) * a[0] - std::sin(turn) * a[1] + shift[0],
                                                   std::sin(turn) * a[0] + std::cos(turn) * a[1] + shift[1], a[2]};
            farthest = std::max(farthest, fan_distance(fan_attachment(q, k), carried));
        }
        std::printf("[ fan on an obstacle %s ] farthest attachment from the carried fan %.6f m\n",
                    attached ? "attached" : "in the world", farthest);
        if (attached) {
            EXPECT_LT(farthest, 0.005);
        } else {
            EXPECT_GT(farthest, 0.05);
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
            if (on_obstacle || in_world) {
                EXPECT_NEAR(q[3 * i + c], expected, 1e-12) << "point " << i << " coordinate " << c;
            }
        }
    }
    // Its neighbours outside the spans are free: the lifted span pulled them up.
    EXPECT_GT(q[3 * 7 + 2], start[3 * 7 + 2] + 1e-3);
    EXPECT_GT(q[3 * 17 + 2], start[3 * 17 + 2] + 1e-3);
}

}  // namespace
