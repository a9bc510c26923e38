// SPDX-License-Identifier: Apache-2.0
// Checks of the MuJoCo peer against what must hold whatever MuJoCo's contact model does:
// the chain starts exactly on the given axis, its free fall follows g t^2 / 2 (internal
// joint forces cannot move the centre of mass), a pinned end stays put, the
// arc-length axis spans the rope's length, drag gives the analytic terminal speed and is
// MuJoCo's own mapping of the segment forces, and the stretch joints give the analytic
// extension of a hanging rope. Built and run only with ENTERON_BENCH_MUJOCO.
#include "peers/mujoco_rope.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using enteron::peers::MujocoRope;
using enteron::peers::MujocoRopeDesc;

ent_scene_desc scene_desc(uint32_t points) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.control_points = points;
    desc.length_m = 1.0;
    desc.shape = ENT_SHAPE_LINE;
    return desc;
}

std::unique_ptr<MujocoRope> make(const MujocoRopeDesc& desc) {
    std::string error;
    auto rope = MujocoRope::create(desc, &error);
    EXPECT_NE(rope, nullptr) << error;
    return rope;
}

// The joint points of a rope before and after falling (or swinging) for `seconds`.
struct Motion {
    std::vector<double> before, after;
    double t = 0.0;  // the time reached
    bool finite = false;
    int contacts = -1;
};
Motion run_for(const MujocoRopeDesc& desc, double seconds) {
    Motion motion;
    auto rope = make(desc);
    if (!rope) return motion;
    rope->joint_points(motion.before);
    motion.finite = rope->advance_to(seconds) && rope->finite();
    rope->joint_points(motion.after);
    motion.t = rope->time_s();
    motion.contacts = rope->contacts();
    return motion;
}

double mean_z(const std::vector<double>& points) {
    double z = 0.0;
    for (std::size_t i = 2; i < points.size(); i += 3) z += points[i];
    return z / static_cast<double>(points.size() / 3);
}

TEST(MujocoRope, StartsOnTheGivenAxis) {
    // A bent polyline: a quarter circle of radius 0.2 m, then a straight leg.
    const uint32_t n = 21;
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(n));
    const double l = desc.length_m / (n - 1);
    desc.initial_points_xyz_m.assign(3 * n, 0.0);
    double heading = 0.0;
    for (uint32_t i = 1; i < n; ++i) {
        heading += i < 10 ? l / 0.2 : 0.0;
        desc.initial_points_xyz_m[3 * i + 0] = desc.initial_points_xyz_m[3 * (i - 1) + 0] + l * std::cos(heading);
        desc.initial_points_xyz_m[3 * i + 1] = desc.initial_points_xyz_m[3 * (i - 1) + 1] + l * 0.6 * std::sin(heading);
        desc.initial_points_xyz_m[3 * i + 2] = desc.initial_points_xyz_m[3 * (i - 1) + 2] + l * 0.8 * std::sin(heading);
    }
    auto rope = make(desc);
    ASSERT_NE(rope, nullptr);
    std::vector<double> points;
    rope->joint_points(points);
    ASSERT_EQ(points.size(), desc.initial_points_xyz_m.size());
    for (std::size_t k = 0; k < points.size(); ++k) EXPECT_NEAR(points[k], desc.initial_points_xyz_m[k], 1e-9) << k;
}

TEST(MujocoRope, FallsFreelyLikeItsCentreOfMass) {
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(31));
    ASSERT_EQ(desc.initial_points_xyz_m.size(), 3u * 31);  // the line shape gives the axis
    const Motion motion = run_for(desc, 0.2);
    ASSERT_TRUE(motion.finite);
    EXPECT_EQ(motion.contacts, 0);
    const std::vector<double>& before = motion.before;
    const std::vector<double>& after = motion.after;
    // Joint forces are internal: every point of the unsupported rope falls g t^2 / 2, to
    // within the first-order integrator's lag of a step, g t h. Without contacts nothing
    // else acts; a wrong mass, gravity or joint placement would show here.
    const double t = motion.t;
    const double h = desc.timestep_s;
    EXPECT_NEAR(mean_z(after) - mean_z(before), -0.5 * 9.81 * t * t, 9.81 * t * h);
    for (std::size_t k = 0; k < after.size(); k += 3) {
        EXPECT_NEAR(after[k], before[k], 1e-9);  // a horizontal rope falls straight down
        EXPECT_NEAR(after[k + 2] - before[k + 2], -0.5 * 9.81 * t * t, 9.81 * t * h);
    }
}

