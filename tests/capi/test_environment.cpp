// SPDX-License-Identifier: Apache-2.0
// The environment through the C API: the abdominal cavity (box_inside), planes, spheres and
// capsules keep the bowel out; obstacles come from JSON ("environment") or
// ent_scene_add_obstacle; the effect costs nothing until the first obstacle; bad obstacles
// are refused with a message naming the field and change nothing.
#include "capi_test_support.h"

#include <functional>
#include <limits>

#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::contains;
using enteron_test::kNaN;
using enteron_test::all_finite;

constexpr double kEnvironmentRadius = 0.0125;  // the default R, m
constexpr double kEnvironmentGravity = 9.81;   // m/s^2


std::vector<double> environment_axis(const ent_scene* scene, uint32_t count = 400) {
    std::vector<double> points(3 * std::size_t{count});
    EXPECT_EQ(ent_scene_axis(scene, count, points.data()), ENT_OK) << ent_last_error();
    return points;
}

double lowest_z(const std::vector<double>& points) {
    double z = 1e300;
    for (std::size_t i = 2; i < points.size(); i += 3) z = std::min(z, points[i]);
    return z;
}

// How far the axis reaches beyond the box shrunk by `margin` (m); <= 0 when inside.
double beyond_box(const std::vector<double>& points, const double center[3], const double half[3], double margin) {
    double worst = -1e300;
    for (std::size_t i = 0; i < points.size(); i += 3)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::fabs(points[i + c] - center[c]) - (half[c] - margin));
    return worst;
}

// Smallest distance from the axis to a segment (a sphere when start == end), m.
double distance_to_segment(const std::vector<double>& points, const double start[3], const double end[3]) {
    double axis_of[3], length2 = 0.0;
    for (int c = 0; c < 3; ++c) axis_of[c] = end[c] - start[c], length2 += axis_of[c] * axis_of[c];
    double best = 1e300;
    for (std::size_t i = 0; i < points.size(); i += 3) {
        double rel[3], t = 0.0;
        for (int c = 0; c < 3; ++c) rel[c] = points[i + c] - start[c], t += rel[c] * axis_of[c];
        t = length2 > 0.0 ? std::clamp(t / length2, 0.0, 1.0) : 0.0;
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) d2 += (rel[c] - t * axis_of[c]) * (rel[c] - t * axis_of[c]);
        best = std::min(best, std::sqrt(d2));
    }
    return best;
}

ent_obstacle_desc obstacle(int32_t kind) {
    ent_obstacle_desc desc;
    ent_obstacle_desc_default(&desc);
    desc.kind = kind;
    return desc;
}

ent_obstacle_desc environment_box(double half) {
    ent_obstacle_desc desc = obstacle(ENT_OBSTACLE_BOX_INSIDE);
    for (double& h : desc.half_extents_m) h = half;
    return desc;
}

int32_t environment_add(ent_scene* scene, const ent_obstacle_desc& desc) {
    int32_t id = -1;
    EXPECT_EQ(ent_scene_add_obstacle(scene, &desc, &id), ENT_OK) << ent_last_error();
    return id;
}

// A straight bowel along x, centred above the origin at height z, under gravity, damped.
ent_scene_desc line_desc(double length, uint32_t control_points, double z) {
    ent_scene_desc desc = default_desc();  // stretch 100 N, bend 2.5e-3 N m^2, damping, gravity
    desc.length_m = length;
    desc.control_points = control_points;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.5 * length;
    desc.shape_center_m[2] = z;
    return desc;
}

// ---- defaults -------------------------------------------------------------------------------

TEST(Environment, DefaultsMatchTheHeaderDocumentation) {
    ent_obstacle_desc o;
    std::memset(&o, 0xab, sizeof o);
    ent_obstacle_desc_default(&o);
    EXPECT_EQ(o.struct_size, sizeof o);
    EXPECT_EQ(o.kind, ENT_OBSTACLE_BOX_INSIDE);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(o.center_m[c], 0.0);
        EXPECT_EQ(o.half_extents_m[c], 0.12);
        EXPECT_EQ(o.start_m[c], 0.0);
    }
    EXPECT_EQ(o.normal[0], 0.0);
    EXPECT_EQ(o.normal[1], 0.0);
    EXPECT_EQ(o.normal[2], 1.0);
    EXPECT_EQ(o.end_m[0], 0.0);
    EXPECT_EQ(o.end_m[1], 0.0);
    EXPECT_EQ(o.end_m[2], 0.1);
    EXPECT_EQ(o.radius_m, 0.05);
    ent_obstacle_desc_default(nullptr);  // ignored

    const ent_scene_desc desc = default_desc();
    EXPECT_EQ(desc.collision_sphere_spacing_m, 0.0);
    EXPECT_EQ(desc.contact_stiffness_N_per_m, 500.0);
    EXPECT_EQ(desc.contact_damping_N_s_per_m, 0.5);
    EXPECT_EQ(desc.contact_friction, 0.3);
    EXPECT_EQ(desc.contact_slip_speed_m_per_s, 0.01);
    EXPECT_EQ(desc.effects & ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT), 0u);
}

