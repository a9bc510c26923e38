/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The haptic shim a haptic-device vendor would write: a 1 kHz loop that reads the device's
 * pose, hands it to the scene as the tool's pose, steps the scene by 1 ms and sends the
 * force on the tool back to the device. Here the device is simulated: a scripted path that
 * approaches the bowel, pushes it aside, grasps it, lifts it, releases it and withdraws.
 *
 *   enteron_haptic_shim [--seconds S] [--long]
 *     --seconds S   how long to run: 1000 S ticks of 1 ms (default 4); the script is
 *                   stretched to fill them
 *     --long        the 6 m small bowel with its mesentery in a 30 cm box (default: a 0.4 m
 *                   bowel lying on the floor of a box)
 *
 * Threads (see "Threads" in enteron.h): the haptic thread drives the scene (ent_scene_step)
 * and posts the tool's commands; the main thread only queries (ent_scene_stats) and reads
 * the last force from the haptic thread, and prints a few lines per second, so that a slow
 * terminal never delays a haptic tick. (The tool commands and ent_tool_read_feedback are
 * safe from any thread: a simulator whose physics thread steps on its own would post the
 * device's pose from the haptic thread the same way, without a lock.) The haptic thread never blocks on the main
 * thread: it hands its force over with pthread_mutex_trylock and skips a hand-over when
 * the main thread holds the lock.
 *
 * The loop is paced by clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME) on an absolute
 * schedule (each tick is due one period after the previous one was due), so the time spent
 * working does not add up into drift. A tick whose work ends after its deadline is a missed
 * deadline: the schedule then restarts from that moment instead of running the missed
 * ticks in a burst (a device wants evenly spaced forces). Every tick steps 1 ms, so on a
 * machine that cannot keep up the simulation runs slower than the wall clock. A real device
 * thread would also lock its memory (mlockall) and run with a real-time priority
 * (SCHED_FIFO); both need privileges, so this example does neither.
 *
 * Prints the force about four times per second and a summary; exits 0 if every call
 * succeeded and the force never exceeded the tool's max_force, 1 otherwise.
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

#define TOOL 0                 /* the id of the scene's one tool: the first of its JSON "tools" */
#define TOOL_MAX_FORCE_N 5.0   /* the tool's max_force: the most the device is asked to render */
#define TICK_S 0.001           /* 1 kHz */
#define AXIS_POINTS 200
#define PRINTS_PER_SECOND 4

/* The simulated device: the tip's path, phase by phase. Each phase moves the tip from where
 * the last one ended to `to`, easing in and out, over its share of the run. */
enum action { NONE, GRASP, RELEASE };
typedef struct {
    const char* name;
    double share;      /* of the run's duration; the shares add up to 1 */
    enum action first; /* done at the phase's first tick, before the move */
    double to[3];      /* m */
} phase;

#define PHASES 7
typedef struct {
    const char* name;
    const char* json;  /* the scene; %g: the tool's max_force, then its start position */
    double start[3];   /* the tool tip's position at the start, m */
    phase script[PHASES];
} scenario;

/* A 0.4 m bowel lying along x on the floor (z = 0) of a box; the tool starts above it. */
static const scenario short_bowel = {
    "0.4 m bowel on the floor of a box",
    "{\"intestine\": {\"length\": 0.4, \"control_points\": 17, \"stretch_stiffness\": 100,"
    "                 \"bend_stiffness\": 2.5e-3,"
    "                 \"shape\": {\"kind\": \"line\", \"center\": [-0.2, 0, 0.0125]}},"
    " \"gravity\": [0, 0, -9.81], \"damping\": {},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0.1], \"half_extents\": [0.25, 0.15, 0.1]}],"
    " \"tools\": [{\"radius\": 0.005, \"length\": 0.3, \"max_force\": %g, \"position\": [%g, %g, %g]}]}",
    {0.0, 0.06, 0.06},
    {
        {"approach", 0.15, NONE, {0.0, 0.04, 0.0125}},    /* down beside the bowel */
        {"push", 0.25, NONE, {0.0, -0.02, 0.0125}},       /* across its rest line: the bowel gives way */
        {"grasp", 0.05, GRASP, {0.0, -0.02, 0.0125}},     /* the bowel touches the tip: grasp it */
        {"lift", 0.20, NONE, {0.0, -0.02, 0.0925}},       /* 8 cm up */
        {"hold", 0.10, NONE, {0.0, -0.02, 0.0925}},
        {"release", 0.10, RELEASE, {0.0, -0.02, 0.0925}}, /* it drops back to the floor */
        {"withdraw", 0.15, NONE, {0.0, 0.06, 0.06}},
    },
};

