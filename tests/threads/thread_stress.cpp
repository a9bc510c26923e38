// SPDX-License-Identifier: Apache-2.0
// Thread stress test of the documented thread model: one thread steps a scene at full speed
// while reader threads query the last published state, for a given wall time. Run under
// ThreadSanitizer by scripts/test (preset `tsan`), where a data race fails it.
//
//   enteron_thread_stress [--seconds S] [--readers N] [--skins N] [--haptic 0|1]
//
// Axis readers (--readers, default 2) query the scene; skin threads (--skins, default 2:
// a convolution skin, then a tube skin, alternating) each own a skin and update it in a
// loop, as render threads do; a haptic thread (--haptic, default 1) runs at 1 kHz, as a
// device's loop does: it posts the tool's pose, grasps and releases, and reads the tool's
// feedback, wrench and state, without any lock of its own.
//
// Every read must be internally consistent, whichever snapshot it saw:
//   - the control point count never changes, and every coordinate is finite;
//   - the axis samples are finite, and both ends of the axis are the end control points
//     of some published state, so they lie within the box the scene can reach;
//   - ent_stats comes from one snapshot: time_s = steps x dt exactly (a torn read of two
//     snapshots would break it), energies are finite, and per reader the time and the
//     step count never go backwards;
//   - effect calls never go backwards per reader;
//   - every skin mesh is whole: vertices and triangles > 0, every index < the vertex
//     count, every position and normal finite, within reach, time and update count never
//     going backwards; a convolution skin's metrics say it is watertight;
//   - every tool feedback comes from one snapshot (time_s = steps x dt), never goes back,
//     is finite, its force within max_force, and agrees with ent_tool_wrench and
//     ent_tool_state read right after it whenever no step came between.
// The stepping thread's every step must succeed. The test fails (exit 1) with a count of
// each kind of violation; it also fails if the readers barely overlapped the stepping.
#include <enteron/enteron.h>

#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr uint32_t kControlPoints = 40;
constexpr uint32_t kAxisSamples = 64;
constexpr double kDt = 1e-3;        // s per step
constexpr double kReachable = 10.0;  // m: nothing of this scene gets this far from the origin
constexpr double kToolMaxForce = 3.0;  // N

struct Violations {
    std::atomic<long> failed_calls{0};
    std::atomic<long> count_changed{0};
    std::atomic<long> not_finite{0};
    std::atomic<long> out_of_reach{0};
    std::atomic<long> torn_stats{0};
    std::atomic<long> went_backwards{0};
    std::atomic<long> bad_mesh{0};      // empty, or an index past the vertex count
    std::atomic<long> not_watertight{0};
    std::atomic<long> over_force{0};     // a tool force beyond max_force
    std::atomic<long> disagreeing{0};    // feedback and wrench/state of one snapshot differ
    std::atomic<long> reads{0};
    std::atomic<long> skin_updates{0};
    std::atomic<long> haptic_ticks{0};

    long total() const {
        return failed_calls + count_changed + not_finite + out_of_reach + torn_stats + went_backwards + bad_mesh +
               not_watertight + over_force + disagreeing;
    }
};

