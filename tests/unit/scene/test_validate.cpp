// SPDX-License-Identifier: Apache-2.0
// The scene validation (lib/scene/validate.h) with both name tables (JSON keys and C
// fields): every field named, non-finite numbers and enums refused by name, messages that
// blame what the caller wrote, scenes refused because they cannot start, and the normalised
// config it returns. The JSON loader's own checks are in scene/test_json_loader.cpp.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "base/error.h"
#include "scene/json_loader.h"
#include "scene/shape_builder.h"
#include "scene/validate.h"
#include "test_helpers.h"

namespace enteron::scene {
namespace {

using enteron_test::contains;

Error validate_error(const SceneConfig& config, const FieldNames& names) {
    try {
        validate(config, names);
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "validate raised no error";
    return Error(ErrorCode::internal, "");
}


std::string json_error(const std::string& text) {
    try {
        load_scene_json(text.data(), text.size());
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::invalid_scene);
        return error.what();
    }
    ADD_FAILURE() << "no error for " << text;
    return "";
}

TEST(Validate, ARadiusInCentimetresIsBlamedNotTheDefaultPitchItClashesWith) {
    // Before: "intestine.shape.helix_pitch must be >= 2 x intestine.radius (2.5), got 0.03",
    // a value the user never wrote.
    const std::string message = json_error(R"({"intestine": {"radius": 1.25}})");
    EXPECT_EQ(message.rfind("intestine.radius (1.25) does not fit the default intestine.shape.helix_pitch (0.03)", 0),
              0u)
        << message;
    EXPECT_TRUE(contains(message, "give intestine.shape.helix_pitch too, or check intestine.radius")) << message;
    EXPECT_TRUE(contains(message, "was it given in centimetres?")) << message;
    // The same mistake from C names the C fields.
    SceneConfig config;
    config.intestine.radius = 1.25;
    try {
        validate(config, c_field_names(), fields_apart_from_defaults(config));
        ADD_FAILURE() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()).rfind("radius_m (1.25) does not fit the default shape_helix_pitch_m", 0), 0u)
            << error.what();
    }
}

TEST(Validate, AFieldTheCallerWroteIsBlamedAndADefaultBoundSaysSo) {
    // Both written: the checked one is blamed, as always.
    EXPECT_EQ(json_error(R"({"intestine": {"radius": 0.0125, "shape": {"helix_pitch": 0.01}}})"),
              "intestine.shape.helix_pitch must be >= 2 x intestine.radius (0.025), got 0.01");
    // The pitch written, the radius its default.
    EXPECT_EQ(json_error(R"({"intestine": {"shape": {"helix_pitch": 0.01}}})"),
              "intestine.shape.helix_pitch must be >= 2 x intestine.radius (0.025, from its default 0.0125), got 0.01");
    // A length shorter than the default radius: the length is what the user wrote.
    EXPECT_EQ(json_error(R"({"intestine": {"length": 0.01}})").rfind(
                  "intestine.length (0.01) does not fit the default intestine.radius (0.0125), which must be < "
                  "intestine.length",
                  0),
              0u);
}

TEST(Validate, ABowelThatStartsFarOutsideItsCavityIsRefusedNamingThePoints) {
    // The default helix (0.29 m high, radius 0.1 m) and a 24 cm box a metre away.
    const std::string away = json_error(
        R"({"environment": [{"type": "box_inside", "center": [1, 0, 0], "half_extents": [0.12, 0.12, 0.12]}]})");
    EXPECT_EQ(away.rfind("environment[0] (box_inside) has control points 0-239 (240 of 240) outside it", 0), 0u)
        << away;
    EXPECT_TRUE(contains(away, "past the guard's max_speed (50 m/s)")) << away;
    EXPECT_TRUE(contains(away, "so that the bowel starts within the cavity")) << away;

    // A 50 m helix in a 30 cm box: most of it far above the lid.
    const std::string tall = json_error(R"({"intestine": {"length": 50, "control_points": 400},
        "environment": [{"type": "box_inside", "half_extents": [0.15, 0.15, 0.15]}]})");
    EXPECT_EQ(tall.rfind("environment[0] (box_inside) has control points ", 0), 0u) << tall;

    // An organ that holds the whole bowel.
    const std::string organ = json_error(
        R"({"environment": [{"type": "plane", "normal": [0, 0, 1], "point": [0, 0, -1]},
                            {"type": "sphere", "center": [0, 0, 0.15], "radius": 0.5}]})");
    EXPECT_EQ(organ.rfind("environment[1] (sphere) has control points 0-239 (240 of 240) inside it", 0), 0u) << organ;
    EXPECT_TRUE(contains(organ, "outside every organ")) << organ;
}