/* The 6 m small bowel held by its mesentery in a 30 cm box, its folds colliding. */
static const scenario long_bowel = {
    "6 m bowel with its mesentery in a 30 cm box",
    "{\"intestine\": {\"length\": 6.0, \"control_points\": 240, \"stretch_stiffness\": 100,"
    "                 \"bend_stiffness\": 2.5e-3,"
    "                 \"shape\": {\"kind\": \"helix\", \"center\": [0, 0, -0.13],"
    "                           \"helix_radius\": 0.1, \"helix_pitch\": 0.025}},"
    " \"gravity\": [0, 0, -9.81], \"damping\": {}, \"mesentery\": {},"
    " \"environment\": [{\"type\": \"box_inside\", \"center\": [0, 0, 0], \"half_extents\": [0.15, 0.15, 0.15]}],"
    " \"self_collision\": {},"
    " \"tools\": [{\"radius\": 0.005, \"length\": 0.3, \"max_force\": %g, \"position\": [%g, %g, %g]}]}",
    {0.1, 0.06, 0.14},
    {
        {"approach", 0.15, NONE, {0.1, 0.02, 0.06}},
        {"push", 0.25, NONE, {0.1, -0.04, 0.02}},
        {"grasp", 0.05, GRASP, {0.1, -0.04, 0.02}},
        {"lift", 0.20, NONE, {0.1, -0.04, 0.10}},
        {"hold", 0.10, NONE, {0.1, -0.04, 0.10}},
        {"release", 0.10, RELEASE, {0.1, -0.04, 0.10}},
        {"withdraw", 0.15, NONE, {0.1, 0.06, 0.14}},
    },
};

/* What the haptic thread hands to the main thread for printing (under `lock`). */
typedef struct {
    double time_s;
    double force_N[3];
    int grasping;
    const char* phase;
    int done;
} handover;

typedef struct {
    ent_scene* scene;
    const scenario* scenario;
    double seconds;
    struct timespec start;
    pthread_mutex_t lock;
    handover shared;
    /* results of the haptic thread, read after it is joined */
    long ticks, failed_calls, over_force, missed_deadlines;
    double max_force_N;
    double max_change_N;          /* largest change of the force from one tick to the next */
    const char* max_change_phase; /* and the phase it happened in */
    double* work_us; /* per tick: set pose + step + read the wrench */
    int grasped, held_through_lift;
    double lifted_z;
} shim;

/* Reports a failed call once (the first), and counts every one. */
static int failed(shim* s, ent_status status, const char* call) {
    if (status == ENT_OK) return 0;
    if (s->failed_calls++ == 0)
        fprintf(stderr, "haptic_shim: %s: %s (%s)\n", call, ent_last_error(), ent_status_string(status));
    return 1;
}

/* The simulated device: where the tip is at time t, and the index of the phase. */
static int device_pose(const shim* s, double t, double position[3]) {
    const phase* script = s->scenario->script;
    const double* from = s->scenario->start;
    double begin = 0.0;
    int i, c;
    for (i = 0; i < PHASES; ++i) {
        const double length = script[i].share * s->seconds;
        if (t < begin + length || i == PHASES - 1) {
            double a = length > 0.0 ? (t - begin) / length : 1.0;
            a = a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a;
            a = a * a * (3.0 - 2.0 * a); /* ease in and out: no jump in the device's velocity */
            for (c = 0; c < 3; ++c) position[c] = from[c] + a * (script[i].to[c] - from[c]);
            return i;
        }
        begin += length;
        from = script[i].to;
    }
    return PHASES - 1;
}

static double highest_axis_point(const ent_scene* scene) {
    static double axis[3 * AXIS_POINTS];
    double highest = -HUGE_VAL;
    int i;
    if (ent_scene_axis(scene, AXIS_POINTS, axis) != ENT_OK) return NAN;
    for (i = 0; i < AXIS_POINTS; ++i)
        if (axis[3 * i + 2] > highest) highest = axis[3 * i + 2];
    return highest;
}

