// SPDX-License-Identifier: Apache-2.0
// The tool as a haptic device renders it (issue 18, docs/haptics.md): the wrench is minus
// what the bowel received in the accepted step (no click at a reversal with friction), the
// proxy keeps the tool out of the tube however fast the device moves and renders a force
// within its bound, the passivity observer's balance stays non-negative on closed paths
// (and the limiter keeps it so), and tools can be removed and counted.
#include "capi_scenes.h"

#include <array>
#include <cstring>
#include <iostream>
#include <string>
#include <utility>

#include "../../bench/skin_piles.h"
#include "test_helpers.h"

using namespace capi_test;

namespace {

using enteron_test::kIdentity;
using enteron_test::norm3;

constexpr double kToolHapticsRadius = kBowelRadius;  // the default R, m


ent_tool_feedback feedback(const ent_scene* scene, int32_t tool) {
    ent_tool_feedback f{};
    f.struct_size = sizeof f;
    EXPECT_EQ(ent_tool_read_feedback(scene, tool, &f), ENT_OK) << ent_last_error();
    return f;
}

// The force rendered in the last step (ent_tool_wrench): what the continuity measures read,
// so that they run on an older library too (docs/haptics.md's "before" columns).
struct RenderedForce {
    double force_N[3];
};
RenderedForce rendered(const ent_scene* scene, int32_t tool) {
    RenderedForce f{};
    double torque[3];
    EXPECT_EQ(ent_tool_wrench(scene, tool, f.force_N, torque), ENT_OK) << ent_last_error();
    return f;
}

ent_tool_stats tool_stats(const ent_scene* scene, int32_t tool) {
    ent_tool_stats s{};
    s.struct_size = sizeof s;
    EXPECT_EQ(ent_tool_read_stats(scene, tool, &s), ENT_OK) << ent_last_error();
    return s;
}

// A straight bowel of `length` m along x centred on the origin, resting on the plane z = 0,
// with `points` control points and the default stiffnesses, damping and friction; settled.
ScenePtr bowel_on_floor(double length, uint32_t points, double dt, int32_t integrator = ENT_INTEGRATOR_IMPLICIT_EULER,
                        int32_t clamped_ends = ENT_PIN_NONE) {
    BowelOnPlane bowel;
    bowel.length_m = length;
    bowel.control_points = points;
    bowel.integrator = integrator;
    bowel.clamped_ends = clamped_ends;
    bowel.settle_s = 0.2;
    bowel.dt_s = dt;
    return bowel_on_plane(bowel);
}

// The demo's 6 m bowel (240 control points, self-collision, mesentery, in its cavity)
// settled for 2 s in 1 ms steps (bench/skin_piles.h), made once and saved; each call gives
// a fresh scene restored to it (to be stepped at any dt).
ScenePtr settled_pile() {
    static const std::vector<unsigned char> saved = [] {
        std::vector<unsigned char> bytes;
        ScenePtr pile(enteron::bench::settle_pile(enteron::bench::kDemoPile));
        EXPECT_TRUE(pile) << ent_last_error();
        if (!pile) return bytes;
        size_t size = 0;
        EXPECT_EQ(ent_scene_save_state(pile.get(), nullptr, 0, &size), ENT_OK) << ent_last_error();
        bytes.resize(size);
        EXPECT_EQ(ent_scene_save_state(pile.get(), bytes.data(), bytes.size(), &size), ENT_OK) << ent_last_error();
        return bytes;
    }();
    ScenePtr scene = create_json(enteron::bench::kDemoPile.json);
    if (!scene || saved.empty()) return nullptr;
    EXPECT_EQ(ent_scene_restore_state(scene.get(), saved.data(), saved.size()), ENT_OK) << ent_last_error();
    return scene;
}

int32_t add_tool(ent_scene* scene, const double p[3], double radius, double max_force, int32_t mode,
                 int32_t limiter = 0) {
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    desc.radius_m = radius;
    desc.max_force_N = max_force;
    desc.mode = mode;
    desc.passivity_limiter = limiter;
    for (int c = 0; c < 3; ++c) desc.position_m[c] = p[c];
    int32_t id = -1;
    EXPECT_EQ(ent_tool_add(scene, &desc, &id), ENT_OK) << ent_last_error();
    return id;
}

// The largest change per tick of the rendered force, its RMS and the largest force, over a
// scripted path of the tool.
struct Continuity {
    double peak = 0.0;
    double largest_change = 0.0;
    double rms_change = 0.0;
};

// The issue's reversal: a 1 m bowel on the floor (40 control points), a vertical tool
// (radius 2.5 mm, max_force 8 N) pressed 15 mm into it at 50 mm/s and pulled back.
Continuity reversal(double dt, int32_t mode, double max_force) {
    Continuity out;
    ScenePtr scene = bowel_on_floor(1.0, 40, dt);
    if (!scene) return out;
    const double r = 0.0025, top = 2 * kToolHapticsRadius + r, speed = 0.05, depth = 0.015;
    const double start[3] = {0.0, 0.0, top + 0.002};
    add_tool(scene.get(), start, r, max_force, mode);
    const int down = int(std::lround((depth + 0.002) / speed / dt));
    std::array<double, 3> previous{};
    double sum2 = 0.0;
    int ticks = 0;
    for (int i = 1; i <= 2 * down; ++i) {
        const double travel = (i <= down ? i : 2 * down - i) * speed * dt;
        const double p[3] = {0.0, 0.0, start[2] - travel};
        EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
        EXPECT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
        const RenderedForce f = rendered(scene.get(), 0);
        const double change[3] = {f.force_N[0] - previous[0], f.force_N[1] - previous[1], f.force_N[2] - previous[2]};
        const double c = norm3(change);
        out.largest_change = std::max(out.largest_change, c);
        sum2 += c * c;
        ++ticks;
        out.peak = std::max(out.peak, norm3(f.force_N));
        std::copy(f.force_N, f.force_N + 3, previous.begin());
    }
    out.rms_change = std::sqrt(sum2 / std::max(1, ticks));
    return out;
}

TEST(ToolHaptics, NoClickAtAReversalWithFriction) {
    // The proxy (the default) with the issue's 8 N, which the coupling reaches before the
    // turnaround, and with 50 N, which it does not: the force through the turnaround is
    // the coupling's, unsaturated. Direct mode is reported beside them (docs/haptics.md).
    struct Case {
        int32_t mode;
        double max_force;
    };
    for (const Case& c : {Case{ENT_TOOL_MODE_PROXY, 8.0}, Case{ENT_TOOL_MODE_PROXY, 50.0}, Case{ENT_TOOL_MODE_DIRECT, 8.0}}) {
        for (double dt : {1e-3, 0.5e-3}) {
            const Continuity r = reversal(dt, c.mode, c.max_force);
            std::cout << "[ reversal " << (c.mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") << " max_force "
                      << c.max_force << " N, dt " << dt * 1e3 << " ms ] peak " << r.peak
                      << " N, largest change per tick " << r.largest_change << " N, RMS " << r.rms_change << " N\n";
            EXPECT_GT(r.peak, 1.0) << "the tool pressed the bowel";
            if (c.max_force > 10.0) {
                EXPECT_LT(r.peak, 0.9 * c.max_force) << "unsaturated";
            }
            // Issue 18: within 5 % of the peak force per tick, with friction on, at 1 ms.
            if (c.mode == ENT_TOOL_MODE_PROXY) {
                EXPECT_LE(r.largest_change, 0.05 * r.peak) << c.max_force << " N, dt " << dt;
            }
        }
    }
}

// The force continuity suite (issue 18): a proxy tool (radius 2.5 mm, max_force 8 N) on
// the 1 m bowel on the floor, or in the settled demo pile ("drag"), each scenario a path of
// the commanded tip; the largest change of the rendered force per tick against 5 % of the
// scenario's peak. The release of a held load is reported but exempt: the weight really
// lets go. Issue 27 added fast presses that turn back within one tick: "fast press" (5 mm
// in at 80 mm/s and straight back), "reversal aside" (the same, turning back along a path
// 2 mm aside of the way in, twice): 0.21 N in one tick before (5.9 % of 3.55 N), of which
// the motion itself is 0.057 N; the rest was the coupling's damper (docs/haptics.md).
Continuity scenario(const char* name, double dt) {
    Continuity out;
    const double r = 0.0025, top = 2 * kToolHapticsRadius + r;
    const std::string which = name;
    ScenePtr scene = which == "drag" ? settled_pile() : bowel_on_floor(1.0, 40, dt);
    if (!scene) return out;
    // path(t) for t in [0, duration]; grasp and release at given times.
    double duration = 0.0, grasp_at = -1.0, release_at = -1.0;
    // The fast presses: straight lines at 80 mm/s through these (x, z) points, turning back
    // at once at the bottom of each.
    const double above = top + 0.002, in = top - 0.005, fast = 0.08;
    std::vector<std::array<double, 2>> corners;
    if (which == "fast press") corners = {{0.0, above}, {0.0, in}, {0.0, above}};
    if (which == "reversal aside") corners = {{0.0, above}, {0.0, in}, {0.002, above}, {0.002, in}, {0.004, above}};
    const auto along_corners = [&](double t, double p[3]) {
        double left = fast * t;
        for (std::size_t k = 1; k < corners.size(); ++k) {
            const double dx = corners[k][0] - corners[k - 1][0], dz = corners[k][1] - corners[k - 1][1];
            const double length = std::hypot(dx, dz);
            const double a = std::min(1.0, left / length);
            p[0] = corners[k - 1][0] + a * dx;
            p[2] = corners[k - 1][1] + a * dz;
            if (left <= length) return;
            left -= length;
        }
    };
    auto path = [&](double t, double p[3]) {
        p[0] = p[1] = 0.0;
        // A device starts and stops smoothly (smoothstep): a step of the commanded velocity
        // would step the dampers' force, which is what the bowel really gives.
        const auto smooth = [](double u) {
            u = std::clamp(u, 0.0, 1.0);
            return u * u * (3.0 - 2.0 * u);
        };
        if (which == "onset") {  // down onto the bowel at 50 mm/s, 5 mm in
            p[2] = top + 0.005 - 0.05 * t;
        } else if (which == "slide") {  // 3 mm in, then 20 cm along the bowel (0.15 m/s at most)
            p[2] = top - 0.003 * smooth(t / 0.1);
            p[0] = -0.1 + 0.2 * smooth((t - 0.2) / 2.0);
        } else if (which == "drag") {  // down into the coil's free middle, out through its wall (+y)
            p[2] = 0.1 - 0.2 * smooth(t / 1.0);
            p[1] = 0.12 * smooth((t - 1.0) / 2.0);
        } else if (!corners.empty()) {
            along_corners(t, p);
        } else {  // grasp, lift 3 cm (75 mm/s at most), hold, release
            p[2] = top + 0.001 + 0.03 * smooth((t - 0.1) / 0.6);
        }
    };
    if (which == "onset") duration = 0.2;
    if (which == "slide") duration = 2.2;
    if (which == "drag") duration = 3.2;
    if (which == "grasp" || which == "release") duration = 1.2, grasp_at = 0.05, release_at = 1.0;
    if (which == "fast press") duration = 0.2;
    if (which == "reversal aside") duration = 0.4;
    double p[3];
    path(0.0, p);
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    desc.radius_m = r;
    desc.max_force_N = 8.0;
    for (int c = 0; c < 3; ++c) desc.position_m[c] = p[c];
    EXPECT_EQ(ent_tool_add(scene.get(), &desc, nullptr), ENT_OK) << ent_last_error();
    std::array<double, 3> previous{};
    double sum2 = 0.0;
    int ticks = 0;
    const int steps = int(std::lround(duration / dt));
    for (int i = 1; i <= steps; ++i) {
        const double t = i * dt;
        path(t, p);
        if (grasp_at >= 0.0 && std::fabs(t - grasp_at) < 0.5 * dt) {
            EXPECT_EQ(ent_tool_grasp(scene.get(), 0), ENT_OK);
        }
        if (release_at >= 0.0 && std::fabs(t - release_at) < 0.5 * dt) {
            EXPECT_EQ(ent_tool_release(scene.get(), 0), ENT_OK);
        }
        EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
        EXPECT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
        const RenderedForce f = rendered(scene.get(), 0);
        const double change[3] = {f.force_N[0] - previous[0], f.force_N[1] - previous[1], f.force_N[2] - previous[2]};
        const double c = norm3(change);
        // The release scenario counts only the ticks around the release; grasp only before it.
        const bool counted = which == "release" ? std::fabs(t - release_at) < 0.01 : (release_at < 0.0 || t < release_at - dt);
        if (counted) {
            out.largest_change = std::max(out.largest_change, c);
            sum2 += c * c;
            ++ticks;
        }
        out.peak = std::max(out.peak, norm3(f.force_N));
        std::copy(f.force_N, f.force_N + 3, previous.begin());
    }
    out.rms_change = std::sqrt(sum2 / std::max(1, ticks));
    return out;
}

TEST(ToolHaptics, ForceContinuitySuite) {
    std::cout << "| scenario | dt ms | peak N | largest change per tick N | RMS change N | bound (5 % of peak) |\n";
    for (const char* name : {"onset", "slide", "grasp", "drag", "release", "fast press", "reversal aside"}) {
        for (double dt : {1e-3, 0.5e-3}) {
            const Continuity c = scenario(name, dt);
            std::cout << "| " << name << " | " << dt * 1e3 << " | " << c.peak << " | " << c.largest_change << " | "
                      << c.rms_change << " | " << 0.05 * c.peak << " |\n";
            EXPECT_GT(c.peak, 0.05) << name;
            // Within 5 % of the peak per tick (docs/haptics.md, "Force continuity"), but for
            // the release of a held load, which really lets go.
            const double bound = std::string(name) == "release" ? 1.0 : 0.05;
            EXPECT_LE(c.largest_change, bound * c.peak) << name << ", dt " << dt;
        }
    }
}

TEST(ToolHaptics, AClosingGraspIsSavedAndRestored) {
    // A grasp taken 1 mm away closes over the next steps; a second tool never grasps. Saved
    // mid-closing, restored: the same forces to the bit (the rest length is state).
    const double dt = 1e-3, r = 0.0025, top = 2 * kToolHapticsRadius + r;
    ScenePtr scene = bowel_on_floor(1.0, 40, dt);
    ASSERT_TRUE(scene);
    const double above[3] = {0.0, 0.0, top + 0.001}, away[3] = {0.3, 0.0, 0.1};
    add_tool(scene.get(), above, r, 8.0, ENT_TOOL_MODE_PROXY);
    add_tool(scene.get(), away, r, 8.0, ENT_TOOL_MODE_PROXY);
    ASSERT_EQ(ent_tool_grasp(scene.get(), 0), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), dt, 5));
    ASSERT_EQ(feedback(scene.get(), 0).grasping, 1);
    size_t size = 0;
    ASSERT_EQ(ent_scene_save_state(scene.get(), nullptr, 0, &size), ENT_OK);
    std::vector<unsigned char> saved(size);
    ASSERT_EQ(ent_scene_save_state(scene.get(), saved.data(), saved.size(), &size), ENT_OK) << ent_last_error();
    const auto run = [&] {
        std::vector<double> forces;
        for (int i = 1; i <= 60; ++i) {
            const double p[3] = {0.0, 0.0, top + 0.001 + 0.0002 * i};
            EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK);
            EXPECT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
            const ent_tool_feedback f = feedback(scene.get(), 0);
            forces.insert(forces.end(), f.force_N, f.force_N + 3);
        }
        return forces;
    };
    const std::vector<double> first = run();
    ASSERT_EQ(ent_scene_restore_state(scene.get(), saved.data(), size), ENT_OK) << ent_last_error();
    const std::vector<double> again = run();
    EXPECT_EQ(first, again);
    EXPECT_GT(std::fabs(first[3 * 59 + 2]), 0.05) << "the grasp held the bowel";
}

