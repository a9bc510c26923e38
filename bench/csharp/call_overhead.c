// SPDX-License-Identifier: Apache-2.0
/*
 * The C side of bench/csharp/compare_call_overhead.sh: the time of one call of
 * ent_version (an empty call), ent_scene_step (a 4-point bowel with no effect: the cheapest
 * step there is) and ent_tool_read_feedback, each the median over rounds of batches of
 * calls. CallOverhead.cs makes the same calls through Enteron.dll; the difference is what
 * the binding adds (P/Invoke, the SafeHandle's reference, the status check). Both step
 * the scene of call_overhead_scene.json: a 4-point, 10 cm bowel that runs no effect but its
 * tool, so that a step costs as little as a step can, in 1 ms steps.
 *
 *   enteron_call_overhead SCENE.json [--rounds N] [--calls N]
 *   prints "C: version_ns 2.1 step_ns 812.3 read_feedback_ns 95.0"
 */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */

#include <enteron/enteron.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>


static double now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

static int compare(const void* a, const void* b) {
    double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static double median(double* values, int count) {
    qsort(values, (size_t)count, sizeof *values, compare);
    return count % 2 ? values[count / 2] : 0.5 * (values[count / 2 - 1] + values[count / 2]);
}

enum { VERSION, STEP, READ_FEEDBACK, CALLS };

int main(int argc, char** argv) {
    int rounds = 21, calls = 20000, round, i, which;
    double per_call[CALLS][256];
    ent_scene* scene = NULL;
    ent_tool_feedback feedback;
    volatile uint32_t sink = 0;

    for (i = 2; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--rounds") == 0) rounds = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--calls") == 0) calls = atoi(argv[i + 1]);
    }
    if (argc < 2 || rounds < 1 || rounds > 256 || calls < 1) {
        fprintf(stderr, "usage: enteron_call_overhead SCENE.json [--rounds 1..256] [--calls N]\n");
        return 2;
    }
    if (ent_scene_create_json_file(argv[1], NULL, &scene) != ENT_OK) {
        fprintf(stderr, "enteron_call_overhead: %s\n", ent_last_error());
        return 1;
    }
    memset(&feedback, 0, sizeof feedback);
    feedback.struct_size = sizeof feedback;
    for (round = -1; round < rounds; ++round) { /* round -1 warms up */
        for (which = 0; which < CALLS; ++which) {
            double start = now_ns();
            for (i = 0; i < calls; ++i) {
                ent_status status = ENT_OK;
                if (which == VERSION) sink += ent_version();
                else if (which == STEP) status = ent_scene_step(scene, 0.001);
                else status = ent_tool_read_feedback(scene, 0, &feedback);
                if (status != ENT_OK) {
                    fprintf(stderr, "enteron_call_overhead: %s\n", ent_last_error());
                    ent_scene_destroy(scene);
                    return 1;
                }
            }
            if (round >= 0) per_call[which][round] = (now_ns() - start) / calls;
        }
    }
    printf("C: version_ns %.1f step_ns %.1f read_feedback_ns %.1f\n", median(per_call[VERSION], rounds),
           median(per_call[STEP], rounds), median(per_call[READ_FEEDBACK], rounds));
    ent_scene_destroy(scene);
    return sink == 0xFFFFFFFFu;
}