static void* haptic_thread(void* argument) {
    static const double identity[4] = {1.0, 0.0, 0.0, 0.0}; /* a vertical tool, tip down */
    shim* s = argument;
    const phase* script = s->scenario->script;
    const long ticks = (long)(s->seconds / TICK_S + 0.5);
    int current = -1;
    int grasp_posted = 0; /* the grasp shows in the state once the next step has taken it */
    double deadline = TICK_S; /* when this tick's work must be done, s since the start */
    double previous[3] = {0.0, 0.0, 0.0};
    long tick;
    for (tick = 1; tick <= ticks; ++tick) {
        const double t = (double)tick * TICK_S;
        double position[3], force[3], torque[3], magnitude;
        int32_t grasping = 0;
        const double before = seconds_since(&s->start);
        /* 1. Read the device (here: the script) and act on its buttons. */
        const int now = device_pose(s, t, position);
        if (now != current) {
            current = now;
            if (script[now].first == GRASP) {
                grasp_posted = !failed(s, ent_tool_grasp(s->scene, TOOL), "ent_tool_grasp");
            } else if (script[now].first == RELEASE) {
                /* Before letting go: is the bowel still held after the lift, and how high is it? */
                if (!failed(s, ent_tool_state(s->scene, TOOL, &grasping), "ent_tool_state"))
                    s->held_through_lift = grasping;
                s->lifted_z = highest_axis_point(s->scene);
                failed(s, ent_tool_release(s->scene, TOOL), "ent_tool_release");
            }
        }
        /* 2. Where the tool is at the end of this step; 3. step; 4. the force for the device. */
        failed(s, ent_tool_set_pose(s->scene, TOOL, position, identity), "ent_tool_set_pose");
        failed(s, ent_scene_step(s->scene, TICK_S), "ent_scene_step");
        if (failed(s, ent_tool_wrench(s->scene, TOOL, force, torque), "ent_tool_wrench"))
            force[0] = force[1] = force[2] = 0.0; /* render nothing rather than garbage */
        failed(s, ent_tool_state(s->scene, TOOL, &grasping), "ent_tool_state");
        if (grasp_posted) {
            s->grasped = grasping;
            grasp_posted = 0;
        }
        s->work_us[tick - 1] = 1e6 * (seconds_since(&s->start) - before);
        /* A real shim sends `force` to the device here. */
        magnitude = sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
        if (!(magnitude <= TOOL_MAX_FORCE_N * (1.0 + 1e-12))) {
            if (s->over_force++ == 0)
                fprintf(stderr, "haptic_shim: |F| = %.6f N exceeds max_force %.3f N at t = %.3f s\n", magnitude,
                        TOOL_MAX_FORCE_N, t);
        }
        if (magnitude > s->max_force_N) s->max_force_N = magnitude;
        {
            /* A device renders steps in the force as knocks: the change per tick should be small. */
            const double d[3] = {force[0] - previous[0], force[1] - previous[1], force[2] - previous[2]};
            const double change = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (change > s->max_change_N) {
                s->max_change_N = change;
                s->max_change_phase = script[now].name;
            }
            memcpy(previous, force, sizeof previous);
        }
        ++s->ticks;
        /* Hand the state to the printer, unless it is reading it right now. */
        if (pthread_mutex_trylock(&s->lock) == 0) {
            s->shared.time_s = t;
            memcpy(s->shared.force_N, force, sizeof force);
            s->shared.grasping = grasping;
            s->shared.phase = script[now].name;
            pthread_mutex_unlock(&s->lock);
        }
        /* 5. Sleep until this tick's deadline, when the next one starts. */
        {
            const double finished = seconds_since(&s->start);
            if (finished > deadline) {
                ++s->missed_deadlines;
                deadline = finished; /* restart the schedule from now */
            } else {
                const struct timespec next = after(&s->start, deadline);
                clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
            }
            deadline += TICK_S;
        }
    }
    pthread_mutex_lock(&s->lock);
    s->shared.done = 1;
    pthread_mutex_unlock(&s->lock);
    return NULL;
}

/* Prints -0.000 as 0.000. */
static double tidy(double x) { return fabs(x) < 5e-4 ? 0.0 : x; }

