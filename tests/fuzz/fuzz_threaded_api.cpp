// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the C API from several threads at once, as a simulator uses it.
//
// The input drives the driving thread: one byte picks a base scene, then up to 48
// operations: steps with an arbitrary dt, obstacles and tools with arbitrary settings, tool
// commands (any thread may post them). Beside it, for the whole input:
//   - a query thread reads the axis, the control points, the stats, the effect stats and a
//     tool's feedback, wrench and state;
//   - a render thread owns a skin and updates it, and goes on updating it after the scene is
//     destroyed (a skin may outlive its scene);
//   - a haptic thread posts poses, grasps and releases and reads the tools' feedback;
//   - a second driver: whenever the scene logs from inside a driving call of the driving
//     thread (a step the guard retries, an obstacle or a tool added), the log callback hands
//     it a driving call of its own and waits for the answer, which must be ENT_ERROR_BUSY.
// The background threads draw their calls from a generator seeded by the input. At the end
// come the races of a destroy with calls in flight (issue 27): a skin is destroyed while
// another thread's update of it runs (seen in flight when the driving thread's own call on
// the skin is refused as busy), and the scene is destroyed while the query and haptic
// threads still call it: a call in flight finishes, a later one is refused as destroyed
// (the render thread's skin keeps the handle); then they stop, and the render thread
// updates its skin a few more times.
//
// Every call must return ENT_OK or its documented failure with a message; the driving
// thread never sees ENT_ERROR_BUSY; every value read is finite; a failing step leaves the
// control points as they were; each feedback is one snapshot's (time = steps x dt, never
// going back). Any violation aborts. ctest replays the seeds (fuzz_replay.threaded_api) in
// the ordinary build, under AddressSanitizer and under ThreadSanitizer.
#include <enteron/enteron.h>

#include "fuzz_bytes.h"

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using fuzz::Bytes;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_threaded_api: %s (last error on this thread: %s)\n", what, ent_last_error());
    std::abort();
}

// A failing call must say why; a driving thread's call is never refused as busy.
void check_status(ent_status status, bool may_be_busy) {
    if (status == ENT_OK) return;
    if (status == ENT_ERROR_BUSY && !may_be_busy) fail("a call that overlapped nothing was refused as busy");
    if (std::strlen(ent_last_error()) == 0 || std::strcmp(ent_status_string(status), "unknown status") == 0)
        fail("a failing call left no message or an unknown status");
}

constexpr double kDt = 1e-3;  // s, a step

const char* const kBaseScenes[] = {
    // a serpentine in a box, self-colliding, with two tools
    R"({"intestine": {"length": 1.0, "control_points": 24,
                      "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
        "solver": {"max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {},
        "environment": [{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1]}], "self_collision": {},
        "tools": [{"position": [0, 0, -0.03]}, {"position": [0.05, 0, 0.05], "max_force": 1}]})",
    // a line on a floor, rk4, one tool resting on it
    R"({"intestine": {"length": 0.4, "control_points": 12, "shape": {"kind": "line", "center": [-0.2, 0, 0.0125]}},
        "solver": {"integrator": "rk4", "max_substeps": 100}, "gravity": [0, 0, -9.81],
        "environment": [{"type": "plane"}], "tools": [{"position": [0, 0, 0.03]}]})",
    // a helix on its mesentery, symplectic Euler, no tool yet
    R"({"intestine": {"length": 1.0, "control_points": 16, "shape": {"helix_radius": 0.05}},
        "solver": {"integrator": "symplectic_euler", "max_substeps": 100}, "gravity": [0, 0, -9.81],
        "damping": {}, "mesentery": {"attachments": 8}, "pinned": {"ends": "first"}})",
};
constexpr int kBaseSceneCount = sizeof kBaseScenes / sizeof kBaseScenes[0];

bool finite_all(const double* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) return false;
    return true;
}

// The second driver: the scene's log callback, on the driving thread inside a driving call,
// asks it for one driving call and waits for the answer.
class SecondDriver {
public:
    explicit SecondDriver(uint64_t seed) : random_(seed) {}

    void start(ent_scene* scene) {
        scene_ = scene;
        thread_ = std::thread([this] { run(); });
    }
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            quit_ = true;
        }
        wake_.notify_all();
        if (thread_.joinable()) thread_.join();
    }
    // The log callback, on the driving thread.
    void overlap() {
        std::unique_lock<std::mutex> lock(mutex_);
        if (scene_ == nullptr || quit_) return;  // creation logs too: not a driving call
        asked_ = true;
        wake_.notify_all();
        wake_.wait(lock, [this] { return !asked_ || quit_; });
    }

