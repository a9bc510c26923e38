// SPDX-License-Identifier: Apache-2.0
// The JSON v1 loader (lib/scene/json_loader.h): what a document turns into, and the exact
// error (code and message) for each kind of mistake.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "base/error.h"
#include "scene/json_loader.h"
#include "scene/validate.h"

namespace enteron::scene {
namespace {

SceneConfig load(const std::string& text) { return load_scene_json(text.data(), text.size()); }

// The error that loading text raises; a test failure if it raises none.
Error load_error(const std::string& text) {
    try {
        load(text);
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "no error for: " << text;
    return Error(ErrorCode::internal, "");
}

void expect_scene_error(const std::string& text, const std::string& message) {
    const Error error = load_error(text);
    EXPECT_EQ(error.code(), ErrorCode::invalid_scene) << text;
    EXPECT_EQ(std::string(error.what()), message) << text;
}

bool starts_with(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

// ---- documents that load -----------------------------------------------------------

TEST(JsonLoader, FullDocumentGivesEveryValue) {
    const SceneConfig c = load(R"({
      "version": 1,
      "intestine": {
        "length": 2.5, "radius": 0.01, "control_points": 80, "linear_density": 0.25,
        "stretch_stiffness": 120, "bend_stiffness": 0.002,
        "shape": { "kind": "helix", "center": [0.1, 0.2, 0.3], "helix_radius": 0.12, "helix_pitch": 0.04 }
      },
      "solver": { "integrator": "rk4", "timestep": 0.0005, "max_substeps": 200,
                  "max_subdivisions": 6, "max_speed": 20 },
      "gravity": [0, -9.81, 0],
      "damping": { "drag": 0.1, "stretch": 0.2, "bend": 0.001 },
      "mesentery": { "root": [[-0.1, 0, 0], [0.1, 0, 0.05]], "stiffness": 7.5, "attachments": 40,
                     "rest_length": 0.02 },
      "pinned": { "ends": "last", "control_points": [3, 40] }
    })");
    EXPECT_EQ(c.intestine.length, 2.5);
    EXPECT_EQ(c.intestine.radius, 0.01);
    EXPECT_EQ(c.intestine.control_points, 80u);
    EXPECT_EQ(c.intestine.linear_density, 0.25);
    EXPECT_EQ(c.intestine.stretch_stiffness, 120.0);
    EXPECT_EQ(c.intestine.bend_stiffness, 0.002);
    EXPECT_EQ(c.intestine.shape.kind, ShapeKind::helix);
    EXPECT_EQ(c.intestine.shape.center, (Vec3{0.1, 0.2, 0.3}));
    EXPECT_EQ(c.intestine.shape.helix_radius, 0.12);
    EXPECT_EQ(c.intestine.shape.helix_pitch, 0.04);
    EXPECT_EQ(c.solver.integrator, IntegratorKind::rk4);
    EXPECT_EQ(c.solver.timestep, 0.0005);
    EXPECT_EQ(c.solver.max_substeps, 200u);
    EXPECT_EQ(c.solver.max_subdivisions, 6u);
    EXPECT_EQ(c.solver.max_speed, 20.0);
    ASSERT_TRUE(c.gravity.has_value());
    EXPECT_EQ(*c.gravity, (Vec3{0.0, -9.81, 0.0}));
    ASSERT_TRUE(c.damping.has_value());
    EXPECT_EQ(c.damping->drag, 0.1);
    EXPECT_EQ(c.damping->stretch, 0.2);
    EXPECT_EQ(c.damping->bend, 0.001);
    ASSERT_TRUE(c.mesentery.has_value());
    EXPECT_EQ(c.mesentery->root_start, (Vec3{-0.1, 0.0, 0.0}));
    EXPECT_EQ(c.mesentery->root_end, (Vec3{0.1, 0.0, 0.05}));
    EXPECT_EQ(c.mesentery->stiffness, 7.5);
    EXPECT_EQ(c.mesentery->attachments, 40u);
    EXPECT_EQ(c.mesentery->rest_length, 0.02);
    ASSERT_TRUE(c.pinned.has_value());
    EXPECT_EQ(c.pinned->ends, pin_last);
    EXPECT_EQ(c.pinned->points, (std::vector<uint32_t>{3, 40}));
}

// The root as a polyline: its points kept, the segment read as its ends; two points are the
// segment itself, as are root_start and root_end; the mapping and the spans as written.
TEST(JsonLoader, TheFanMesenterysRootMappingAndSpans) {
    const SceneConfig fan = load(R"({"intestine": {"length": 1},
        "mesentery": {"root": [[-0.07, 0, 0], [0, 0.02, 0], [0.07, 0, 0.01]], "root_mapping": [[0, 0], [1, 1]]},
        "environment": [{"type": "plane"}],
        "pinned": {"spans": [{"from": 0.2, "to": 0.4}, {"from": 0.5, "to": 0.6, "obstacle": 0}]}})");
    EXPECT_EQ(fan.mesentery->root_points, (std::vector<double>{-0.07, 0, 0, 0, 0.02, 0, 0.07, 0, 0.01}));
    EXPECT_EQ(fan.mesentery->root_start, (Vec3{-0.07, 0.0, 0.0}));
    EXPECT_EQ(fan.mesentery->root_end, (Vec3{0.07, 0.0, 0.01}));
    EXPECT_EQ(fan.mesentery->root_mapping, (std::vector<double>{0, 0, 1, 1}));
    ASSERT_EQ(fan.pinned->spans.size(), 2u);
    EXPECT_EQ(fan.pinned->spans[0].from, 0.2);
    EXPECT_EQ(fan.pinned->spans[0].to, 0.4);
    EXPECT_FALSE(fan.pinned->spans[0].obstacle.has_value());
    EXPECT_EQ(fan.pinned->spans[1].obstacle, std::optional<std::size_t>(0));
    for (const char* segment : {R"({"mesentery": {"root": [[-0.1, 0, 0], [0.1, 0, 0.05]]}})",
                                R"({"mesentery": {"root_start": [-0.1, 0, 0], "root_end": [0.1, 0, 0.05]}})"}) {
        const SceneConfig c = load(segment);
        EXPECT_TRUE(c.mesentery->root_points.empty()) << segment;
        EXPECT_EQ(c.mesentery->root_start, (Vec3{-0.1, 0.0, 0.0})) << segment;
        EXPECT_EQ(c.mesentery->root_end, (Vec3{0.1, 0.0, 0.05})) << segment;
    }
}

TEST(JsonLoader, EmptyDocumentIsTheDefaultElasticBowelWithNoOtherEffect) {
    const SceneConfig c = load("{}");
    const SceneConfig defaults;
    // One set of defaults for JSON and C: the bowel is elastic unless told otherwise.
    EXPECT_EQ(c.intestine.stretch_stiffness, 100.0);
    EXPECT_EQ(c.intestine.bend_stiffness, 2.5e-3);
    EXPECT_FALSE(c.gravity.has_value());
    EXPECT_FALSE(c.damping.has_value());
    EXPECT_FALSE(c.mesentery.has_value());
    EXPECT_FALSE(c.pinned.has_value());
    EXPECT_EQ(c.intestine.length, defaults.intestine.length);
    EXPECT_EQ(c.intestine.radius, defaults.intestine.radius);
    EXPECT_EQ(c.intestine.control_points, defaults.intestine.control_points);
    EXPECT_EQ(c.intestine.shape.kind, defaults.intestine.shape.kind);
    EXPECT_EQ(c.solver.integrator, defaults.solver.integrator);
    EXPECT_EQ(c.solver.timestep, defaults.solver.timestep);
}

TEST(JsonLoader, EachPresentEffectTurnsOnAloneWithItsDefaults) {
    const SceneConfig damped = load(R"({"damping": {}})");
    ASSERT_TRUE(damped.damping.has_value());
    EXPECT_EQ(damped.damping->drag, DampingConfig{}.drag);
    EXPECT_EQ(damped.damping->stretch, DampingConfig{}.stretch);
    EXPECT_FALSE(damped.mesentery.has_value());
    EXPECT_FALSE(damped.gravity.has_value());

    const SceneConfig bent = load(R"({"intestine": {"stretch_stiffness": 0, "bend_stiffness": 0.003}})");
    EXPECT_EQ(bent.intestine.stretch_stiffness, 0.0);
    EXPECT_EQ(bent.intestine.bend_stiffness, 0.003);
    EXPECT_FALSE(bent.damping.has_value());

    const SceneConfig hung = load(R"({"mesentery": {"stiffness": 2}})");
    ASSERT_TRUE(hung.mesentery.has_value());
    EXPECT_EQ(hung.mesentery->attachments, MesenteryConfig{}.attachments);
    EXPECT_EQ(hung.mesentery->root_start, MesenteryConfig{}.root_start);

    const SceneConfig pinned = load(R"({"pinned": {}})");
    ASSERT_TRUE(pinned.pinned.has_value());
    EXPECT_EQ(pinned.pinned->ends, pin_none);
    EXPECT_TRUE(pinned.pinned->points.empty());
}

TEST(JsonLoader, LineAndSerpentineShapes) {
    const SceneConfig line = load(R"({"intestine": {"shape": {"kind": "line", "center": [1, 2, 3],
                                                              "direction": [0, 0, -2]}}})");
    EXPECT_EQ(line.intestine.shape.kind, ShapeKind::line);
    EXPECT_EQ(line.intestine.shape.center, (Vec3{1.0, 2.0, 3.0}));
    EXPECT_EQ(line.intestine.shape.direction, (Vec3{0.0, 0.0, -2.0}));

    const SceneConfig serpentine = load(R"({"intestine": {"shape": {"kind": "serpentine",
                                                                    "leg_length": 0.4, "leg_spacing": 0.06}}})");
    EXPECT_EQ(serpentine.intestine.shape.kind, ShapeKind::serpentine);
    EXPECT_EQ(serpentine.intestine.shape.leg_length, 0.4);
    EXPECT_EQ(serpentine.intestine.shape.leg_spacing, 0.06);
}