static int by_value(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

int main(int argc, char** argv) {
    shim s;
    char json[2048];
    pthread_t haptic;
    ent_status status;
    long print;
    int i, ok;
    memset(&s, 0, sizeof s);
    s.seconds = 4.0;
    s.scenario = &short_bowel;
    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            s.seconds = atof(argv[++i]);
        } else if (strcmp(argv[i], "--long") == 0) {
            s.scenario = &long_bowel;
        } else {
            fprintf(stderr, "usage: enteron_haptic_shim [--seconds S] [--long]\n");
            return 2;
        }
    }
    if (!(s.seconds >= 0.1 && s.seconds <= 3600.0)) {
        fprintf(stderr, "haptic_shim: --seconds must be between 0.1 and 3600\n");
        return 2;
    }
    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "haptic_shim: libenteron has major version %u, this program needs %d\n",
                (unsigned)(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    snprintf(json, sizeof json, s.scenario->json, TOOL_MAX_FORCE_N, s.scenario->start[0], s.scenario->start[1],
             s.scenario->start[2]);
    status = ent_scene_create_json(json, strlen(json), &s.scene);
    if (status != ENT_OK) {
        fprintf(stderr, "haptic_shim: ent_scene_create_json: %s (%s)\n", ent_last_error(), ent_status_string(status));
        return 1;
    }
    s.work_us = calloc((size_t)(s.seconds / TICK_S + 1.5), sizeof *s.work_us); /* before the loop: it never allocates */
    if (s.work_us == NULL || pthread_mutex_init(&s.lock, NULL) != 0) {
        fprintf(stderr, "haptic_shim: out of memory\n");
        ent_scene_destroy(s.scene);
        return 1;
    }
    printf("haptic_shim: %s, tool max_force %.1f N, %.2f s at 1 kHz\n", s.scenario->name, TOOL_MAX_FORCE_N,
           s.seconds);
    clock_gettime(CLOCK_MONOTONIC, &s.start);
    if (pthread_create(&haptic, NULL, haptic_thread, &s) != 0) {
        fprintf(stderr, "haptic_shim: cannot start the haptic thread\n");
        ent_scene_destroy(s.scene);
        return 1;
    }
    /* The main thread: print what the device feels, a few times per second. */
    for (print = 1;; ++print) {
        const struct timespec next = after(&s.start, (double)print / PRINTS_PER_SECOND);
        handover seen;
        ent_stats stats;
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
        pthread_mutex_lock(&s.lock);
        seen = s.shared;
        pthread_mutex_unlock(&s.lock);
        if (seen.done) break;
        if (seen.phase == NULL) continue;
        memset(&stats, 0, sizeof stats);
        stats.struct_size = sizeof stats;
        if (ent_scene_stats(s.scene, &stats) != ENT_OK) stats.contacts = 0; /* a query: safe from this thread */
        printf("haptic_shim: t = %6.3f s  %-8s  F = (%+.3f, %+.3f, %+.3f) N  |F| = %.3f N  %s  %u contacts\n",
               seen.time_s, seen.phase, tidy(seen.force_N[0]), tidy(seen.force_N[1]), tidy(seen.force_N[2]),
               sqrt(seen.force_N[0] * seen.force_N[0] + seen.force_N[1] * seen.force_N[1] +
                    seen.force_N[2] * seen.force_N[2]),
               seen.grasping ? "holding" : "free   ", (unsigned)stats.contacts);
        fflush(stdout);
    }
    pthread_join(haptic, NULL);
    pthread_mutex_destroy(&s.lock);
    ent_scene_destroy(s.scene);

    qsort(s.work_us, (size_t)s.ticks, sizeof *s.work_us, by_value);
    printf("haptic_shim: %ld steps of 1 ms, max |F| %.3f N (max_force %.1f N), grasp %s, bowel lifted to "
           "z = %.3f m, %ld missed deadlines, step time median %.0f us, max %.0f us\n",
           s.ticks, s.max_force_N, TOOL_MAX_FORCE_N,
           !s.grasped ? "found nothing in reach" : s.held_through_lift ? "held through the lift" : "slipped",
           s.lifted_z, s.missed_deadlines, s.ticks > 0 ? s.work_us[s.ticks / 2] : 0.0,
           s.ticks > 0 ? s.work_us[s.ticks - 1] : 0.0);
    printf("haptic_shim: largest change of the force in one tick %.3f N (%s)\n", s.max_change_N,
           s.max_change_phase != NULL ? s.max_change_phase : "none");
    free(s.work_us);
    ok = s.failed_calls == 0 && s.over_force == 0;
    if (!ok)
        fprintf(stderr, "haptic_shim: FAILED (%ld failed calls, %ld ticks over max_force)\n", s.failed_calls,
                s.over_force);
    return ok ? 0 : 1;
}
