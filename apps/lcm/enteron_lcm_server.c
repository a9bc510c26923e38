/* SPDX-License-Identifier: Apache-2.0 */
/*
 * enteron-lcm-server: runs a scene at 1 kHz and serves it over LCM (docs/lcm.md).
 *
 *   enteron-lcm-server --scene FILE.json [--lcm-url URL] [--channel-suffix S] [--seconds T]
 *                      [--journal FILE] [--state-hz F] [--mesh-hz F] [--watchdog-ms M]
 *                      [--mesh-skin tube|point_skeleton|convolution] [--force-ramp-ms M]
 *                      [--max-tool-speed V] [--device-max-force N] [--max-force-change N]
 *                      [--workspace-scale S] [--workspace-rotation W,X,Y,Z]
 *                      [--workspace-offset X,Y,Z] [--force-scale G] [--realtime P] [--quiet]
 *
 * Channels ENTERON_TOOL_COMMAND (in), ENTERON_TOOL_FEEDBACK, ENTERON_STATE, ENTERON_MESH,
 * ENTERON_SESSION, ENTERON_STATUS (out), each with the suffix appended. The scene runs on
 * the bridge's physics thread, on an absolute-deadline clock; this thread only prints one
 * line a second and waits for SIGINT or SIGTERM (or the end of --seconds), then stops
 * everything and prints how long stopping took.
 *
 * Exit status: 0 after a clean stop; 1 when the bridge cannot run; 2 on a bad command line
 * or scene file.
 */
#define _POSIX_C_SOURCE 200809L

#include <enteron/enteron_lcm.h>

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>

static const char usage[] =
    "usage: enteron-lcm-server --scene FILE.json [--lcm-url URL] [--channel-suffix S] [--seconds T]\n"
    "                          [--journal FILE] [--state-hz F] [--mesh-hz F] [--watchdog-ms M]\n"
    "                          [--mesh-skin tube|point_skeleton|convolution] [--force-ramp-ms M]\n"
    "                          [--max-tool-speed V] [--device-max-force N] [--max-force-change N]\n"
    "                          [--workspace-scale S] [--workspace-rotation W,X,Y,Z]\n"
    "                          [--workspace-offset X,Y,Z] [--force-scale G] [--realtime P] [--quiet]\n"
    "Serves the scene over LCM at 1 kHz until SIGINT or SIGTERM (or --seconds). docs/lcm.md.\n";

static void log_line(void* user_data, int32_t level, const char* message) {
    static const char* const names[] = {"debug", "info", "warning", "error"};
    (void)user_data;
    fprintf(stderr, "enteron-lcm-server: [%s] %s\n", level >= 0 && level <= 3 ? names[level] : "log", message);
}

static int bad_value(const char* flag, const char* value) {
    fprintf(stderr, "enteron-lcm-server: %s: bad value \"%s\"\n%s", flag, value, usage);
    return 2;
}

/* Parses "a,b,c": exactly `count` finite numbers. */
static int parse_list(const char* text, double* values, int count) {
    int i;
    for (i = 0; i < count; ++i) {
        char* end = NULL;
        values[i] = strtod(text, &end);
        if (end == text || values[i] != values[i]) return 0;
        if (i + 1 < count) {
            if (*end != ',') return 0;
            text = end + 1;
        } else if (*end != '\0') {
            return 0;
        }
    }
    return 1;
}

static int parse_number(const char* text, double* value) { return parse_list(text, value, 1); }

static char* read_file(const char* path, size_t* length) {
    FILE* file = fopen(path, "rb");
    char* text = NULL;
    long size;
    if (file == NULL) return NULL;
    if (fseek(file, 0, SEEK_END) == 0 && (size = ftell(file)) >= 0 && fseek(file, 0, SEEK_SET) == 0 &&
        (text = malloc((size_t)size + 1)) != NULL) {
        *length = fread(text, 1, (size_t)size, file);
        text[*length] = '\0';
    }
    fclose(file);
    return text;
}

static double since(const struct timespec* start) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + 1e-9 * (double)(now.tv_nsec - start->tv_nsec);
}

