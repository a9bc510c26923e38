/* SPDX-License-Identifier: Apache-2.0 */
/* The library never prints: with standard output and standard error redirected to files,
 * a run full of failures (bad JSON, bad descriptions, NULL arguments, a small buffer, an
 * unknown effect, unstable steps) writes nothing to either, with and without a log
 * callback; the callback receives the scene's log lines instead. Exits non-zero (after
 * restoring the streams) on any output or failed check. */
#define _POSIX_C_SOURCE 200809L /* dup, dup2, fileno */
#include <enteron/enteron.h>

#include <stdio.h>
#include <string.h>
#include <unistd.h>

static int failures = 0;
static int checks = 0;
static char first_failure[256] = "";

/* Records a failed check without printing (the streams are redirected while it runs). */
#define CHECK(condition)                                                                       \
    do {                                                                                       \
        ++checks;                                                                              \
        if (!(condition)) {                                                                    \
            if (failures++ == 0)                                                               \
                snprintf(first_failure, sizeof first_failure, "line %d: %s", __LINE__, #condition); \
        }                                                                                      \
    } while (0)

static int log_lines = 0;
static void count_log_line(void* user_data, int32_t level, const char* message) {
    (void)user_data;
    (void)level;
    if (message != NULL && message[0] != '\0') ++log_lines;
}

/* Everything that fails, on one scene made with the given callbacks (may be NULL). */
static void fail_in_every_way(const ent_callbacks* callbacks) {
    static const char bad_json[] = "{\"intestine\": {\"radius\": -1}}";
    static const char not_json[] = "{\"intestine\": ,}";
    static const char good_json[] = "{\"intestine\": {\"length\": 1.0, \"control_points\": 10}, "
                                    "\"gravity\": [0, 0, -9.81], "
                                    "\"solver\": {\"integrator\": \"symplectic_euler\", \"max_speed\": 1e-6}}";
    ent_scene* scene = NULL;
    ent_scene_desc desc;
    ent_stats stats;
    ent_effect_stats effect;
    double buffer[3 * 4];
    uint32_t count = 0;

    CHECK(ent_scene_create_json_with(not_json, sizeof not_json - 1, callbacks, &scene) == ENT_ERROR_PARSE);
    CHECK(ent_scene_create_json_with(bad_json, sizeof bad_json - 1, callbacks, &scene) == ENT_ERROR_INVALID_SCENE);
    CHECK(ent_scene_create_json_with(NULL, 3, callbacks, &scene) == ENT_ERROR_INVALID_ARGUMENT);
    ent_scene_desc_default(&desc);
    desc.radius_m = -1.0;
    desc.callbacks = callbacks;
    CHECK(ent_scene_create(&desc, &scene) == ENT_ERROR_INVALID_ARGUMENT);
    desc.struct_size = 3;
    CHECK(ent_scene_create(&desc, &scene) == ENT_ERROR_VERSION);
    CHECK(ent_scene_step(NULL, 1e-3) == ENT_ERROR_INVALID_ARGUMENT);
    CHECK(ent_scene_desc_init(NULL, sizeof desc) == ENT_ERROR_INVALID_ARGUMENT);

    CHECK(ent_scene_create_json_with(good_json, sizeof good_json - 1, callbacks, &scene) == ENT_OK);
    if (scene == NULL) return;
    /* max_speed 1e-6 m/s: every step of a falling bowel is rejected by the guard. */
    CHECK(ent_scene_step(scene, 1e-3) == ENT_ERROR_UNSTABLE);
    CHECK(ent_scene_step(scene, -1.0) == ENT_ERROR_INVALID_ARGUMENT);
    CHECK(ent_scene_step(scene, 1e9) == ENT_ERROR_INVALID_ARGUMENT);
    CHECK(ent_scene_control_points(scene, 4, buffer, &count) == ENT_ERROR_BUFFER_TOO_SMALL);
    CHECK(ent_scene_axis(scene, 1, buffer) == ENT_ERROR_INVALID_ARGUMENT);
    memset(&stats, 0, sizeof stats);
    CHECK(ent_scene_stats(scene, &stats) == ENT_ERROR_VERSION);
    memset(&effect, 0, sizeof effect);
    effect.struct_size = sizeof effect;
    CHECK(ent_scene_effect_stats(scene, 99, &effect) == ENT_ERROR_NOT_FOUND);
    CHECK(strcmp(ent_status_string(12345), "unknown status") == 0);
    ent_scene_destroy(scene);
    ent_scene_destroy(NULL);
}

static long size_of(FILE* file) {
    fflush(file);
    fseek(file, 0, SEEK_END);
    return ftell(file);
}

int main(void) {
    FILE* out = tmpfile();
    FILE* err = tmpfile();
    int saved_out, saved_err;
    long out_bytes, err_bytes;
    ent_callbacks callbacks;

    if (out == NULL || err == NULL) {
        perror("tmpfile");
        return 1;
    }
    fflush(stdout);
    fflush(stderr);
    saved_out = dup(1);
    saved_err = dup(2);
    if (saved_out < 0 || saved_err < 0 || dup2(fileno(out), 1) < 0 || dup2(fileno(err), 2) < 0) {
        perror("dup");
        return 1;
    }

    fail_in_every_way(NULL);
    ent_callbacks_default(&callbacks);
    callbacks.log = count_log_line;
    fail_in_every_way(&callbacks);

    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    out_bytes = size_of(out);
    err_bytes = size_of(err);

    if (failures != 0) fprintf(stderr, "test_silent: %d check(s) failed, first at %s\n", failures, first_failure);
    if (out_bytes != 0 || err_bytes != 0)
        fprintf(stderr, "test_silent: the library wrote %ld bytes to stdout and %ld to stderr\n", out_bytes,
                err_bytes);
    if (log_lines == 0) fprintf(stderr, "test_silent: the log callback received nothing\n");
    if (failures != 0 || out_bytes != 0 || err_bytes != 0 || log_lines == 0) return 1;
    printf("test_silent: nothing printed during %d checked calls; %d log lines went to the callback\n", checks,
           log_lines);
    return 0;
}
