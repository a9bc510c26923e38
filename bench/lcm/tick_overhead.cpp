// SPDX-License-Identifier: Apache-2.0
// The LCM bridge's own cost, in one process over memq (docs/lcm.md, "Latency"): the demo
// scene (examples/lcm/scenes/demo.json, the 6 m bowel in the cavity) with its tool down in
// the pile, sweeping, ticked at 1 kHz by this thread as a host would. Per tick:
//   step      the step's own wall time (ent_stats.last_step_ns, measured by libenteron)
//   tick      the wall time of ent_lcm_bridge_tick (the bridge's work around the step + the step)
//   overhead  tick - step: what the bridge adds (target: under 5 us)
//   round trip  a command published on the bridge's memq instance -> received and checked
//             by its receive thread -> taken by the tick -> feedback published -> handled
// Prints a markdown table of median, p99 and largest over the measured ticks.
//   enteron_lcm_tick_bench SCENE.json [--seconds S]   (default 10 measured seconds)
#include <enteron/enteron_lcm.h>
#include <lcm/lcm.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <lcmtypes/enteron_tool_feedback_t.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

struct Device {
    lcm_t* lcm = nullptr;
    std::vector<int64_t> sent_ns, arrived_ns;  // per seq
    std::atomic<int64_t> echoed{0};
};

void on_feedback(const lcm_recv_buf_t* buffer, const char*, void* user) {
    const int64_t now = ent_lcm_monotonic_ns();
    auto* device = static_cast<Device*>(user);
    enteron_tool_feedback_t feedback;
    if (ent_lcm_check_message(ENT_LCM_TOOL_FEEDBACK, buffer->data, buffer->data_size) != ENT_OK ||
        enteron_tool_feedback_t_decode(buffer->data, 0, static_cast<int>(buffer->data_size), &feedback) < 0)
        return;
    const int64_t seq = feedback.command_seq;
    if (seq > device->echoed.load() && seq < static_cast<int64_t>(device->arrived_ns.size())) {
        device->arrived_ns[static_cast<std::size_t>(seq)] = now;
        device->echoed.store(seq);
    }
}

void publish(Device& device, int64_t seq, double x, double z) {
    enteron_tool_command_t c{};
    c.seq = seq;
    c.utime = seq;
    c.position_m[0] = x;
    c.position_m[2] = z;
    c.orientation_wxyz[0] = 1.0;
    c.force_enable = 1;
    uint8_t bytes[256];
    const int size = enteron_tool_command_t_encode(bytes, 0, sizeof bytes, &c);
    device.sent_ns[static_cast<std::size_t>(seq)] = ent_lcm_monotonic_ns();
    lcm_publish(device.lcm, "ENTERON_TOOL_COMMAND", bytes, static_cast<unsigned>(size));
}

// The demo's tool path (examples/demo.c): above the pile while it settles (2 s), down into it
// (to 2.6 s), then across the cavity and back every 4 s.
void tool_path(double t, double& x, double& z) {
    if (t < 2.0) {
        x = -0.1, z = 0.3;
    } else if (t < 2.6) {
        x = -0.1, z = 0.3 - (0.38 * (t - 2.0) / 0.6);
    } else {
        const double phase = std::fmod(t - 2.6, 4.0) / 2.0;  // 0..2
        x = -0.1 + 0.2 * (phase < 1.0 ? phase : 2.0 - phase);
        z = -0.08;
    }
}

struct Row {
    const char* name;
    std::vector<double> values;  // us
};

