/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The driver side of the LCM bridge: what a haptic-device vendor writes to drive a running
 * enteron-lcm-server. It speaks only LCM through the C types lcm-gen makes from
 * bindings/lcm (it does not link libenteron): a 1 kHz loop that sends the tool's pose as a
 * tool_command_t and receives a tool_feedback_t every physics tick. The device here is
 * simulated: a scripted tool path, in millimetres in the device's own frame (the server
 * maps it into the scene: --workspace-scale 0.001). It renders nothing; it prints the
 * force it would render, the command-to-feedback round trip and how many feedback ticks
 * it missed.
 *
 *   enteron_lcm_haptic_device [--lcm-url URL] [--channel-suffix S] [--seconds T] [--tool N]
 *                             [--script grasp|sweep] [--free-running] [--quiet]
 *     --script grasp   approach the bowel, push it aside, grasp it, lift it, release it,
 *                      withdraw (examples/lcm/scenes/short_bowel.json; the default)
 *     --script sweep   go down into the pile and sweep it back and forth until the end
 *                      (examples/lcm/scenes/demo.json; the benchmark's device)
 *     --free-running   send on the device's own 1 kHz clock (see "Timing" below)
 *
 * Start the server first, e.g.
 *   enteron-lcm-server --scene examples/lcm/scenes/short_bowel.json --workspace-scale 0.001
 *
 * Timing. The server ticks on its own clock; a command waits in its mailbox until the next
 * tick. A device sending on an unrelated 1 kHz clock waits half a period on average. This
 * one phase-locks its sends to the feedback stream instead: it sends its next command a
 * lead time before the next feedback is due, so that it arrives just before the tick that
 * uses it, and adapts the lead: longer after a command missed its tick, slowly shorter
 * while none does. The round trip then settles near the system's own latency (network
 * both ways + the physics step + publication).
 *
 * Safety, as a vendor's driver would do it: a feedback message is decoded only after its
 * exact size and fingerprint were checked; the device sends force_enable = 1 (the deadman
 * pressed) and would render zero force when the feedback says STALE, UNSTABLE or stops
 * arriving.
 *
 * Single-threaded: pselect() on LCM's file descriptor until the next send time, then send.
 * Exit status: 0 when feedback arrived, 1 when none did, 2 on a bad command line.
 */
#define _POSIX_C_SOURCE 200809L

#include <lcm/lcm.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>

#include <math.h>
#include <sys/select.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PERIOD_NS 1000000LL    /* 1 kHz */
#define PRINTS_PER_SECOND 4
#define MAX_CHANNEL 128
#define NEEDED_WINDOW 1000     /* commands the lead adapts over */
#define LEAD_MARGIN_US 50.0

/* ---- the scripted device: key poses of the tip, mm, device frame ------------------------ */

enum action { NONE, GRASP, RELEASE };
typedef struct {
    const char* name;
    double share;       /* of the run's duration (grasp script) */
    enum action first;  /* done when the phase starts */
    double to[3];       /* mm */
} phase;

/* examples/lcm/scenes/short_bowel.json: a 0.4 m bowel along x on the floor (z = 0). */
static const double grasp_start[3] = {0.0, 60.0, 60.0};
static const phase grasp_script[] = {
    {"approach", 0.15, NONE, {0.0, 40.0, 12.5}},    /* down beside the bowel */
    {"push", 0.25, NONE, {0.0, -20.0, 12.5}},       /* across its rest line: the bowel gives way */
    {"grasp", 0.05, GRASP, {0.0, -20.0, 12.5}},     /* it touches the tip: close the jaws */
    {"lift", 0.20, NONE, {0.0, -20.0, 92.5}},       /* 8 cm up */
    {"hold", 0.10, NONE, {0.0, -20.0, 92.5}},
    {"release", 0.10, RELEASE, {0.0, -20.0, 92.5}}, /* it drops back to the floor */
    {"withdraw", 0.15, NONE, {0.0, 60.0, 60.0}},
};
#define GRASP_PHASES (sizeof grasp_script / sizeof grasp_script[0])
#define LIFT_PHASE 3

/* examples/lcm/scenes/demo.json: down into the settled pile in 1.5 s, then across the
   cavity and back every 4 s (50 mm/s at most). */