// ---- the bowel stays out of the obstacles ---------------------------------------------------

TEST(Environment, ABowelDroppedIntoABoxStaysInside) {
    // 1.5 m in 60 control points, coiled as a serpentine 5 cm above the centre of a 24 cm
    // box. Its tight turns (radius ~R) hold about 3 J of bending energy, so it springs open
    // against the walls while it falls: a harder test than a gentle drop.
    const std::string json = R"({
        "intestine": { "length": 1.5, "control_points": 60,
                       "stretch_stiffness": 100, "bend_stiffness": 0.0025,
                       "shape": { "kind": "serpentine", "center": [0, 0, 0.05],
                                  "leg_length": 0.18, "leg_spacing": 0.026 } },
        "gravity": [0, 0, -9.81],
        "damping": {},
        "environment": [ { "type": "box_inside", "center": [0, 0, 0], "half_extents": [0.12, 0.12, 0.12] } ]
    })";
    ScenePtr scene = create_json(json);
    ASSERT_TRUE(scene);
    const double center[3] = {0, 0, 0}, half[3] = {0.12, 0.12, 0.12};
    ASSERT_LT(beyond_box(environment_axis(scene.get()), center, half, kEnvironmentRadius), 0.0) << "starts clear of the walls";
    double peak = 0.0;
    for (int i = 0; i < 2000; ++i) {  // 2 s
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        peak = std::max(peak, stats(scene.get()).max_penetration_m);
        if (i % 10 == 0) {
            // No tunnelling, even while it springs open: the axis never leaves the box
            // (the deepest contact was measured at 0.63 R during the first 0.1 s).
            const std::vector<double> points = environment_axis(scene.get());
            ASSERT_TRUE(all_finite(points)) << "step " << i;
            ASSERT_LT(beyond_box(points, center, half, 0.0), 0.0) << "step " << i;
        }
    }
    const ent_stats s = stats(scene.get());
    const std::vector<double> points = environment_axis(scene.get());
    ASSERT_TRUE(all_finite(points));
    EXPECT_LE(beyond_box(points, center, half, 0.75 * kEnvironmentRadius), 0.0);
    EXPECT_LT(s.max_penetration_m, 0.25 * kEnvironmentRadius);
    EXPECT_GT(s.contacts, 0u);
    EXPECT_LT(peak, kEnvironmentRadius);
    // It lies on the floor.
    EXPECT_LT(lowest_z(points), -0.12 + 1.25 * kEnvironmentRadius);
}

TEST(Environment, ABowelFallingOntoAPlaneStopsOnIt) {
    ScenePtr scene = create(line_desc(0.6, 24, 0.1));
    ASSERT_TRUE(scene);
    ent_obstacle_desc floor = obstacle(ENT_OBSTACLE_PLANE);
    floor.normal[2] = 2.5;  // not unit: the library normalises it
    EXPECT_EQ(environment_add(scene.get(), floor), 0);
    for (int i = 0; i < 1000; ++i) {
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        const std::vector<double> points = environment_axis(scene.get(), 100);
        ASSERT_TRUE(all_finite(points)) << "step " << i;
        // The impact was measured at 0.13 R deep.
        ASSERT_GE(lowest_z(points), 0.75 * kEnvironmentRadius) << "step " << i;
    }
    const std::vector<double> points = environment_axis(scene.get(), 100);
    for (std::size_t i = 2; i < points.size(); i += 3) {
        EXPECT_GE(points[i], 0.75 * kEnvironmentRadius);
        EXPECT_LE(points[i], 1.25 * kEnvironmentRadius) << "lying flat on the plane";
    }
    const ent_stats s = stats(scene.get());
    EXPECT_GT(s.contacts, 0u);
    EXPECT_LT(s.kinetic_energy_J, 1e-6) << "at rest";
}

// A straight bowel at rest on a plane carries its weight on its spheres: each sinks by the
// weight of its share of the axis over the stiffness, d = mu g s / k.
double resting_depth(ent_scene* scene) {
    if (!step_n(scene, 1e-3, 1000)) return -1.0;
    return stats(scene).max_penetration_m;
}

