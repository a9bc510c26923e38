/* SPDX-License-Identifier: Apache-2.0 */
/*
 * enteron_demo: a 6 m small bowel dropped into the abdominal cavity, held by its mesentery,
 * then swept aside by a surgical tool.
 *
 * Creates the scene from a JSON v1 description, steps it 1 ms at a time for a few
 * simulated seconds, prints one line per simulated second (energies, where the bowel is,
 * how long it is, its contacts and their deepest penetration, how many rollbacks the
 * stability guard made, the largest force on the tool, and the wall time per step). The
 * tool waits above the pile while it settles, then goes down into it, sweeps across the
 * cavity and rises again (the scene and the path are in demo_scene.h, shared with
 * enteron-viewer), as a haptic device would drive it. Then writes the final axis as
 * axis.obj (an OBJ polyline) and axis.csv, and the bowel's surface (convolution skin of
 * the last frame) as bowel.obj.
 *
 * With --scene FILE it runs a scene file instead (its mesh files found next to it) with
 * that scene's motion (demo_scene.h): examples/scenes/abdomen.json, the bowel among organ
 * meshes, gets the retractor that lifts the liver and the grasper of abdomen_motion.h; any
 * other file gets the demo's tool path for its tool 0 (a scene without tools just runs).
 *
 * Usage: enteron_demo [--seconds S] [--out DIR] [--scene FILE]
 *   --seconds S  simulated time, s (default 5)
 *   --out DIR    where to write axis.obj and axis.csv; created if missing (default out)
 *   --scene FILE a JSON scene file instead of the demo scene (docs/scene-json.md)
 *
 * Plain C99 against the public header only: this is what a simulator links.
 * Exit status: 0 on success, 1 when a call fails (its ent_last_error() is printed),
 * 2 on a bad command line.
 */
#define _POSIX_C_SOURCE 200809L

#include <enteron/enteron.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "demo_scene.h"

#define STEP_S 0.001           /* one ent_scene_step, s */
#define STEPS_PER_REPORT 1000  /* one report line per simulated second */
#define STATS_POINTS 1000      /* axis samples for the centre, lowest point and length */
#define OUTPUT_POINTS 200      /* axis samples written to axis.obj and axis.csv */

static double stats_axis[STATS_POINTS * 3];
static double output_axis[OUTPUT_POINTS * 3];
static double step_us[STEPS_PER_REPORT];

static int report_failure(const char* call, ent_status status) {
    fprintf(stderr, "enteron_demo: %s failed: %s: %s\n", call, ent_status_string(status),
            ent_last_error());
    return 1;
}

static double now_us(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e6 + (double)ts.tv_nsec * 1e-3;
}

static int compare_doubles(const void* a, const void* b) {
    const double x = *(const double*)a;
    const double y = *(const double*)b;
    return (x > y) - (x < y);
}

/* mkdir -p: creates dir and its missing parents. 0 on success. */
static int make_directories(const char* dir) {
    char path[4096];
    size_t i;
    const size_t length = strlen(dir);
    if (length == 0 || length >= sizeof path) {
        fprintf(stderr, "enteron_demo: bad output directory '%s'\n", dir);
        return -1;
    }
    memcpy(path, dir, length + 1);
    for (i = 1; i <= length; ++i) {
        if (path[i] == '/' || path[i] == '\0') {
            const char saved = path[i];
            path[i] = '\0';
            if (mkdir(path, 0777) != 0 && errno != EEXIST) {
                fprintf(stderr, "enteron_demo: cannot create %s: %s\n", path, strerror(errno));
                return -1;
            }
            path[i] = saved;
        }
    }
    return 0;
}

/* One report line: the published state, the largest force on the tool since the last line,
 * and the median and largest wall time of the `timed` steps since then (step_us, sorted
 * in place). */
