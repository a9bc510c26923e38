/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The threads of a simulator: a physics thread steps the scene at 1 kHz, paced by the
 * wall clock, while a render thread at 60 Hz reads the axis and updates a convolution
 * skin, the triangle mesh a renderer would draw. The render thread never blocks the
 * physics thread: both the axis read and the skin update read the last published
 * snapshot (see "Threads" in enteron.h). The skin belongs to the render thread: it alone
 * updates it and reads its mesh.
 *
 *   enteron_render_thread [--seconds S]    (default 1.5)
 *
 * Prints one line per thread and exits 0 if every step, every read and every skin update
 * succeeded, every mesh was whole (triangles, indices below the vertex count) and the
 * render thread saw the simulation advance. Ticks the physics thread could not keep (a
 * loaded machine) are counted, not treated as failures.
 */
#define _POSIX_C_SOURCE 200809L /* clock_nanosleep, pthreads */
#include <enteron/enteron.h>

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "monotonic_clock.h"

#define AXIS_POINTS 200

typedef struct {
    ent_scene* scene;
    struct timespec start; /* both threads run from here for `seconds` */
    double seconds;
    /* physics thread results */
    long steps, late_ticks, failed_steps;
    double worst_step_us;
    /* render thread results */
    long frames, failed_reads, advanced_frames;
    double lowest_z, last_time;
    ent_skin* skin;             /* updated by the render thread only */
    uint32_t min_triangles, max_triangles, last_triangles;
    double skin_update_us_sum, skin_update_us_max;
} shared_state;

static void* physics_thread(void* argument) {
    shared_state* s = argument;
    const double period = 0.001; /* 1 kHz */
    const long ticks = (long)(s->seconds / period + 0.5);
    long tick;
    for (tick = 1; tick <= ticks; ++tick) {
        const double before = seconds_since(&s->start);
        if (ent_scene_step(s->scene, period) != ENT_OK) {
            if (s->failed_steps++ == 0) fprintf(stderr, "render_thread: step: %s\n", ent_last_error());
        } else {
            ++s->steps;
        }
        {
            const double took_us = 1e6 * (seconds_since(&s->start) - before);
            const struct timespec next = after(&s->start, (double)tick * period);
            if (took_us > s->worst_step_us) s->worst_step_us = took_us;
            if (seconds_since(&s->start) > (double)tick * period) ++s->late_ticks;
            clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
        }
    }
    return NULL;
}

static void* render_thread(void* argument) {
    shared_state* s = argument;
    static double axis[AXIS_POINTS * 3];
    const double period = 1.0 / 60.0;
    long frame;
    s->lowest_z = HUGE_VAL;
    s->last_time = -1.0;
    for (frame = 1; (double)frame * period <= s->seconds; ++frame) {
        const struct timespec next = after(&s->start, (double)frame * period);
        ent_stats stats;
        ent_mesh_view mesh;
        double skin_start, skin_us;
        uint32_t i;
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
        memset(&stats, 0, sizeof stats);
        stats.struct_size = sizeof stats;
        if (ent_scene_axis(s->scene, AXIS_POINTS, axis) != ENT_OK || ent_scene_stats(s->scene, &stats) != ENT_OK) {
            if (s->failed_reads++ == 0) fprintf(stderr, "render_thread: read: %s\n", ent_last_error());
            continue;
        }
        /* Rebuild the bowel's surface from the same kind of snapshot, and time it. */
        skin_start = seconds_since(&s->start);
        memset(&mesh, 0, sizeof mesh);
        mesh.struct_size = sizeof mesh;
        if (ent_skin_update(s->skin) != ENT_OK || ent_skin_mesh(s->skin, &mesh) != ENT_OK) {
            if (s->failed_reads++ == 0) fprintf(stderr, "render_thread: skin: %s\n", ent_last_error());
            continue;
        }
        skin_us = 1e6 * (seconds_since(&s->start) - skin_start);
        s->skin_update_us_sum += skin_us;
        if (skin_us > s->skin_update_us_max) s->skin_update_us_max = skin_us;
        /* "Draw" the mesh: here, check that every triangle names a vertex of it. */
        if (mesh.triangle_count == 0) ++s->failed_reads;
        for (i = 0; i < 3 * mesh.triangle_count; ++i)
            if (mesh.indices[i] >= mesh.vertex_count) ++s->failed_reads;
        if (s->frames == 0 || mesh.triangle_count < s->min_triangles) s->min_triangles = mesh.triangle_count;
        if (mesh.triangle_count > s->max_triangles) s->max_triangles = mesh.triangle_count;
        s->last_triangles = mesh.triangle_count;
        /* And find the axis's lowest point. */
        for (i = 0; i < AXIS_POINTS; ++i) {
            if (!isfinite(axis[3 * i + 2])) ++s->failed_reads;
            else if (axis[3 * i + 2] < s->lowest_z) s->lowest_z = axis[3 * i + 2];
        }
        if (stats.time_s > s->last_time) ++s->advanced_frames;
        s->last_time = stats.time_s;
        ++s->frames;
    }
    return NULL;
}