TEST(Environment, TheRestingDepthFollowsTheContactSettings) {
    const double mu = 0.3;  // default linear density, kg/m
    struct Case {
        double spacing, stiffness;  // 0: the defaults R / 2 and 500 N/m
    };
    for (const Case& c : {Case{0.0, 0.0}, Case{0.0, 100.0}, Case{kEnvironmentRadius, 0.0}}) {
        const double spacing = c.spacing > 0.0 ? c.spacing : 0.5 * kEnvironmentRadius;
        const double stiffness = c.stiffness > 0.0 ? c.stiffness : 500.0;
        const double expected = mu * kEnvironmentGravity * spacing / stiffness;
        SCOPED_TRACE("spacing " + std::to_string(spacing) + ", stiffness " + std::to_string(stiffness));

        ent_scene_desc desc = line_desc(0.6, 24, 0.02);
        if (c.spacing > 0.0) desc.collision_sphere_spacing_m = c.spacing;
        if (c.stiffness > 0.0) desc.contact_stiffness_N_per_m = c.stiffness;
        ScenePtr from_c = create(desc);
        ASSERT_TRUE(from_c);
        environment_add(from_c.get(), obstacle(ENT_OBSTACLE_PLANE));
        // The ends and the spline weights spread the load a little unevenly (2% measured).
        EXPECT_NEAR(resting_depth(from_c.get()), expected, 0.1 * expected) << "C description";

        std::string collision;
        if (c.spacing > 0.0) collision += "\"sphere_spacing\": " + std::to_string(c.spacing);
        if (c.stiffness > 0.0) {
            collision += (collision.empty() ? "" : ", ") + ("\"stiffness\": " + std::to_string(c.stiffness));
        }
        collision = "{" + collision + "}";
        ScenePtr from_json = create_json(R"({
            "intestine": { "length": 0.6, "control_points": 24, "stretch_stiffness": 100,
                           "bend_stiffness": 0.0025,
                           "shape": { "kind": "line", "center": [-0.3, 0, 0.02] } },
            "gravity": [0, 0, -9.81], "damping": {},
            "collision": )" + collision + R"(,
            "environment": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] } ] })");
        ASSERT_TRUE(from_json);
        EXPECT_NEAR(resting_depth(from_json.get()), expected, 0.1 * expected) << "JSON";
    }
}

struct Organ {
    const char* name;
    int32_t kind;
    double start[3], end[3];  // a sphere: start == end, its centre
    double radius;
};

// Drapes a 60 cm bowel over an organ lying on a floor and checks, step by step, that the
// axis never comes closer to the organ than radius + 0.75 R (penetration below R / 4).
void drape_over(const Organ& organ, bool from_json) {
    SCOPED_TRACE(std::string(organ.name) + (from_json ? " from JSON" : " from C"));
    const double top = organ.start[2] + organ.radius;
    ScenePtr scene;
    if (from_json) {
        const auto vec = [](const double v[3]) {
            return "[" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + "]";
        };
        const std::string shape = organ.kind == ENT_OBSTACLE_SPHERE
                                      ? R"("type": "sphere", "center": )" + vec(organ.start)
                                      : R"("type": "capsule", "start": )" + vec(organ.start) + R"(, "end": )" +
                                            vec(organ.end);
        const std::string json = R"({
            "intestine": { "length": 0.6, "control_points": 24, "stretch_stiffness": 100,
                           "bend_stiffness": 0.0025,
                           "shape": { "kind": "line", "center": [-0.3, 0, )" +
                                 std::to_string(top + kEnvironmentRadius + 0.03) + R"(] } },
            "gravity": [0, 0, -9.81], "damping": {},
            "environment": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1] },
                             { )" + shape + R"(, "radius": )" + std::to_string(organ.radius) + " } ] }";
        scene = create_json(json);
    } else {
        scene = create(line_desc(0.6, 24, top + kEnvironmentRadius + 0.03));
        if (scene) {
            EXPECT_EQ(environment_add(scene.get(), obstacle(ENT_OBSTACLE_PLANE)), 0);
            ent_obstacle_desc o = obstacle(organ.kind);
            for (int c = 0; c < 3; ++c) {
                o.center_m[c] = organ.start[c];
                o.start_m[c] = organ.start[c];
                o.end_m[c] = organ.end[c];
            }
            o.radius_m = organ.radius;
            EXPECT_EQ(environment_add(scene.get(), o), 1);
        }
    }
    ASSERT_TRUE(scene);
    double closest = 1e300;
    for (int i = 0; i < 1500; ++i) {
        ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
        const std::vector<double> points = environment_axis(scene.get(), 200);
        ASSERT_TRUE(all_finite(points)) << "step " << i;
        const double d = distance_to_segment(points, organ.start, organ.end);
        closest = std::min(closest, d);
        // Measured at most 0.17 R deep.
        ASSERT_GE(d, organ.radius + 0.75 * kEnvironmentRadius) << "step " << i;
    }
    // Still draped over it, and resting.
    const std::vector<double> points = environment_axis(scene.get(), 200);
    EXPECT_LT(distance_to_segment(points, organ.start, organ.end), organ.radius + 1.05 * kEnvironmentRadius);
    EXPECT_GT(stats(scene.get()).contacts, 0u);
    EXPECT_LT(stats(scene.get()).kinetic_energy_J, 1e-4);
    ::testing::Test::RecordProperty(std::string(organ.name) + (from_json ? "_json" : "_c") + "_deepest_over_R",
                                    std::to_string(1.0 - (closest - organ.radius) / kEnvironmentRadius));
}

