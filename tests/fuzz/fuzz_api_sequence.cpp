// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes decoded into a sequence of C API calls on one scene:
// create (from a few base scenes, or from an ent_scene_desc with arbitrary numbers), then
// up to 64 of: step with an arbitrary dt, add an obstacle, create / update / measure /
// destroy a skin with arbitrary settings, add a tool, set its pose, grasp, release, read
// its wrench and state, the queries, and the moving anatomy (mesh obstacles with arbitrary
// vertices and indices, obstacle poses, velocities, friction and removal, gravity, pins and
// the mesentery's root on obstacles, the obstacle queries). Every call must return ENT_OK or
// a status with a message; a failing step must leave the control points exactly as they
// were; a scene that returned ENT_OK must be finite everywhere (control points, axis, stats,
// skin vertices); a mesh's indices must stay within its vertices. Any violation aborts.
//
// The bytes are read front to back (see Bytes), so a seed is easy to write by hand:
// tests/fuzz/corpus/api_sequence/ holds a few, made by tests/fuzz/make_api_seeds.py.
#include <enteron/enteron.h>

#include "fuzz_bytes.h"

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using fuzz::Bytes;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_api_sequence: %s (last error: %s)\n", what, ent_last_error());
    std::abort();
}

// A failing call must say why.
void check_status(ent_status status) {
    if (status != ENT_OK && (std::strlen(ent_last_error()) == 0 || std::strcmp(ent_status_string(status), "unknown status") == 0))
        fail("a failing call left no message or an unknown status");
}

const char* const kBaseScenes[] = {
    // a line, rk4, gravity only
    R"({"intestine": {"length": 0.5, "control_points": 8, "shape": {"kind": "line"}},
        "solver": {"integrator": "rk4", "max_substeps": 100}, "gravity": [0, 0, -9.81],
        "tools": [{"position": [0.1, 0, 0.02]}]})",
    // a serpentine in a box, self-colliding, implicit Euler
    R"({"intestine": {"length": 1.0, "control_points": 24, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                      "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
        "solver": {"max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {},
        "environment": [{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1]}], "self_collision": {},
        "tools": [{"position": [0, 0, -0.03]}, {"position": [0.05, 0, 0.05], "max_force": 1}]})",
    // a helix on its mesentery, both ends held, symplectic Euler
    R"({"intestine": {"length": 1.0, "control_points": 16, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                      "shape": {"kind": "helix", "helix_radius": 0.05, "helix_pitch": 0.03}},
        "solver": {"integrator": "symplectic_euler", "max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {},
        "mesentery": {"attachments": 8}, "pinned": {"ends": "both"}})",
    // degenerate points: coincident and folded back, on a floor
    R"({"intestine": {"length": 0.3, "control_points": 6, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                      "shape": {"kind": "points", "points": [[0,0,0.02],[0,0,0.02],[0.1,0,0.02],[0,0,0.02],
                                                              [0.1,0,0.02],[0.1,0,0.02]]}},
        "solver": {"max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {}, "self_collision": {},
        "environment": [{"type": "plane", "normal": [0, 0, 1]}]})",
};
constexpr int kBaseSceneCount = sizeof kBaseScenes / sizeof kBaseScenes[0];

