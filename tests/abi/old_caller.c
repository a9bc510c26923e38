/* SPDX-License-Identifier: Apache-2.0 */
/*
 * A program built against an older header (tests/abi/enteron_v0_0.h, the simulated
 * "0.0 preview": ent_scene_desc without `callbacks`, ent_stats without `last_step_ns`)
 * and run against the current library. It must work unchanged:
 *
 * - ent_scene_desc_default fills the old, smaller ent_scene_desc, and ent_scene_create
 *   accepts it, neither touching anything past it: the struct sits at the very end of a
 *   page followed by an inaccessible page, so a write past it or a read of the missing
 *   `callbacks` field would crash this program;
 * - the scene (a rigid free fall) follows the exact discrete solution, with the defaults
 *   the old header documents, and is silent (no callbacks: the default for the missing
 *   field);
 * - ent_scene_stats fills the old, smaller ent_stats and writes nothing past it: checked
 *   with a canary after the struct, and again with the struct against an inaccessible page;
 * - a struct_size that no release knows is refused with ENT_ERROR_VERSION and a message.
 *
 * Prints one line per failed check and exits non-zero on any.
 */
#define _DEFAULT_SOURCE /* mmap's MAP_ANONYMOUS */
#include "enteron_v0_0.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

static int failures = 0;