TEST(Environment, ABowelDrapedOverASphereNeverEntersIt) {
    const Organ sphere{"sphere", ENT_OBSTACLE_SPHERE, {0, 0, 0.05}, {0, 0, 0.05}, 0.05};
    drape_over(sphere, false);
    drape_over(sphere, true);
}

TEST(Environment, ABowelDrapedOverACapsuleNeverEntersIt) {
    const Organ capsule{"capsule", ENT_OBSTACLE_CAPSULE, {0, -0.1, 0.03}, {0, 0.1, 0.03}, 0.03};
    drape_over(capsule, false);
    drape_over(capsule, true);
}

TEST(Environment, EveryIntegratorKeepsAShortBowelInTheBox) {
    // Explicit integrators take the substeps their stability limit needs (the contact
    // stiffness shortens it), without being asked.
    const double center[3] = {0, 0, 0}, half[3] = {0.1, 0.1, 0.1};
    for (int32_t integrator : kIntegrators) {
        SCOPED_TRACE(integrator_name(integrator));
        ent_scene_desc desc = default_desc();
        desc.integrator = integrator;
        desc.length_m = 0.5;
        desc.control_points = 16;
        desc.shape = ENT_SHAPE_SERPENTINE;
        desc.shape_leg_length_m = 0.1;
        desc.shape_leg_spacing_m = 0.026;
        desc.shape_center_m[2] = 0.05;
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene);
        environment_add(scene.get(), environment_box(0.1));
        for (int i = 0; i < 1000; ++i) {
            ASSERT_EQ(ent_scene_step(scene.get(), 1e-3), ENT_OK) << "step " << i << ": " << ent_last_error();
            if (i % 10 == 0) {
                ASSERT_LT(beyond_box(environment_axis(scene.get(), 100), center, half, 0.0), 0.0) << "step " << i;
            }
        }
        const std::vector<double> points = environment_axis(scene.get(), 100);
        ASSERT_TRUE(all_finite(points));
        EXPECT_LE(beyond_box(points, center, half, 0.75 * kEnvironmentRadius), 0.0);
        const ent_stats s = stats(scene.get());
        EXPECT_LT(s.max_penetration_m, 0.25 * kEnvironmentRadius);
        EXPECT_GT(s.contacts, 0u);
        EXPECT_LT(lowest_z(points), -0.1 + 1.25 * kEnvironmentRadius) << "on the floor";
        if (integrator == ENT_INTEGRATOR_RK4 || integrator == ENT_INTEGRATOR_SYMPLECTIC_EULER) {
            // The contacts' stiffness and friction shorten the stable substep: more substeps
            // than the same bowel takes without obstacles.
            ScenePtr free = create(desc);
            ASSERT_TRUE(free);
            ASSERT_TRUE(step_n(free.get(), 1e-3, 1000));
            EXPECT_GT(s.substeps, stats(free.get()).substeps);
        }
    }
}

// ---- the effect is off until the first obstacle ---------------------------------------------

TEST(Environment, IsOffWithoutObstaclesAndOnFromTheFirst) {
    ScenePtr scene = create(line_desc(0.6, 24, 0.0));
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 20));
    ent_effect_stats e = effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT);
    EXPECT_EQ(e.enabled, 0);
    EXPECT_EQ(e.calls, 0u);
    EXPECT_EQ(e.total_time_ns, 0u);
    ent_stats s = stats(scene.get());
    EXPECT_EQ(s.contacts, 0u);
    EXPECT_EQ(s.max_penetration_m, 0.0);

    // A floor just below the falling bowel: on, it runs, and it catches the bowel.
    const double z = lowest_z(environment_axis(scene.get()));
    ent_obstacle_desc floor = obstacle(ENT_OBSTACLE_PLANE);
    floor.center_m[2] = z - kEnvironmentRadius - 0.02;
    EXPECT_EQ(environment_add(scene.get(), floor), 0);
    e = effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT);
    EXPECT_EQ(e.enabled, 1);
    EXPECT_EQ(e.calls, 0u);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 500));
    e = effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT);
    EXPECT_EQ(e.enabled, 1);
    EXPECT_GE(e.calls, 500u);
    s = stats(scene.get());
    EXPECT_GT(s.contacts, 0u);
    EXPECT_GE(lowest_z(environment_axis(scene.get())), floor.center_m[2] + 0.75 * kEnvironmentRadius);
}