TEST(JsonLoader, IntegratorsAndPinnedEndsByName) {
    EXPECT_EQ(load(R"({"solver": {"integrator": "symplectic_euler"}})").solver.integrator,
              IntegratorKind::symplectic_euler);
    EXPECT_EQ(load(R"({"solver": {"integrator": "implicit_euler"}})").solver.integrator,
              IntegratorKind::implicit_euler);
    EXPECT_EQ(load(R"({"pinned": {"ends": "first"}})").pinned->ends, pin_first);
    EXPECT_EQ(load(R"({"pinned": {"ends": "both"}})").pinned->ends, pin_both);
    EXPECT_EQ(load(R"({"pinned": {"clamped": "last"}})").pinned->clamped, pin_last);
    EXPECT_EQ(load(R"({"pinned": {"ends": "first", "clamped": "both"}})").pinned->clamped, pin_both);
    EXPECT_EQ(load(R"({"pinned": {}})").pinned->clamped, pin_none);
}

TEST(JsonLoader, PointsShapeSetsControlPointCount) {
    const SceneConfig c = load(R"({"intestine": {"length": 0.5, "shape": {"kind": "points",
        "points": [[0, 0, 0], [0.1, 0, 0], [0.2, 0, 0], [0.3, 0, 0], [0.4, 0, 0.5]]}}})");
    EXPECT_EQ(c.intestine.control_points, 5u);
    EXPECT_EQ(c.intestine.shape.points,
              (std::vector<double>{0, 0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0, 0.4, 0, 0.5}));
}