TEST(MujocoRope, PinnedEndStaysAndTheAxisKeepsItsLength) {
    ent_scene_desc scene = scene_desc(21);
    scene.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    scene.pinned_ends = ENT_PIN_FIRST;
    const MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene);
    ASSERT_TRUE(desc.pin_first);
    auto rope = make(desc);
    ASSERT_NE(rope, nullptr);
    ASSERT_TRUE(rope->advance_to(0.3));
    std::vector<double> points, axis;
    rope->joint_points(points);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(points[c], desc.initial_points_xyz_m[c], 1e-9);
    EXPECT_LT(points[3 * 20 + 2], -0.05);  // the free end swung down
    rope->axis(101, axis);
    ASSERT_EQ(axis.size(), 3u * 101);
    double length = 0.0;
    for (std::size_t i = 1; i < 101; ++i) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) d2 += (axis[3 * i + c] - axis[3 * i - 3 + c]) * (axis[3 * i + c] - axis[3 * i - 3 + c]);
        length += std::sqrt(d2);
    }
    EXPECT_NEAR(length, desc.length_m, 0.01 * desc.length_m);  // rigid segments; chords cut corners
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(axis[3 * 100 + c], points[3 * 20 + c], 1e-12);
}

TEST(MujocoRope, DragGivesTheTerminalSpeedOfALine) {
    // A horizontal rope falling with drag c per metre: every point follows
    // v(t) = v_t (1 - exp(-t / tau)), v_t = mu g / c, tau = mu / c (the rope stays straight
    // and level, so the drag is the same on every metre). Tests the drag callback's force
    // and its projection onto the free root's degrees of freedom.
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(21));
    desc.drag_N_s_per_m2 = 1.0;
    const Motion motion = run_for(desc, 0.6);
    ASSERT_TRUE(motion.finite);
    const std::vector<double>& before = motion.before;
    const std::vector<double>& after = motion.after;
    const double t = motion.t;
    const double tau = desc.linear_density_kg_per_m / desc.drag_N_s_per_m2;
    const double v_t = 9.81 * tau;
    const double fall = v_t * (t - tau * (1.0 - std::exp(-t / tau)));  // 1.01 m; 1.77 m without drag
    for (std::size_t k = 0; k < after.size(); k += 3) {
        EXPECT_NEAR(after[k], before[k], 1e-9);
        EXPECT_NEAR(before[k + 2] - after[k + 2], fall, 9.81 * t * desc.timestep_s);
    }
}