TEST(Environment, AnEmptyJsonEnvironmentIsOff) {
    ScenePtr scene = create_json(R"({"intestine": {"length": 0.5, "control_points": 10},
                                     "gravity": [0, 0, -9.81], "environment": []})");
    ASSERT_TRUE(scene);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 10));
    const ent_effect_stats e = effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT);
    EXPECT_EQ(e.enabled, 0);
    EXPECT_EQ(e.calls, 0u);
    EXPECT_EQ(stats(scene.get()).contacts, 0u);
}

TEST(Environment, TheDescriptionCannotTurnItOnByItsBit) {
    ent_scene_desc desc = line_desc(0.6, 24, 0.0);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_ENVIRONMENT);
    ent_scene* scene = reinterpret_cast<ent_scene*>(&desc);  // must stay untouched
    EXPECT_EQ(ent_scene_create(&desc, &scene), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(scene, reinterpret_cast<ent_scene*>(&desc));
    EXPECT_TRUE(contains(ent_last_error(), "effects")) << ent_last_error();
}

// ---- ids ------------------------------------------------------------------------------------

TEST(Environment, ObstacleIdsCountInOrderJsonFirst) {
    ScenePtr scene = create_json(R"({
        "intestine": { "length": 0.5, "control_points": 10 },
        "environment": [ { "type": "box_inside", "center": [0, 0, 0], "half_extents": [0.5, 0.5, 0.5] },
                         { "type": "plane", "point": [0, 0, -0.2], "normal": [0, 0, 1] } ] })");
    ASSERT_TRUE(scene);
    EXPECT_EQ(effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT).enabled, 1);
    EXPECT_EQ(environment_add(scene.get(), obstacle(ENT_OBSTACLE_SPHERE)), 2);
    // No place for the id: still added, still counted.
    const ent_obstacle_desc capsule = obstacle(ENT_OBSTACLE_CAPSULE);
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &capsule, nullptr), ENT_OK) << ent_last_error();
    EXPECT_EQ(environment_add(scene.get(), environment_box(0.3)), 4);

    ScenePtr from_c = create(line_desc(0.5, 10, 0.0));
    ASSERT_TRUE(from_c);
    EXPECT_EQ(environment_add(from_c.get(), obstacle(ENT_OBSTACLE_PLANE)), 0);
    EXPECT_EQ(environment_add(from_c.get(), obstacle(ENT_OBSTACLE_SPHERE)), 1);
    EXPECT_EQ(environment_add(from_c.get(), obstacle(ENT_OBSTACLE_CAPSULE)), 2);
    ASSERT_TRUE(step_n(from_c.get(), 1e-3, 5));
}

TEST(Environment, FieldsAKindDoesNotUseAreIgnored) {
    ScenePtr scene = create(line_desc(0.5, 10, 0.0));
    ASSERT_TRUE(scene);
    ent_obstacle_desc sphere = obstacle(ENT_OBSTACLE_SPHERE);
    sphere.center_m[2] = -0.2;
    sphere.half_extents_m[0] = -1.0;
    sphere.normal[0] = sphere.normal[1] = sphere.normal[2] = 0.0;
    sphere.start_m[1] = kNaN;
    sphere.end_m[2] = kNaN;
    EXPECT_EQ(environment_add(scene.get(), sphere), 0);
    ent_obstacle_desc plane = obstacle(ENT_OBSTACLE_PLANE);
    plane.center_m[2] = -0.5;
    plane.radius_m = -1.0;
    plane.half_extents_m[1] = kNaN;
    EXPECT_EQ(environment_add(scene.get(), plane), 1);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 10));
    EXPECT_TRUE(all_finite(control_points(scene.get())));
}

// ---- bad obstacles --------------------------------------------------------------------------

struct BadObstacle {
    const char* name;
    std::function<void(ent_obstacle_desc&)> change;
    ent_status status;
    const char* message_part;  // must appear in ent_last_error()
};