void print_row(Row& row) {
    std::sort(row.values.begin(), row.values.end());
    const std::size_t n = row.values.size();
    std::printf("| %-58s | %8.1f | %8.1f | %8.1f |\n", row.name, row.values[n / 2],
                row.values[static_cast<std::size_t>(0.99 * static_cast<double>(n - 1))], row.values.back());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: enteron_lcm_tick_bench SCENE.json [--seconds S]\n");
        return 2;
    }
    double measured_s = 10.0;
    if (argc == 4 && std::strcmp(argv[2], "--seconds") == 0) measured_s = std::atof(argv[3]);
    std::ifstream file(argv[1]);
    const std::string json((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = json.data();
    desc.scene_json_length = json.size();
    desc.lcm_url = "memq://";
    desc.watchdog_s = 1.0;  // this thread publishes and ticks: a hiccup of the machine is not a stale device
    Device device;
    ent_lcm_bridge* bridge = nullptr;
    if (json.empty() || ent_lcm_bridge_create(&desc, &bridge) != ENT_OK) {
        std::fprintf(stderr, "enteron_lcm_tick_bench: %s: %s\n", argv[1], ent_lcm_last_error());
        return 1;
    }
    void* lcm = nullptr;
    ent_lcm_bridge_lcm(bridge, &lcm);
    device.lcm = static_cast<lcm_t*>(lcm);
    const double settle_s = 3.0;
    const int64_t ticks = static_cast<int64_t>((settle_s + measured_s) * 1000.0);
    device.sent_ns.assign(static_cast<std::size_t>(ticks) + 2, 0);
    device.arrived_ns.assign(static_cast<std::size_t>(ticks) + 2, 0);
    lcm_subscribe(device.lcm, "ENTERON_TOOL_FEEDBACK", on_feedback, &device);
    ent_scene* scene = ent_lcm_bridge_scene(bridge);

    Row step{"step: ent_scene_step alone", {}}, tick{"tick: ent_lcm_bridge_tick (bridge + step)", {}},
        overhead{"bridge overhead: tick - step", {}}, round_trip{"memq round trip: command published -> its feedback handled", {}};
    int64_t missed = 0, contacts = 0;
    timespec due{};
    clock_gettime(CLOCK_MONOTONIC, &due);
    for (int64_t seq = 1; seq <= ticks; ++seq) {
        double x, z;
        tool_path(1e-3 * static_cast<double>(seq), x, z);
        publish(device, seq, x, z);
        // The receive thread checks it and puts it in the mailbox; the tick takes it.
        ent_lcm_stats stats{};
        stats.struct_size = sizeof stats;
        for (int spin = 0; spin < 100000; ++spin)
            if (ent_lcm_bridge_stats(bridge, &stats) == ENT_OK && stats.commands_accepted >= seq) break;
        const int64_t before = ent_lcm_monotonic_ns();
        ent_lcm_bridge_tick(bridge, before);
        const int64_t after = ent_lcm_monotonic_ns();
        ent_lcm_bridge_notify(bridge);
        ent_stats scene_stats{};
        scene_stats.struct_size = sizeof scene_stats;
        ent_scene_stats(scene, &scene_stats);
        if (seq > settle_s * 1000.0) {
            step.values.push_back(1e-3 * static_cast<double>(scene_stats.last_step_ns));
            tick.values.push_back(1e-3 * static_cast<double>(after - before));
            overhead.values.push_back(1e-3 * static_cast<double>(after - before - static_cast<int64_t>(scene_stats.last_step_ns)));
            contacts += scene_stats.contacts > 0 ? 1 : 0;
        }
        due.tv_nsec += 1000000;
        if (due.tv_nsec >= 1000000000) due.tv_nsec -= 1000000000, ++due.tv_sec;
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (now.tv_sec > due.tv_sec || (now.tv_sec == due.tv_sec && now.tv_nsec > due.tv_nsec)) {
            ++missed;
            due = now;
        } else {
            clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &due, nullptr);
        }
    }
    const timespec pause{0, 50000000};
    nanosleep(&pause, nullptr);  // the last feedback
    for (int64_t seq = static_cast<int64_t>(settle_s * 1000.0) + 1; seq <= ticks; ++seq)
        if (device.arrived_ns[static_cast<std::size_t>(seq)] > 0)
            round_trip.values.push_back(1e-3 * static_cast<double>(device.arrived_ns[static_cast<std::size_t>(seq)] -
                                                                   device.sent_ns[static_cast<std::size_t>(seq)]));
    ent_lcm_bridge_destroy(bridge);

    std::printf("In-process over memq, %s, %.0f s measured after %.0f s of settling (the tool in the pile from 2.6 s; "
                "contacts in %lld of %zu ticks), %lld ticks of this thread late:\n\n",
                argv[1], measured_s, settle_s, static_cast<long long>(contacts), step.values.size(),
                static_cast<long long>(missed));
    std::printf("| %-58s | %8s | %8s | %8s |\n|---|---:|---:|---:|\n", "per tick (us)", "median", "p99", "max");
    for (Row* row : {&step, &tick, &overhead, &round_trip}) print_row(*row);
    return 0;
}
