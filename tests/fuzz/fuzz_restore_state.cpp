// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: ent_scene_restore_state on damaged and forged saved states. A saved
// state of a scene with self-contact, a floor and a grasping tool is the starting point;
// the input either patches bytes of it (and may re-seal the checksum, so that the damage
// reaches the sections behind the header) or is the image itself. Every image must be
// refused with a message and the scene left exactly as it was (its saved state the same
// bytes), or be accepted and then step to finite states (ENT_OK or ENT_ERROR_UNSTABLE).
//   input[0]   even: patches of the saved state; odd: the rest of the input is the image
//   input[1]   bit 0: re-seal the checksum after patching
//   then       patches: a 32-bit offset (modulo the image's size) and a byte, repeated
#include <enteron/enteron.h>

#include "fuzz_bytes.h"
#include "saved_state_image.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

const char kScene[] =
    "{\"intestine\": {\"length\": 0.6, \"control_points\": 25, \"shape\": {\"kind\": \"helix\"}},"
    " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {}, \"self_collision\": {},"
    " \"environment\": [{\"type\": \"plane\", \"point\": [0, 0, -0.06], \"normal\": [0, 0, 1]}],"
    " \"tools\": [{\"radius\": 0.004, \"position\": [0, 0, 0.05]}]}";

std::vector<unsigned char> saved_state(ent_scene* scene) {
    size_t size = 0;
    if (ent_scene_save_state(scene, nullptr, 0, &size) != ENT_OK) std::abort();
    std::vector<unsigned char> image(size);
    if (ent_scene_save_state(scene, image.data(), image.size(), &size) != ENT_OK || size != image.size())
        std::abort();
    return image;
}

// One scene for every input, and the state it is brought back to after each.
struct Fixture {
    ent_scene* scene = nullptr;
    std::vector<unsigned char> good;

    Fixture() {
        if (ent_scene_create_json(kScene, sizeof kScene - 1, &scene) != ENT_OK) std::abort();
        for (int step = 0; step < 60; ++step) {
            const double z = 0.05 - 0.001 * step;
            const double position[3] = {0.0, 0.0, z}, orientation[4] = {1.0, 0.0, 0.0, 0.0};
            if (ent_tool_set_pose(scene, 0, position, orientation) != ENT_OK) std::abort();
            if (step == 40 && ent_tool_grasp(scene, 0) != ENT_OK) std::abort();
            if (ent_scene_step(scene, 1e-3) != ENT_OK) std::abort();
        }
        good = saved_state(scene);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Fixture fixture;
    fuzz::Bytes bytes(data, size);
    const uint8_t mode = bytes.u8();
    std::vector<unsigned char> image;
    if (mode % 2 == 1) {
        image.assign(data + (size > 0 ? 1 : 0), data + size);
    } else {
        image = fixture.good;
        const bool reseal = (bytes.u8() & 1) != 0;
        while (!bytes.empty()) {
            const uint32_t offset = bytes.u32();
            image[offset % image.size()] = bytes.u8();
        }
        // Only the checksum: a patched size field stays patched.
        if (reseal) saved_state_image::seal_checksum(image.data(), image.size());
    }

    const std::vector<unsigned char> before = saved_state(fixture.scene);
    const ent_status status = ent_scene_restore_state(fixture.scene, image.data(), image.size());
    if (status != ENT_OK) {
        if (std::strlen(ent_last_error()) == 0) std::abort();            // a refusal explains itself
        if (saved_state(fixture.scene) != before) std::abort();           // and changes nothing
        return 0;
    }
    for (int step = 0; step < 5; ++step) {
        const ent_status stepped = ent_scene_step(fixture.scene, 1e-3);
        if (stepped != ENT_OK && stepped != ENT_ERROR_UNSTABLE) std::abort();
    }
    double axis[8 * 3];
    if (ent_scene_axis(fixture.scene, 8, axis) != ENT_OK) std::abort();
    for (double v : axis)
        if (!std::isfinite(v)) std::abort();  // the guard never publishes a non-finite state
    if (ent_scene_restore_state(fixture.scene, fixture.good.data(), fixture.good.size()) != ENT_OK) std::abort();
    return 0;
}