private:
    void run() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return asked_ || quit_; });
            if (quit_) return;
            const ent_status status = call();
            if (status != ENT_ERROR_BUSY) fail("a driving call during another was not refused as busy");
            if (std::string(ent_last_error()).find("another thread is in a driving call") == std::string::npos)
                fail("the busy message does not say why");
            asked_ = false;
            wake_.notify_all();
        }
    }
    ent_status call() {
        switch (random_() % 3) {
            case 0: return ent_scene_step(scene_, kDt);
            case 1: {
                ent_obstacle_desc d;
                ent_obstacle_desc_default(&d);
                d.kind = ENT_OBSTACLE_PLANE;
                d.center_m[2] = -1.0;
                return ent_scene_add_obstacle(scene_, &d, nullptr);
            }
            default: {
                ent_tool_desc d;
                ent_tool_desc_default(&d);
                d.position_m[2] = 1.0;
                return ent_tool_add(scene_, &d, nullptr);
            }
        }
    }

    std::mt19937_64 random_;
    ent_scene* scene_ = nullptr;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool asked_ = false, quit_ = false;
};

// A call refused because the scene was destroyed under its thread (the end of the input):
// the thread stops calling.
bool destroyed(ent_status status) {
    return status == ENT_ERROR_INVALID_ARGUMENT && std::strstr(ent_last_error(), "destroyed") != nullptr;
}

void log_line(void* user, int32_t level, const char* message) {
    if (level < ENT_LOG_DEBUG || level > ENT_LOG_ERROR || message == nullptr) fail("a malformed log line");
    static_cast<SecondDriver*>(user)->overlap();
}

// A tool's feedback: one snapshot's, finite, never going back (per reader). False once the
// scene was destroyed.
bool check_feedback(const ent_scene* scene, int32_t tool, uint64_t& last_steps) {
    ent_tool_feedback f;
    std::memset(&f, 0, sizeof f);
    f.struct_size = sizeof f;
    const ent_status status = ent_tool_read_feedback(scene, tool, &f);
    if (destroyed(status)) return false;
    if (status == ENT_ERROR_NOT_FOUND) return true;  // no such tool (yet)
    check_status(status, false);
    if (status != ENT_OK) fail("ent_tool_read_feedback failed");
    if (!finite_all(f.force_N, 3) || !finite_all(f.torque_Nm, 3) || !std::isfinite(f.time_s))
        fail("a tool's feedback is not finite");
    if (f.grasping != 0 && f.grasping != 1) fail("grasping is neither 0 nor 1");
    if (f.steps < last_steps) fail("a tool's feedback went back in time");
    last_steps = f.steps;
    return true;
}

void query_until(const ent_scene* scene, const std::atomic<bool>& stop, uint64_t seed) {
    std::mt19937_64 random(seed);
    std::vector<double> points, axis(3 * 32);
    uint64_t last_steps = 0, last_tool_steps = 0;
    double last_time = -1.0;
    // Each call may be the first after the destroy: refused as destroyed, it ends the loop.
    while (!stop.load()) {
        uint32_t count = 0;
        const ent_status counted = ent_scene_control_points(scene, 0, nullptr, &count);
        if (destroyed(counted)) return;
        check_status(counted, false);
        points.resize(3 * std::size_t{count});
        const ent_status copied = ent_scene_control_points(scene, count, points.data(), &count);
        if (destroyed(copied)) return;
        check_status(copied, false);
        if (copied == ENT_OK && !finite_all(points.data(), points.size())) fail("a control point is not finite");
        const ent_status sampled = ent_scene_axis(scene, 32, axis.data());
        if (destroyed(sampled)) return;
        check_status(sampled, false);
        if (sampled == ENT_OK && !finite_all(axis.data(), axis.size())) fail("an axis sample is not finite");
        ent_stats s;
        std::memset(&s, 0, sizeof s);
        s.struct_size = sizeof s;
        const ent_status read = ent_scene_stats(scene, &s);
        if (destroyed(read)) return;
        check_status(read, false);
        if (!std::isfinite(s.time_s) || !std::isfinite(s.kinetic_energy_J) || !std::isfinite(s.potential_energy_J))
            fail("stats are not finite");
        if (s.steps < last_steps || s.time_s < last_time) fail("stats went back in time");
        last_steps = s.steps;
        last_time = s.time_s;
        ent_effect_stats e;
        e.struct_size = sizeof e;
        const ent_status effect = ent_scene_effect_stats(scene, static_cast<int32_t>(random() % ENT_EFFECT_COUNT), &e);
        if (destroyed(effect)) return;
        check_status(effect, false);
        if (!check_feedback(scene, 0, last_tool_steps)) return;
        double force[3], torque[3];
        int32_t grasping = -1;
        const int32_t tool = static_cast<int32_t>(random() % 3);
        const ent_status wrench = ent_tool_wrench(scene, tool, force, torque);
        if (destroyed(wrench)) return;
        if (wrench != ENT_ERROR_NOT_FOUND) check_status(wrench, false);
        if (wrench == ENT_OK && (!finite_all(force, 3) || !finite_all(torque, 3))) fail("a wrench is not finite");
        const ent_status state = ent_tool_state(scene, tool, &grasping);
        if (destroyed(state)) return;
        if (state != ENT_ERROR_NOT_FOUND) check_status(state, false);
    }
}

