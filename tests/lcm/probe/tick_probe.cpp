// SPDX-License-Identifier: Apache-2.0
// "The tick makes no system call and allocates nothing": 3000 ticks of a bridge at work
// (commands arriving from another thread, a grasp, a watchdog trip, the journal on, the
// publishing and report threads busy over memq) run on a thread where
//   - every system call traps (seccomp, SECCOMP_RET_TRAP: the SIGSYS handler records the
//     call and makes it fail), but clock reads, which libenteron's step makes for its
//     timing statistics and which x86-64 Linux serves from the vDSO without a system call;
//   - every allocation of that thread is counted (tests/no_alloc/alloc_counter.c).
// The probe first makes one system call on purpose and expects the handler to catch it, so
// that a filter that catches nothing cannot pass. The first 200 ticks run before, on the
// main thread (the first steps allocate their buffers).
#include <enteron/enteron_lcm.h>
#include <lcmtypes/enteron_tool_command_t.h>
#include <linux/audit.h>
#include <linux/filter.h>
#include <linux/seccomp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <ucontext.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "alloc_counter.h"
#include "first_callers.h"
#include "../short_bowel_scene.h"

namespace {

constexpr int kWarmupTicks = 200;
constexpr int kProbedTicks = 3000;

// What the SIGSYS handler saw on the probed thread.
std::atomic<int> trapped{0};
long first_trapped[8];

void on_sigsys(int, siginfo_t* info, void* context) {
    const int index = trapped.fetch_add(1);
    if (index < 8) first_trapped[index] = info->si_syscall;
    // The call fails instead of running.
    static_cast<ucontext_t*>(context)->uc_mcontext.gregs[REG_RAX] = -ENOSYS;
}

bool install_filter() {
    sock_filter program[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, AUDIT_ARCH_X86_64, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_rt_sigreturn, 4, 0),  // leaving the handler
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_exit, 3, 0),          // the probe's own end
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_clock_gettime, 2, 0),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, __NR_gettimeofday, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_TRAP),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    sock_fprog filter{static_cast<unsigned short>(sizeof program / sizeof program[0]), program};
    return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 &&
           syscall(SYS_seccomp, SECCOMP_SET_MODE_FILTER, 0, &filter) == 0;
}

std::vector<uint8_t> command_bytes(int64_t seq, double x, double z, bool grasp) {
    enteron_tool_command_t c{};
    c.utime = seq;
    c.seq = seq;
    c.position_m[0] = x;
    c.position_m[2] = z;
    c.orientation_wxyz[0] = 1.0;
    c.grasp = grasp ? 1 : 0;
    c.force_enable = 1;
    std::vector<uint8_t> bytes(static_cast<std::size_t>(enteron_tool_command_t_encoded_size(&c)));
    enteron_tool_command_t_encode(bytes.data(), 0, static_cast<int>(bytes.size()), &c);
    return bytes;
}

struct Probe {
    ent_lcm_bridge* bridge = nullptr;
    std::atomic<bool> done{false};
    bool filter_installed = false;
    int caught_on_purpose = 0;
    int syscalls = 0;
    unsigned long allocations = 0;
    int failed_ticks = 0;
};

void probe_thread(Probe* probe) {
    if (!(probe->filter_installed = install_filter())) {
        probe->done.store(true);
        return;
    }
    syscall(SYS_getppid);  // caught on purpose: the handler works
    probe->caught_on_purpose = trapped.exchange(0);
    alloc_counter_start_this_thread();
    for (int tick = 0; tick < kProbedTicks; ++tick) {
        if (ent_lcm_bridge_tick(probe->bridge, ent_lcm_monotonic_ns()) != ENT_OK) ++probe->failed_ticks;
        // Paced by spinning on the clock (a sleep would be a system call): about 1 kHz.
        const int64_t until = ent_lcm_monotonic_ns() + 1000000;
        while (ent_lcm_monotonic_ns() < until) {
        }
    }
    probe->allocations = alloc_counter_stop();
    probe->syscalls = trapped.load();
    probe->done.store(true);
    syscall(SYS_exit, 0);  // allowed: the thread ends without glibc's clean-up system calls
}

}  // namespace

