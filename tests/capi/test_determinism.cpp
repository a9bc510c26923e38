// SPDX-License-Identifier: Apache-2.0
// Determinism: the same scene and the same calls give bit-identical states, run to run,
// across create/destroy cycles and with another scene stepping in between.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "capi_test_support.h"

namespace {

// A scene with every kind of effect, so contacts, the grid and the guard are all exercised.
const std::string kScene = R"({
  "intestine": {"length": 1.2, "control_points": 48, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
  "gravity": [0, 0, -9.81],
  "damping": {},
  "mesentery": {"attachments": 12, "root": [[-0.05, 0, 0.05], [0.05, 0, 0.05]]},
  "environment": [{"type": "box_inside", "center": [0, 0, 0], "half_extents": [0.1, 0.1, 0.1]}],
  "self_collision": {}
})";

std::vector<double> run(int steps, ent_scene* other = nullptr) {
    ent_scene* scene = nullptr;
    EXPECT_EQ(ent_scene_create_json(kScene.data(), kScene.size(), &scene), ENT_OK) << ent_last_error();
    for (int i = 0; i < steps; ++i) {
        EXPECT_EQ(ent_scene_step(scene, 1e-3), ENT_OK) << ent_last_error();
        if (other != nullptr) ent_scene_step(other, 1e-3);
    }
    uint32_t count = 0;
    ent_scene_control_points(scene, 0, nullptr, &count);
    std::vector<double> points(3 * count);
    EXPECT_EQ(ent_scene_control_points(scene, count, points.data(), &count), ENT_OK);
    ent_stats stats;
    stats.struct_size = sizeof stats;
    EXPECT_EQ(ent_scene_stats(scene, &stats), ENT_OK);
    EXPECT_GT(stats.contacts, 0u) << "the scene should be in contact by then";
    points.push_back(stats.kinetic_energy_J);
    points.push_back(stats.potential_energy_J);
    ent_scene_destroy(scene);
    return points;
}

TEST(Determinism, SameSceneSameCallsGiveBitIdenticalStates) {
    const std::vector<double> first = run(400);
    const std::vector<double> second = run(400);
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(double)), 0);
}

TEST(Determinism, AnotherSceneSteppingInBetweenChangesNothing) {
    const std::vector<double> alone = run(300);
    ent_scene* other = nullptr;
    ASSERT_EQ(ent_scene_create_json(kScene.data(), kScene.size(), &other), ENT_OK);
    const std::vector<double> interleaved = run(300, other);
    ent_scene_destroy(other);
    ASSERT_EQ(alone.size(), interleaved.size());
    EXPECT_EQ(std::memcmp(alone.data(), interleaved.data(), alone.size() * sizeof(double)), 0);
}

TEST(Determinism, AShorterRunDiffers) {
    // The comparison above can fail: a different number of steps gives a different state.
    const std::vector<double> a = run(300);
    const std::vector<double> b = run(301);
    EXPECT_NE(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
}

}  // namespace