TEST(JsonLoader, IntegralFloatsCountAsIntegers) {
    EXPECT_EQ(load(R"({"intestine": {"control_points": 1e2}})").intestine.control_points, 100u);
    EXPECT_EQ(load(R"({"intestine": {"control_points": 80.0}})").intestine.control_points, 80u);
}

TEST(JsonLoader, ReadsOnlyTheGivenLength) {
    // The buffer goes on past the document; only `length` bytes belong to it.
    const std::string text = R"({"intestine": {"control_points": 12}})";
    std::vector<char> buffer(text.begin(), text.end());
    const std::string tail = R"(, "garbage": })";
    buffer.insert(buffer.end(), tail.begin(), tail.end());  // and no NUL anywhere
    EXPECT_EQ(load_scene_json(buffer.data(), text.size()).intestine.control_points, 12u);

    // Cut short, the same bytes are not a document; the error is at its end.
    const Error error = [&] {
        try {
            load_scene_json(buffer.data(), text.size() - 1);
        } catch (const Error& e) {
            return e;
        }
        return Error(ErrorCode::internal, "no error");
    }();
    EXPECT_EQ(error.code(), ErrorCode::parse);
    EXPECT_TRUE(starts_with(error.what(), "JSON parse error at byte " + std::to_string(text.size()) + " "))
        << error.what();
}

// ---- parse errors ------------------------------------------------------------------

TEST(JsonLoader, ParseErrorGivesByteLineAndColumn) {
    const Error error = load_error("{,}");
    EXPECT_EQ(error.code(), ErrorCode::parse);
    EXPECT_EQ(std::string(error.what()),
              "JSON parse error at byte 2 (line 1, column 2): syntax error while parsing object key - "
              "unexpected ','; expected string literal");

    const std::string text = "{\n  \"solver\": {\"timestep\": 0.001,}\n}";
    const Error second_line = load_error(text);
    EXPECT_EQ(second_line.code(), ErrorCode::parse);
    const std::size_t brace = text.find(",}") + 2;  // the byte where the parser gives up, from 1
    EXPECT_TRUE(starts_with(second_line.what(),
                            "JSON parse error at byte " + std::to_string(brace) + " (line 2, column "))
        << second_line.what();
}