static int report(const ent_scene* scene, double tool_force_N, size_t timed) {
    ent_stats stats;
    ent_status status;
    double center[3] = {0.0, 0.0, 0.0};
    double lowest_z = INFINITY;
    double length_m = 0.0;
    size_t i;

    memset(&stats, 0, sizeof stats);
    stats.struct_size = sizeof stats;
    status = ent_scene_stats(scene, &stats);
    if (status != ENT_OK) return report_failure("ent_scene_stats", status);
    status = ent_scene_axis(scene, STATS_POINTS, stats_axis);
    if (status != ENT_OK) return report_failure("ent_scene_axis", status);

    for (i = 0; i < STATS_POINTS; ++i) {
        const double* p = &stats_axis[3 * i];
        center[0] += p[0];
        center[1] += p[1];
        center[2] += p[2];
        if (p[2] < lowest_z) lowest_z = p[2];
        if (i > 0) {
            const double dx = p[0] - p[-3], dy = p[1] - p[-2], dz = p[2] - p[-1];
            length_m += sqrt(dx * dx + dy * dy + dz * dz);
        }
    }
    for (i = 0; i < 3; ++i) center[i] /= STATS_POINTS;
    if (!isfinite(center[0] + center[1] + center[2] + length_m + lowest_z) ||
        !isfinite(stats.kinetic_energy_J + stats.potential_energy_J)) {
        fprintf(stderr, "enteron_demo: the state is not finite at t = %.3f s\n", stats.time_s);
        return 1;
    }

    printf("%7.3f %12.6f %12.6f  %+8.4f %+8.4f %+8.4f  %+8.4f  %8.4f %8u %9.5f %9llu %8.3f",
           stats.time_s, stats.kinetic_energy_J, stats.potential_energy_J, center[0], center[1],
           center[2], lowest_z, length_m, (unsigned)stats.contacts, stats.max_penetration_m,
           (unsigned long long)stats.rollbacks, tool_force_N);
    if (timed > 0) {
        qsort(step_us, timed, sizeof step_us[0], compare_doubles);
        printf("  %10.1f %10.1f\n",
               timed % 2 ? step_us[timed / 2]
                         : 0.5 * (step_us[timed / 2 - 1] + step_us[timed / 2]),
               step_us[timed - 1]);
    } else {
        printf("  %10s %10s\n", "-", "-");
    }
    fflush(stdout);
    return 0;
}