TEST(Validate, ABowelThatStartsALittleOutsideIsPushedInNotRefused) {
    // Draped 5 cm over the rim (the contact throws it in at about 30 m/s): a scene that works.
    const std::string text = R"({"intestine": {"length": 1.2, "control_points": 48,
        "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
        "environment": [{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1]}]})";
    EXPECT_NO_THROW(load_scene_json(text.data(), text.size()));
    // Softer contacts throw gentler: the same bowel 10 cm out, with stiffness 100 N/m.
    const std::string soft = R"({"intestine": {"shape": {"center": [0, 0, -0.1]}},
        "collision": {"stiffness": 100},
        "environment": [{"type": "plane", "normal": [0, 0, 1]}]})";
    EXPECT_NO_THROW(load_scene_json(soft.data(), soft.size()));
    // ...but not with the default 500 N/m.
    EXPECT_TRUE(contains(json_error(R"({"intestine": {"shape": {"center": [0, 0, -0.1]}},
        "environment": [{"type": "plane", "normal": [0, 0, 1]}]})"), "(plane) has control points"));
}

TEST(Validate, TheConfigReturnedIsNormalised) {
    SceneConfig config;
    config.intestine.control_points = 10;
    config.intestine.length = 0.5;
    collision::ToolConfig tool;
    tool.pose.orientation = {2.0, 0.0, 0.0, 0.0};
    config.tools.push_back(tool);
    const SceneConfig valid = validate(config, json_field_names());
    EXPECT_EQ(valid.tools[0].pose.orientation, (std::array<double, 4>{1.0, 0.0, 0.0, 0.0}));
    std::vector<double> expected(30);
    build_shape(config.intestine.shape, config.intestine.length, 10, expected.data());
    EXPECT_EQ(valid.start_points, expected);

    const collision::ToolPose unit = validate_tool_pose(tool.pose, "", c_field_names());
    EXPECT_EQ(unit.orientation[0], 1.0);
    tool.pose.orientation = {0.0, 0.0, 0.0, 0.0};
    try {
        validate_tool(tool, "", c_field_names());
        ADD_FAILURE() << "a zero quaternion was accepted";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::invalid_argument);
        EXPECT_EQ(std::string(error.what()).rfind("orientation_wxyz must be a non-zero quaternion", 0), 0u);
    }
}

TEST(Validate, TheNamesAndCodesOfJsonAndC) {
    EXPECT_EQ(json_field_names().code, ErrorCode::invalid_scene);
    EXPECT_EQ(c_field_names().code, ErrorCode::invalid_argument);
    EXPECT_EQ(json_field_names().obstacle(2), "environment[2]");
    EXPECT_EQ(c_field_names().obstacle(2), "obstacle[2]");
}

TEST(Validate, DefaultConfigWithEveryEffectIsValid) {
    SceneConfig config;
    config.intestine.stretch_stiffness = 100.0;
    config.intestine.bend_stiffness = 2.5e-3;
    config.gravity = Vec3{0.0, 0.0, -9.81};
    config.damping.emplace();
    config.mesentery.emplace();
    config.pinned.emplace();
    EXPECT_NO_THROW(validate(config, c_field_names()));
    EXPECT_NO_THROW(validate(config, json_field_names()));
}

TEST(Validate, CNamesAndCode) {
    SceneConfig config;
    config.intestine.radius = -1.0;
    const Error error = validate_error(config, c_field_names());
    EXPECT_EQ(error.code(), ErrorCode::invalid_argument);
    EXPECT_STREQ(error.what(), "radius_m must be > 0, got -1");

    SceneConfig helix;
    helix.intestine.shape.helix_pitch = 0.001;
    EXPECT_STREQ(validate_error(helix, c_field_names()).what(),
                 "shape_helix_pitch_m must be >= 2 x radius_m (0.025), got 0.001");

    SceneConfig pinned;
    pinned.pinned = PinnedConfig{pin_both, {1, 2, 240}, {}};
    EXPECT_STREQ(validate_error(pinned, c_field_names()).what(),
                 "pinned_points[2] must be < control_points (240), got 240");
}