TEST(JsonLoader, EmptyAndNullInput) {
    EXPECT_EQ(load_error("").code(), ErrorCode::parse);
    EXPECT_TRUE(starts_with(load_error("").what(), "JSON parse error at byte 1 "));
    EXPECT_EQ(load_error("   ").code(), ErrorCode::parse);
    try {
        load_scene_json(nullptr, 0);
        ADD_FAILURE() << "null empty input loaded";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::parse);
    }
    try {
        load_scene_json(nullptr, 5);
        ADD_FAILURE() << "null input loaded";
    } catch (const Error& error) {
        EXPECT_EQ(error.code(), ErrorCode::invalid_argument);
    }
}

TEST(JsonLoader, NumberTooLargeForADoubleIsAParseError) {
    const Error error = load_error(R"({"intestine": {"length": 1e400}})");
    EXPECT_EQ(error.code(), ErrorCode::parse);
    EXPECT_NE(std::string(error.what()).find("1e400"), std::string::npos) << error.what();
}

// ---- unknown, reserved and repeated keys --------------------------------------------

TEST(JsonLoader, UnknownKeysAtEveryLevel) {
    const std::string top = load_error(R"({"foo": 1})").what();
    EXPECT_TRUE(starts_with(top, "unknown key \"foo\" at the top level (expected one of: version, intestine,"))
        << top;
    expect_scene_error(R"({"intestine": {"lenght": 2}})",
                       "unknown key \"lenght\" in intestine (expected one of: length, radius, radius_profile, "
                       "control_points, linear_density, linear_density_profile, stretch_stiffness, "
                       "stretch_stiffness_profile, bend_stiffness, bend_stiffness_profile, shape)");
    const char* const nested[][2] = {
        {R"({"intestine": {"shape": {"foo": 1}}})", "unknown key \"foo\" in intestine.shape "},
        {R"({"solver": {"foo": 1}})", "unknown key \"foo\" in solver "},
        {R"({"damping": {"foo": 1}})", "unknown key \"foo\" in damping "},
        {R"({"mesentery": {"foo": 1}})", "unknown key \"foo\" in mesentery "},
        {R"({"pinned": {"foo": 1}})", "unknown key \"foo\" in pinned "},
    };
    for (const auto& [text, prefix] : nested) {
        const Error error = load_error(text);
        EXPECT_EQ(error.code(), ErrorCode::invalid_scene);
        EXPECT_TRUE(starts_with(error.what(), prefix)) << error.what();
    }
}

TEST(JsonLoader, LongKeysAndStringsAreShortenedInMessages) {
    const std::string key(10000, 'k');
    const std::string message = load_error("{\"" + key + "\": 1}").what();
    EXPECT_LT(message.size(), 400u);
    EXPECT_NE(message.find("kkk...\" at the top level"), std::string::npos) << message;

    // Never cut inside a UTF-8 sequence: 59 ASCII bytes, then 3-byte characters.
    std::string text(59, 'a');
    for (int i = 0; i < 10; ++i) text += "\xE2\x82\xAC";  // the euro sign
    expect_scene_error("{\"intestine\": {\"length\": \"" + text + "\"}}",
                       "intestine.length must be a number, got \"" + std::string(59, 'a') + "...\"");
}

TEST(JsonLoader, ToolsGiveEveryValue) {
    const SceneConfig c = load(R"({
      "tools": [
        { "radius": 0.004, "length": 0.25, "max_force": 7, "grasp_margin": 0.003,
          "grasp_stiffness": 150, "grasp_damping": 1.5, "position": [0.1, 0.2, 0.3],
          "orientation": [0, 1, 0, 0] },
        {}
      ]})");
    ASSERT_EQ(c.tools.size(), 2u);
    const collision::ToolConfig& t = c.tools[0];
    EXPECT_EQ(t.settings.radius, 0.004);
    EXPECT_EQ(t.settings.length, 0.25);
    EXPECT_EQ(t.settings.max_force, 7.0);
    EXPECT_EQ(t.settings.grasp_margin, 0.003);
    EXPECT_EQ(t.settings.grasp_stiffness, 150.0);
    EXPECT_EQ(t.settings.grasp_damping, 1.5);
    EXPECT_EQ(t.pose.position, (Vec3{0.1, 0.2, 0.3}));
    EXPECT_EQ(t.pose.orientation, (std::array<double, 4>{0.0, 1.0, 0.0, 0.0}));
    const collision::ToolConfig defaults;
    EXPECT_EQ(c.tools[1].settings.max_force, defaults.settings.max_force);
    EXPECT_EQ(c.tools[1].pose.orientation, defaults.pose.orientation);
    expect_scene_error(R"({"tools": [{"orientation": [1, 0, 0]}]})",
                       "tools[0].orientation must be an array of 4 numbers [w, x, y, z], got an array of 3 elements");
    expect_scene_error(R"({"tools": {}})", "tools must be an array of tools, got an object");
}

