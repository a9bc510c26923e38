// SPDX-License-Identifier: Apache-2.0
// Scenes that cannot start, and steps that cannot be saved (issue 16, defect 6). A bowel far
// outside its cavity, a 50 m helix in a 30 cm box, a bowel inside an organ: creation (or
// ent_scene_add_obstacle) refuses them, naming the obstacle and the control points. A step
// the guard cannot save says which check failed and by how much, at which control point,
// and which effect drove it; and it gives up within the bound the header states.
#include "capi_test_support.h"
#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::contains;


std::string refused_json(const std::string& json) {
    ent_scene* scene = nullptr;
    EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), &scene), ENT_ERROR_INVALID_SCENE) << json;
    EXPECT_EQ(scene, nullptr);
    if (scene != nullptr) ent_scene_destroy(scene);
    return ent_last_error();
}

TEST(ImpossibleScenes, ABowelOutsideItsCavityIsRefusedAtCreation) {
    const std::string message = refused_json(R"({"gravity": [0, 0, -9.81],
        "environment": [{"type": "box_inside", "center": [1, 0, 0], "half_extents": [0.12, 0.12, 0.12]}]})");
    EXPECT_EQ(message.rfind("environment[0] (box_inside) has control points 0-239 (240 of 240) outside it", 0), 0u)
        << message;
}

TEST(ImpossibleScenes, AFiftyMetreHelixInAThirtyCentimetreBoxIsRefused) {
    const std::string message = refused_json(R"({"intestine": {"length": 50, "control_points": 400},
        "environment": [{"type": "box_inside", "half_extents": [0.15, 0.15, 0.15]}]})");
    EXPECT_TRUE(contains(message, "environment[0] (box_inside) has control points")) << message;
    EXPECT_TRUE(contains(message, "outside it")) << message;
}

TEST(ImpossibleScenes, ABowelInsideAnOrganIsRefused) {
    const std::string message = refused_json(
        R"({"environment": [{"type": "sphere", "center": [0, 0, 0.15], "radius": 0.5}]})");
    EXPECT_TRUE(contains(message, "environment[0] (sphere) has control points 0-239 (240 of 240) inside it"))
        << message;
}

TEST(ImpossibleScenes, AnObstacleAddedAroundTheBowelWhereItIsNowIsRefusedInC) {
    ScenePtr scene = create(default_desc());
    ASSERT_TRUE(scene);
    const std::vector<double> before = control_points(scene.get());
    ent_obstacle_desc organ;
    ent_obstacle_desc_default(&organ);
    organ.kind = ENT_OBSTACLE_SPHERE;
    organ.center_m[2] = 0.15;
    organ.radius_m = 0.5;
    int32_t id = -7;
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &organ, &id), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(id, -7);
    EXPECT_EQ(std::string(ent_last_error()).rfind("obstacle[0] (sphere) has control points 0-239", 0), 0u)
        << ent_last_error();
    EXPECT_EQ(effect_stats(scene.get(), ENT_EFFECT_ENVIRONMENT).enabled, 0) << "nothing changed";
    EXPECT_EQ(control_points(scene.get()), before);
    // A bowel draped over a cavity's rim is pushed in: accepted.
    ent_obstacle_desc box;
    ent_obstacle_desc_default(&box);
    // The helix rises 0.29 m from z = 0: the box spans z = 0.01 to 0.27, its ends 1 and 2 cm out.
    box.center_m[2] = 0.14;
    box.half_extents_m[0] = box.half_extents_m[1] = 0.15;
    box.half_extents_m[2] = 0.13;
    EXPECT_EQ(ent_scene_add_obstacle(scene.get(), &box, &id), ENT_OK) << ent_last_error();
    EXPECT_TRUE(step_n(scene.get(), 1e-3, 20));
}