// The closest approach of the tool's surface (the shaft in the scene: the proxy's) to the
// bowel's axis, m: the distance from the axis to the shaft less the tool's radius.
double closest_approach(const ent_scene* scene, const double tip[3], double length, double radius,
                        uint32_t samples = 400) {
    std::vector<double> points(3 * samples);
    EXPECT_EQ(ent_scene_axis(scene, samples, points.data()), ENT_OK) << ent_last_error();
    double closest = 1e9;
    for (std::size_t i = 0; i < points.size(); i += 3) {
        // The shaft rises from the tip along +z (the identity orientation).
        const double along = std::clamp(points[i + 2] - tip[2], 0.0, length);
        const double dx = points[i] - tip[0], dy = points[i + 1] - tip[1], dz = points[i + 2] - (tip[2] + along);
        closest = std::min(closest, std::sqrt(dx * dx + dy * dy + dz * dz) - radius);
    }
    return closest;
}

TEST(ToolHaptics, TheProxyNeverPassesThroughTheBowelAndItsForceStaysBounded) {
    // A vertical tool (radius 2.5 mm) swept across a bowel on the floor, its tip at the
    // height of the bowel's axis: the device goes through, the tool in the scene does not.
    const double dt = 1e-3, r = 0.0025;
    for (double max_force : {5.0, 50.0}) {
        for (double speed : {0.1, 0.5, 2.0, 5.0}) {
            ScenePtr scene = bowel_on_floor(0.6, 25, dt);
            ASSERT_TRUE(scene);
            const double from[3] = {0.0, -0.05, kToolHapticsRadius}, length = 0.3;
            add_tool(scene.get(), from, r, max_force, ENT_TOOL_MODE_PROXY);
            const double travel = 0.10;  // to y = 5 cm, well beyond the tube
            const int steps = std::max(1, int(std::lround(travel / speed / dt)));
            double closest = 1e9, largest = 0.0;
            for (int i = 1; i <= steps + 50; ++i) {
                const double p[3] = {from[0], from[1] + travel * std::min(i, steps) / steps, from[2]};
                ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
                ASSERT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
                const ent_tool_feedback f = feedback(scene.get(), 0);
                largest = std::max(largest, norm3(f.force_N));
                closest = std::min(closest, closest_approach(scene.get(), f.proxy_position_m, length, r));
                EXPECT_EQ(f.commanded_position_m[1], p[1]);
            }
            std::cout << "[ sweep max_force " << max_force << " N, " << speed << " m/s ] closest approach to the axis "
                      << closest / kToolHapticsRadius << " R, largest force " << largest << " N\n";
            // Issue 18: the surface never comes closer to the axis than 0.8 R.
            EXPECT_GE(closest, 0.8 * kToolHapticsRadius) << speed << " m/s, " << max_force << " N";
            EXPECT_LE(largest, max_force * (1 + 1e-9));
            EXPECT_GT(largest, 0.05 * std::min(max_force, 5.0)) << "the bowel resisted";
        }
    }
}