int main(int argc, char** argv) {
    static const char json[] =
        "{\"intestine\": {\"length\": 2.0, \"control_points\": 80,"
        "                 \"stretch_stiffness\": 100, \"bend_stiffness\": 2.5e-3,"
        "                 \"shape\": {\"kind\": \"serpentine\", \"leg_length\": 0.25}},"
        " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {}}";
    shared_state s;
    ent_skin_desc skin_desc;
    pthread_t physics, render;
    memset(&s, 0, sizeof s);
    s.seconds = 1.5;
    if (argc == 3 && strcmp(argv[1], "--seconds") == 0) s.seconds = atof(argv[2]);
    else if (argc != 1) {
        fprintf(stderr, "usage: enteron_render_thread [--seconds S]\n");
        return 2;
    }
    if (ent_scene_create_json(json, strlen(json), &s.scene) != ENT_OK) {
        fprintf(stderr, "render_thread: %s\n", ent_last_error());
        return 1;
    }
    ent_skin_desc_default(&skin_desc);
    skin_desc.method = ENT_SKIN_CONVOLUTION;
    if (ent_skin_create(s.scene, &skin_desc, &s.skin) != ENT_OK) {
        fprintf(stderr, "render_thread: %s\n", ent_last_error());
        ent_scene_destroy(s.scene);
        return 1;
    }
    clock_gettime(CLOCK_MONOTONIC, &s.start);
    if (pthread_create(&physics, NULL, physics_thread, &s) != 0 ||
        pthread_create(&render, NULL, render_thread, &s) != 0) {
        fprintf(stderr, "render_thread: cannot start the threads\n");
        return 1;
    }
    pthread_join(physics, NULL);
    pthread_join(render, NULL);
    ent_skin_destroy(s.skin); /* skins first: the scene must outlive them */
    ent_scene_destroy(s.scene);

    printf("render_thread: physics: %ld steps of 1 ms in %.2f s of wall time, %ld late ticks, "
           "slowest step %.0f us\n", s.steps, s.seconds, s.late_ticks, s.worst_step_us);
    printf("render_thread: render: %ld frames at 60 Hz, %ld saw a newer state, lowest point z = %.4f m, "
           "last frame at simulated t = %.3f s\n", s.frames, s.advanced_frames, s.lowest_z, s.last_time);
    printf("render_thread: skin: convolution, %u triangles in the last frame (%u to %u), update %.0f us mean, "
           "%.0f us worst\n", (unsigned)s.last_triangles, (unsigned)s.min_triangles, (unsigned)s.max_triangles,
           s.frames > 0 ? s.skin_update_us_sum / (double)s.frames : 0.0, s.skin_update_us_max);
    /* Pass or fail on correctness only: how many frames see a newer state depends on how
       loaded the machine is (sanitizers, shared CI), so one is enough to show the hand-off. */
    if (s.failed_steps != 0 || s.failed_reads != 0 || s.frames == 0 || s.advanced_frames == 0) {
        fprintf(stderr, "render_thread: FAILED (%ld failed steps, %ld failed reads)\n", s.failed_steps,
                s.failed_reads);
        return 1;
    }
    return 0;
}