static const double sweep_start[3] = {-100.0, 0.0, 300.0};

typedef struct {
    /* settings */
    const char* url;
    char command_channel[MAX_CHANNEL], feedback_channel[MAX_CHANNEL];
    double seconds;
    int tool, sweep, phase_lock, quiet;
    /* the loop */
    lcm_t* lcm;
    struct timespec start;
    int64_t seq;
    int64_t* sent_ns;       /* per seq: when it was sent (index seq) */
    int64_t* aimed_tick;    /* per seq: the tick it was sent for (the one after the last feedback seen) */
    long commands;
    int64_t lead_ns;        /* phase lock: send this long before the next feedback is due */
    double needed_us[NEEDED_WINDOW]; /* the lead each of the last commands needed */
    long needed_count, late_commands;
    int64_t next_send_ns;
    int64_t last_send_ns;
    int current_phase;
    int grasp;
    /* feedback */
    long feedback, missed_ticks, bad_feedback;
    int64_t last_tick, last_echoed_seq;
    double* round_trip_us;  /* one per command whose feedback came back */
    double* system_us;      /* the same less its wait for the tick: the system's own latency */
    long round_trips, over_one_tick;
    double force[3], largest_force;
    int32_t status;
    int locked_out; /* the commands rejected are this device's (docs/lcm.md) */
    int grasping, grasped, held_through_lift;
} device;

static int64_t now_ns(const device* d) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (int64_t)(t.tv_sec - d->start.tv_sec) * 1000000000LL + (t.tv_nsec - d->start.tv_nsec);
}

static int64_t wall_us(void) {
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    return (int64_t)t.tv_sec * 1000000 + t.tv_nsec / 1000;
}

/* Eases in and out between two poses: no jump in the device's velocity. */
static void ease(const double from[3], const double to[3], double a, double out[3]) {
    int c;
    a = a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a;
    a = a * a * (3.0 - 2.0 * a);
    for (c = 0; c < 3; ++c) out[c] = from[c] + a * (to[c] - from[c]);
}

/* Where the tip is at t (s), and the phase; the grasp level follows the phases' actions. */
static const char* script_pose(device* d, double t, double position[3]) {
    if (d->sweep) {
        const double bottom[3] = {-100.0, 0.0, -80.0}, across[3] = {100.0, 0.0, -80.0};
        if (t < 1.5) {
            ease(sweep_start, bottom, t / 1.5, position);
            return "down";
        }
        t = fmod(t - 1.5, 4.0);
        if (t < 2.0) ease(bottom, across, t / 2.0, position);
        else ease(across, bottom, (t - 2.0) / 2.0, position);
        return "sweep";
    } else {
        const double* from = grasp_start;
        double begin = 0.0;
        size_t i;
        for (i = 0; i < GRASP_PHASES; ++i) {
            const double length = grasp_script[i].share * d->seconds;
            if (t < begin + length || i == GRASP_PHASES - 1) {
                if ((int)i != d->current_phase) {
                    d->current_phase = (int)i;
                    if (grasp_script[i].first == GRASP) d->grasp = 1;
                    if (grasp_script[i].first == RELEASE) {
                        d->held_through_lift = d->grasping;
                        d->grasp = 0;
                    }
                }
                ease(from, grasp_script[i].to, length > 0.0 ? (t - begin) / length : 1.0, position);
                return grasp_script[i].name;
            }
            begin += length;
            from = grasp_script[i].to;
        }
        return "done";
    }
}

static void send_command(device* d, int64_t t_ns) {
    enteron_tool_command_t command;
    memset(&command, 0, sizeof command);
    script_pose(d, 1e-9 * (double)t_ns, command.position_m);
    command.utime = wall_us();
    command.seq = ++d->seq;
    command.tool = d->tool;
    command.orientation_wxyz[0] = 1.0; /* a vertical tool, tip down */
    command.grasp = (int8_t)d->grasp;
    command.force_enable = 1;          /* the deadman is pressed */
    d->sent_ns[d->seq] = t_ns;
    d->aimed_tick[d->seq] = d->last_tick + 1;
    enteron_tool_command_t_publish(d->lcm, d->command_channel, &command);
    ++d->commands;
    d->last_send_ns = t_ns;
}