// Issue 27, defect 6: a tool whose force max_force bounded says so (ent_tool_feedback's
// saturated), in proxy and in direct mode; one that never reaches it never does. Before,
// nothing said that 5.000 N was the bound and not what the bowel pushed.
TEST(ToolHaptics, AForceBoundedAtMaxForceIsSaidSaturated) {
    const double dt = 1e-3, r = 0.0025;
    for (const int32_t mode : {ENT_TOOL_MODE_PROXY, ENT_TOOL_MODE_DIRECT}) {
        for (const double max_force : {2.0, 50.0}) {
            SCOPED_TRACE(std::string(mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") + ", max_force " +
                         std::to_string(max_force));
            ScenePtr scene = bowel_on_floor(0.6, 25, dt);
            ASSERT_TRUE(scene);
            // Down 12 mm into the bowel at 50 mm/s, then held there.
            const double top = 2 * kToolHapticsRadius + r, start[3] = {0.0, 0.0, top + 0.002};
            add_tool(scene.get(), start, r, max_force, mode);
            int saturated = 0, at_bound = 0, at_bound_and_saturated = 0;
            double smallest_saturated = 1e9;
            for (int i = 1; i <= 600; ++i) {
                const double p[3] = {0.0, 0.0, start[2] - std::min(0.014, 0.05 * i * dt)};
                ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
                ASSERT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
                const ent_tool_feedback f = feedback(scene.get(), 0);
                ASSERT_TRUE(f.saturated == 0 || f.saturated == 1);
                saturated += f.saturated;
                if (f.saturated) smallest_saturated = std::min(smallest_saturated, norm3(f.force_N));
                if (norm3(f.force_N) >= max_force * (1 - 1e-9)) {
                    ++at_bound;
                    at_bound_and_saturated += f.saturated;
                }
            }
            std::cout << "[ saturated " << (mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") << " max_force "
                      << max_force << " N ] " << saturated << " steps saturated, " << at_bound
                      << " at the bound, smallest saturated force " << smallest_saturated << " N\n";
            if (max_force < 10.0) {
                EXPECT_GT(saturated, 100) << "held at the bound";
                EXPECT_EQ(at_bound_and_saturated, at_bound) << "every step at the bound says so";
            } else {
                EXPECT_EQ(saturated, 0) << "50 N is never reached";
            }
        }
    }
}

// Where the proxy is not solved with the bowel (both ends clamped; bdf2's second-order
// substeps) minus what the bowel received can exceed max_force (docs/haptics.md "The
// wrench"): the reported force is clipped to it. The sweep of the test above, faster: with
// bdf2 at 10 m/s minus what the bowel received reached 5.035 N against 5 N before the clip.
TEST(ToolHaptics, TheReportedForceNeverExceedsMaxForceWithClampedEndsOrBdf2) {
    const double dt = 1e-3, r = 0.0025, max_force = 5.0;
    for (const auto& [integrator, clamped] : {std::pair{ENT_INTEGRATOR_BDF2, ENT_PIN_NONE},
                                              std::pair{ENT_INTEGRATOR_IMPLICIT_EULER, ENT_PIN_BOTH}}) {
        for (double speed : {2.0, 5.0, 10.0}) {
            SCOPED_TRACE(std::to_string(integrator) + " clamped " + std::to_string(clamped) + ", " +
                         std::to_string(speed) + " m/s");
            ScenePtr scene = bowel_on_floor(0.6, 25, dt, integrator, clamped);
            ASSERT_TRUE(scene) << ent_last_error();
            const double from[3] = {0.0, -0.05, kToolHapticsRadius}, travel = 0.10;
            add_tool(scene.get(), from, r, max_force, ENT_TOOL_MODE_PROXY);
            const int steps = std::max(1, int(std::lround(travel / speed / dt)));
            double largest = 0.0;
            for (int i = 1; i <= steps + 50; ++i) {
                const double p[3] = {from[0], from[1] + travel * std::min(i, steps) / steps, from[2]};
                ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
                ASSERT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
                largest = std::max(largest, norm3(feedback(scene.get(), 0).force_N));
            }
            EXPECT_LE(largest, max_force * (1 + 1e-12));
            EXPECT_GT(largest, 0.05 * max_force) << "the bowel resisted";
        }
    }
}

// The issue's sweep: a vertical tool (radius 2.5 mm, 0.3 m long) swept along +y through the
// settled demo pile at x = 0, its tip 2 cm above the cavity's floor, from the cavity's wall
// (y = -0.15 m, clear of the pile) to the other (+0.15 m), then held 50 ms. The closest
// approach of the tool's surface in the scene to the bowel's axis (sampled every 2.5 mm:
// within 0.1 mm of the true distance) and the largest rendered force.
struct PileSweep {
    double closest = 1e9;  // m
    double largest = 0.0;  // N
    bool stepped = true;   // every step succeeded
};

PileSweep sweep_through_pile(int32_t mode, double max_force, double speed) {
    PileSweep out;
    const double dt = 1e-3, r = 0.0025, length = 0.3, travel = 0.3;
    ScenePtr scene = settled_pile();
    if (!scene) return out;
    const double from[3] = {0.0, -0.15, -0.13};
    add_tool(scene.get(), from, r, max_force, mode);
    const int steps = std::max(1, int(std::lround(travel / speed / dt)));
    for (int i = 1; i <= steps + 50; ++i) {
        const double p[3] = {from[0], from[1] + travel * std::min(i, steps) / steps, from[2]};
        EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK) << ent_last_error();
        if (ent_scene_step(scene.get(), dt) != ENT_OK) {
            out.stepped = false;
            break;
        }
        const ent_tool_feedback f = feedback(scene.get(), 0);
        out.largest = std::max(out.largest, norm3(f.force_N));
        out.closest = std::min(out.closest, closest_approach(scene.get(), f.proxy_position_m, length, r, 2400));
    }
    return out;
}

void print_sweep(double speed, double max_force, const char* mode, const PileSweep& s) {
    std::cout << "| " << speed << " | " << max_force << " | " << mode << " | " << s.closest / kToolHapticsRadius
              << (s.stepped ? "" : " (a step failed)") << " | " << s.largest << " |\n";
}

TEST(ToolHaptics, TheProxyNeverEntersTheSettledPileAtAnySpeed) {
    std::cout << "| speed m/s | max_force N | mode | closest approach to the axis, R | largest force N |\n";
    for (double max_force : {5.0, 50.0}) {
        for (double speed : {0.1, 0.5, 2.0, 5.0}) {
            const PileSweep proxy = sweep_through_pile(ENT_TOOL_MODE_PROXY, max_force, speed);
            print_sweep(speed, max_force, "proxy", proxy);
            // Issue 18: the tool's surface never closer to the axis than 0.8 R (into the tube
            // less than 0.2 R), the force within its bound.
            EXPECT_TRUE(proxy.stepped) << ent_last_error();
            EXPECT_GE(proxy.closest, 0.8 * kToolHapticsRadius) << speed << " m/s, " << max_force << " N";
            EXPECT_LE(proxy.largest, max_force * (1 + 1e-9)) << speed << " m/s, " << max_force << " N";
            EXPECT_GT(proxy.largest, 0.05 * max_force) << "the pile resisted";
        }
        // The sweep finds what it measures: the capsule where the device puts it (direct
        // mode, the behaviour before the proxy) goes through the tube.
        const PileSweep direct = sweep_through_pile(ENT_TOOL_MODE_DIRECT, max_force, 5.0);
        print_sweep(5.0, max_force, "direct", direct);
        EXPECT_LT(direct.closest, 0.8 * kToolHapticsRadius) << max_force << " N";
    }
}

// The rest of the table of docs/haptics.md (the direct tool at every speed), run by hand:
//   enteron_capi_tests --gtest_also_run_disabled_tests --gtest_filter='ToolHaptics.*SettledPile*'
TEST(ToolHaptics, DISABLED_SettledPileSweepInDirectMode) {
    std::cout << "| speed m/s | max_force N | mode | closest approach to the axis, R | largest force N |\n";
    for (double max_force : {5.0, 50.0})
        for (double speed : {0.1, 0.5, 2.0, 5.0})
            print_sweep(speed, max_force, "direct", sweep_through_pile(ENT_TOOL_MODE_DIRECT, max_force, speed));
}

TEST(ToolHaptics, DirectModeStillPassesThroughAtSpeed) {
    // The old behaviour, kept where a scene asks for it: at 5 m/s with 5 N the capsule is
    // where the device is, inside the tube.
    const double dt = 1e-3, r = 0.0025;
    ScenePtr scene = bowel_on_floor(0.6, 25, dt);
    ASSERT_TRUE(scene);
    const double from[3] = {0.0, -0.05, kToolHapticsRadius};
    add_tool(scene.get(), from, r, 5.0, ENT_TOOL_MODE_DIRECT);
    double closest = 1e9;
    for (int i = 1; i <= 20; ++i) {
        const double p[3] = {0.0, from[1] + 0.005 * i, from[2]};
        ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK);
        ASSERT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
        const ent_tool_feedback f = feedback(scene.get(), 0);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f.proxy_position_m[c], f.commanded_position_m[c]);
        closest = std::min(closest, closest_approach(scene.get(), f.proxy_position_m, 0.3, r));
    }
    EXPECT_LT(closest, 0.5 * kToolHapticsRadius);
}

