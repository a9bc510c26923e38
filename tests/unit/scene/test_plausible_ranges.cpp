// SPDX-License-Identifier: Apache-2.0
// The ranges a human abdomen gives a scene (lib/scene/plausible_ranges.h): a value inside is
// silent, one outside names itself and, where a unit mistake explains it, that mistake; the
// warnings name each key as the caller wrote it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/logger.h"
#include "scene/plausible_ranges.h"
#include "scene/scene_config.h"
#include "scene/scene_table.h"
#include "scene/validate.h"
#include "test_helpers.h"

namespace enteron::scene {
namespace {

using enteron_test::contains;

std::vector<std::string> warnings_of(const SceneConfig& config, const FieldNames& names) {
    std::vector<std::string> lines;
    const Logger logger(
        [](void* user, int32_t level, const char* message) {
            EXPECT_EQ(level, static_cast<int32_t>(LogLevel::warning));
            static_cast<std::vector<std::string>*>(user)->push_back(message);
        },
        &lines);
    warn_implausible(config, names, logger);
    return lines;
}

TEST(PlausibleRanges, AValueInsideIsSilentAndOneOutsideNamesTheLikelyUnit) {
    const PlausibleRange& radius = *find_path(scene_block(), "intestine.radius").field->plausible;
    EXPECT_EQ(implausibility(radius, 0.0125), "");
    const std::string millimetres = implausibility(radius, 12.5);
    EXPECT_TRUE(contains(millimetres, "12.5 m is far above a human small bowel's radius")) << millimetres;
    EXPECT_TRUE(contains(millimetres, "millimetres?")) << millimetres;
    EXPECT_TRUE(contains(implausibility(radius, 1.25), "centimetres?"));
    // Far outside, but no unit explains it: no guess.
    const std::string no_guess = implausibility(radius, 400.0);
    EXPECT_TRUE(contains(no_guess, "far above")) << no_guess;
    EXPECT_FALSE(contains(no_guess, "given in")) << no_guess;
    EXPECT_TRUE(contains(implausibility(radius, 1e-4), "far below"));
}

TEST(PlausibleRanges, TheDefaultSceneIsPlausibleInJsonAndC) {
    SceneConfig config;
    config.gravity = kStandardGravity;
    config.damping.emplace();
    config.mesentery.emplace();
    config.self_collision = true;
    config.environment.push_back(default_obstacle(collision::ObstacleKind::box_inside));
    config.environment.push_back(default_obstacle(collision::ObstacleKind::sphere));
    config.tools.emplace_back();
    EXPECT_TRUE(warnings_of(config, json_field_names()).empty());
    EXPECT_TRUE(warnings_of(config, c_field_names()).empty());
}

TEST(PlausibleRanges, TheUnitMistakesOfAFirstHourAreNamedWithTheirKeys) {
    SceneConfig config;
    config.gravity = Vec3{0.0, 0.0, -9810.0};     // mm/s^2
    config.intestine.linear_density = 300.0;      // x 1000
    MesenteryConfig mesentery;
    mesentery.stiffness = 1e9;                     // no unit explains it
    config.mesentery = mesentery;
    collision::Obstacle box = default_obstacle(collision::ObstacleKind::box_inside);
    box.extent = {150.0, 150.0, 150.0};            // millimetres
    config.environment.push_back(box);

    const std::vector<std::string> json = warnings_of(config, json_field_names());
    ASSERT_EQ(json.size(), 6u);
    EXPECT_TRUE(contains(json[0], "intestine.linear_density: 300 kg/m is far above")) << json[0];
    EXPECT_TRUE(contains(json[0], "g/m")) << json[0];
    EXPECT_TRUE(contains(json[1], "|gravity|: 9810 m/s^2 is far above the Earth's gravity")) << json[1];
    EXPECT_TRUE(contains(json[1], "mm/s^2?")) << json[1];
    EXPECT_TRUE(contains(json[2], "mesentery.stiffness: 1e+09 N/m is far above")) << json[2];
    EXPECT_FALSE(contains(json[2], "given in")) << json[2];
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(contains(json[3 + k], "environment[0].half_extents[" + std::to_string(k) + "]: 150 m"))
            << json[3 + k];
        EXPECT_TRUE(contains(json[3 + k], "millimetres?")) << json[3 + k];
    }
    // The C names.
    const std::vector<std::string> c = warnings_of(config, c_field_names());
    ASSERT_EQ(c.size(), 6u);
    EXPECT_TRUE(contains(c[0], "linear_density_kg_per_m: 300")) << c[0];
    EXPECT_TRUE(contains(c[1], "|gravity_m_per_s2|: 9810")) << c[1];
    EXPECT_TRUE(contains(c[2], "mesentery_stiffness_N_per_m: 1e+09")) << c[2];
    EXPECT_TRUE(contains(c[3], "obstacle[0].half_extents[0]: 150 m")) << c[3];
}

TEST(PlausibleRanges, GravityInGAndAZeroGravityAreTold) {
    SceneConfig config;
    config.gravity = Vec3{0.0, 0.0, -1.0};
    const std::vector<std::string> in_g = warnings_of(config, json_field_names());
    ASSERT_EQ(in_g.size(), 1u);
    EXPECT_TRUE(contains(in_g[0], "was it given in g?")) << in_g[0];
    config.gravity = Vec3{0.0, 0.0, 0.0};  // weightless: a choice, not a mistake
    EXPECT_TRUE(warnings_of(config, json_field_names()).empty());
}

TEST(PlausibleRanges, ASilentLoggerCostsNothingAndSaysNothing) {
    SceneConfig config;
    config.gravity = Vec3{0.0, 0.0, -9810.0};
    warn_implausible(config, json_field_names(), Logger());  // no callback: nothing to do
}

}  // namespace
}  // namespace enteron::scene