#define CHECK(condition)                                                                   \
    do {                                                                                   \
        if (!(condition)) {                                                                \
            fprintf(stderr, "%s:%d: check failed: %s (last error: %s)\n", __FILE__, __LINE__, \
                    #condition, ent_last_error());                                        \
            ++failures;                                                                    \
        }                                                                                  \
    } while (0)

#define CHECK_STATUS(call, expected)                                                        \
    do {                                                                                    \
        ent_status status_ = (call);                                                        \
        if (status_ != (expected)) {                                                        \
            fprintf(stderr, "%s:%d: %s returned %d (%s), expected %d (last error: %s)\n",     \
                    __FILE__, __LINE__, #call, (int)status_, ent_status_string(status_),    \
                    (int)(expected), ent_last_error());                                     \
            ++failures;                                                                     \
        }                                                                                   \
    } while (0)

enum { kPoints = 20, kSteps = 200, kCanaryBytes = 64 };
static const double kStep = 1e-3;      /* s */
static const double kLength = 1.0;     /* m */
static const double kDensity = 0.3;    /* kg/m */
static const double kGravity = -9.81;  /* m/s^2, along z */

/* A function, not an expression: with this header's version 0.0.0, `version >= 0` would
 * draw a warning. */
static int at_least(uint32_t version, uint32_t minimum) { return version >= minimum; }

/*
 * Memory that ends exactly at an inaccessible page: `size` bytes are usable at the returned
 * address, and touching the byte after them faults. NULL if mmap is not available.
 */
static void* map_before_guard(size_t size, void** mapping, size_t* mapping_size) {
    const size_t page = (size_t)sysconf(_SC_PAGESIZE);
    const size_t pages = (size + page - 1) / page + 1;
    unsigned char* base = mmap(NULL, pages * page, PROT_READ | PROT_WRITE,
                               MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED) return NULL;
    if (mprotect(base + (pages - 1) * page, page, PROT_NONE) != 0) {
        munmap(base, pages * page);
        return NULL;
    }
    *mapping = base;
    *mapping_size = pages * page;
    /* Both structs hold doubles: keep 8-byte alignment (their sizes are multiples of 8). */
    return base + (pages - 1) * page - size;
}

int main(void) {
    const uint32_t version = ent_version();
    void* desc_mapping = NULL;
    void* stats_mapping = NULL;
    size_t desc_mapping_size = 0, stats_mapping_size = 0;
    ent_scene_desc* desc;
    ent_stats* guarded_stats;
    ent_scene* scene = NULL;
    double start[kPoints * 3], points[kPoints * 3];
    uint32_t count = 0;
    unsigned char buffer[sizeof(ent_stats) + kCanaryBytes];
    ent_stats stats;
    int i, c, step;

    printf("old_caller: built against header %d.%d.%d (sizeof ent_scene_desc %u, ent_stats %u), "
           "running on library %u.%u.%u\n",
           ENT_VERSION_MAJOR, ENT_VERSION_MINOR, ENT_VERSION_PATCH,
           (unsigned)sizeof(ent_scene_desc), (unsigned)sizeof(ent_stats),
           (unsigned)(version >> 16), (unsigned)((version >> 8) & 0xffu), (unsigned)(version & 0xffu));
    /* The handshake an old program does: same major, and a library at least as new. */
    CHECK((version >> 16) == ENT_VERSION_MAJOR);
    CHECK(at_least(version, (uint32_t)ENT_VERSION));

    /* ---- create from the old description, which ends at a guard page ------------------ */
    desc = map_before_guard(sizeof *desc, &desc_mapping, &desc_mapping_size);
    CHECK(desc != NULL);
    if (desc == NULL) return 1;
    /* The old header's ent_scene_desc_default passes the old sizeof: the library fills
     * exactly that much (a write past it would hit the guard page). */
    ent_scene_desc_default(desc);
    CHECK(desc->struct_size == sizeof(ent_scene_desc));
    desc->effects = ENT_EFFECT_BIT(ENT_EFFECT_GRAVITY);
    desc->control_points = kPoints;
    desc->length_m = kLength;
    desc->linear_density_kg_per_m = kDensity;
    desc->shape = ENT_SHAPE_LINE;
    desc->integrator = ENT_INTEGRATOR_SYMPLECTIC_EULER;
    desc->timestep_s = kStep;
    desc->gravity_m_per_s2[0] = 0.0;
    desc->gravity_m_per_s2[1] = 0.0;
    desc->gravity_m_per_s2[2] = kGravity;
    CHECK_STATUS(ent_scene_create(desc, &scene), ENT_OK);
    if (scene == NULL) return 1;

    /* ---- step: a rigid free fall, dq = g (t^2 + h t) / 2 for symplectic Euler ----------- */
    CHECK_STATUS(ent_scene_control_points(scene, kPoints, start, &count), ENT_OK);
    CHECK(count == kPoints);
    for (step = 0; step < kSteps; ++step) CHECK_STATUS(ent_scene_step(scene, kStep), ENT_OK);
    CHECK_STATUS(ent_scene_control_points(scene, kPoints, points, &count), ENT_OK);
    {
        const double t = kSteps * kStep;
        const double expected_dz = 0.5 * kGravity * (t * t + kStep * t);
        double worst = 0.0;
        for (i = 0; i < kPoints; ++i)
            for (c = 0; c < 3; ++c) {
                const double d = points[3 * i + c] - start[3 * i + c] - (c == 2 ? expected_dz : 0.0);
                if (fabs(d) > worst) worst = fabs(d);
            }
        CHECK(worst < 1e-9);
        printf("old_caller: after %d steps the axis fell %.6f m (expected %.6f m, worst error %.1e m)\n",
               kSteps, points[2] - start[2], expected_dz, worst);
    }

    /* ---- stats into the old, smaller struct, with a canary after it -------------------- */
    memset(buffer, 0xa5, sizeof buffer);
    memset(buffer, 0, sizeof(ent_stats));
    ((ent_stats*)(void*)buffer)->struct_size = sizeof(ent_stats);
    CHECK_STATUS(ent_scene_stats(scene, (ent_stats*)(void*)buffer), ENT_OK);
    for (i = 0; i < kCanaryBytes; ++i) CHECK(buffer[sizeof(ent_stats) + i] == 0xa5);
    memcpy(&stats, buffer, sizeof stats);
    CHECK(stats.struct_size == sizeof(ent_stats));
    CHECK(stats.control_points == kPoints);
    CHECK(stats.steps == kSteps);
    CHECK(stats.substeps == kSteps);
    CHECK(stats.rollbacks == 0);
    CHECK(fabs(stats.time_s - kSteps * kStep) < 1e-12);
    {
        /* Kinetic energy of the rigid fall: M v^2 / 2 with v = g t (symplectic Euler). */
        const double v = kGravity * kSteps * kStep;
        const double expected = 0.5 * kDensity * kLength * v * v;
        CHECK(fabs(stats.kinetic_energy_J - expected) < 1e-9 * expected);
        printf("old_caller: stats: %llu steps, t = %.3f s, kinetic energy %.6f J (expected %.6f J)\n",
               (unsigned long long)stats.steps, stats.time_s, stats.kinetic_energy_J, expected);
    }

    /* ---- and against a guard page: a write past the old size would crash --------------- */
    guarded_stats = map_before_guard(sizeof *guarded_stats, &stats_mapping, &stats_mapping_size);
    CHECK(guarded_stats != NULL);
    if (guarded_stats != NULL) {
        memset(guarded_stats, 0, sizeof *guarded_stats);
        guarded_stats->struct_size = sizeof *guarded_stats;
        CHECK_STATUS(ent_scene_stats(scene, guarded_stats), ENT_OK);
        CHECK(guarded_stats->steps == kSteps);
    }

    /* ---- sizes no release has: refused, with a message, nothing written ---------------- */
    {
        const uint32_t unknown[] = {0u, (uint32_t)sizeof(ent_stats) + 4u, (uint32_t)sizeof(ent_stats) + 1024u};
        for (i = 0; i < 3; ++i) {
            memset(&stats, 0x3c, sizeof stats);
            stats.struct_size = unknown[i];
            CHECK_STATUS(ent_scene_stats(scene, &stats), ENT_ERROR_VERSION);
            CHECK(strstr(ent_last_error(), "ent_stats.struct_size") != NULL);
            CHECK(stats.steps == 0x3c3c3c3c3c3c3c3cull);
        }
        desc->struct_size = (uint32_t)sizeof(ent_scene_desc) + 1024u;
        {
            ent_scene* refused = NULL;
            CHECK_STATUS(ent_scene_create(desc, &refused), ENT_ERROR_VERSION);
            CHECK(refused == NULL);
            CHECK(strstr(ent_last_error(), "ent_scene_desc.struct_size") != NULL);
            printf("old_caller: an unknown struct_size is refused: %s\n", ent_last_error());
        }
    }

    ent_scene_destroy(scene);
    munmap(desc_mapping, desc_mapping_size);
    if (stats_mapping != NULL) munmap(stats_mapping, stats_mapping_size);
    if (failures != 0) {
        fprintf(stderr, "old_caller: %d check(s) failed\n", failures);
        return 1;
    }
    printf("old_caller: ok\n");
    return 0;
}