// Drives tool 0 round a closed path (down into the bowel, along it, up, back) `laps` times.
void closed_paths(ent_scene* scene, int laps, double dt) {
    const double corners[4][3] = {
        {-0.02, 0.0, 2 * kToolHapticsRadius + 0.01}, {-0.02, 0.0, kToolHapticsRadius}, {0.02, 0.0, kToolHapticsRadius}, {0.02, 0.0, 2 * kToolHapticsRadius + 0.01}};
    const int per_side = int(std::lround(0.1 / dt));
    for (int lap = 0; lap < laps; ++lap)
        for (int side = 0; side < 4; ++side)
            for (int i = 1; i <= per_side; ++i) {
                const double* a = corners[side];
                const double* b = corners[(side + 1) % 4];
                const double s = double(i) / per_side;
                const double p[3] = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
                EXPECT_EQ(ent_tool_set_pose(scene, 0, p, kIdentity), ENT_OK);
                EXPECT_EQ(ent_scene_step(scene, dt), ENT_OK) << ent_last_error();
            }
}

TEST(ToolHaptics, ThePassivityObserverGivesBackNoMoreThanWentIn) {
    const double dt = 1e-3;
    for (int32_t mode : {ENT_TOOL_MODE_PROXY, ENT_TOOL_MODE_DIRECT}) {
        for (int32_t limiter : {0, 1}) {
            ScenePtr scene = bowel_on_floor(0.6, 25, dt);
            ASSERT_TRUE(scene);
            const double start[3] = {-0.02, 0.0, 2 * kToolHapticsRadius + 0.01};
            add_tool(scene.get(), start, 0.005, 5.0, mode, limiter);
            closed_paths(scene.get(), 3, dt);
            const ent_tool_stats s = tool_stats(scene.get(), 0);
            std::cout << "[ passivity " << (mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") << " limiter " << limiter
                      << " ] in " << s.energy_in_J << " J, out " << s.energy_out_J << " J, limiter "
                      << s.limiter_energy_J << " J, largest change " << s.largest_force_change_N << " N\n";
            EXPECT_GT(s.energy_in_J, 1e-4) << "the tool worked against the bowel";
            EXPECT_GE(s.energy_out_J, 0.0);
            // What the bowel gives back is at most what it was given; the tolerance is the
            // energy the force's change within a step could misplace (1 % of what went in).
            EXPECT_LE(s.energy_out_J, s.energy_in_J * (1.0 + 1e-2));
            if (limiter == 1) {
                EXPECT_GE(s.energy_in_J - s.energy_out_J, -1e-12) << "the limiter keeps the balance";
            } else {
                EXPECT_EQ(s.limiter_energy_J, 0.0);
            }
            EXPECT_GT(s.largest_force_change_N, 0.0);
            EXPECT_EQ(s.steps, 3u * 4u * 100u + 200u);
        }
    }
}

TEST(ToolHaptics, TheStiffnessIsPublishedAndPushesBack) {
    const double dt = 1e-3;
    ScenePtr scene = bowel_on_floor(0.6, 25, dt);
    ASSERT_TRUE(scene);
    double K[9];
    const double above[3] = {0.0, 0.0, 3 * kToolHapticsRadius};
    add_tool(scene.get(), above, 0.005, 5.0, ENT_TOOL_MODE_PROXY);
    ASSERT_TRUE(step_n(scene.get(), dt, 1));
    ASSERT_EQ(ent_tool_stiffness(scene.get(), 0, K), ENT_OK) << ent_last_error();
    for (double k : K) EXPECT_EQ(k, 0.0) << "nothing touched";
    const double pressed[3] = {0.0, 0.0, 2 * kToolHapticsRadius + 0.005 - 0.003};
    ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, pressed, kIdentity), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), dt, 100));
    ASSERT_EQ(ent_tool_stiffness(scene.get(), 0, K), ENT_OK) << ent_last_error();
    const ent_tool_feedback f = feedback(scene.get(), 0);
    for (int k = 0; k < 9; ++k) EXPECT_EQ(f.stiffness_N_per_m[k], K[k]);
    // Pressing deeper (-z) pushes the tool up harder: dF_z/dz < 0, within the coupling's 1 N/mm.
    EXPECT_LT(K[8], -10.0);
    EXPECT_GE(K[8], -1000.0 * (1 + 1e-9));
    EXPECT_EQ(ent_tool_stiffness(scene.get(), 0, nullptr), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_tool_stiffness(nullptr, 0, K), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_tool_stiffness(scene.get(), 1, K), ENT_ERROR_NOT_FOUND);
}