TEST(JsonLoader, CollisionAndEnvironmentGiveEveryValue) {
    using collision::ObstacleKind;
    // A short bowel that starts inside the box and above the plane.
    const SceneConfig c = load(R"({
      "intestine": { "length": 0.05, "shape": { "kind": "line", "center": [0.1, 0.2, 0.3] } },
      "collision": { "sphere_spacing": 0.005, "stiffness": 800, "damping": 0.7, "friction": 0.4,
                     "slip_speed": 0.02 },
      "environment": [
        { "type": "box_inside", "center": [0.1, 0.2, 0.3], "half_extents": [0.11, 0.12, 0.13] },
        { "type": "plane", "point": [1, 2, 0.2], "normal": [0, 0, 2] },
        { "type": "sphere", "center": [4, 5, 6], "radius": 0.07 },
        { "type": "capsule", "start": [7, 8, 9], "end": [10, 11, 12], "radius": 0.03 }
      ]
    })");
    EXPECT_EQ(c.collision.sphere_spacing, 0.005);
    EXPECT_EQ(c.collision.contact.stiffness, 800.0);
    EXPECT_EQ(c.collision.contact.damping, 0.7);
    EXPECT_EQ(c.collision.contact.friction, 0.4);
    EXPECT_EQ(c.collision.contact.slip_speed, 0.02);
    ASSERT_EQ(c.environment.size(), 4u);
    EXPECT_EQ(c.environment[0].kind, ObstacleKind::box_inside);
    EXPECT_EQ(c.environment[0].center, (Vec3{0.1, 0.2, 0.3}));
    EXPECT_EQ(c.environment[0].extent, (Vec3{0.11, 0.12, 0.13}));
    EXPECT_EQ(c.environment[1].kind, ObstacleKind::plane);
    EXPECT_EQ(c.environment[1].center, (Vec3{1, 2, 0.2}));
    EXPECT_EQ(c.environment[1].extent, (Vec3{0, 0, 2}));  // normalised when the scene is built
    EXPECT_EQ(c.environment[2].kind, ObstacleKind::sphere);
    EXPECT_EQ(c.environment[2].center, (Vec3{4, 5, 6}));
    EXPECT_EQ(c.environment[2].radius, 0.07);
    EXPECT_EQ(c.environment[3].kind, ObstacleKind::capsule);
    EXPECT_EQ(c.environment[3].center, (Vec3{7, 8, 9}));
    EXPECT_EQ(c.environment[3].extent, (Vec3{10, 11, 12}));
    EXPECT_EQ(c.environment[3].radius, 0.03);

    // Absent: the defaults of scene_config.h and contact_model.h, and no obstacle.
    const SceneConfig d = load("{}");
    EXPECT_EQ(d.collision.sphere_spacing, 0.0);
    EXPECT_EQ(d.collision.contact.stiffness, 500.0);
    EXPECT_EQ(d.collision.contact.damping, 0.5);
    EXPECT_EQ(d.collision.contact.friction, 0.3);
    EXPECT_EQ(d.collision.contact.slip_speed, 0.01);
    EXPECT_TRUE(d.environment.empty());
}

TEST(JsonLoader, RepeatedKeysAreRejected) {
    expect_scene_error(R"({"intestine": {"radius": 0.01, "radius": 0.02}})",
                       "duplicate key \"radius\" in intestine");
    expect_scene_error(R"({"gravity": [0, 0, -9.81], "gravity": [0, 0, 0]})",
                       "duplicate key \"gravity\" at the top level");
    // Found while parsing, so even inside arrays of objects the place is exact.
    expect_scene_error(R"({"x": [{"a": 1}, [2, {"a": 1}], {"b": 1, "b": 2}]})", "duplicate key \"b\" in x[2]");
}

TEST(JsonLoader, VersionMustBeOne) {
    EXPECT_NO_THROW(load(R"({"version": 1})"));
    expect_scene_error(R"({"version": 2})", "version must be 1, got 2");
    expect_scene_error(R"({"version": "1"})", "version must be 1, got \"1\"");
}

// ---- wrong types ---------------------------------------------------------------------