bool finite_all(const double* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

bool within_reach(const double* xyz) {
    return std::fabs(xyz[0]) < kReachable && std::fabs(xyz[1]) < kReachable && std::fabs(xyz[2]) < kReachable;
}

// One reader: runs every kind of query in turn until `done`.
void read_until_done(const ent_scene* scene, const std::atomic<bool>& done, Violations& v) {
    std::vector<double> points(3 * kControlPoints), axis(3 * kAxisSamples);
    double last_time = -1.0;
    uint64_t last_steps = 0;
    uint64_t last_calls[ENT_EFFECT_COUNT] = {};
    while (!done.load(std::memory_order_relaxed)) {
        uint32_t count = 0;
        if (ent_scene_control_points(scene, kControlPoints, points.data(), &count) != ENT_OK) ++v.failed_calls;
        else if (count != kControlPoints) ++v.count_changed;
        else if (!finite_all(points.data(), points.size())) ++v.not_finite;

        if (ent_scene_axis(scene, kAxisSamples, axis.data()) != ENT_OK) ++v.failed_calls;
        else if (!finite_all(axis.data(), axis.size())) ++v.not_finite;
        else if (!within_reach(&axis[0]) || !within_reach(&axis[3 * (kAxisSamples - 1)])) ++v.out_of_reach;

        ent_stats stats;
        std::memset(&stats, 0, sizeof stats);
        stats.struct_size = sizeof stats;
        if (ent_scene_stats(scene, &stats) != ENT_OK) {
            ++v.failed_calls;
        } else {
            if (stats.control_points != kControlPoints) ++v.count_changed;
            if (!std::isfinite(stats.kinetic_energy_J) || !std::isfinite(stats.potential_energy_J)) ++v.not_finite;
            const double expected_time = double(stats.steps) * kDt;
            if (std::fabs(stats.time_s - expected_time) > 1e-9 * (1.0 + expected_time)) ++v.torn_stats;
            if (stats.time_s < last_time || stats.steps < last_steps) ++v.went_backwards;
            last_time = stats.time_s;
            last_steps = stats.steps;
        }

        for (int32_t effect = 0; effect < ENT_EFFECT_COUNT; ++effect) {
            ent_effect_stats e;
            std::memset(&e, 0, sizeof e);
            e.struct_size = sizeof e;
            if (ent_scene_effect_stats(scene, effect, &e) != ENT_OK) {
                ++v.failed_calls;
                continue;
            }
            if (e.calls < last_calls[effect]) ++v.went_backwards;
            last_calls[effect] = e.calls;
        }
        ++v.reads;
    }
}

bool finite_all(const float* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

// One skin thread: owns a skin of `method`, updates it until `done` and checks every mesh.
void skin_until_done(ent_scene* scene, int32_t method, const std::atomic<bool>& done, Violations& v) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    ent_skin* skin = nullptr;
    if (ent_skin_create(scene, &desc, &skin) != ENT_OK) {
        std::fprintf(stderr, "thread_stress: ent_skin_create: %s\n", ent_last_error());
        ++v.failed_calls;
        return;
    }
    double last_time = -1.0;
    uint64_t last_updates = 0;
    while (!done.load(std::memory_order_relaxed)) {
        if (ent_skin_update(skin) != ENT_OK) {
            ++v.failed_calls;
            continue;
        }
        ent_mesh_view mesh;
        std::memset(&mesh, 0, sizeof mesh);
        mesh.struct_size = sizeof mesh;
        if (ent_skin_mesh(skin, &mesh) != ENT_OK) {
            ++v.failed_calls;
            continue;
        }
        ++v.skin_updates;
        if (mesh.vertex_count == 0 || mesh.triangle_count == 0 || !mesh.positions_xyz_m || !mesh.indices) {
            ++v.bad_mesh;
            continue;
        }
        for (std::size_t i = 0; i < 3 * std::size_t(mesh.triangle_count); ++i) {
            if (mesh.indices[i] >= mesh.vertex_count) {
                ++v.bad_mesh;
                break;
            }
        }
        const std::size_t coordinates = 3 * std::size_t(mesh.vertex_count);
        if (!finite_all(mesh.positions_xyz_m, coordinates) || !finite_all(mesh.normals_xyz, coordinates) ||
            !finite_all(mesh.axis_u, mesh.vertex_count)) {
            ++v.not_finite;
        } else {
            for (std::size_t i = 0; i < coordinates; ++i) {
                if (std::fabs(mesh.positions_xyz_m[i]) >= kReachable) {
                    ++v.out_of_reach;
                    break;
                }
            }
        }
        if (mesh.time_s < last_time || mesh.updates <= last_updates) ++v.went_backwards;
        last_time = mesh.time_s;
        last_updates = mesh.updates;
        if (method == ENT_SKIN_CONVOLUTION) {
            struct ent_skin_metrics metrics;
            std::memset(&metrics, 0, sizeof metrics);
            metrics.struct_size = sizeof metrics;
            if (ent_skin_metrics(skin, &metrics) != ENT_OK) ++v.failed_calls;
            else if (!metrics.watertight || metrics.vertex_count != mesh.vertex_count) ++v.not_watertight;
        }
    }
    ent_skin_destroy(skin);
}

// The haptic thread: at 1 kHz, posts the device's pose (the tip circling over the bowel,
// dipping into it), grasps and releases now and then, and reads what the tool feels.
void haptic_until_done(ent_scene* scene, const std::atomic<bool>& done, Violations& v) {
    const double identity[4] = {1.0, 0.0, 0.0, 0.0};
    uint64_t last_steps = 0;
    auto next = std::chrono::steady_clock::now();
    for (long tick = 0; !done.load(std::memory_order_relaxed); ++tick) {
        const double angle = 2e-3 * double(tick);
        const double tip[3] = {0.05 * std::cos(angle), 0.05 * std::sin(angle), 0.02 + 0.02 * std::sin(3.0 * angle)};
        if (ent_tool_set_pose(scene, 0, tip, identity) != ENT_OK) ++v.failed_calls;
        if (tick % 400 == 100 && ent_tool_grasp(scene, 0) != ENT_OK) ++v.failed_calls;
        if (tick % 400 == 300 && ent_tool_release(scene, 0) != ENT_OK) ++v.failed_calls;
        ent_tool_feedback feedback;
        std::memset(&feedback, 0, sizeof feedback);
        feedback.struct_size = sizeof feedback;
        double force[3], torque[3];
        int32_t grasping = -1;
        if (ent_tool_read_feedback(scene, 0, &feedback) != ENT_OK || ent_tool_wrench(scene, 0, force, torque) != ENT_OK ||
            ent_tool_state(scene, 0, &grasping) != ENT_OK) {
            ++v.failed_calls;
        } else {
            ent_tool_feedback again;
            std::memset(&again, 0, sizeof again);
            again.struct_size = sizeof again;
            const bool same_snapshot = ent_tool_read_feedback(scene, 0, &again) == ENT_OK && again.steps == feedback.steps;
            if (same_snapshot && (std::memcmp(force, feedback.force_N, sizeof force) != 0 ||
                                  std::memcmp(torque, feedback.torque_Nm, sizeof torque) != 0 ||
                                  grasping != feedback.grasping))
                ++v.disagreeing;
            if (!finite_all(feedback.force_N, 3) || !finite_all(feedback.torque_Nm, 3)) ++v.not_finite;
            const double magnitude = std::sqrt(feedback.force_N[0] * feedback.force_N[0] +
                                               feedback.force_N[1] * feedback.force_N[1] +
                                               feedback.force_N[2] * feedback.force_N[2]);
            if (!(magnitude <= kToolMaxForce * (1.0 + 1e-12))) ++v.over_force;
            if (std::fabs(feedback.time_s - double(feedback.steps) * kDt) > 1e-9 * (1.0 + feedback.time_s)) ++v.torn_stats;
            if (feedback.steps < last_steps) ++v.went_backwards;
            last_steps = feedback.steps;
        }
        ++v.haptic_ticks;
        next += std::chrono::milliseconds(1);
        std::this_thread::sleep_until(next);
    }
}

}  // namespace

