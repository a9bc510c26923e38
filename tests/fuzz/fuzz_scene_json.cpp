// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: arbitrary bytes as a JSON scene. Every input must give ENT_OK or a
// status with a message, never a crash, a hang or a leak; a scene that is created is
// stepped a little, so what the loader accepts the step must survive.
#include <enteron/enteron.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    ent_scene* scene = nullptr;
    const ent_status status = ent_scene_create_json(reinterpret_cast<const char*>(data), size, &scene);
    if (status != ENT_OK) {
        if (scene != nullptr || std::strlen(ent_last_error()) == 0) std::abort();  // failure must explain itself
        return 0;
    }
    ent_stats stats;
    stats.struct_size = sizeof stats;
    // Large scenes are legal but slow to step; the loader is what this target explores.
    if (ent_scene_stats(scene, &stats) == ENT_OK && stats.control_points <= 2000) {
        for (int i = 0; i < 3; ++i) {
            const ent_status step = ent_scene_step(scene, 1e-3);
            if (step != ENT_OK && step != ENT_ERROR_UNSTABLE && step != ENT_ERROR_INVALID_ARGUMENT) std::abort();
        }
        double axis[4 * 3];
        if (ent_scene_axis(scene, 4, axis) != ENT_OK) std::abort();
        for (double v : axis)
            if (!std::isfinite(v)) std::abort();  // the guard never publishes a non-finite state
    }
    ent_scene_destroy(scene);
    return 0;
}