const BadObstacle kBadObstacles[] = {
    {"struct_size 0", [](ent_obstacle_desc& o) { o.struct_size = 0; }, ENT_ERROR_VERSION, "struct_size"},
    {"struct_size too large", [](ent_obstacle_desc& o) { o.struct_size = sizeof(ent_obstacle_desc) + 8; },
     ENT_ERROR_VERSION, "struct_size"},
    {"kind 9", [](ent_obstacle_desc& o) { o.kind = 9; }, ENT_ERROR_INVALID_ARGUMENT, "kind"},
    {"kind -1", [](ent_obstacle_desc& o) { o.kind = -1; }, ENT_ERROR_INVALID_ARGUMENT, "kind"},
    {"negative sphere radius",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_SPHERE;
         o.radius_m = -0.01;
     },
     ENT_ERROR_INVALID_ARGUMENT, "radius"},
    {"zero capsule radius",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_CAPSULE;
         o.radius_m = 0.0;
     },
     ENT_ERROR_INVALID_ARGUMENT, "radius"},
    {"NaN sphere centre",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_SPHERE;
         o.center_m[1] = kNaN;
     },
     ENT_ERROR_INVALID_ARGUMENT, "center"},
    {"infinite capsule end",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_CAPSULE;
         o.end_m[0] = std::numeric_limits<double>::infinity();
     },
     ENT_ERROR_INVALID_ARGUMENT, "end"},
    {"NaN capsule start",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_CAPSULE;
         o.start_m[2] = kNaN;
     },
     ENT_ERROR_INVALID_ARGUMENT, "start"},
    {"zero plane normal",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_PLANE;
         o.normal[2] = 0.0;
     },
     ENT_ERROR_INVALID_ARGUMENT, "normal"},
    {"NaN plane point",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_PLANE;
         o.center_m[0] = kNaN;
     },
     ENT_ERROR_INVALID_ARGUMENT, "point"},
    {"zero box half extent", [](ent_obstacle_desc& o) { o.half_extents_m[1] = 0.0; }, ENT_ERROR_INVALID_ARGUMENT,
     "half_extents"},
    {"negative box half extent", [](ent_obstacle_desc& o) { o.half_extents_m[2] = -0.1; },
     ENT_ERROR_INVALID_ARGUMENT, "half_extents"},
    {"NaN box centre", [](ent_obstacle_desc& o) { o.center_m[0] = kNaN; }, ENT_ERROR_INVALID_ARGUMENT, "center"},
};

struct Snapshot {
    std::vector<double> points;
    ent_stats stats;
    ent_effect_stats environment;
};

Snapshot snapshot(const ent_scene* scene) {
    return {control_points(scene), stats(scene), effect_stats(scene, ENT_EFFECT_ENVIRONMENT)};
}

void expect_unchanged(const Snapshot& before, const Snapshot& after, const char* name) {
    ASSERT_EQ(before.points.size(), after.points.size()) << name;
    EXPECT_EQ(std::memcmp(before.points.data(), after.points.data(), before.points.size() * sizeof(double)), 0)
        << name;
    const ent_stats &a = before.stats, &b = after.stats;
    EXPECT_EQ(a.time_s, b.time_s) << name;
    EXPECT_EQ(a.steps, b.steps) << name;
    EXPECT_EQ(a.substeps, b.substeps) << name;
    EXPECT_EQ(a.rollbacks, b.rollbacks) << name;
    EXPECT_EQ(std::memcmp(&a.kinetic_energy_J, &b.kinetic_energy_J, sizeof(double)), 0) << name;
    EXPECT_EQ(std::memcmp(&a.potential_energy_J, &b.potential_energy_J, sizeof(double)), 0) << name;
    EXPECT_EQ(a.contacts, b.contacts) << name;
    EXPECT_EQ(std::memcmp(&a.max_penetration_m, &b.max_penetration_m, sizeof(double)), 0) << name;
    EXPECT_EQ(a.last_step_ns, b.last_step_ns) << name;
    EXPECT_EQ(before.environment.enabled, after.environment.enabled) << name;
    EXPECT_EQ(before.environment.calls, after.environment.calls) << name;
    EXPECT_EQ(before.environment.total_time_ns, after.environment.total_time_ns) << name;
}