TEST(JsonLoader, WrongTypesNameThePath) {
    const char* const cases[][2] = {
        {R"({"intestine": {"control_points": "ten"}})",
         "intestine.control_points must be an integer, got \"ten\""},
        {R"({"intestine": {"control_points": 2.5}})", "intestine.control_points must be an integer, got 2.5"},
        {R"({"intestine": {"control_points": -3}})",
         "intestine.control_points must be a non-negative integer, got -3"},
        {R"({"intestine": {"length": "2"}})", "intestine.length must be a number, got \"2\""},
        {R"({"intestine": {"radius": true}})", "intestine.radius must be a number, got true"},
        {R"({"intestine": {"radius": null}})", "intestine.radius must be a number, got null"},
        {R"({"intestine": 5})", "intestine must be an object, got 5"},
        {R"([])", "the scene must be an object, got an array of 0 elements"},
        {R"({"intestine": {"shape": {"kind": "spiral"}}})",
         "intestine.shape.kind must be one of \"line\", \"serpentine\", \"helix\", \"points\", got \"spiral\""},
        {R"({"intestine": {"shape": {"kind": 2}}})",
         "intestine.shape.kind must be one of \"line\", \"serpentine\", \"helix\", \"points\", got 2"},
        {R"({"intestine": {"shape": {"kind": "points", "points": [[0, 0, 0], [1, 2]]}}})",
         "intestine.shape.points[1] must be an array of 3 numbers [x, y, z], got an array of 2 elements"},
        {R"({"intestine": {"shape": {"kind": "points", "points": {"a": 1}}}})",
         "intestine.shape.points must be an array of [x, y, z] points, got an object"},
        {R"({"solver": {"integrator": "rk5"}})",
         "solver.integrator must be one of \"rk4\", \"symplectic_euler\", \"implicit_euler\", \"bdf2\", got \"rk5\""},
        {R"({"solver": {"max_substeps": [1]}})",
         "solver.max_substeps must be an integer, got an array of 1 element"},
        {R"({"gravity": [0, 0]})",
         "gravity must be an array of 3 numbers [x, y, z], got an array of 2 elements"},
        {R"({"gravity": [0, "x", 0]})", "gravity[1] must be a number, got \"x\""},
        {R"({"damping": []})", "damping must be an object, got an array of 0 elements"},
        {R"({"mesentery": {"root": [[0, 0, 0]]}})",
         "mesentery.root must have at least 2 points (the root's ends), got 1"},
        {R"({"mesentery": {"root": [[0, 0, 0], [1, 1, {}]]}})",
         "mesentery.root[1][2] must be a number, got an object"},
        {R"({"pinned": {"ends": "middle"}})",
         "pinned.ends must be one of \"none\", \"first\", \"last\", \"both\", got \"middle\""},
        {R"({"pinned": {"clamped": "middle"}})",
         "pinned.clamped must be one of \"none\", \"first\", \"last\", \"both\", got \"middle\""},
        {R"({"pinned": {"control_points": [1, -2]}})",
         "pinned.control_points[1] must be a non-negative integer, got -2"},
        {R"({"pinned": {"control_points": 3}})",
         "pinned.control_points must be an array of control point indices, got 3"},
    };
    for (const auto& [text, message] : cases) expect_scene_error(text, message);
}

TEST(JsonLoader, ShapeKeysMustFitTheKind) {
    expect_scene_error(R"({"intestine": {"shape": {"kind": "line", "helix_radius": 0.1}}})",
                       "intestine.shape.helix_radius does not apply to kind \"line\"");
    // Without a kind the shape is the default helix.
    expect_scene_error(R"({"intestine": {"shape": {"leg_length": 0.3}}})",
                       "intestine.shape.leg_length does not apply to kind \"helix\"");
    expect_scene_error(R"({"intestine": {"shape": {"kind": "points", "center": [0, 0, 0]}}})",
                       "intestine.shape.center does not apply to kind \"points\"");
}

// ---- huge counts ---------------------------------------------------------------------

TEST(JsonLoader, HugeCountsAreRejectedWithTheirPath) {
    expect_scene_error(R"({"intestine": {"control_points": 1e30}})",
                       "intestine.control_points must be <= 18446744073709551615, got 1e+30");
    expect_scene_error(R"({"intestine": {"control_points": 18446744073709551615}})",
                       "intestine.control_points must be <= 100000, got 18446744073709551615");
    expect_scene_error(R"({"intestine": {"control_points": 100001}})",
                       "intestine.control_points must be <= 100000, got 100001");
    expect_scene_error(R"({"solver": {"max_substeps": 1e7}})",
                       "solver.max_substeps must be <= 1000000, got 10000000");
    expect_scene_error(R"({"mesentery": {"attachments": 100001}})",
                       "mesentery.attachments must be <= 100000, got 100001");
    expect_scene_error(R"({"pinned": {"control_points": [5000000000]}})",
                       "pinned.control_points[0] must be <= 4294967295, got 5000000000");
    EXPECT_EQ(load(R"({"intestine": {"control_points": 100000}})").intestine.control_points, 100000u);
}