// A scene from an ent_scene_desc whose numbers come from the input (small: at most 32 points).
// The base scenes and this one allow at most 100 substeps per step, so that an input costs
// milliseconds, not seconds.
ent_status create_from_desc(Bytes& in, ent_scene** out) {
    ent_scene_desc d;
    ent_scene_desc_default(&d);
    d.effects = in.u32() & 0x1ff;
    d.length_m = in.number(1.0);
    d.radius_m = in.number(0.0125);
    d.control_points = 4 + in.u8() % 29;
    d.linear_density_kg_per_m = in.number(0.3);
    d.stretch_stiffness_N = in.number(100.0);
    d.bend_stiffness_N_m2 = in.number(2.5e-3);
    d.shape = static_cast<int32_t>(in.u8() % 5);
    d.shape_helix_radius_m = in.number(0.05);
    d.shape_leg_length_m = in.number(0.1);
    std::vector<double> points(3 * d.control_points);
    for (double& p : points) p = in.number(0.1);
    d.shape_points_xyz_m = points.data();
    d.integrator = static_cast<int32_t>(in.u8() % 4);
    d.timestep_s = in.number(1e-3);
    d.max_substeps = 1 + in.u8() % 100;  // more is legal, but slow to fuzz
    d.max_subdivisions = in.u8() % 8;
    d.max_speed_m_per_s = in.number(50.0);
    d.gravity_m_per_s2[2] = in.number(-9.81);
    d.drag_N_s_per_m2 = in.number(0.05);
    d.mesentery_attachments = in.u8() % 16;
    d.mesentery_stiffness_N_per_m = in.number(5.0);
    d.pinned_ends = static_cast<int32_t>(in.u8() % 5);
    d.collision_sphere_spacing_m = in.number(0.005);
    d.contact_stiffness_N_per_m = in.number(500.0);
    d.contact_friction = in.number(0.3);
    d.contact_slip_speed_m_per_s = in.number(0.01);
    return ent_scene_create(&d, out);
}

std::vector<double> control_points(const ent_scene* scene) {
    uint32_t count = 0;
    if (ent_scene_control_points(scene, 0, nullptr, &count) != ENT_OK) fail("control point count");
    std::vector<double> points(3 * std::size_t{count});
    if (ent_scene_control_points(scene, count, points.data(), &count) != ENT_OK) fail("control points");
    return points;
}

void check_finite_state(const ent_scene* scene) {
    for (double v : control_points(scene))
        if (!std::isfinite(v)) fail("a control point is not finite after ENT_OK");
    ent_stats s;
    s.struct_size = sizeof s;
    if (ent_scene_stats(scene, &s) != ENT_OK) fail("stats");
    if (!std::isfinite(s.time_s)) fail("time_s is not finite after ENT_OK");
    if (!std::isfinite(s.kinetic_energy_J)) fail("kinetic_energy_J is not finite after ENT_OK");
    if (!std::isfinite(s.potential_energy_J)) fail("potential_energy_J is not finite after ENT_OK");
    if (!std::isfinite(s.max_penetration_m)) fail("max_penetration_m is not finite after ENT_OK");
}

void step(Bytes& in, ent_scene* scene) {
    const double dt = in.number(1e-3);
    const std::vector<double> before = control_points(scene);
    const ent_status status = ent_scene_step(scene, dt);
    check_status(status);
    if (status == ENT_OK) return check_finite_state(scene);
    const std::vector<double> after = control_points(scene);
    if (std::memcmp(before.data(), after.data(), before.size() * sizeof(double)) != 0)
        fail("a failing step changed the control points");
}

void add_obstacle(Bytes& in, ent_scene* scene) {
    ent_obstacle_desc d;
    ent_obstacle_desc_default(&d);
    d.kind = static_cast<int32_t>(in.u8() % 6);
    for (int c = 0; c < 3; ++c) {
        d.center_m[c] = in.number(0.01) - 0.01;
        d.half_extents_m[c] = in.number(0.1);
        d.normal[c] = in.number(1.0) - 1.0;
        d.end_m[c] = in.number(0.05);
    }
    d.radius_m = in.number(0.03);
    // A mesh: up to 8 vertices near the origin and 8 triangles whose indices may be out of
    // range; or a count claim far past the arrays (refused before they are read).
    std::vector<double> vertices;
    std::vector<uint32_t> triangles;
    if (d.kind == ENT_OBSTACLE_MESH) {
        vertices.resize(3 * std::size_t{in.u8()} % 27);
        for (double& v : vertices) v = in.number(0.03) - 0.04;
        triangles.resize(3 * std::size_t{in.u8()} % 27);
        for (uint32_t& t : triangles) t = in.u8() % 10;
        d.mesh_vertices_xyz_m = in.u8() < 8 ? nullptr : vertices.data();
        d.mesh_triangles = triangles.data();
        d.mesh_vertex_count = static_cast<uint32_t>(vertices.size() / 3);
        d.mesh_triangle_count = static_cast<uint32_t>(triangles.size() / 3);
        if (in.u8() == 255) d.mesh_triangle_count = (1u << 24) + 1 + in.u32() % 1000000000u;
        d.mesh_voxel_size_m = in.u8() < 128 ? 0.0 : in.number(0.005);
    }
    for (double& p : d.position_m) p = in.number(0.01) - 0.01;
    if (in.u8() >= 200)
        for (double& q : d.orientation_wxyz) q = in.number(0.5);
    d.friction = in.number(0.3) - 0.1;
    if (in.u8() == 255) d.struct_size = in.u32();
    const std::vector<double> before = control_points(scene);
    const ent_status status = ent_scene_add_obstacle(scene, &d, nullptr);
    check_status(status);
    if (status != ENT_OK && std::memcmp(before.data(), control_points(scene).data(), before.size() * sizeof(double)))
        fail("a failing add_obstacle changed the control points");
}