// A 1.5 m tube along x from the origin (61 control points), of radius 1.3 cm or tapering
// from 3.5 cm to 1.3 cm, with a sphere organ of radius `depth` centred on its first or last
// control point (which then lies `depth` inside it).
std::string tapered_start_json(bool tapered, bool at_thin_end, double depth) {
    const std::string radius = tapered ? R"("radius_profile": [[0, 0.035], [1.5, 0.013]])" : R"("radius": 0.013)";
    return R"({"intestine": {"length": 1.5, "control_points": 61, )" + radius +
           R"(, "shape": {"kind": "line"}}, "environment": [{"type": "sphere", "center": [)" +
           (at_thin_end ? "1.5" : "0") + R"(, 0, 0], "radius": )" + std::to_string(depth) + "}]}";
}

TEST(ImpossibleScenes, EachPartOfATaperedTubeStartsAsDeepAsItsOwnRadiusAllows) {
    // The contact throws a sphere out at (depth + r) sqrt(k / (rho s)), s the spheres'
    // spacing there (R / 2 x r / R_max): with the defaults (k = 500 N/m, rho = 0.3 kg/m)
    // and max_speed 50 m/s, 8.6 cm deep at r = 1.3 cm and 12.7 cm at 3.5 cm. The thin end
    // is refused 10 cm deep, as a tube of its radius is (the largest radius' sphere would
    // let it start); the wide end starts 10 cm deep, unlike the thin tube.
    for (bool tapered : {false, true}) {
        const std::string message = refused_json(tapered_start_json(tapered, true, 0.10));
        EXPECT_EQ(message.rfind("environment[0] (sphere) has control points 60 (1 of 61) inside it", 0), 0u)
            << message;
        ScenePtr shallower = create_json(tapered_start_json(tapered, true, 0.08));
        EXPECT_TRUE(shallower) << ent_last_error();
    }
    ScenePtr wide_end = create_json(tapered_start_json(true, false, 0.10));
    EXPECT_TRUE(wide_end) << ent_last_error();
    refused_json(tapered_start_json(false, false, 0.10));
}

TEST(ImpossibleScenes, AnUnstableStepNamesTheCheckTheEffectAndTheControlPoint) {
    // Gravity given in mm/s^2: the bowel falls a thousand times too fast and passes
    // max_speed within a few steps; the message tells where and why.
    const std::string json = R"({"intestine": {"length": 1.0, "control_points": 20}, "gravity": [0, 0, -9810]})";
    ScenePtr scene = create_json(json);
    ASSERT_TRUE(scene);
    ent_status status = ENT_OK;
    for (int i = 0; i < 100 && status == ENT_OK; ++i) status = ent_scene_step(scene.get(), 1e-3);
    ASSERT_EQ(status, ENT_ERROR_UNSTABLE);
    const std::string message = ent_last_error();
    EXPECT_TRUE(contains(message, "the guard's last check failed: speed: control point ")) << message;
    EXPECT_TRUE(contains(message, "times max_speed (50 m/s)")) << message;
    EXPECT_TRUE(contains(message, "at the start of the step was gravity's")) << message;
    EXPECT_TRUE(contains(message, "the state is unchanged")) << message;
}

TEST(ImpossibleScenes, AFailingStepGivesUpWithinTheBoundTheHeaderStates) {
    // (2^(max_subdivisions + 1) - 1) n substeps at most, n those of the first attempt.
    for (uint32_t subdivisions : {0u, 1u, 4u, 6u}) {
        SCOPED_TRACE(subdivisions);
        ent_scene_desc desc = default_desc();
        desc.control_points = 20;
        desc.length_m = 1.0;
        desc.max_speed_m_per_s = 1e-9;  // every attempt fails
        desc.max_subdivisions = subdivisions;
        desc.timestep_s = 1e-3;
        ScenePtr scene = create(desc);
        ASSERT_TRUE(scene);
        const uint64_t n = 3;  // 3 ms in substeps of 1 ms
        ASSERT_EQ(ent_scene_step(scene.get(), 3e-3), ENT_ERROR_UNSTABLE);
        const ent_stats s = stats(scene.get());
        EXPECT_EQ(s.substeps, ((uint64_t{2} << subdivisions) - 1) * n);
        EXPECT_EQ(s.rollbacks, uint64_t{subdivisions} + 1);
    }
}

}  // namespace