void haptic_until(ent_scene* scene, const std::atomic<bool>& stop, uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> offset(-0.05, 0.05);
    uint64_t last_steps[3] = {0, 0, 0};
    while (!stop.load()) {
        const int32_t tool = static_cast<int32_t>(random() % 3);
        ent_status status = ENT_OK;
        switch (random() % 8) {
            case 0: status = ent_tool_grasp(scene, tool); break;
            case 1: status = ent_tool_release(scene, tool); break;
            default: {
                const double tip[3] = {offset(random), offset(random), 0.02 + offset(random)};
                double q[4] = {1.0, offset(random), offset(random), offset(random)};
                if (random() % 64 == 0) q[0] = q[1] = q[2] = q[3] = 0.0;  // refused: a zero quaternion
                status = ent_tool_set_pose(scene, tool, tip, q);
                break;
            }
        }
        if (destroyed(status)) return;
        if (status != ENT_ERROR_NOT_FOUND) check_status(status, false);
        if (!check_feedback(scene, tool, last_steps[tool])) return;
        std::this_thread::yield();
    }
}

// A skin destroyed while another thread's update of it runs. The driving thread asks for
// the mesh until its call is refused as busy (the update is then in flight) and destroys the
// skin at once; the update must still succeed. If the update ends first, the skin is
// destroyed after it.
void destroy_during_an_update(ent_scene* scene, int32_t method) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    ent_skin* skin = nullptr;
    check_status(ent_skin_create(scene, &desc, &skin), false);
    if (skin == nullptr) fail("a default skin was refused");
    std::atomic<bool> finished{false};
    ent_status updated = ENT_OK;
    std::thread render([&] {
        do updated = ent_skin_update(skin);
        while (updated == ENT_ERROR_BUSY);  // the driving thread's ent_skin_mesh was running
        finished = true;
    });
    bool gone = false;
    while (!finished.load() && !gone) {
        ent_mesh_view v;
        std::memset(&v, 0, sizeof v);
        v.struct_size = sizeof v;
        const ent_status status = ent_skin_mesh(skin, &v);
        check_status(status, true);
        if (status == ENT_ERROR_BUSY) {
            ent_skin_destroy(skin);
            gone = true;
        }
    }
    render.join();
    if (!gone) ent_skin_destroy(skin);
    if (updated != ENT_OK) fail("an update racing with the destroy of its skin failed");
}

// Owns a skin of the scene, updating it until told the scene is gone, then a few times more.
// It says when its skin exists: a skin is made from a live scene (the scene may go first
// once the skin holds it).
void render_until(ent_scene* scene, std::atomic<bool>& skin_made, const std::atomic<bool>& scene_gone,
                  int32_t method) {
    ent_skin_desc desc;
    ent_skin_desc_default(&desc);
    desc.method = method;
    ent_skin* skin = nullptr;
    check_status(ent_skin_create(scene, &desc, &skin), false);
    skin_made = true;
    if (skin == nullptr) fail("a default skin was refused");
    double last_time = -1.0;
    for (int after = 0; after < 3;) {
        if (scene_gone.load()) ++after;
        check_status(ent_skin_update(skin), false);
        ent_mesh_view v;
        std::memset(&v, 0, sizeof v);
        v.struct_size = sizeof v;
        check_status(ent_skin_mesh(skin, &v), false);
        for (uint32_t i = 0; i < 3 * v.vertex_count; ++i)
            if (!std::isfinite(v.positions_xyz_m[i]) || !std::isfinite(v.normals_xyz[i]))
                fail("a skin vertex is not finite");
        for (uint32_t i = 0; i < 3 * v.triangle_count; ++i)
            if (v.indices[i] >= v.vertex_count) fail("a mesh index is past the vertices");
        if (v.time_s < last_time) fail("a skin went back in time");
        last_time = v.time_s;
        std::this_thread::yield();
    }
    ent_skin_destroy(skin);
}