static int write_outputs(const ent_scene* scene, const char* dir) {
    char obj_path[4200], csv_path[4200];
    FILE* obj;
    FILE* csv;
    size_t i;
    int ok;
    const ent_status status = ent_scene_axis(scene, OUTPUT_POINTS, output_axis);
    if (status != ENT_OK) return report_failure("ent_scene_axis", status);

    snprintf(obj_path, sizeof obj_path, "%s/axis.obj", dir);
    snprintf(csv_path, sizeof csv_path, "%s/axis.csv", dir);
    obj = fopen(obj_path, "w");
    if (!obj) {
        fprintf(stderr, "enteron_demo: cannot write %s: %s\n", obj_path, strerror(errno));
        return 1;
    }
    fprintf(obj, "# Enteron demo: intestine axis, %d points evenly spaced in arc length, m\n",
            OUTPUT_POINTS);
    for (i = 0; i < OUTPUT_POINTS; ++i) {
        const double* p = &output_axis[3 * i];
        fprintf(obj, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
    }
    fprintf(obj, "l");
    for (i = 1; i <= OUTPUT_POINTS; ++i) fprintf(obj, " %lu", (unsigned long)i);
    fprintf(obj, "\n");
    ok = !ferror(obj);
    if (fclose(obj) != 0 || !ok) {
        fprintf(stderr, "enteron_demo: error writing %s\n", obj_path);
        return 1;
    }

    csv = fopen(csv_path, "w");
    if (!csv) {
        fprintf(stderr, "enteron_demo: cannot write %s: %s\n", csv_path, strerror(errno));
        return 1;
    }
    fprintf(csv, "x,y,z\n");
    for (i = 0; i < OUTPUT_POINTS; ++i) {
        const double* p = &output_axis[3 * i];
        fprintf(csv, "%.9g,%.9g,%.9g\n", p[0], p[1], p[2]);
    }
    ok = !ferror(csv);
    if (fclose(csv) != 0 || !ok) {
        fprintf(stderr, "enteron_demo: error writing %s\n", csv_path);
        return 1;
    }
    printf("wrote %s\nwrote %s\n", obj_path, csv_path);
    return 0;
}

/* Skins the final state with the convolution method and writes it as bowel.obj:
 * positions (m), normals, the axis parameter u as a texture coordinate, triangles. */
static int write_skin(ent_scene* scene, const char* dir) {
    char path[4096];
    ent_skin_desc desc;
    ent_skin* skin = NULL;
    ent_mesh_view view;
    struct ent_skin_metrics metrics;
    ent_status status;
    FILE* obj;
    uint32_t i;
    int ok;

    ent_skin_desc_default(&desc);
    desc.method = ENT_SKIN_CONVOLUTION;
    status = ent_skin_create(scene, &desc, &skin);
    if (status != ENT_OK) return report_failure("ent_skin_create", status);
    status = ent_skin_update(skin);
    if (status != ENT_OK) {
        ent_skin_destroy(skin);
        return report_failure("ent_skin_update", status);
    }
    memset(&view, 0, sizeof view);
    view.struct_size = sizeof view;
    memset(&metrics, 0, sizeof metrics);
    metrics.struct_size = sizeof metrics;
    status = ent_skin_mesh(skin, &view);
    if (status == ENT_OK) status = ent_skin_metrics(skin, &metrics);
    if (status != ENT_OK) {
        ent_skin_destroy(skin);
        return report_failure("ent_skin_mesh", status);
    }
    snprintf(path, sizeof path, "%s/bowel.obj", dir);
    obj = fopen(path, "w");
    if (!obj) {
        fprintf(stderr, "enteron_demo: cannot write %s: %s\n", path, strerror(errno));
        ent_skin_destroy(skin);
        return 1;
    }
    fprintf(obj, "# Enteron demo: convolution skin of the last frame, %lu vertices, %lu triangles, m\n",
            (unsigned long)view.vertex_count, (unsigned long)view.triangle_count);
    for (i = 0; i < view.vertex_count; ++i)
        fprintf(obj, "v %.7g %.7g %.7g\n", view.positions_xyz_m[3 * i], view.positions_xyz_m[3 * i + 1],
                view.positions_xyz_m[3 * i + 2]);
    for (i = 0; i < view.vertex_count; ++i)
        fprintf(obj, "vn %.5g %.5g %.5g\n", view.normals_xyz[3 * i], view.normals_xyz[3 * i + 1],
                view.normals_xyz[3 * i + 2]);
    for (i = 0; i < view.vertex_count; ++i) fprintf(obj, "vt %.6g 0\n", view.axis_u[i]);
    for (i = 0; i < view.triangle_count; ++i) {
        const unsigned long a = view.indices[3 * i] + 1ul, b = view.indices[3 * i + 1] + 1ul,
                            c = view.indices[3 * i + 2] + 1ul;
        fprintf(obj, "f %lu/%lu/%lu %lu/%lu/%lu %lu/%lu/%lu\n", a, a, a, b, b, b, c, c, c);
    }
    ok = !ferror(obj);
    if (fclose(obj) != 0 || !ok) {
        fprintf(stderr, "enteron_demo: error writing %s\n", path);
        ent_skin_destroy(skin);
        return 1;
    }
    printf("wrote %s (convolution skin: %lu triangles, radius error RMS %.2f %% of R, %s, "
           "%.2f ms per update)\n",
           path, (unsigned long)view.triangle_count, 100.0 * metrics.radius_error_rms,
           metrics.watertight ? "watertight" : "NOT watertight", (double)metrics.last_update_ns * 1e-6);
    ent_skin_destroy(skin);
    return metrics.watertight ? 0 : 1;
}

static void usage(FILE* to) {
    fprintf(to, "usage: enteron_demo [--seconds S] [--out DIR] [--scene FILE]\n"
                "  --seconds S  simulated time in seconds (default 5)\n"
                "  --out DIR    output directory for axis.obj and axis.csv (default out)\n"
                "  --scene FILE a JSON scene file instead of the demo scene, played with its motion\n"
                "               (examples/scenes/abdomen.json: the retractor lifts the liver)\n");
}

int main(int argc, char** argv) {
    double seconds = 5.0;
    const char* out_dir = "out";
    const char* scene_path = NULL;  /* NULL: the demo scene */
    const demo_motion* motion;
    int32_t tools = 0; /* a scene file may have none: then no tool path and no force column */
    double obstacle_start_m[3] = {0.0, 0.0, 0.0}, obstacle_orientation[4] = {1.0, 0.0, 0.0, 0.0};
    ent_scene* scene = NULL;
    ent_status status;
    long total_steps, step;
    size_t timed = 0;
    double tool_force_N = 0.0;     /* largest |F| on the tool since the last report line */
    double tool_force_max_N = 0.0; /* over the whole run */
    const uint32_t version = ent_version();
    int i;

    for (i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            char* end = NULL;
            seconds = strtod(argv[++i], &end);
            if (end == argv[i] || *end != '\0' || !isfinite(seconds) || seconds <= 0.0 ||
                seconds > 3600.0) {
                fprintf(stderr, "enteron_demo: --seconds wants a number in (0, 3600], got '%s'\n",
                        argv[i]);
                return 2;
            }
        } else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc) {
            out_dir = argv[++i];
        } else if (strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
            scene_path = argv[++i];
        } else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "enteron_demo: unknown or incomplete argument '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }

    if ((version >> 16) != ENT_VERSION_MAJOR) {
        fprintf(stderr, "enteron_demo: libenteron major version %u, built for %d\n",
                (unsigned)(version >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    if (make_directories(out_dir) != 0) return 1;

    if (scene_path == NULL) {
        status = ent_scene_create_json(demo_scene_json, strlen(demo_scene_json), &scene);
        if (status != ENT_OK) return report_failure("ent_scene_create_json", status);
    } else {
        status = ent_scene_create_json_file(scene_path, NULL, &scene);
        if (status != ENT_OK) return report_failure("ent_scene_create_json_file", status);
    }
    status = ent_scene_tool_count(scene, &tools);
    if (status != ENT_OK) {
        ent_scene_destroy(scene);
        return report_failure("ent_scene_tool_count", status);
    }
    motion = demo_motion_for_scene(scene_path);
    if (motion == NULL) motion = demo_motion_named("demo");
    if (motion->obstacle >= 0) {
        /* The organ moves from where the scene puts it. */
        status = ent_obstacle_pose(scene, motion->obstacle, obstacle_start_m, obstacle_orientation);
        if (status != ENT_OK) {
            ent_scene_destroy(scene);
            return report_failure("ent_obstacle_pose", status);
        }
    }

    total_steps = lround(seconds / STEP_S);
    if (total_steps < 1) total_steps = 1;
    if (scene_path == NULL) {
        printf("enteron_demo: libenteron %u.%u.%u, 6 m bowel, 240 control points, implicit Euler,"
               " a tool, %ld steps of %g ms\n",
               (unsigned)(version >> 16), (unsigned)((version >> 8) & 0xffu),
               (unsigned)(version & 0xffu), total_steps, STEP_S * 1e3);
    } else {
        uint32_t control_points = 0, obstacles = 0;
        status = ent_scene_control_points(scene, 0, NULL, &control_points);
        if (status == ENT_OK) status = ent_scene_obstacle_count(scene, &obstacles);
        if (status != ENT_OK) {
            ent_scene_destroy(scene);
            return report_failure("the scene's queries", status);
        }
        printf("enteron_demo: libenteron %u.%u.%u, %s: %u control points, %u obstacles, the %s motion,"
               " %ld steps of %g ms\n",
               (unsigned)(version >> 16), (unsigned)((version >> 8) & 0xffu),
               (unsigned)(version & 0xffu), scene_path, (unsigned)control_points, (unsigned)obstacles,
               motion->name, total_steps, STEP_S * 1e3);
    }
    printf("%7s %12s %12s  %26s  %8s  %8s %8s %9s %9s %8s  %10s %10s\n", "t_s", "kinetic_J",
           "potential_J", "axis_centre_xyz_m", "lowest_z", "length_m", "contacts", "max_pen_m",
           "rollbacks", "tool_F_N", "median_us", "max_us");
    if (report(scene, 0.0, 0) != 0) {
        ent_scene_destroy(scene);
        return 1;
    }

    for (step = 1; step <= total_steps; ++step) {
        static const double upright[4] = {1.0, 0.0, 0.0, 0.0};
        double tip[3], force[3], torque[3], magnitude;
        double start;
        /* Where the device puts the tool at the end of this step; it moves there
         * continuously during the step. */
        path_at(motion->tool_keys, motion->tool_key_count, (double)step * STEP_S, tip);
        status = tools > 0 ? ent_tool_set_pose(scene, 0, tip, upright) : ENT_OK;
        if (status != ENT_OK) {
            ent_scene_destroy(scene);
            return report_failure("ent_tool_set_pose", status);
        }
        if (motion->obstacle >= 0) {
            /* The retractor: the organ's pose at the end of this step. */
            status = obstacle_follow_path(scene, motion->obstacle, obstacle_start_m, obstacle_orientation,
                                          motion->obstacle_keys, motion->obstacle_key_count, (double)step * STEP_S);
            if (status != ENT_OK) {
                ent_scene_destroy(scene);
                return report_failure("ent_obstacle_set_pose", status);
            }
        }
        start = now_us();
        status = ent_scene_step(scene, STEP_S);
        step_us[timed++] = now_us() - start;
        if (status != ENT_OK) {
            report_failure("ent_scene_step", status);
            fprintf(stderr, "enteron_demo: at step %ld\n", step);
            ent_scene_destroy(scene);
            return 1;
        }
        /* The force the haptic device would render. */
        memset(force, 0, sizeof force);
        status = tools > 0 ? ent_tool_wrench(scene, 0, force, torque) : ENT_OK;
        if (status != ENT_OK) {
            ent_scene_destroy(scene);
            return report_failure("ent_tool_wrench", status);
        }
        magnitude = sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
        if (magnitude > tool_force_N) tool_force_N = magnitude;
        if (magnitude > tool_force_max_N) tool_force_max_N = magnitude;
        if (timed == STEPS_PER_REPORT || step == total_steps) {
            if (report(scene, tool_force_N, timed) != 0) {
                ent_scene_destroy(scene);
                return 1;
            }
            timed = 0;
            tool_force_N = 0.0;
        }
    }
    if (tools > 0) printf("tool: largest force %.3f N (bound 5 N)\n", tool_force_max_N);
    if (motion->obstacle >= 0) {
        /* Where the retractor left the organ, as a renderer sees it (the published pose). */
        double at[3], orientation[4];
        status = ent_obstacle_pose(scene, motion->obstacle, at, orientation);
        if (status != ENT_OK) {
            ent_scene_destroy(scene);
            return report_failure("ent_obstacle_pose", status);
        }
        printf("obstacle %d moved (%+.3f, %+.3f, %+.3f) m by the %s motion\n", motion->obstacle,
               at[0] - obstacle_start_m[0], at[1] - obstacle_start_m[1], at[2] - obstacle_start_m[2], motion->name);
    }
    {
        /* The tool's passivity observer over the whole path (docs/haptics.md, Passivity). */
        ent_tool_stats observer;
        memset(&observer, 0, sizeof observer);
        observer.struct_size = sizeof observer;
        if (tools > 0 && ent_tool_read_stats(scene, 0, &observer) == ENT_OK)
            printf("tool: passivity: %.4f J put in, %.4f J given back, balance %.4f J\n", observer.energy_in_J,
                   observer.energy_out_J, observer.energy_in_J - observer.energy_out_J);
    }

    if (write_outputs(scene, out_dir) != 0 || write_skin(scene, out_dir) != 0) {
        ent_scene_destroy(scene);
        return 1;
    }
    ent_scene_destroy(scene);
    return 0;
}