TEST(ToolHaptics, ToolsCanBeRemovedAndCounted) {
    const double dt = 1e-3;
    ScenePtr scene = bowel_on_floor(0.6, 25, dt);
    ASSERT_TRUE(scene);
    int32_t count = -1;
    ASSERT_EQ(ent_scene_tool_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 0);
    const double pressed[3] = {0.0, 0.0, 2 * kToolHapticsRadius + 0.005 - 0.003}, away[3] = {0.2, 0.0, 0.1};
    add_tool(scene.get(), pressed, 0.005, 5.0, ENT_TOOL_MODE_PROXY);
    add_tool(scene.get(), away, 0.005, 5.0, ENT_TOOL_MODE_DIRECT);
    ASSERT_EQ(ent_scene_tool_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 2);
    ASSERT_EQ(ent_tool_grasp(scene.get(), 0), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), dt, 50));
    EXPECT_GT(feedback(scene.get(), 0).contacts, 0u);
    ent_stats before{};
    before.struct_size = sizeof before;
    ASSERT_EQ(ent_scene_stats(scene.get(), &before), ENT_OK);
    EXPECT_GT(before.contacts, 0u);

    ASSERT_EQ(ent_tool_remove(scene.get(), 0), ENT_OK) << ent_last_error();
    ASSERT_EQ(ent_scene_tool_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 1);
    // Its id is gone for every call; the other tool keeps its id.
    double v[3], w[3], K[9];
    ent_tool_feedback f{};
    f.struct_size = sizeof f;
    EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, pressed, kIdentity), ENT_ERROR_NOT_FOUND);
    EXPECT_NE(std::string(ent_last_error()).find("removed"), std::string::npos) << ent_last_error();
    EXPECT_EQ(ent_tool_grasp(scene.get(), 0), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_release(scene.get(), 0), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_wrench(scene.get(), 0, v, w), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_read_feedback(scene.get(), 0, &f), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_stiffness(scene.get(), 0, K), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_remove(scene.get(), 0), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_remove(scene.get(), 7), ENT_ERROR_NOT_FOUND);
    EXPECT_EQ(ent_tool_remove(nullptr, 1), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_scene_tool_count(scene.get(), nullptr), ENT_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(ent_tool_read_feedback(scene.get(), 1, &f), ENT_OK);
    // The bowel is let go and touched by nothing (the other tool is far above it).
    ASSERT_TRUE(step_n(scene.get(), dt, 5));
    ent_stats after{};
    after.struct_size = sizeof after;
    ASSERT_EQ(ent_scene_stats(scene.get(), &after), ENT_OK);
    ent_effect_stats e{};
    e.struct_size = sizeof e;
    (void)e;
    EXPECT_EQ(feedback(scene.get(), 1).contacts, 0u);
    EXPECT_EQ(ent_tool_remove(scene.get(), 1), ENT_OK);
    ASSERT_EQ(ent_scene_tool_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 0);
    ASSERT_TRUE(step_n(scene.get(), dt, 5));
}