// The calls of moving anatomy, between steps. None moves the bowel by itself.
void anatomy_call(Bytes& in, ent_scene* scene) {
    const uint8_t what = in.u8();
    // what % 11: the call; bits 4-5: obstacle 0-2 or none (-1); bit 7: an arbitrary id instead.
    const int32_t obstacle = what & 0x80 ? static_cast<int32_t>(in.u32()) : int32_t((what >> 4) % 4) - 1;
    const std::vector<double> before = control_points(scene);
    ent_status status = ENT_OK;
    switch (what % 11) {
        case 0: {
            double position[3], orientation[4] = {1.0, 0.0, 0.0, 0.0};
            for (double& p : position) p = in.number(0.01) - 0.01;
            if (in.u8() >= 200)
                for (double& q : orientation) q = in.number(0.5);
            status = ent_obstacle_set_pose(scene, obstacle, position, orientation);
            break;
        }
        case 1: {
            double linear[3], angular[3];
            for (double& v : linear) v = in.number(0.05) - 0.05;
            for (double& w : angular) w = in.number(0.5) - 0.5;
            status = ent_obstacle_set_velocity(scene, obstacle, linear, angular);
            break;
        }
        case 2: status = ent_obstacle_set_friction(scene, obstacle, in.number(0.3) - 0.1); break;
        case 3: status = ent_scene_remove_obstacle(scene, obstacle); break;
        case 4: {
            double g[3];
            for (double& c : g) c = in.number(3.0) - 3.0;
            status = ent_scene_set_gravity(scene, g);
            break;
        }
        case 5: status = ent_scene_pin_point(scene, in.u8() % 40, obstacle); break;
        case 6: status = ent_scene_unpin_point(scene, in.u8() % 40); break;
        case 7: status = ent_scene_attach_mesentery(scene, obstacle); break;
        case 10: status = ent_scene_attach_clamped_end(scene, int32_t(in.u8() % 5), obstacle); break;
        case 8: {
            double position[3], orientation[4];
            status = ent_obstacle_pose(scene, obstacle, position, orientation);
            if (status == ENT_OK)
                for (double v : {position[0], position[1], position[2], orientation[0], orientation[1],
                                 orientation[2], orientation[3]})
                    if (!std::isfinite(v)) fail("an obstacle pose is not finite");
            uint32_t count = 0;
            check_status(ent_scene_obstacle_count(scene, &count));
            break;
        }
        default: {
            uint32_t vertices = 0, triangles = 0;
            status = ent_obstacle_mesh(scene, obstacle, 0, nullptr, &vertices, 0, nullptr, &triangles);
            if (status != ENT_OK) break;
            std::vector<double> v(3 * std::size_t{vertices});
            std::vector<uint32_t> t(3 * std::size_t{triangles});
            status = ent_obstacle_mesh(scene, obstacle, vertices, v.data(), &vertices, triangles, t.data(), &triangles);
            if (status != ENT_OK) fail("ent_obstacle_mesh failed with the capacity it asked for");
            for (uint32_t index : t)
                if (index >= vertices) fail("an obstacle mesh index is past its vertices");
            break;
        }
    }
    check_status(status);
    if (std::memcmp(before.data(), control_points(scene).data(), before.size() * sizeof(double)) != 0)
        fail("a moving-anatomy call changed the control points");
}

