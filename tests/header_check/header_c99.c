/* SPDX-License-Identifier: Apache-2.0 */
/* enteron.h must compile as strict C99 (-std=c99 -pedantic -Wall -Wextra -Werror). This file
 * also uses what the header declares, so that a declaration that only looks right fails. */
#include <enteron/enteron.h>

#include <stddef.h>

/* C99 has no static_assert: a negative array size fails the build instead. */
#define HEADER_CHECK(name, condition) typedef char header_check_##name[(condition) ? 1 : -1]

HEADER_CHECK(status_is_32_bits, sizeof(ent_status) == 4);
HEADER_CHECK(struct_size_first_desc, offsetof(ent_scene_desc, struct_size) == 0);
HEADER_CHECK(struct_size_first_stats, offsetof(ent_stats, struct_size) == 0);
HEADER_CHECK(struct_size_first_effect, offsetof(ent_effect_stats, struct_size) == 0);
HEADER_CHECK(struct_size_first_callbacks, offsetof(ent_callbacks, struct_size) == 0);
HEADER_CHECK(effect_bits_fit, ENT_EFFECT_COUNT <= 32);
HEADER_CHECK(version_packs, ENT_VERSION == ((ENT_VERSION_MAJOR << 16) | (ENT_VERSION_MINOR << 8) | ENT_VERSION_PATCH));

int enteron_header_check_c99(void);

int enteron_header_check_c99(void) {
    ent_scene_desc desc;
    ent_stats stats;
    ent_effect_stats effect;
    ent_callbacks callbacks;
    ent_scene* scene = NULL;
    int failures = 0;
    ent_scene_desc_default(&desc);
    ent_callbacks_default(&callbacks);
    stats.struct_size = sizeof stats;
    effect.struct_size = sizeof effect;
    desc.effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc.control_points = 8;
    desc.length_m = 0.5;
    desc.callbacks = &callbacks;
    if (ent_version() != ENT_VERSION) ++failures;
    if (ent_scene_create(&desc, &scene) != ENT_OK) return failures + 1;
    if (ent_scene_step(scene, 1e-3) != ENT_OK) ++failures;
    if (ent_scene_stats(scene, &stats) != ENT_OK || stats.steps != 1) ++failures;
    if (ent_scene_effect_stats(scene, ENT_EFFECT_GRAVITY, &effect) != ENT_OK || effect.enabled != 1) ++failures;
    ent_scene_destroy(scene);
    return failures;
}
