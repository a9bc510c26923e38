// SPDX-License-Identifier: Apache-2.0
// What a saved state belongs to (lib/scene/scene_fingerprint.h): the same description
// gives the same fingerprint; each value the physics depends on changes it (one row per
// value below), and so do the obstacles' and tools' order; what belongs to the state (a
// tool's start pose, an obstacle's pose) does not.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene_config.h"
#include "scene/scene_fingerprint.h"

namespace enteron::scene {
namespace {

SceneConfig base_config() {
    SceneConfig config;
    config.start_points = {0, 0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0};
    config.gravity = kStandardGravity;
    config.damping.emplace();
    config.mesentery.emplace();
    config.pinned.emplace();
    config.environment.push_back(default_obstacle(collision::ObstacleKind::sphere));
    config.environment.push_back(default_obstacle(collision::ObstacleKind::plane));
    config.tools.emplace_back();
    return config;
}

uint64_t fingerprint_of(const SceneConfig& config) {
    Fingerprint f;
    add_to_fingerprint(f, config);
    return f.value();
}

TEST(SceneFingerprint, TheSameDescriptionGivesTheSameFingerprint) {
    EXPECT_EQ(fingerprint_of(base_config()), fingerprint_of(base_config()));
}

TEST(SceneFingerprint, EveryValueThePhysicsDependsOnChangesIt) {
    struct Change {
        const char* what;
        std::function<void(SceneConfig&)> apply;
    };
    const std::vector<Change> changes = {
        {"length", [](SceneConfig& c) { c.intestine.length += 0.1; }},
        {"radius", [](SceneConfig& c) { c.intestine.radius *= 1.1; }},
        {"control points", [](SceneConfig& c) { c.intestine.control_points += 1; }},
        {"density", [](SceneConfig& c) { c.intestine.linear_density *= 2; }},
        {"stretch stiffness", [](SceneConfig& c) { c.intestine.stretch_stiffness *= 2; }},
        {"bend stiffness", [](SceneConfig& c) { c.intestine.bend_stiffness *= 2; }},
        {"a start point", [](SceneConfig& c) { c.start_points[4] = 1e-9; }},
        {"integrator", [](SceneConfig& c) { c.solver.integrator = IntegratorKind::rk4; }},
        {"timestep", [](SceneConfig& c) { c.solver.timestep = 5e-4; }},
        {"max substeps", [](SceneConfig& c) { c.solver.max_substeps = 7; }},
        {"max subdivisions", [](SceneConfig& c) { c.solver.max_subdivisions = 2; }},
        {"max speed", [](SceneConfig& c) { c.solver.max_speed = 10; }},
        {"gravity off", [](SceneConfig& c) { c.gravity.reset(); }},
        {"gravity", [](SceneConfig& c) { c.gravity = Vec3(0, 0, -1); }},
        {"drag", [](SceneConfig& c) { c.damping->drag = 1; }},
        {"stretch damping", [](SceneConfig& c) { c.damping->stretch = 1; }},
        {"bend damping", [](SceneConfig& c) { c.damping->bend = 1; }},
        {"mesentery off", [](SceneConfig& c) { c.mesentery.reset(); }},
        {"mesentery root", [](SceneConfig& c) { c.mesentery->root_end.x() += 0.01; }},
        {"mesentery attachments", [](SceneConfig& c) { c.mesentery->attachments = 3; }},
        {"mesentery stiffness", [](SceneConfig& c) { c.mesentery->stiffness = 1; }},
        {"mesentery rest length", [](SceneConfig& c) { c.mesentery->rest_length = 0.1; }},
        {"mesentery on an obstacle", [](SceneConfig& c) { c.mesentery->obstacle = 0; }},
        {"pinned ends", [](SceneConfig& c) { c.pinned->ends = pin_first; }},
        {"clamped ends", [](SceneConfig& c) { c.pinned->clamped = pin_last; }},
        {"pinned points", [](SceneConfig& c) { c.pinned->points = {2}; }},
        {"attached pins", [](SceneConfig& c) { c.pinned->attached = {PinAttachment{1, 0}}; }},
        {"a root polyline", [](SceneConfig& c) { c.mesentery->root_points = {0, 0, 0, 0.1, 0, 0, 0.1, 0.1, 0}; }},
        {"a root mapping", [](SceneConfig& c) { c.mesentery->root_mapping = {0, 0, 1, 1}; }},
        {"a pinned span", [](SceneConfig& c) { c.pinned->spans = {PinSpan{0.1, 0.2, {}}}; }},
        {"a pinned span's obstacle", [](SceneConfig& c) { c.pinned->spans = {PinSpan{0.1, 0.2, 0}}; }},
        {"sphere spacing", [](SceneConfig& c) { c.collision.sphere_spacing = 0.003; }},
        {"contact stiffness", [](SceneConfig& c) { c.collision.contact.stiffness *= 2; }},
        {"contact damping", [](SceneConfig& c) { c.collision.contact.damping *= 2; }},
        {"friction", [](SceneConfig& c) { c.collision.contact.friction += 0.1; }},
        {"slip speed", [](SceneConfig& c) { c.collision.contact.slip_speed *= 2; }},
        {"self collision", [](SceneConfig& c) { c.self_collision = !c.self_collision; }},
        {"an obstacle's radius", [](SceneConfig& c) { c.environment[0].radius *= 2; }},
        {"an obstacle's centre", [](SceneConfig& c) { c.environment[0].center.y() += 0.01; }},
        {"an obstacle's voxel size", [](SceneConfig& c) { c.environment[0].voxel_size = 0.002; }},
        {"the obstacles' order", [](SceneConfig& c) { std::swap(c.environment[0], c.environment[1]); }},
        {"one more obstacle", [](SceneConfig& c) { c.environment.push_back(c.environment[0]); }},
        {"a tool's radius", [](SceneConfig& c) { c.tools[0].settings.radius *= 2; }},
        {"a tool's max force", [](SceneConfig& c) { c.tools[0].settings.max_force += 1; }},
        {"a tool's grasp stiffness", [](SceneConfig& c) { c.tools[0].settings.grasp_stiffness *= 2; }},
        {"a tool's friction", [](SceneConfig& c) { c.tools[0].settings.friction += 0.1; }},
        {"a tool's passivity limiter", [](SceneConfig& c) { c.tools[0].settings.passivity_limiter = !c.tools[0].settings.passivity_limiter; }},
        {"a tool's jaws", [](SceneConfig& c) { c.tools[0].settings.jaw_length = 0.02; }},
        {"a tool's jaw opening", [](SceneConfig& c) { c.tools[0].settings.jaw_opening = 0.01; }},
        {"a tool's blade", [](SceneConfig& c) { c.tools[0].settings.blade_width = 0.05; }},
        {"a tool's blade length", [](SceneConfig& c) { c.tools[0].settings.blade_length = 0.05; }},
        {"one more tool", [](SceneConfig& c) { c.tools.emplace_back(); }},
    };
    const uint64_t base = fingerprint_of(base_config());
    for (const Change& change : changes) {
        SceneConfig changed = base_config();
        change.apply(changed);
        EXPECT_NE(fingerprint_of(changed), base) << change.what;
    }
    // A mesh obstacle by its data.
    SceneConfig with_mesh = base_config();
    auto mesh = std::make_shared<collision::TriangleMesh>();
    mesh->vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    mesh->indices = {0, 1, 2};
    with_mesh.environment[0].kind = collision::ObstacleKind::mesh;
    with_mesh.environment[0].mesh = mesh;
    const uint64_t meshed = fingerprint_of(with_mesh);
    auto moved_vertex = std::make_shared<collision::TriangleMesh>(*mesh);
    moved_vertex->vertices[3] = 2.0;
    with_mesh.environment[0].mesh = moved_vertex;
    EXPECT_NE(fingerprint_of(with_mesh), meshed) << "a mesh's vertex";
}

TEST(SceneFingerprint, WhatBelongsToTheStateLeavesItAlone) {
    const uint64_t base = fingerprint_of(base_config());
    SceneConfig moved = base_config();
    moved.tools[0].pose.position = Vec3(0.1, 0.2, 0.3);
    EXPECT_EQ(fingerprint_of(moved), base) << "a tool's start pose";
    moved.environment[0].friction = 0.5;
    moved.environment[0].pose.position = Vec3(0.0, 0.0, 0.1);
    EXPECT_EQ(fingerprint_of(moved), base) << "an obstacle's friction and pose (changed at run time, saved with the state)";
}

}  // namespace
}  // namespace enteron::scene