ent_skin* create_skin(Bytes& in, ent_scene* scene) {
    ent_skin_desc d;
    ent_skin_desc_default(&d);
    d.method = static_cast<int32_t>(in.u8() % 4);
    // Mostly modest resolutions (a fine skin of a long bowel is legal but slow to fuzz).
    d.segments = in.u8() < 250 ? 3 + in.u8() % 30 : in.u32();
    d.ring_spacing_radii = in.number(1.0);
    d.cap_rings = in.u8() % 70;
    d.skeleton_spacing_radii = in.number(0.5);
    d.voxel_size_radii = in.number(0.5);
    d.window_radii = in.number(1.0);
    if (in.u8() == 255) d.struct_size = in.u32();
    ent_skin* skin = nullptr;
    const ent_status status = ent_skin_create(scene, &d, &skin);
    check_status(status);
    if ((status == ENT_OK) != (skin != nullptr)) fail("out_skin and status disagree");
    return skin;
}

void update_skin(ent_skin* skin) {
    const ent_status status = ent_skin_update(skin);
    check_status(status);
    if (status != ENT_OK) return;
    ent_mesh_view v;
    v.struct_size = sizeof v;
    if (ent_skin_mesh(skin, &v) != ENT_OK) fail("mesh");
    for (uint32_t i = 0; i < 3 * v.vertex_count; ++i)
        if (!std::isfinite(v.positions_xyz_m[i]) || !std::isfinite(v.normals_xyz[i])) fail("a skin vertex is not finite");
    for (uint32_t i = 0; i < 3 * v.triangle_count; ++i)
        if (v.indices[i] >= v.vertex_count) fail("a mesh index is past the vertices");
}

void tool_call(Bytes& in, ent_scene* scene) {
    const uint8_t what = in.u8();
    // Bits 0-2: the call; bits 3-4: tool 0, 1 or 2; bit 7: an arbitrary id instead.
    const int32_t tool = what & 0x80 ? static_cast<int32_t>(in.u32()) : (what >> 3) % 3;
    const std::vector<double> before = control_points(scene);
    ent_status status = ENT_OK;
    switch (what % 8) {
        case 0: {
            double position[3], orientation[4] = {1.0, 0.0, 0.0, 0.0};
            for (double& p : position) p = in.number(0.05) - 0.05;
            if (in.u8() >= 200)
                for (double& q : orientation) q = in.number(0.5);
            status = ent_tool_set_pose(scene, tool, position, orientation);
            break;
        }
        case 1: status = ent_tool_grasp(scene, tool); break;
        case 2: status = ent_tool_release(scene, tool); break;
        case 3: {
            double force[3], torque[3];
            status = ent_tool_wrench(scene, tool, force, torque);
            if (status == ENT_OK)
                for (int c = 0; c < 3; ++c)
                    if (!std::isfinite(force[c]) || !std::isfinite(torque[c])) fail("a tool wrench is not finite");
            break;
        }
        case 4: {
            int32_t grasping = -1;
            status = ent_tool_state(scene, tool, &grasping);
            if (status == ENT_OK && grasping != 0 && grasping != 1) fail("ent_tool_state gave neither 0 nor 1");
            break;
        }
        default: {
            ent_tool_desc d;
            ent_tool_desc_default(&d);
            d.radius_m = in.number(0.005);
            d.length_m = in.number(0.3);
            d.max_force_N = in.number(5.0);
            d.grasp_margin_m = in.number(0.005);
            d.grasp_stiffness_N_per_m = in.number(200.0);
            d.grasp_damping_N_s_per_m = in.number(2.0);
            for (double& p : d.position_m) p = in.number(0.05) - 0.05;
            if (in.u8() >= 200)
                for (double& q : d.orientation_wxyz) q = in.number(0.5);
            if (in.u8() == 255) d.struct_size = in.u32();
            status = ent_tool_add(scene, &d, nullptr);
            break;
        }
    }
    check_status(status);
    // No tool call moves the bowel by itself (a pose, a grasp take effect in the next step).
    if (std::memcmp(before.data(), control_points(scene).data(), before.size() * sizeof(double)) != 0)
        fail("a tool call changed the control points");
}