int main() {
    struct sigaction action {};
    action.sa_sigaction = on_sigsys;
    action.sa_flags = SA_SIGINFO;
    sigaction(SIGSYS, &action, nullptr);

    const std::string journal = std::string("/tmp/enteron_tick_probe_") + std::to_string(getpid()) + ".lcmlog";
    ent_lcm_bridge_desc desc;
    ent_lcm_bridge_desc_default(&desc);
    desc.scene_json = kShortBowelScene;
    desc.scene_json_length = sizeof kShortBowelScene - 1;
    desc.lcm_url = "memq://";
    desc.state_hz = 1000.0;
    desc.journal_path = journal.c_str();
    Probe probe;
    if (ent_lcm_bridge_create(&desc, &probe.bridge) != ENT_OK) {
        std::printf("tick_probe: FAILED: ent_lcm_bridge_create: %s\n", ent_lcm_last_error());
        return 1;
    }
    // The device: a command every millisecond from its own thread; down onto the bowel,
    // grasp, lift, a 50 ms silence (a watchdog trip), then on again.
    std::atomic<bool> stop_device{false};
    std::thread device([&] {
        for (int64_t seq = 1; !stop_device.load(); ++seq) {
            const int64_t phase = seq % 2000;
            if (phase >= 1500 && phase < 1550) {  // silence
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
                continue;
            }
            const bool grasp = phase >= 600 && phase < 1200;
            const double z = phase < 600 ? 0.012 : phase < 1200 ? 0.012 + 0.00005 * static_cast<double>(phase - 600) : 0.05;
            const std::vector<uint8_t> bytes = command_bytes(seq, -0.1, z, grasp);
            ent_lcm_bridge_feed_command(probe.bridge, bytes.data(), bytes.size(), ent_lcm_monotonic_ns());
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
    for (int tick = 0; tick < kWarmupTicks; ++tick) {
        ent_lcm_bridge_tick(probe.bridge, ent_lcm_monotonic_ns());
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    std::thread(probe_thread, &probe).detach();
    while (!probe.done.load()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    stop_device.store(true);
    device.join();

    ent_lcm_stats stats{};
    stats.struct_size = sizeof stats;
    ent_lcm_bridge_stats(probe.bridge, &stats);
    ent_lcm_bridge_destroy(probe.bridge);
    std::remove(journal.c_str());
    int failures = 0;
    if (!probe.filter_installed) {
        std::printf("tick_probe: FAILED: cannot install the seccomp filter\n");
        return 1;
    }
    std::printf("tick_probe: %d ticks on a seccomp-filtered thread (%lld commands accepted, %lld watchdog trips, "
                "%lld journal entries): %d system calls, %lu allocations\n",
                kProbedTicks, static_cast<long long>(stats.commands_accepted),
                static_cast<long long>(stats.watchdog_trips), static_cast<long long>(stats.journal_entries),
                probe.syscalls, probe.allocations);
    if (probe.caught_on_purpose != 1) {
        std::printf("tick_probe: FAILED: the filter did not catch the probe's own getppid\n");
        ++failures;
    }
    if (probe.syscalls != 0) {
        std::printf("tick_probe: FAILED: the tick made system calls; the first:");
        for (int i = 0; i < probe.syscalls && i < 8; ++i) std::printf(" %ld", first_trapped[i]);
        std::printf(" (numbers of <asm/unistd_64.h>)\n");
        ++failures;
    }
    if (probe.allocations != 0) {
        std::printf("tick_probe: FAILED: the tick allocated; first callers:\n");
        print_first_callers(probe.allocations);
        ++failures;
    }
    if (probe.failed_ticks != 0 || stats.commands_accepted < 1000 || stats.watchdog_trips < 1 ||
        stats.journal_entries < kWarmupTicks + kProbedTicks / 2) {
        std::printf("tick_probe: FAILED: the bridge did not do its work (%d failed ticks)\n", probe.failed_ticks);
        ++failures;
    }
    return failures == 0 ? 0 : 1;
}
