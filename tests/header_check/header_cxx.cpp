// SPDX-License-Identifier: Apache-2.0
// enteron.h must compile as C++17 with -pedantic -Wall -Wextra -Werror, inside and outside a
// namespace-free translation unit, and declare its functions with C linkage.
#include <enteron/enteron.h>

#include <cstddef>
#include <type_traits>

static_assert(std::is_same<ent_status, int32_t>::value, "ent_status is int32_t");
static_assert(offsetof(ent_scene_desc, struct_size) == 0, "struct_size comes first");
static_assert(std::is_trivially_copyable<ent_scene_desc>::value, "plain C struct");
static_assert(std::is_standard_layout<ent_stats>::value, "plain C struct");
static_assert(ENT_EFFECT_BIT(ENT_EFFECT_PINNED) == 32u, "effect bits");

extern "C" int enteron_header_check_cxx(void);

extern "C" int enteron_header_check_cxx(void) {
    // Taking the address with the exact C signature checks each declaration's type.
    uint32_t (*version)(void) = &ent_version;
    ent_status (*step)(ent_scene*, double) = &ent_scene_step;
    ent_status (*axis)(const ent_scene*, uint32_t, double*) = &ent_scene_axis;
    const char* (*status_string)(ent_status) = &ent_status_string;
    int failures = 0;
    if (version() != ENT_VERSION) ++failures;
    if (step(nullptr, 1e-3) != ENT_ERROR_INVALID_ARGUMENT) ++failures;
    if (axis(nullptr, 2, nullptr) != ENT_ERROR_INVALID_ARGUMENT) ++failures;
    if (status_string(ENT_OK)[0] == '\0') ++failures;
    return failures;
}
