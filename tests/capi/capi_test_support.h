// SPDX-License-Identifier: Apache-2.0
// Helpers for the C API tests: they reach the library only through enteron.h.
#pragma once

#include <enteron/enteron.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace capi_test {

struct SceneDeleter {
    void operator()(ent_scene* scene) const { ent_scene_destroy(scene); }
};
using ScenePtr = std::unique_ptr<ent_scene, SceneDeleter>;

inline const char* integrator_name(int32_t integrator) {
    switch (integrator) {
        case ENT_INTEGRATOR_RK4: return "rk4";
        case ENT_INTEGRATOR_SYMPLECTIC_EULER: return "symplectic_euler";
        case ENT_INTEGRATOR_IMPLICIT_EULER: return "implicit_euler";
        case ENT_INTEGRATOR_BDF2: return "bdf2";
        default: return "unknown";
    }
}

inline const int32_t kIntegrators[] = {ENT_INTEGRATOR_RK4, ENT_INTEGRATOR_SYMPLECTIC_EULER,
                                       ENT_INTEGRATOR_IMPLICIT_EULER, ENT_INTEGRATOR_BDF2};

inline ent_scene_desc default_desc() {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    return desc;
}

// Creates a scene that must succeed (the test fails with the library's message otherwise).
inline ScenePtr create(const ent_scene_desc& desc) {
    ent_scene* scene = nullptr;
    const ent_status status = ent_scene_create(&desc, &scene);
    EXPECT_EQ(status, ENT_OK) << ent_last_error();
    return ScenePtr(status == ENT_OK ? scene : nullptr);
}

inline ScenePtr create_json(const std::string& json) {
    ent_scene* scene = nullptr;
    const ent_status status = ent_scene_create_json(json.data(), json.size(), &scene);
    EXPECT_EQ(status, ENT_OK) << ent_last_error() << "\n" << json;
    return ScenePtr(status == ENT_OK ? scene : nullptr);
}

inline std::vector<double> control_points(const ent_scene* scene) {
    uint32_t count = 0;
    EXPECT_EQ(ent_scene_control_points(scene, 0, nullptr, &count), ENT_OK) << ent_last_error();
    std::vector<double> points(3 * std::size_t{count});
    uint32_t copied = 0;
    EXPECT_EQ(ent_scene_control_points(scene, count, points.data(), &copied), ENT_OK) << ent_last_error();
    EXPECT_EQ(copied, count);
    return points;
}

inline ent_stats stats(const ent_scene* scene) {
    ent_stats s;
    std::memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    EXPECT_EQ(ent_scene_stats(scene, &s), ENT_OK) << ent_last_error();
    return s;
}

inline ent_effect_stats effect_stats(const ent_scene* scene, int32_t effect) {
    ent_effect_stats s;
    std::memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    EXPECT_EQ(ent_scene_effect_stats(scene, effect, &s), ENT_OK) << ent_last_error();
    return s;
}

inline ent_contact_summary summary(const ent_scene* scene) {
    ent_contact_summary s;
    std::memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    EXPECT_EQ(ent_scene_contact_summary(scene, &s), ENT_OK) << ent_last_error();
    return s;
}

// The warnings a scene logs (ENT_LOG_WARNING), through callbacks made by logging_to.
struct Warnings {
    std::mutex mutex;
    std::vector<std::string> lines;
    bool has(const std::string& part) {
        std::lock_guard<std::mutex> lock(mutex);
        for (const std::string& line : lines)
            if (line.find(part) != std::string::npos) return true;
        return false;
    }
    // Every line, one per line ("" when none): what a failed expectation prints.
    std::string all() {
        std::lock_guard<std::mutex> lock(mutex);
        std::string text;
        for (const std::string& line : lines) text += line + "\n";
        return text;
    }
};

inline void collect_warning(void* user, int32_t level, const char* message) {
    if (level != ENT_LOG_WARNING) return;
    Warnings& w = *static_cast<Warnings*>(user);
    std::lock_guard<std::mutex> lock(w.mutex);
    w.lines.push_back(message);
}

inline ent_callbacks logging_to(Warnings& warnings) {
    ent_callbacks callbacks;
    ent_callbacks_default(&callbacks);
    callbacks.log = collect_warning;
    callbacks.user_data = &warnings;
    return callbacks;
}

inline double total_energy(const ent_scene* scene) {
    const ent_stats s = stats(scene);
    return s.kinetic_energy_J + s.potential_energy_J;
}

// Steps `count` times by dt, asserting success.
inline ::testing::AssertionResult step_n(ent_scene* scene, double dt, int count) {
    for (int i = 0; i < count; ++i) {
        const ent_status status = ent_scene_step(scene, dt);
        if (status != ENT_OK)
            return ::testing::AssertionFailure() << "step " << i << " failed: " << ent_status_string(status) << ": "
                                                 << ent_last_error();
    }
    return ::testing::AssertionSuccess();
}

inline double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
    return m;
}

// Points evenly spaced at `chord` along +x, with a gentle bend in the x-y plane: point i+1 sits
// at distance `chord` from point i in the direction of angle amplitude * sin(2 pi i / (n-1)).
inline std::vector<double> bent_points(uint32_t n, double chord, double amplitude) {
    std::vector<double> q(3 * std::size_t{n}, 0.0);
    const double pi = 3.14159265358979323846;
    for (uint32_t i = 1; i < n; ++i) {
        const double angle = amplitude * std::sin(2.0 * pi * double(i - 1) / double(n - 1));
        q[3 * i + 0] = q[3 * (i - 1) + 0] + chord * std::cos(angle);
        q[3 * i + 1] = q[3 * (i - 1) + 1] + chord * std::sin(angle);
        q[3 * i + 2] = 0.0;
    }
    return q;
}

}  // namespace capi_test