TEST(ToolHaptics, BadToolSettingsAreRefusedByName) {
    ScenePtr scene = bowel_on_floor(0.6, 25, 1e-3);
    ASSERT_TRUE(scene);
    const auto refused = [&](auto change, const char* name) {
        ent_tool_desc desc;
        ent_tool_desc_default(&desc);
        change(desc);
        int32_t id = -1;
        EXPECT_EQ(ent_tool_add(scene.get(), &desc, &id), ENT_ERROR_INVALID_ARGUMENT) << name;
        EXPECT_NE(std::string(ent_last_error()).find(name), std::string::npos) << ent_last_error();
        EXPECT_EQ(id, -1);
    };
    refused([](ent_tool_desc& d) { d.mode = 2; }, "mode");
    refused([](ent_tool_desc& d) { d.mode = -1; }, "mode");
    refused([](ent_tool_desc& d) { d.coupling_stiffness_N_per_m = 0.0; }, "coupling_stiffness_N_per_m");
    refused([](ent_tool_desc& d) { d.coupling_damping_N_s_per_m = -1.0; }, "coupling_damping_N_s_per_m");
    refused([](ent_tool_desc& d) { d.friction = std::nan(""); }, "friction");
    refused([](ent_tool_desc& d) { d.passivity_limiter = 2; }, "passivity_limiter");
    int32_t count = -1;
    ASSERT_EQ(ent_scene_tool_count(scene.get(), &count), ENT_OK);
    EXPECT_EQ(count, 0) << "nothing changed";
    // An older desc without the new fields gets their defaults.
    ent_tool_desc old;
    ent_tool_desc_init(&old, uint32_t(offsetof(ent_tool_desc, mode)));
    old.mode = 99;  // past the old size: not read
    EXPECT_EQ(ent_tool_add(scene.get(), &old, nullptr), ENT_OK) << ent_last_error();
}