static void print_summary(const ent_lcm_bridge* bridge, double wall_s) {
    ent_lcm_stats s;
    long long rejected;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    if (ent_lcm_bridge_stats(bridge, &s) != ENT_OK) return;
    rejected = (long long)(s.rejected_size + s.rejected_fingerprint + s.rejected_not_finite +
                           s.rejected_zero_quaternion + s.rejected_unknown_tool + s.rejected_sequence +
                           s.rejected_out_of_range);
    printf("enteron-lcm-server: %.0f s: %lld ticks (t = %.3f s), %lld missed deadlines, step %d/%d us "
           "(median/max), tick max %d us, commands %lld accepted %lld rejected, feedback %lld sent %lld dropped, "
           "%lld watchdog trips, %lld step failures\n",
           wall_s, (long long)s.ticks, s.sim_time_s, (long long)s.missed_deadlines, s.step_us_median, s.step_us_max,
           s.tick_us_max, (long long)s.commands_accepted, rejected, (long long)s.feedback_published,
           (long long)s.feedback_dropped, (long long)s.watchdog_trips, (long long)s.step_failures);
    fflush(stdout);
}

int main(int argc, char** argv) {
    ent_lcm_bridge_desc desc;
    ent_callbacks callbacks;
    ent_lcm_bridge* bridge = NULL;
    const char* scene_path = NULL;
    double seconds = 0.0, number = 0.0;
    int quiet = 0, realtime = 0, i, signal_number = 0;
    char* json;
    size_t json_length = 0;
    sigset_t stop_signals;
    struct timespec started, stopping;
    double last_print = 0.0;

    ent_lcm_bridge_desc_default(&desc);
    for (i = 1; i < argc; ++i) {
        const char* flag = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(flag, "--help") == 0 || strcmp(flag, "-h") == 0) {
            fputs(usage, stdout);
            return 0;
        }
        if (strcmp(flag, "--quiet") == 0) {
            quiet = 1;
            continue;
        }
        if (value == NULL) {
            fprintf(stderr, "enteron-lcm-server: unknown flag or missing value: %s\n%s", flag, usage);
            return 2;
        }
        ++i;
        if (strcmp(flag, "--scene") == 0) {
            scene_path = value;
        } else if (strcmp(flag, "--lcm-url") == 0) {
            desc.lcm_url = value;
        } else if (strcmp(flag, "--channel-suffix") == 0) {
            desc.channel_suffix = value;
        } else if (strcmp(flag, "--journal") == 0) {
            desc.journal_path = value;
        } else if (strcmp(flag, "--mesh-skin") == 0) {
            if (strcmp(value, "tube") == 0) desc.mesh_skin_method = ENT_SKIN_TUBE;
            else if (strcmp(value, "point_skeleton") == 0) desc.mesh_skin_method = ENT_SKIN_POINT_SKELETON;
            else if (strcmp(value, "convolution") == 0) desc.mesh_skin_method = ENT_SKIN_CONVOLUTION;
            else return bad_value(flag, value);
        } else if (strcmp(flag, "--workspace-rotation") == 0) {
            if (!parse_list(value, desc.workspace_rotation_wxyz, 4)) return bad_value(flag, value);
        } else if (strcmp(flag, "--workspace-offset") == 0) {
            if (!parse_list(value, desc.workspace_offset_m, 3)) return bad_value(flag, value);
        } else if (strcmp(flag, "--realtime") == 0) {
            if (!parse_number(value, &number) || number < 1 || number > 99) return bad_value(flag, value);
            desc.realtime_priority = (int32_t)number;
            realtime = 1;
        } else {
            /* The remaining flags take one number; the bridge checks its range and names it. */
            if (!parse_number(value, &number)) return bad_value(flag, value);
            if (strcmp(flag, "--seconds") == 0) {
                if (!(number > 0.0)) return bad_value(flag, value);
                seconds = number;
            } else if (strcmp(flag, "--state-hz") == 0) desc.state_hz = number;
            else if (strcmp(flag, "--mesh-hz") == 0) desc.mesh_hz = number;
            else if (strcmp(flag, "--watchdog-ms") == 0) desc.watchdog_s = 1e-3 * number;
            else if (strcmp(flag, "--force-ramp-ms") == 0) desc.force_ramp_s = 1e-3 * number;
            else if (strcmp(flag, "--max-tool-speed") == 0) desc.max_tool_speed_m_per_s = number;
            else if (strcmp(flag, "--device-max-force") == 0) desc.device_max_force = number;
            else if (strcmp(flag, "--max-force-change") == 0) desc.max_force_change_per_tick = number;
            else if (strcmp(flag, "--workspace-scale") == 0) desc.workspace_scale = number;
            else if (strcmp(flag, "--force-scale") == 0) desc.force_scale = number;
            else {
                fprintf(stderr, "enteron-lcm-server: unknown flag %s\n%s", flag, usage);
                return 2;
            }
        }
    }
    if (scene_path == NULL) {
        fprintf(stderr, "enteron-lcm-server: --scene FILE.json is required\n%s", usage);
        return 2;
    }
    json = read_file(scene_path, &json_length);
    if (json == NULL) {
        fprintf(stderr, "enteron-lcm-server: --scene %s: cannot read it: %s\n", scene_path, strerror(errno));
        return 2;
    }
    if ((ent_lcm_version() >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "enteron-lcm-server: libenteron_lcm has major version %u, this program needs %d\n",
                (unsigned)(ent_lcm_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    /* A vendor's server keeps its pages in memory: a page fault in the physics thread is a
       missed deadline. Needs the privilege, like the real-time priority. */
    if (realtime && mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
        fprintf(stderr, "enteron-lcm-server: --realtime: mlockall: %s (continuing)\n", strerror(errno));

    /* The bridge's threads inherit this mask: SIGINT and SIGTERM reach only sigtimedwait below. */
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, NULL);

    ent_callbacks_default(&callbacks);
    callbacks.log = log_line;
    desc.callbacks = &callbacks;
    desc.scene_json = json;
    desc.scene_json_length = json_length;
    if (ent_lcm_bridge_create(&desc, &bridge) != ENT_OK) {
        fprintf(stderr, "enteron-lcm-server: %s\n", ent_lcm_last_error());
        free(json);
        return strstr(ent_lcm_last_error(), "scene_json") != NULL ? 2 : 1;
    }
    free(json);
    if (ent_lcm_bridge_start(bridge) != ENT_OK) {
        fprintf(stderr, "enteron-lcm-server: %s\n", ent_lcm_last_error());
        ent_lcm_bridge_destroy(bridge);
        return 1;
    }
    clock_gettime(CLOCK_MONOTONIC, &started);
    printf("enteron-lcm-server: serving %s on %s%s%s, 1 tick every %.3f ms%s%s\n", scene_path,
           desc.lcm_url != NULL ? desc.lcm_url : ENT_LCM_DEFAULT_URL, desc.channel_suffix != NULL ? ", suffix " : "",
           desc.channel_suffix != NULL ? desc.channel_suffix : "", 1e3 * desc.tick_s,
           desc.journal_path != NULL ? ", journal " : "", desc.journal_path != NULL ? desc.journal_path : "");
    fflush(stdout);

    for (;;) {
        const double now = since(&started);
        double wait = last_print + 1.0 - now;
        struct timespec timeout;
        if (seconds > 0.0 && seconds - now < wait) wait = seconds - now;
        if (wait < 0.0) wait = 0.0;
        timeout.tv_sec = (time_t)wait;
        timeout.tv_nsec = (long)(1e9 * (wait - (double)timeout.tv_sec));
        signal_number = sigtimedwait(&stop_signals, NULL, &timeout);
        if (signal_number > 0) break;
        if (seconds > 0.0 && since(&started) >= seconds) break;
        if (since(&started) >= last_print + 1.0) {
            last_print += 1.0;
            if (!quiet) print_summary(bridge, last_print);
        }
    }
    clock_gettime(CLOCK_MONOTONIC, &stopping);
    print_summary(bridge, since(&started));
    ent_lcm_bridge_destroy(bridge);
    printf("enteron-lcm-server: stopped %s in %.1f ms\n",
           signal_number == SIGINT ? "after SIGINT" : signal_number == SIGTERM ? "after SIGTERM" : "at --seconds",
           1e3 * since(&stopping));
    return 0;
}