void query(Bytes& in, const ent_scene* scene, const ent_skin* skin) {
    switch (in.u8() % 5) {
        case 0: {
            const uint32_t count = in.u8() * 3u;
            std::vector<double> axis(3 * std::size_t{count} + 3);
            const ent_status status = ent_scene_axis(scene, count, axis.data());
            check_status(status);
            if (status == ENT_OK)
                for (std::size_t i = 0; i < 3 * std::size_t{count}; ++i)
                    if (!std::isfinite(axis[i])) fail("an axis sample is not finite");
            // The same count for intestine -1, 0 or 1 (no further input read): intestine 0 is
            // the axis; the others do not exist in the scenes this fuzzer makes, and are refused.
            const int32_t intestine = static_cast<int32_t>(count % 3) - 1;
            std::vector<double> tube(axis.size());
            const ent_status tube_status = ent_scene_intestine_axis(scene, intestine, count, tube.data());
            check_status(tube_status);
            if ((tube_status == ENT_OK) != (intestine == 0 && status == ENT_OK))
                fail("ent_scene_intestine_axis and ent_scene_axis disagree on what they accept");
            return;
        }
        case 1: {
            const uint32_t capacity = in.u8();
            std::vector<double> points(3 * std::size_t{capacity} + 3);
            uint32_t count = 0;
            check_status(ent_scene_control_points(scene, capacity, in.u8() < 16 ? nullptr : points.data(), &count));
            return;
        }
        case 2: {
            // Room past any size: the library must not write beyond the struct_size it accepts.
            unsigned char buffer[sizeof(ent_stats) + 64];
            std::memset(buffer, 0xa5, sizeof buffer);
            const uint32_t size = in.u8() < 200 ? uint32_t{sizeof(ent_stats)} : in.u32();
            std::memcpy(buffer, &size, sizeof size);
            check_status(ent_scene_stats(scene, reinterpret_cast<ent_stats*>(buffer)));
            for (std::size_t i = sizeof(ent_stats); i < sizeof buffer; ++i)
                if (buffer[i] != 0xa5) fail("ent_scene_stats wrote past the struct");
            return;
        }
        case 3: {
            ent_effect_stats e;
            e.struct_size = sizeof e;
            check_status(ent_scene_effect_stats(scene, static_cast<int32_t>(in.u32()), &e));
            return;
        }
        default: {
            if (skin == nullptr) return;
            struct ent_skin_metrics m;
            m.struct_size = sizeof m;
            check_status(ent_skin_metrics(skin, &m));
            return;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Bytes in(data, size);
    ent_scene* scene = nullptr;
    const uint8_t base = in.u8();
    ent_status status;
    if (base % (kBaseSceneCount + 1) < kBaseSceneCount) {
        const char* json = kBaseScenes[base % (kBaseSceneCount + 1)];
        status = ent_scene_create_json(json, std::strlen(json), &scene);
        if (status != ENT_OK) fail("a base scene failed to load");
    } else {
        status = create_from_desc(in, &scene);
        check_status(status);
        if (status != ENT_OK) return 0;
    }
    check_finite_state(scene);

    constexpr int kMaxSkins = 2;
    ent_skin* skins[kMaxSkins] = {nullptr, nullptr};
    for (int op = 0; op < 64 && !in.empty(); ++op) {
        const uint8_t code = in.u8();
        ent_skin*& skin = skins[code & 1];
        switch ((code >> 1) % 10) {
            case 0:
            case 1:
            case 2: step(in, scene); break;
            case 3: add_obstacle(in, scene); break;
            case 4:
                ent_skin_destroy(skin);
                skin = create_skin(in, scene);
                break;
            case 5:
                if (skin != nullptr) update_skin(skin);
                break;
            case 6:
                ent_skin_destroy(skin);
                skin = nullptr;
                break;
            case 7: query(in, scene, skin); break;
            case 8: tool_call(in, scene); break;
            default: anatomy_call(in, scene); break;
        }
    }
    for (ent_skin* skin : skins) ent_skin_destroy(skin);
    ent_scene_destroy(scene);
    return 0;
}