// The mean drag along x on a tool pressed 3 mm into the bowel and slid 10 cm along it.
double mean_drag(int32_t mode, double friction) {
    const double dt = 1e-3, r = 0.0025, top = 2 * kToolHapticsRadius + r;
    ScenePtr scene = bowel_on_floor(0.6, 25, dt);
    if (!scene) return -1.0;
    ent_tool_desc desc;
    ent_tool_desc_default(&desc);
    desc.radius_m = r;
    desc.mode = mode;
    desc.friction = friction;
    desc.position_m[0] = -0.05;
    desc.position_m[2] = top - 0.003;
    EXPECT_EQ(ent_tool_add(scene.get(), &desc, nullptr), ENT_OK) << ent_last_error();
    double sum = 0.0;
    const int steps = 1000;  // 0.1 m/s
    for (int i = 1; i <= steps; ++i) {
        const double p[3] = {-0.05 + 0.1 * i / steps, 0.0, top - 0.003};
        EXPECT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK);
        EXPECT_EQ(ent_scene_step(scene.get(), dt), ENT_OK) << ent_last_error();
        if (i > steps / 5) sum += feedback(scene.get(), 0).force_N[0];
    }
    return -sum / (steps - steps / 5);
}

TEST(ToolHaptics, FrictionPerTool) {
    for (int32_t mode : {ENT_TOOL_MODE_PROXY, ENT_TOOL_MODE_DIRECT}) {
        const double none = mean_drag(mode, 0.0), scene = mean_drag(mode, -1.0), rough = mean_drag(mode, 0.9);
        std::cout << "[ friction " << (mode == ENT_TOOL_MODE_PROXY ? "proxy" : "direct") << " ] mean drag: 0 -> " << none
                  << " N, the scene's 0.3 -> " << scene << " N, 0.9 -> " << rough << " N\n";
        // The drag opposes the motion (+x) and grows with the tool's coefficient.
        EXPECT_GT(scene, 0.0);
        EXPECT_LT(none, 0.5 * scene);
        EXPECT_GT(rough, 1.5 * scene);
    }
}