std::vector<double> control_points(const ent_scene* scene) {
    uint32_t count = 0;
    if (ent_scene_control_points(scene, 0, nullptr, &count) != ENT_OK) fail("control point count");
    std::vector<double> points(3 * std::size_t{count});
    if (ent_scene_control_points(scene, count, points.data(), &count) != ENT_OK) fail("control points");
    return points;
}

// One operation of the driving thread.
void drive(Bytes& in, ent_scene* scene) {
    const uint8_t code = in.u8();
    switch (code % 6) {
        case 0:
        case 1:
        case 2: {
            const double dt = code % 6 == 0 ? in.number(kDt) : kDt;
            const std::vector<double> before = control_points(scene);
            const ent_status status = ent_scene_step(scene, dt);
            check_status(status, false);
            if (status != ENT_OK && control_points(scene) != before) fail("a failing step moved the bowel");
            return;
        }
        case 3: {
            ent_obstacle_desc d;
            ent_obstacle_desc_default(&d);
            d.kind = static_cast<int32_t>(in.u8() % 5);
            for (int c = 0; c < 3; ++c) {
                d.center_m[c] = in.number(0.01) - 0.01;
                d.half_extents_m[c] = in.number(0.2);
                d.normal[c] = in.number(1.0) - 1.0;
            }
            d.radius_m = in.number(0.02);
            const std::vector<double> before = control_points(scene);
            const ent_status status = ent_scene_add_obstacle(scene, &d, nullptr);
            check_status(status, false);
            if (status != ENT_OK && control_points(scene) != before) fail("a refused obstacle moved the bowel");
            return;
        }
        case 4: {
            ent_tool_desc d;
            ent_tool_desc_default(&d);
            d.radius_m = in.number(0.005);
            d.max_force_N = in.number(5.0);
            for (double& p : d.position_m) p = in.number(0.05) - 0.05;
            check_status(ent_tool_add(scene, &d, nullptr), false);
            return;
        }
        default: {
            // Tool commands from the driving thread too.
            const int32_t tool = static_cast<int32_t>(in.u8() % 3);
            double tip[3];
            for (double& p : tip) p = in.number(0.05) - 0.05;
            const double q[4] = {1.0, 0.0, 0.0, 0.0};
            const ent_status status = in.u8() % 2 ? ent_tool_set_pose(scene, tool, tip, q) : ent_tool_grasp(scene, tool);
            if (status != ENT_ERROR_NOT_FOUND) check_status(status, false);
            return;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    uint64_t seed = 1469598103934665603ull;  // FNV-1a of the input: the background threads' choices
    for (size_t i = 0; i < size; ++i) seed = (seed ^ data[i]) * 1099511628211ull;
    Bytes in(data, size);
    const uint8_t base = in.u8();

    SecondDriver second(seed + 1);
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = log_line;
    callbacks.user_data = &second;
    const char* json = kBaseScenes[base % kBaseSceneCount];
    ent_scene* scene = nullptr;
    if (ent_scene_create_json_with(json, std::strlen(json), &callbacks, &scene) != ENT_OK)
        fail("a base scene failed to load");
    second.start(scene);

    std::atomic<bool> stop{false}, skin_made{false}, scene_gone{false};
    std::thread query(query_until, scene, std::cref(stop), seed + 2);
    std::thread haptic(haptic_until, scene, std::cref(stop), seed + 3);
    std::thread render(render_until, scene, std::ref(skin_made), std::cref(scene_gone),
                       static_cast<int32_t>(base / kBaseSceneCount % 3));

    for (int op = 0; op < 48 && !in.empty(); ++op) drive(in, scene);

    destroy_during_an_update(scene, static_cast<int32_t>(seed % 3));
    second.stop();
    while (!skin_made.load()) std::this_thread::yield();  // a slow render thread has not made its skin yet
    ent_scene_destroy(scene);  // the query and haptic threads' calls in flight finish
    stop = true;
    query.join();
    haptic.join();
    scene_gone = true;
    render.join();
    return 0;
}