static int by_value(const void* a, const void* b) {
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

/* Sorts values and gives their median and 99th percentile. */
static void percentiles(double* values, long count, double* median, double* p99) {
    qsort(values, (size_t)count, sizeof *values, by_value);
    *median = values[count / 2];
    *p99 = values[(long)(0.99 * (double)(count - 1))];
}

/* The lead: what 99 % of the last commands needed, plus a margin, within [50 us, 0.9 period]. */
static void adapt_lead(device* d) {
    double sorted[NEEDED_WINDOW];
    const long count = d->needed_count < NEEDED_WINDOW ? d->needed_count : NEEDED_WINDOW;
    double median, lead_us;
    memcpy(sorted, d->needed_us, (size_t)count * sizeof *sorted);
    percentiles(sorted, count, &median, &lead_us);
    lead_us += LEAD_MARGIN_US;
    lead_us = lead_us < 50.0 ? 50.0 : lead_us > 0.9e-3 * PERIOD_NS ? 0.9e-3 * PERIOD_NS : lead_us;
    d->lead_ns = (int64_t)(1e3 * lead_us);
}

/* Receives raw bytes and decodes only an exact tool_feedback_t: never trust the network. */
static void on_feedback(const lcm_recv_buf_t* buffer, const char* channel, void* user) {
    device* d = user;
    enteron_tool_feedback_t feedback, empty;
    const int64_t arrival_ns = now_ns(d);
    (void)channel;
    memset(&empty, 0, sizeof empty);
    if (buffer->data_size != (uint32_t)enteron_tool_feedback_t_encoded_size(&empty) ||
        enteron_tool_feedback_t_decode(buffer->data, 0, (int)buffer->data_size, &feedback) < 0) {
        ++d->bad_feedback; /* the decoder checks the fingerprint */
        return;
    }
    if (feedback.tool != d->tool) return;
    ++d->feedback;
    if (d->last_tick >= 0 && feedback.tick > d->last_tick + 1) d->missed_ticks += (long)(feedback.tick - d->last_tick - 1);
    if (feedback.tick > d->last_tick) d->last_tick = feedback.tick;
    memcpy(d->force, feedback.force_N, sizeof d->force);
    d->status = feedback.status;
    /* Commands rejected, and the one applied is not ours: this device is the one locked out
       (another sender keeps the tool's sequence, or the bridge refuses what we send). */
    d->locked_out = (feedback.status & ENTERON_TOOL_FEEDBACK_T_STATUS_COMMANDS_REJECTED) != 0 &&
                    feedback.command_seq != d->seq;
    d->grasping = feedback.grasping;
    if (feedback.grasping) d->grasped = 1;
    {
        const double magnitude = sqrt(feedback.force_N[0] * feedback.force_N[0] + feedback.force_N[1] * feedback.force_N[1] +
                                      feedback.force_N[2] * feedback.force_N[2]);
        if (magnitude > d->largest_force) d->largest_force = magnitude;
    }
    /* The first feedback that applied a command closes its round trip. The command made its
       tick if the tick it was aimed at applied it; if a later one did, the lead was too short. */
    if (feedback.command_seq > d->last_echoed_seq && feedback.command_seq <= d->seq) {
        const double round_trip_us = 1e-3 * (double)(arrival_ns - d->sent_ns[feedback.command_seq]);
        d->last_echoed_seq = feedback.command_seq;
        d->system_us[d->round_trips] = round_trip_us - feedback.command_age_us;
        d->round_trip_us[d->round_trips++] = round_trip_us;
        if (round_trip_us > 1e-3 * PERIOD_NS) ++d->over_one_tick;
        if (feedback.tick > d->aimed_tick[feedback.command_seq]) ++d->late_commands;
        /* What this command needed as lead: its round trip less the time it waited for its
           tick (measured by the server). Both are durations on one clock each: no clock sync. */
        d->needed_us[d->needed_count++ % NEEDED_WINDOW] = d->system_us[d->round_trips - 1];
        if (d->needed_count % (NEEDED_WINDOW / 4) == 0) adapt_lead(d);
    }
    /* Phase lock: the next feedback is due one period after this one. */
    if (d->phase_lock) {
        const int64_t target = arrival_ns + PERIOD_NS - d->lead_ns;
        if (target > d->last_send_ns + PERIOD_NS / 2) d->next_send_ns = target;
    }
}

static const char* status_text(int32_t status, int locked_out, char* text, size_t size) {
    static const char* const names[] = {"STALE", "NO_COMMAND", "FORCE_LIMITED", "RATE_LIMITED", "UNSTABLE",
                                        "FORCE_DISABLED", "COMMANDS_REJECTED"};
    static const char* const reasons[] = {"size", "fingerprint", "not finite", "zero quaternion", "unknown tool",
                                          "out of range", "sequence"};
    const int reason = (status & ENTERON_TOOL_FEEDBACK_T_REJECTION_MASK) >> ENTERON_TOOL_FEEDBACK_T_REJECTION_SHIFT;
    size_t i, length = 0;
    text[0] = '\0';
    for (i = 0; i < 7; ++i)
        if (status & (1 << i)) length += (size_t)snprintf(text + length, size - length, "%s%s", length ? "|" : "", names[i]);
    if (reason >= 1 && reason <= 7 && length < size)
        length += (size_t)snprintf(text + length, size - length, " (%s%s)", reasons[reason - 1],
                                   locked_out ? ": ours, locked out" : "");
    if (length == 0) snprintf(text, size, "ok");
    return text;
}

int main(int argc, char** argv) {
    device d;
    const char* suffix = "";
    long expected, i;
    int64_t end_ns, next_print_ns = 0;
    int descriptor;
    memset(&d, 0, sizeof d);
    d.url = "udpm://239.255.76.67:7667?ttl=0";
    d.seconds = 4.0;
    d.phase_lock = 1;
    d.last_tick = -1;
    d.current_phase = -1;
    d.lead_ns = 400000;
    for (i = 1; i < argc; ++i) {
        const char* flag = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(flag, "--free-running") == 0) d.phase_lock = 0;
        else if (strcmp(flag, "--quiet") == 0) d.quiet = 1;
        else if (value != NULL && strcmp(flag, "--lcm-url") == 0) d.url = argv[++i];
        else if (value != NULL && strcmp(flag, "--channel-suffix") == 0) suffix = argv[++i];
        else if (value != NULL && strcmp(flag, "--seconds") == 0) d.seconds = atof(argv[++i]);
        else if (value != NULL && strcmp(flag, "--tool") == 0) d.tool = atoi(argv[++i]);
        else if (value != NULL && strcmp(flag, "--script") == 0 && (strcmp(value, "grasp") == 0 || strcmp(value, "sweep") == 0))
            d.sweep = strcmp(argv[++i], "sweep") == 0;
        else {
            fprintf(stderr, "usage: enteron_lcm_haptic_device [--lcm-url URL] [--channel-suffix S] [--seconds T] "
                            "[--tool N] [--script grasp|sweep] [--free-running] [--quiet]\n");
            return 2;
        }
    }
    if (!(d.seconds >= 0.5 && d.seconds <= 3600.0) || strlen(suffix) > MAX_CHANNEL - 32) {
        fprintf(stderr, "haptic_device: --seconds must be in [0.5, 3600] and the suffix short\n");
        return 2;
    }
    snprintf(d.command_channel, MAX_CHANNEL, "ENTERON_TOOL_COMMAND%s", suffix);
    snprintf(d.feedback_channel, MAX_CHANNEL, "ENTERON_TOOL_FEEDBACK%s", suffix);
    expected = (long)(d.seconds * 1000.0) + 1000;
    d.sent_ns = calloc((size_t)expected * 2, sizeof *d.sent_ns); /* before the loop: it never allocates */
    d.aimed_tick = calloc((size_t)expected * 2, sizeof *d.aimed_tick);
    d.round_trip_us = calloc((size_t)expected * 2, sizeof *d.round_trip_us);
    d.system_us = calloc((size_t)expected * 2, sizeof *d.system_us);
    d.lcm = lcm_create(d.url);
    if (d.sent_ns == NULL || d.aimed_tick == NULL || d.round_trip_us == NULL || d.system_us == NULL || d.lcm == NULL) {
        fprintf(stderr, "haptic_device: cannot open LCM at %s\n", d.url);
        return 1;
    }
    {
        lcm_subscription_t* subscription = lcm_subscribe(d.lcm, d.feedback_channel, on_feedback, &d);
        lcm_subscription_set_queue_capacity(subscription, 1000); /* a late loop must not lose feedback */
    }
    printf("haptic_device: %s script, %.1f s at 1 kHz on %s, tool %d, %s\n", d.sweep ? "sweep" : "grasp", d.seconds,
           d.url, d.tool, d.phase_lock ? "phase-locked to the feedback" : "free-running");
    fflush(stdout);

    clock_gettime(CLOCK_MONOTONIC, &d.start);
    end_ns = (int64_t)(d.seconds * 1e9);
    descriptor = lcm_get_fileno(d.lcm);
    for (;;) {
        int64_t t = now_ns(&d);
        if (t >= end_ns) break;
        if (t >= d.next_send_ns) {
            send_command(&d, t);
            /* Free-running, or until the feedback sets the phase: one period later. */
            d.next_send_ns += PERIOD_NS;
            if (d.next_send_ns <= t) d.next_send_ns = t + PERIOD_NS;
        }
        if (!d.quiet && t >= next_print_ns) {
            char text[128];
            const double magnitude = sqrt(d.force[0] * d.force[0] + d.force[1] * d.force[1] + d.force[2] * d.force[2]);
            double position[3];
            const char* phase_name = script_pose(&d, 1e-9 * (double)t, position);
            printf("haptic_device: t = %5.2f s  %-8s  F = (%6.3f, %6.3f, %6.3f) N  |F| = %5.3f N  %s%s\n", 1e-9 * (double)t,
                   phase_name, d.force[0], d.force[1], d.force[2], magnitude, status_text(d.status, d.locked_out, text, sizeof text),
                   d.grasping ? "  grasping" : "");
            fflush(stdout);
            next_print_ns += 1000000000LL / PRINTS_PER_SECOND;
        }
        t = now_ns(&d);
        {
            const int64_t wait_ns = d.next_send_ns > t ? d.next_send_ns - t : 0;
            const struct timespec timeout = {(time_t)(wait_ns / 1000000000LL), (long)(wait_ns % 1000000000LL)};
            fd_set readable;
            FD_ZERO(&readable);
            FD_SET(descriptor, &readable);
            if (pselect(descriptor + 1, &readable, NULL, NULL, &timeout, NULL) > 0) lcm_handle(d.lcm);
        }
        if (d.seq >= expected * 2 - 1) break;
    }
    /* Let the feedback of the last commands in (the server keeps publishing: 20 ms at most). */
    end_ns = now_ns(&d) + 20000000LL;
    while (now_ns(&d) < end_ns && lcm_handle_timeout(d.lcm, 5) >= 0) {
    }

    if (d.round_trips > 0) {
        double median, p99, system_median, system_p99;
        percentiles(d.system_us, d.round_trips, &system_median, &system_p99);
        percentiles(d.round_trip_us, d.round_trips, &median, &p99);
        printf("haptic_device: %ld commands, %ld feedback ticks (%ld missed), round trip median %.0f us, p99 %.0f us, "
               "max %.0f us (%ld over one tick, %ld late for their tick, lead %.0f us; without the wait for the tick: "
               "median %.0f us, p99 %.0f us), largest |F| %.3f N",
               d.commands, d.feedback, d.missed_ticks, median, p99, d.round_trip_us[d.round_trips - 1], d.over_one_tick,
               d.late_commands, 1e-3 * (double)d.lead_ns, system_median, system_p99, d.largest_force);
        if (!d.sweep)
            printf(", grasped %s, held through the lift %s", d.grasped ? "yes" : "no", d.held_through_lift ? "yes" : "no");
        printf("\n");
    } else {
        printf("haptic_device: %ld commands, no feedback on %s: is the server running (same URL and suffix)?\n",
               d.commands, d.feedback_channel);
    }
    if (d.bad_feedback > 0) printf("haptic_device: %ld feedback messages were not a tool_feedback_t\n", d.bad_feedback);
    lcm_destroy(d.lcm);
    free(d.sent_ns);
    free(d.aimed_tick);
    free(d.round_trip_us);
    free(d.system_us);
    return d.feedback > 0 ? 0 : 1;
}