TEST(ToolHaptics, JsonToolsTakeTheModeCouplingFrictionAndLimiter) {
    const std::string base = R"({"intestine": {"length": 0.4, "control_points": 17,
        "shape": {"kind": "line", "center": [-0.2, 0, 0.0125]}}, "tools": [)";
    ScenePtr scene = create_json(base + R"({"mode": "direct", "coupling_stiffness": 500, "coupling_damping": 0.5,
        "friction": 0.1, "passivity_limiter": true, "position": [0, 0, 0.0175]}]})");
    ASSERT_TRUE(scene) << ent_last_error();
    // Direct: the capsule is where it is put (1 mm into the bowel): the feedback's proxy
    // position is the commanded one.
    const double p[3] = {0.0, 0.0, 0.0165};
    ASSERT_EQ(ent_tool_set_pose(scene.get(), 0, p, kIdentity), ENT_OK);
    ASSERT_TRUE(step_n(scene.get(), 1e-3, 1));
    const ent_tool_feedback f = feedback(scene.get(), 0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(f.proxy_position_m[c], p[c]);
    struct Bad {
        const char* json;
        const char* name;
    };
    for (const Bad& bad : {Bad{R"({"mode": "ghost"}]})", "tools[0].mode"},
                           Bad{R"({"coupling_stiffness": 0}]})", "tools[0].coupling_stiffness"},
                           Bad{R"({"coupling_damping": -1}]})", "tools[0].coupling_damping"},
                           Bad{R"({"passivity_limiter": 1}]})", "tools[0].passivity_limiter"}}) {
        ent_scene* out = nullptr;
        const std::string json = base + bad.json;
        EXPECT_EQ(ent_scene_create_json(json.data(), json.size(), &out), ENT_ERROR_INVALID_SCENE) << bad.json;
        EXPECT_NE(std::string(ent_last_error()).find(bad.name), std::string::npos) << ent_last_error();
        EXPECT_EQ(out, nullptr);
    }
}

}  // namespace