// A bad obstacle, into a fresh scene with `existing` planes already (0: the environment is
// still off and must stay off): refused with its status and a message naming the field;
// control points, stats and the environment's effect stats stay bit-identical; no id is used.
void refuse(const BadObstacle& bad, int existing) {
    SCOPED_TRACE(std::string(bad.name) + ", " + std::to_string(existing) + " obstacles before");
    ScenePtr scene = create(line_desc(0.5, 12, kEnvironmentRadius));
    ASSERT_TRUE(scene);
    for (int i = 0; i < existing; ++i) EXPECT_EQ(environment_add(scene.get(), obstacle(ENT_OBSTACLE_PLANE)), i);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 30));  // on the plane, if there is one
    const Snapshot before = snapshot(scene.get());
    if (existing > 0) {
        EXPECT_GT(before.stats.contacts, 0u);
    }

    ent_obstacle_desc desc;
    ent_obstacle_desc_default(&desc);
    bad.change(desc);
    int32_t id = 12345;
    const ent_status status = ent_scene_add_obstacle(scene.get(), &desc, &id);
    EXPECT_EQ(status, bad.status);
    if (status != ENT_OK) {
        EXPECT_TRUE(contains(ent_last_error(), bad.message_part))
            << "the message should name " << bad.message_part << ": " << ent_last_error();
    }
    EXPECT_EQ(id, 12345) << "out_obstacle written on failure";
    expect_unchanged(before, snapshot(scene.get()), bad.name);

    // No id was used up, and the scene still steps.
    ent_obstacle_desc far_sphere = obstacle(ENT_OBSTACLE_SPHERE);
    far_sphere.center_m[2] = 10.0;
    EXPECT_EQ(environment_add(scene.get(), far_sphere), existing);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 10));
    EXPECT_TRUE(all_finite(control_points(scene.get())));
}

TEST(Environment, BadObstaclesAreRefusedAndChangeNothing) {
    for (const BadObstacle& bad : kBadObstacles)
        for (int existing : {0, 1}) refuse(bad, existing);
}

TEST(Environment, NullSceneOrDescriptionIsRefused) {
    ScenePtr scene = create(line_desc(0.5, 12, kEnvironmentRadius));
    ASSERT_TRUE(scene);
    EXPECT_EQ(environment_add(scene.get(), obstacle(ENT_OBSTACLE_PLANE)), 0);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 30));
    const Snapshot before = snapshot(scene.get());
    int32_t id = 12345;
    const ent_obstacle_desc good = obstacle(ENT_OBSTACLE_SPHERE);
    EXPECT_EQ(ent_scene_add_obstacle(nullptr, &good, &id), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(ent_last_error(), "scene")) << ent_last_error();
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), nullptr, &id), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(ent_last_error(), "desc")) << ent_last_error();
    EXPECT_EQ(id, 12345);
    expect_unchanged(before, snapshot(scene.get()), "NULL scene or desc");
    EXPECT_EQ(environment_add(scene.get(), good), 1);
}

// A normal whose length underflows or overflows cannot be normalised: the rule of
// shape_direction (non-zero, finite length) applies. Accepted, the first makes a plane that
// never touches anything (its normal turns NaN), the second one whose normal is zero and
// whose every sphere counts as a contact of depth R.
const BadObstacle kUnnormalisableNormals[] = {
    {"plane normal too short to normalise",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_PLANE;
         o.normal[0] = 0.0;
         o.normal[1] = 1e-200;
         o.normal[2] = 1e-200;
     },
     ENT_ERROR_INVALID_ARGUMENT, "normal"},
    {"plane normal too long to normalise",
     [](ent_obstacle_desc& o) {
         o.kind = ENT_OBSTACLE_PLANE;
         o.normal[1] = 1e200;
         o.normal[2] = 1e200;
     },
     ENT_ERROR_INVALID_ARGUMENT, "normal"},
};

TEST(Environment, APlaneNormalThatCannotBeNormalisedIsRefused) {
    for (const BadObstacle& bad : kUnnormalisableNormals)
        for (int existing : {0, 1}) refuse(bad, existing);
}

// ---- JSON errors ----------------------------------------------------------------------------

void expect_json_error(const std::string& environment, const std::string& message_start,
                       const std::string& collision = "") {
    const std::string json = R"({"intestine": {"length": 0.5, "control_points": 10})" +
                             (collision.empty() ? "" : ", \"collision\": " + collision) +
                             (environment.empty() ? "" : ", \"environment\": " + environment) + "}";
    ent_scene* scene = nullptr;
    EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), &scene), ENT_ERROR_INVALID_SCENE) << json;
    EXPECT_EQ(scene, nullptr);
    EXPECT_EQ(std::string(ent_last_error()).rfind(message_start, 0), 0u)
        << "expected a message starting with: " << message_start << "\ngot: " << ent_last_error();
    if (scene != nullptr) ent_scene_destroy(scene);
}