TEST(Validate, NonFiniteNumbersAreNamed) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    SceneConfig length;
    length.intestine.length = nan;
    EXPECT_STREQ(validate_error(length, c_field_names()).what(), "length_m must be finite, got nan");
    EXPECT_STREQ(validate_error(length, json_field_names()).what(), "intestine.length must be finite, got nan");

    SceneConfig gravity;
    gravity.gravity = Vec3{0.0, -inf, 0.0};
    EXPECT_STREQ(validate_error(gravity, c_field_names()).what(),
                 "gravity_m_per_s2[1] must be finite, got -inf");

    SceneConfig root;
    root.mesentery.emplace().root_end[2] = inf;
    EXPECT_STREQ(validate_error(root, json_field_names()).what(),
                 "mesentery.root_end[2] must be finite, got inf");
    SceneConfig polyline;
    polyline.mesentery.emplace().root_points = {0.0, 0.0, 0.0, 0.05, 0.0, 0.0, 0.1, inf, 0.0};
    // Given as a C description gives it: root_start and root_end left at their defaults.
    for (const auto& [names, message] :
         {std::pair{&json_field_names(), "mesentery.root[2][1] must be finite, got inf"},
          std::pair{&c_field_names(), "mesentery_root_points_m[7] must be finite, got inf"}}) {
        try {
            validate(polyline, *names, fields_apart_from_defaults(polyline));
            ADD_FAILURE() << "validate raised no error";
        } catch (const Error& error) {
            EXPECT_STREQ(error.what(), message);
        }
    }

    SceneConfig stretch;
    stretch.intestine.stretch_stiffness = inf;
    EXPECT_STREQ(validate_error(stretch, c_field_names()).what(),
                 "stretch_stiffness_N must be finite, got inf");

    SceneConfig timestep;
    timestep.solver.timestep = nan;
    EXPECT_STREQ(validate_error(timestep, json_field_names()).what(),
                 "solver.timestep must be finite, got nan");
}

TEST(Validate, PointsAreNamedPerPointInJsonAndFlatInC) {
    SceneConfig config;
    config.intestine.length = 0.5;
    config.intestine.control_points = 4;
    config.intestine.shape.kind = ShapeKind::points;
    config.intestine.shape.points = {0, 0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0};
    EXPECT_NO_THROW(validate(config, c_field_names()));

    config.intestine.shape.points[4] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_STREQ(validate_error(config, c_field_names()).what(),
                 "shape_points_xyz_m[4] must be finite, got nan");
    EXPECT_STREQ(validate_error(config, json_field_names()).what(),
                 "intestine.shape.points[1][1] must be finite, got nan");

    config.intestine.shape.points.resize(9);
    EXPECT_STREQ(validate_error(config, c_field_names()).what(),
                 "shape_points_xyz_m must hold 12 values (control_points x 3), got 9");
}

TEST(Validate, EnumsOutOfRangeFromC) {
    SceneConfig shape;
    shape.intestine.shape.kind = static_cast<ShapeKind>(7);
    EXPECT_STREQ(validate_error(shape, c_field_names()).what(), "shape must be <= 3, got 7");

    SceneConfig integrator;
    integrator.solver.integrator = static_cast<IntegratorKind>(-1);
    EXPECT_STREQ(validate_error(integrator, c_field_names()).what(), "integrator must be >= 0, got -1");

    SceneConfig pinned;
    pinned.pinned = PinnedConfig{4, {}, {}};
    EXPECT_STREQ(validate_error(pinned, c_field_names()).what(), "pinned_ends must be <= 3, got 4");
}

TEST(Validate, UnusedShapeFieldsAreNotChecked) {
    SceneConfig config;  // a helix: the line and serpentine fields are never read
    config.intestine.shape.direction = {0.0, 0.0, 0.0};
    config.intestine.shape.leg_spacing = -1.0;
    EXPECT_NO_THROW(validate(config, c_field_names()));
    config.intestine.shape.kind = ShapeKind::line;
    EXPECT_STREQ(validate_error(config, c_field_names()).what(),
                 "shape_direction must be non-zero, got [0, 0, 0]");
}

}  // namespace
}  // namespace enteron::scene