// ---- validation ----------------------------------------------------------------------

TEST(JsonLoader, RadiusMessageIsExact) {
    const Error error = load_error(R"({"intestine": {"radius": -1}})");
    EXPECT_EQ(error.code(), ErrorCode::invalid_scene);
    EXPECT_STREQ(error.what(), "intestine.radius must be > 0, got -1");
}

TEST(JsonLoader, ValuesOutOfRangeNameThePathAndTheLimit) {
    const char* const cases[][2] = {
        {R"({"intestine": {"length": 0}})", "intestine.length must be > 0, got 0"},
        {R"({"intestine": {"length": 1000.5}})", "intestine.length must be <= 1000, got 1000.5"},
        {R"({"intestine": {"length": 1, "radius": 1}})",
         "intestine.radius must be < intestine.length (1), got 1"},
        {R"({"intestine": {"control_points": 3}})", "intestine.control_points must be >= 4, got 3"},
        {R"({"intestine": {"linear_density": 0}})", "intestine.linear_density must be > 0, got 0"},
        {R"({"intestine": {"stretch_stiffness": -5}})", "intestine.stretch_stiffness must be >= 0, got -5"},
        {R"({"intestine": {"bend_stiffness": -1e-3}})", "intestine.bend_stiffness must be >= 0, got -0.001"},
        {R"({"intestine": {"shape": {"kind": "line", "direction": [0, 0, 0]}}})",
         "intestine.shape.direction must be non-zero, got [0, 0, 0]"},
        {R"({"intestine": {"shape": {"kind": "line", "direction": [1e200, 0, 0]}}})",
         "intestine.shape.direction must have a length between 1e-150 and 1e150, got [1e+200, 0, 0]"},
        {R"({"intestine": {"shape": {"kind": "serpentine", "leg_length": 0}}})",
         "intestine.shape.leg_length must be > 0, got 0"},
        {R"({"intestine": {"radius": 0.01, "shape": {"kind": "serpentine", "leg_spacing": 0.015}}})",
         "intestine.shape.leg_spacing must be >= 2 x intestine.radius (0.02), got 0.015"},
        {R"({"intestine": {"shape": {"helix_radius": -0.1}}})",
         "intestine.shape.helix_radius must be > 0, got -0.1"},
        // A size whose square overflows left the helix no points to place: the scene hung.
        {R"({"intestine": {"shape": {"helix_radius": 1e200}}})",
         "intestine.shape.helix_radius must be <= 1000, got 1e+200"},
        {R"({"intestine": {"shape": {"helix_pitch": 1e300}}})",
         "intestine.shape.helix_pitch must be <= 1000, got 1e+300"},
        {R"({"intestine": {"shape": {"kind": "serpentine", "leg_length": 1001}}})",
         "intestine.shape.leg_length must be <= 1000, got 1001"},
        {R"({"intestine": {"radius": 0.0125, "shape": {"helix_pitch": 0.01}}})",
         "intestine.shape.helix_pitch must be >= 2 x intestine.radius (0.025), got 0.01"},
        {R"({"intestine": {"control_points": 5, "shape": {"kind": "points",
             "points": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]}}})",
         "intestine.shape.points must hold 5 points (intestine.control_points), got 4"},
        {R"({"intestine": {"shape": {"kind": "points", "points": [[0, 0, 0], [1, 0, 0]]}}})",
         "intestine.control_points must be >= 4, got 2"},
        {R"({"solver": {"timestep": 0}})", "solver.timestep must be > 0, got 0"},
        {R"({"solver": {"timestep": 0.30000000000000004}})",
         "solver.timestep must be <= 0.1, got 0.30000000000000004"},
        {R"({"solver": {"max_substeps": 0}})", "solver.max_substeps must be >= 1, got 0"},
        {R"({"solver": {"max_subdivisions": 31}})", "solver.max_subdivisions must be <= 30, got 31"},
        {R"({"solver": {"max_speed": -2}})", "solver.max_speed must be > 0, got -2"},
        {R"({"damping": {"drag": -1}})", "damping.drag must be >= 0, got -1"},
        {R"({"damping": {"stretch": -1}})", "damping.stretch must be >= 0, got -1"},
        {R"({"damping": {"bend": -1}})", "damping.bend must be >= 0, got -1"},
        {R"({"mesentery": {"attachments": 0}})", "mesentery.attachments must be >= 1, got 0"},
        {R"({"mesentery": {"stiffness": -1}})", "mesentery.stiffness must be >= 0, got -1"},
        {R"({"mesentery": {"rest_length": -0.5}})", "mesentery.rest_length must be >= 0, got -0.5"},
        {R"({"intestine": {"control_points": 80}, "pinned": {"control_points": [0, 80]}})",
         "pinned.control_points[1] must be < intestine.control_points (80), got 80"},
        {R"({"intestine": {"control_points": 5}, "pinned": {"clamped": "both"}})",
         "pinned.clamped clamps both ends, which needs at least 6 control points (intestine.control_points is 5)"},
        {R"({"pinned": {"clamped": "first", "control_points": [2]}})",
         "pinned.control_points[0] is 2, a control point whose motion the clamped first end already constrains "
         "(pinned.clamped): a point pin there would fight the clamp; remove it"},
        // The fan mesentery's root and mapping, and the pinned spans.
        {R"({"mesentery": {"root": [[0, 0, 0], [0.1, 0, 0], [0.1, 0, 0]]}})",
         "mesentery.root[2] is the point before it again, [0.1, 0, 0]: each segment of a root of more than 2 points "
         "needs a length"},
        {R"({"mesentery": {"root": [[0, 0, 0], [0.1, 0, 0]], "root_end": [0.1, 0, 0]}})",
         "mesentery.root and mesentery.root_end are both given: the root is a polyline or the segment from its start "
         "to its end, give one of them"},
        {R"({"mesentery": {"root_mapping": [[0, 0]]}})",
         "mesentery.root_mapping must have at least 2 pairs [s, t] (s along the bowel in m, t the fraction of the "
         "root's length), got 1"},
        {R"({"mesentery": {"root_mapping": [[0, 0], [0, 0.5]]}})",
         "mesentery.root_mapping[1][0] must be greater than the s before it (0): s must increase along the mapping, "
         "got 0"},
        {R"({"mesentery": {"root_mapping": [[0, 0], [6, 1.5]]}})",
         "mesentery.root_mapping[1][1] must be in [0, 1], a fraction of the root's length, got 1.5"},
        {R"({"mesentery": {"root_mapping": [[0, -0.1], [6, 1]]}})",
         "mesentery.root_mapping[0][1] must be in [0, 1], a fraction of the root's length, got -0.1"},
        {R"({"mesentery": {"root_mapping": [[0, 0.5], [6, 0.2]]}})",
         "mesentery.root_mapping[1][1] must be >= the t before it (0.5): the bowel's order along the root must not "
         "turn back, got 0.2"},
        {R"({"pinned": {"spans": [{"from": 0.5, "to": 0.2}]}})",
         "pinned.spans[0].to must be >= pinned.spans[0].from (0.5), got 0.2"},
        {R"({"pinned": {"spans": [{"from": -1, "to": 0.2}]}})", "pinned.spans[0].from must be >= 0, got -1"},
        {R"({"pinned": {"spans": [{"from": 5, "to": 6.5}]}})",
         "pinned.spans[0].to must be <= intestine.length (6): a span lies along the bowel, got 6.5"},
        {R"({"intestine": {"length": 1, "control_points": 11}, "pinned": {"spans": [{"from": 0.31, "to": 0.39}]}})",
         "pinned.spans[0] holds no control point: they lie every 0.1 m along the bowel at rest, and none in [0.31, "
         "0.39]; widen the span"},
        {R"({"pinned": {"spans": [{"from": 0, "to": 1, "obstacle": 0}]}})",
         "pinned.spans[0].obstacle must be < the number of obstacles (0), got 0"},
        {R"({"pinned": {"clamped": "last", "spans": [{"from": 5, "to": 6}]}})",
         "pinned.spans[0] holds control point 237, which the clamped last end (pinned.clamped) already moves: a pin "
         "there would fight the clamp; end the span before it"},
        {R"({"pinned": {"spans": [{"from": 0}]}})",
         "pinned.spans[0] must be an object with \"from\" and \"to\", got an object"},
    };
    for (const auto& [text, message] : cases) expect_scene_error(text, message);
}

TEST(JsonLoader, BoundaryValuesAreAccepted) {
    EXPECT_NO_THROW(load(R"({"intestine": {"length": 1000, "control_points": 4, "stretch_stiffness": 0},
                            "solver": {"timestep": 0.1, "max_substeps": 1, "max_subdivisions": 30},
                            "mesentery": {"attachments": 1, "stiffness": 0, "rest_length": 0},
                            "pinned": {"control_points": [3]}})"));
    EXPECT_NO_THROW(
        load(R"({"intestine": {"radius": 0.01, "shape": {"kind": "serpentine", "leg_spacing": 0.02}}})"));
}

}  // namespace
}  // namespace enteron::scene