TEST(Environment, JsonErrorsNameThePath) {
    expect_json_error(R"({"type": "plane"})", "environment must be an array of obstacles");
    expect_json_error(R"([{"center": [0, 0, 0], "radius": 0.1}])", "environment[0] must be an object with a \"type\"");
    expect_json_error(R"([3])", "environment[0] must be an object with a \"type\"");
    expect_json_error(R"([{"type": "cube"}])",
                      "environment[0].type must be one of \"box_inside\", \"plane\", \"sphere\", \"capsule\"");
    expect_json_error(R"([{"type": 2}])", "environment[0].type must be one of");
    expect_json_error(R"([{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1], "radius": 0.1}])",
                      "unknown key \"radius\" in environment[0] (expected one of: center, half_extents, "
                      "position, orientation, friction)");
    expect_json_error(R"([{"type": "plane", "normal": [0, 0, 1], "center": [0, 0, 0]}])",
                      "unknown key \"center\" in environment[0] (expected one of: point, normal, "
                      "position, orientation, friction)");
    expect_json_error(R"([{"type": "sphere", "radius": 0.1}, {"type": "capsule", "center": [0, 0, 0]}])",
                      "unknown key \"center\" in environment[1] (expected one of: start, end, radius, "
                      "position, orientation, friction)");
    expect_json_error(R"([{"type": "sphere", "center": [0, 0], "radius": 0.1}])",
                      "environment[0].center must be an array of 3 numbers");
    expect_json_error(R"([{"type": "capsule", "start": [0, 0, 0], "end": [0, 0, "1"], "radius": 0.1}])",
                      "environment[0].end[2] must be a number");
    expect_json_error(R"([{"type": "plane", "normal": [0, 0, 1]}, {"type": "sphere", "radius": -1}])",
                      "environment[1].radius must be > 0, got -1");
    expect_json_error(R"([{"type": "sphere", "radius": 0}])", "environment[0].radius must be > 0, got 0");
    expect_json_error(R"([{"type": "plane", "normal": [0, 0, 0]}])", "environment[0].normal must be non-zero");
    expect_json_error(R"([{"type": "box_inside", "half_extents": [0.1, -0.1, 0.1]}])",
                      "environment[0].half_extents[1] must be > 0, got -0.1");
    expect_json_error(R"([{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1], "type": "plane"}])",
                      "duplicate key \"type\" in environment[0]");

    // The radius was left at its default: the message says so.
    expect_json_error("", "collision.sphere_spacing must be <= intestine.radius (0.0125, the default), got 0.02",
                      R"({"sphere_spacing": 0.02})");
    expect_json_error("", "collision.sphere_spacing must be >= 0", R"({"sphere_spacing": -0.001})");
    expect_json_error("", "collision.stiffness must be >= 0, got -1", R"({"stiffness": -1})");
    expect_json_error("", "collision.damping must be >= 0", R"({"damping": -0.5})");
    expect_json_error("", "collision.friction must be >= 0", R"({"friction": -0.3})");
    expect_json_error("", "collision.slip_speed must be > 0, got 0", R"({"slip_speed": 0})");
    expect_json_error("", "unknown key \"restitution\" in collision (expected one of: sphere_spacing, stiffness, "
                          "damping, friction, slip_speed)",
                      R"({"restitution": 0.5})");
    expect_json_error("", "collision must be an object", "[]");
}

TEST(Environment, CollisionFieldsOfTheDescriptionAreChecked) {
    struct Case {
        const char* field;
        std::function<void(ent_scene_desc&)> change;
    };
    const Case cases[] = {
        {"collision_sphere_spacing_m", [](ent_scene_desc& d) { d.collision_sphere_spacing_m = 2 * d.radius_m; }},
        {"collision_sphere_spacing_m", [](ent_scene_desc& d) { d.collision_sphere_spacing_m = kNaN; }},
        {"contact_stiffness_N_per_m", [](ent_scene_desc& d) { d.contact_stiffness_N_per_m = -1.0; }},
        {"contact_damping_N_s_per_m", [](ent_scene_desc& d) { d.contact_damping_N_s_per_m = -1.0; }},
        {"contact_friction", [](ent_scene_desc& d) { d.contact_friction = kNaN; }},
        {"contact_slip_speed_m_per_s", [](ent_scene_desc& d) { d.contact_slip_speed_m_per_s = 0.0; }},
    };
    for (const Case& c : cases) {
        ent_scene_desc desc = line_desc(0.5, 10, 0.0);
        c.change(desc);
        ent_scene* scene = nullptr;
        EXPECT_EQ(ent_scene_create(&desc, &scene), ENT_ERROR_INVALID_ARGUMENT) << c.field;
        EXPECT_EQ(scene, nullptr);
        EXPECT_TRUE(contains(ent_last_error(), c.field)) << c.field << ": " << ent_last_error();
        if (scene != nullptr) ent_scene_destroy(scene);
    }
}

}  // namespace
