/* SPDX-License-Identifier: Apache-2.0 */
/* A haptic device's servo loop faster than the physics (docs/haptics.md, "Local stiffness
 * for fast servo loops"): physics at 1 kHz, a device loop at 4 kHz that renders, between
 * two physics ticks, either the last force (zero-order hold) or the local linear model
 * F_k + K_k (x - x_k) with K_k = ent_tool_stiffness. Both are measured against a reference
 * run whose physics steps at 4 kHz with the device's own samples: the RMS error of each
 * rendered force and the largest step of each from one device tick to the next.
 *
 * The device presses a vertical tool into a bowel lying on a floor and palpates it (up
 * and down). Everything runs on one thread, in
 * simulated time, so that the comparison is exact and repeatable; a real device runs
 * the same loop on its own clock (examples/haptic_shim.c).
 *
 *   enteron_multirate_device [--seconds S]
 *
 * Prints one line per rendering and a verdict; exits 1 if the local model is not better
 * than the hold. */
#include <enteron/enteron.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RATIO 4 /* device ticks per physics tick */

static const double kRadius = 0.0125;   /* m, the default R */
static const double kPhysicsDt = 1e-3;  /* s */
static const double kIdentity[4] = {1.0, 0.0, 0.0, 0.0};

/* The device's tip at time t: down into the bowel's top over the first 0.2 s, then a
 * palpation: 3 mm deep, up and down by 2 mm at 4 Hz. */
static void device_at(double t, double x[3]) {
    const double top = 2.0 * kRadius + 0.005; /* the tool's tip touching the bowel */
    const double depth = t < 0.2 ? 0.003 * t / 0.2 : 0.003 + 0.002 * sin(2.0 * 3.14159265358979323846 * 4.0 * (t - 0.2));
    x[0] = 0.0;
    x[1] = 0.0;
    x[2] = top - depth;
}

static int ok(ent_status status, const char* call) {
    if (status == ENT_OK) return 1;
    fprintf(stderr, "multirate_device: %s failed: %s\n", call, ent_last_error());
    return 0;
}

/* A 0.4 m bowel along x on a floor with a tool above its middle; settled. */
static ent_scene* make_scene(double dt) {
    ent_scene_desc desc;
    ent_scene_desc_default(&desc);
    desc.length_m = 0.4;
    desc.control_points = 17;
    desc.shape = ENT_SHAPE_LINE;
    desc.shape_center_m[0] = -0.2;
    desc.shape_center_m[2] = kRadius;
    ent_scene* scene = NULL;
    if (!ok(ent_scene_create(&desc, &scene), "ent_scene_create")) return NULL;
    ent_obstacle_desc floor_desc;
    ent_obstacle_desc_default(&floor_desc);
    floor_desc.kind = ENT_OBSTACLE_PLANE;
    ent_tool_desc tool;
    ent_tool_desc_default(&tool);
    device_at(0.0, tool.position_m);
    int settled = ok(ent_scene_add_obstacle(scene, &floor_desc, NULL), "ent_scene_add_obstacle") &&
                  ok(ent_tool_add(scene, &tool, NULL), "ent_tool_add");
    for (int i = 0; settled && i < (int)lround(0.2 / dt); ++i) settled = ok(ent_scene_step(scene, dt), "ent_scene_step");
    if (!settled) {
        ent_scene_destroy(scene);
        return NULL;
    }
    return scene;
}

struct Rendering {
    double error2;      /* sum of squared errors against the reference, N^2 */
    double largest_step; /* N, from one device tick to the next */
    double previous[3];
};

static void render(struct Rendering* r, const double force[3], const double reference[3], int first) {
    double step2 = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double e = force[c] - reference[c], s = force[c] - r->previous[c];
        r->error2 += e * e;
        step2 += s * s;
        r->previous[c] = force[c];
    }
    if (!first && sqrt(step2) > r->largest_step) r->largest_step = sqrt(step2);
}

int main(int argc, char** argv) {
    double seconds = 2.0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            seconds = atof(argv[++i]);
        } else {
            fprintf(stderr, "usage: %s [--seconds S]\n", argv[0]);
            return 2;
        }
    }
    if (!(seconds > 0.25 && seconds < 600.0)) {
        fprintf(stderr, "multirate_device: --seconds must be within 0.25 and 600\n");
        return 2;
    }
    ent_scene* physics = make_scene(kPhysicsDt);
    ent_scene* reference = make_scene(kPhysicsDt / RATIO);
    if (physics == NULL || reference == NULL) return 1;

    struct Rendering hold, model;
    memset(&hold, 0, sizeof hold);
    memset(&model, 0, sizeof model);
    double peak = 0.0;
    int samples = 0, good = 1;
    const int ticks = (int)lround(seconds / kPhysicsDt);
    double force[3] = {0.0, 0.0, 0.0}, K[9] = {0.0}, x_k[3];
    device_at(0.0, x_k);
    for (int k = 0; k < ticks && good; ++k) {
        /* The device ticks between physics tick k and k + 1 render what tick k published. */
        for (int j = 0; j < RATIO && good; ++j) {
            const double t = (k * RATIO + j + 1) * (kPhysicsDt / RATIO);
            double x[3], wanted[3], torque[3], interpolated[3];
            device_at(t, x);
            good = ok(ent_tool_set_pose(reference, 0, x, kIdentity), "ent_tool_set_pose") &&
                   ok(ent_scene_step(reference, kPhysicsDt / RATIO), "ent_scene_step") &&
                   ok(ent_tool_wrench(reference, 0, wanted, torque), "ent_tool_wrench");
            for (int i = 0; i < 3; ++i) {
                interpolated[i] = force[i];
                for (int c = 0; c < 3; ++c) interpolated[i] += K[3 * i + c] * (x[c] - x_k[c]);
            }
            if (t > 0.25) { /* after the press, in the palpation */
                render(&hold, force, wanted, samples == 0);
                render(&model, interpolated, wanted, samples == 0);
                peak = fmax(peak, sqrt(wanted[0] * wanted[0] + wanted[1] * wanted[1] + wanted[2] * wanted[2]));
                ++samples;
            }
        }
        /* Physics tick k + 1: the device's pose at its end, then the force and its stiffness. */
        double torque[3];
        device_at((k + 1) * kPhysicsDt, x_k);
        good = good && ok(ent_tool_set_pose(physics, 0, x_k, kIdentity), "ent_tool_set_pose") &&
               ok(ent_scene_step(physics, kPhysicsDt), "ent_scene_step") &&
               ok(ent_tool_wrench(physics, 0, force, torque), "ent_tool_wrench") &&
               ok(ent_tool_stiffness(physics, 0, K), "ent_tool_stiffness");
    }
    ent_scene_destroy(physics);
    ent_scene_destroy(reference);
    if (!good || samples == 0) return 1;
    const double hold_rms = sqrt(hold.error2 / samples), model_rms = sqrt(model.error2 / samples);
    printf("multirate_device: physics 1 kHz, device 4 kHz, %d device ticks, peak |F| %.3f N (reference: physics at 4 kHz)\n",
           samples, peak);
    printf("multirate_device: zero-order hold: RMS error %.4f N, largest step %.4f N\n", hold_rms, hold.largest_step);
    printf("multirate_device: F + K (x - x_k): RMS error %.4f N, largest step %.4f N\n", model_rms, model.largest_step);
    const int better = model_rms < hold_rms && model.largest_step < hold.largest_step;
    printf("multirate_device: the local model is %s than the hold\n", better ? "closer and smoother" : "NOT better");
    return better ? 0 : 1;
}