TEST(MujocoRope, DragIsMujocosOwnMappingOfTheSegmentForces) {
    // The drag callback accumulates the generalised force from the leaves to the root
    // (O(N)); MuJoCo's own mj_applyFT, body by body, must give the same on a bent, moving,
    // stretching chain with a free root: force -c l v at each capsule's centre, torque
    // -c l^3 / 12 omega across its axis.
    const uint32_t n = 12;
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(n));
    desc.stretch_stiffness_N = 50.0;
    desc.drag_N_s_per_m2 = 0.7;
    auto rope = make(desc);  // installs the callback
    ASSERT_NE(rope, nullptr);
    char error[1000] = "";
    auto vfs = std::make_unique<mjVFS>();  // large: on the heap
    mj_defaultVFS(vfs.get());
    ASSERT_EQ(mj_makeEmptyFileVFS(vfs.get(), "rope.xml", static_cast<int>(rope->xml().size())), 0);
    std::copy(rope->xml().begin(), rope->xml().end(),
              static_cast<char*>(vfs->filedata[mj_findFileVFS(vfs.get(), "rope.xml")]));
    mjModel* m = mj_loadXML("rope.xml", vfs.get(), error, sizeof error);
    mj_deleteVFS(vfs.get());
    ASSERT_NE(m, nullptr) << error;
    mjData* d = mj_makeData(m);
    for (int i = 7; i < m->nq; ++i) d->qpos[i] += 0.1 * std::sin(3.0 * i);  // past the free joint
    for (int i = 0; i < m->nv; ++i) d->qvel[i] = 0.5 * std::cos(1.7 * i);
    mj_forward(m, d);
    const std::vector<mjtNum> with(d->qfrc_passive, d->qfrc_passive + m->nv);
    const mjfGeneric callback = mjcb_passive;
    mjcb_passive = nullptr;
    mj_forward(m, d);
    mjcb_passive = callback;
    std::vector<mjtNum> expected(d->qfrc_passive, d->qfrc_passive + m->nv);
    const double c = desc.drag_N_s_per_m2, l = desc.length_m / (n - 1);
    for (int b = 1; b < m->nbody; ++b) {
        mjtNum velocity[6];  // [angular, linear] at the body's origin, the capsule's centre
        mj_objectVelocity(m, d, mjOBJ_BODY, b, velocity, 0);
        const mjtNum axis[3] = {d->xmat[9 * b], d->xmat[9 * b + 3], d->xmat[9 * b + 6]};
        const mjtNum spin = mju_dot3(velocity, axis);
        mjtNum force[3], torque[3];
        for (int k = 0; k < 3; ++k) {
            force[k] = -c * l * velocity[3 + k];
            torque[k] = -c * l * l * l / 12.0 * (velocity[k] - spin * axis[k]);
        }
        mj_applyFT(m, d, force, torque, d->xipos + 3 * b, b, expected.data());
    }
    double largest = 0.0;
    for (int i = 0; i < m->nv; ++i) {
        EXPECT_NEAR(with[i], expected[i], 1e-12) << i;
        largest = std::max(largest, std::fabs(expected[i]));
    }
    EXPECT_GT(largest, 0.1);  // the drag is not negligible here
    mj_deleteData(d);
    mj_deleteModel(m);
}

TEST(MujocoRope, StretchJointsHangAsTheDiscreteWeightSays) {
    // A rope of N points pinned at its top, hanging straight down with stretch stiffness
    // EA: at rest, the joint below segment k carries the weight of the N - 1 - k segments
    // under it, so the rope lengthens by mu g l^2 (N - 1)(N - 2) / (2 EA), the continuous
    // mu g L^2 / (2 EA) times (N - 2) / (N - 1). Drag and stretch damping settle it.
    const uint32_t n = 21;
    ent_scene_desc scene = scene_desc(n);
    scene.effects |= ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    scene.pinned_ends = ENT_PIN_FIRST;
    scene.shape_direction[0] = 0.0;
    scene.shape_direction[1] = 0.0;
    scene.shape_direction[2] = -1.0;
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene);
    desc.stretch_stiffness_N = 10.0;
    desc.stretch_damping_N_s = 0.5;
    desc.drag_N_s_per_m2 = 1.0;
    const Motion motion = run_for(desc, 6.0);
    ASSERT_TRUE(motion.finite);
    const std::vector<double>& points = motion.after;
    const double l = desc.length_m / (n - 1);
    const double stretch =
        desc.linear_density_kg_per_m * 9.81 * l * l * (n - 1) * (n - 2) / (2.0 * desc.stretch_stiffness_N);
    EXPECT_NEAR(points[3 * (n - 1) + 2] - points[2], -(desc.length_m + stretch), 1e-3 * stretch);
    EXPECT_NEAR(points[3 * (n - 1)], points[0], 1e-9);
    EXPECT_NEAR(points[3 * (n - 1) + 1], points[1], 1e-9);
}

TEST(MujocoRope, RefusesAWrongAxis) {
    MujocoRopeDesc desc = enteron::peers::mujoco_rope_desc_from(scene_desc(10));
    desc.initial_points_xyz_m.resize(6);
    std::string error;
    EXPECT_EQ(MujocoRope::create(desc, &error), nullptr);
    EXPECT_NE(error.find("initial_points_xyz_m"), std::string::npos) << error;
}

}  // namespace