int main(int argc, char** argv) {
    double seconds = 2.0;
    int readers = 2;
    int skins = 2;
    bool haptic = true;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc) seconds = std::atof(argv[++i]);
        else if (arg == "--readers" && i + 1 < argc) readers = std::atoi(argv[++i]);
        else if (arg == "--skins" && i + 1 < argc) skins = std::atoi(argv[++i]);
        else if (arg == "--haptic" && i + 1 < argc) haptic = std::atoi(argv[++i]) != 0;
        else {
            std::fprintf(stderr, "usage: enteron_thread_stress [--seconds S] [--readers N] [--skins N] [--haptic 0|1]\n");
            return 2;
        }
    }

    // Every effect this version has, on a bowel that moves: gravity pulls it out of its
    // helix against its mesentery, with one end pinned.
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.effects |= ENT_EFFECT_BIT(ENT_EFFECT_MESENTERY) | ENT_EFFECT_BIT(ENT_EFFECT_PINNED);
    desc.control_points = kControlPoints;
    desc.length_m = 1.0;
    desc.shape_helix_radius_m = 0.05;
    desc.mesentery_attachments = 10;
    desc.pinned_ends = ENT_PIN_FIRST;
    desc.timestep_s = kDt;
    ent_scene* scene = nullptr;
    if (ent_scene_create(&desc, &scene) != ENT_OK) {
        std::fprintf(stderr, "thread_stress: ent_scene_create: %s\n", ent_last_error());
        return 1;
    }
    // The haptic thread's tool, above the helix.
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    tool.position_m[2] = 0.1;
    tool.max_force_N = kToolMaxForce;
    if (ent_tool_add(scene, &tool, nullptr) != ENT_OK) {
        std::fprintf(stderr, "thread_stress: ent_tool_add: %s\n", ent_last_error());
        return 1;
    }

    Violations violations;
    std::atomic<bool> done{false};
    std::vector<std::thread> threads;
    for (int r = 0; r < readers; ++r)
        threads.emplace_back(read_until_done, scene, std::cref(done), std::ref(violations));
    for (int k = 0; k < skins; ++k)
        threads.emplace_back(skin_until_done, scene, k % 2 == 0 ? ENT_SKIN_CONVOLUTION : ENT_SKIN_TUBE,
                             std::cref(done), std::ref(violations));
    if (haptic) threads.emplace_back(haptic_until_done, scene, std::cref(done), std::ref(violations));

    long steps = 0, failed_steps = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (ent_scene_step(scene, kDt) != ENT_OK) {
            if (failed_steps++ == 0) std::fprintf(stderr, "thread_stress: step %ld: %s\n", steps, ent_last_error());
        } else {
            ++steps;
        }
    }
    done = true;
    for (std::thread& t : threads) t.join();

    ent_stats final_stats;
    std::memset(&final_stats, 0, sizeof final_stats);
    final_stats.struct_size = sizeof final_stats;
    const bool stats_ok = ent_scene_stats(scene, &final_stats) == ENT_OK && final_stats.steps == uint64_t(steps);
    ent_scene_destroy(scene);

    std::printf("thread_stress: %.1f s, %ld steps (%.0f per s), %d readers made %ld reads, %d skins made %ld "
                "updates, the haptic thread %ld ticks; simulated %.3f s\n",
                seconds, steps, double(steps) / seconds, readers, violations.reads.load(), skins,
                violations.skin_updates.load(), violations.haptic_ticks.load(), final_stats.time_s);
    std::printf("thread_stress: violations: failed calls %ld, count changed %ld, not finite %ld, out of reach %ld, "
                "torn stats %ld, went backwards %ld, bad mesh %ld, not watertight %ld, over max_force %ld, "
                "feedback disagreeing %ld; failed steps %ld\n",
                violations.failed_calls.load(), violations.count_changed.load(), violations.not_finite.load(),
                violations.out_of_reach.load(), violations.torn_stats.load(), violations.went_backwards.load(),
                violations.bad_mesh.load(), violations.not_watertight.load(), violations.over_force.load(),
                violations.disagreeing.load(), failed_steps);
    bool ok = violations.total() == 0 && failed_steps == 0 && stats_ok;
    // A run where the readers hardly ran proves nothing (TSan slows everything ~10x, so
    // the bar is low on purpose).
    if (steps < 100 || violations.reads.load() < 100L * readers || violations.skin_updates.load() < 10L * skins ||
        (haptic && violations.haptic_ticks.load() < 100)) {
        std::fprintf(stderr, "thread_stress: too little overlap (%ld steps, %ld reads, %ld skin updates)\n", steps,
                     violations.reads.load(), violations.skin_updates.load());
        ok = false;
    }
    if (!stats_ok) std::fprintf(stderr, "thread_stress: final stats disagree with the %ld steps made\n", steps);
    std::printf("thread_stress: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
