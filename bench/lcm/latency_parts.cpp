// SPDX-License-Identifier: Apache-2.0
// The parts of the LCM round trip, each measured alone (docs/lcm.md, "Latency"), so that a
// round trip slower than its target can be laid at the door of the part that takes the time:
//
//   timer    a thread sleeping to absolute 1 ms deadlines (clock_nanosleep, timer slack
//            1 ns as the bridge's threads set it): how late it wakes. The physics thread's
//            tick and a phase-locked device's send both start this way.
//   handoff  the bridge's physics -> publishing thread hand-off (lib/lcm/wakeup.h, the
//            futex the bridge uses): one thread notifies every 1 ms, after a busy interval
//            as long as a step; how long until the other runs. Both on --cpu (a server
//            pinned to one core) or the second on --peer-cpu.
//   udp      raw UDP multicast ping-pong between this process (--role ping) and another
//            (--role pong), 1 kHz, a feedback-sized datagram: the kernel's loopback and the
//            two receivers' wake-ups, without LCM.
//   lcm      the same ping-pong through LCM's udpm (lcm_publish, lcm_handle): udp plus
//            LCM's own dispatch (its reading thread, its queue, the handler call).
//
//   enteron_lcm_latency_parts timer|handoff [--cpu C] [--peer-cpu C] [--fifo P] [--seconds S] [--busy-us U]
//   enteron_lcm_latency_parts udp|lcm --role ping|pong [--cpu C] [--fifo P] [--seconds S] [--lcm-url URL]
//
// ping prints the round trip; the one-way time is about half of it. Run the pair inside a
// network namespace (bench/lcm/latency_parts.sh makes one): nothing may leave the machine.
// Prints one markdown table row per run: part, samples, median, p99, p99.9, largest (us),
// samples over 100 us and over 1 ms.
#include <arpa/inet.h>
#include <lcm/lcm.h>
#include <netinet/in.h>
#include <poll.h>
#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "lcm/wakeup.h"

namespace {

constexpr int64_t kPeriodNs = 1000000;  // 1 kHz
constexpr std::size_t kMessageBytes = 200;  // about a tool_feedback_t
constexpr const char* kGroup = "239.255.76.67";
constexpr uint16_t kPingPort = 7671, kPongPort = 7672;  // not LCM's 7667: both may run at once

int64_t monotonic_ns() {
    timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}

void sleep_until(int64_t ns) {
    const timespec when{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &when, nullptr) == EINTR) {
    }
}

void busy_for(int64_t ns) {
    const int64_t until = monotonic_ns() + ns;
    while (monotonic_ns() < until) {
    }
}

struct Options {
    std::string part, role;
    int cpu = -1, peer_cpu = -1, fifo = 0;
    double seconds = 10.0;
    double busy_us = 100.0;
    std::string lcm_url = "udpm://239.255.76.67:7667?ttl=0";
};

// Pins the calling thread and sets its scheduling, as asked; exits with a message if refused.
void place_thread(int cpu, int fifo) {
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    if (cpu >= 0) {
        cpu_set_t set;
        CPU_ZERO(&set);
        CPU_SET(cpu, &set);
        if (pthread_setaffinity_np(pthread_self(), sizeof set, &set) != 0) {
            std::fprintf(stderr, "latency_parts: cannot pin to CPU %d\n", cpu);
            std::exit(1);
        }
    }
    if (fifo > 0) {
        sched_param parameter{};
        parameter.sched_priority = fifo;
        if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &parameter) != 0) {
            std::fprintf(stderr, "latency_parts: SCHED_FIFO %d refused (needs root)\n", fifo);
            std::exit(1);
        }
    }
}

void report(const std::string& part, std::vector<double> us) {
    if (us.empty()) {
        std::printf("| %s | 0 | - | - | - | - | - | - |\n", part.c_str());
        return;
    }
    std::sort(us.begin(), us.end());
    const auto at = [&](double q) {
        const std::size_t rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(us.size())));
        return us[std::min(us.size(), std::max<std::size_t>(rank, 1)) - 1];
    };
    const auto over = [&](double limit) { return us.end() - std::upper_bound(us.begin(), us.end(), limit); };
    std::printf("| %s | %zu | %.1f | %.1f | %.1f | %.1f | %td | %td |\n", part.c_str(), us.size(), at(0.5), at(0.99),
                at(0.999), us.back(), over(100.0), over(1000.0));
}

std::string placement(const Options& o) {
    std::string text = o.cpu >= 0 ? "CPU " + std::to_string(o.cpu) : "unpinned";
    if (o.part == "handoff") text += o.peer_cpu >= 0 ? " -> CPU " + std::to_string(o.peer_cpu) : " -> the same CPU";
    if (o.fifo > 0) text += ", SCHED_FIFO " + std::to_string(o.fifo);
    return text;
}

// ---- timer: how late an absolute 1 ms sleep wakes ------------------------------------------------
void run_timer(const Options& o) {
    place_thread(o.cpu, o.fifo);
    const std::size_t ticks = static_cast<std::size_t>(o.seconds * 1000.0);
    std::vector<double> late_us;
    late_us.reserve(ticks);
    int64_t due = monotonic_ns() + kPeriodNs;
    for (std::size_t k = 0; k < ticks; ++k, due += kPeriodNs) {
        sleep_until(due);
        late_us.push_back(1e-3 * static_cast<double>(monotonic_ns() - due));
    }
    report("timer wake-up, late by (" + placement(o) + ")", late_us);
}

// ---- handoff: physics thread -> publishing thread ------------------------------------------------
void run_handoff(const Options& o) {
    const std::size_t ticks = static_cast<std::size_t>(o.seconds * 1000.0);
    enteron::lcm::Wakeup wakeup;
    std::atomic<int64_t> notified_ns{0};
    std::atomic<bool> stop{false};
    std::vector<double> delay_us;
    delay_us.reserve(ticks);
    std::thread consumer([&] {
        place_thread(o.peer_cpu >= 0 ? o.peer_cpu : o.cpu, o.fifo > 0 ? o.fifo - 1 : 0);
        int64_t seen = 0;
        while (!stop.load()) {
            wakeup.wait(kPeriodNs, [&] { return notified_ns.load() != seen || stop.load(); });
            const int64_t now = monotonic_ns();
            const int64_t sent = notified_ns.load();
            if (sent != seen) {
                delay_us.push_back(1e-3 * static_cast<double>(now - sent));
                seen = sent;
            }
        }
    });
    place_thread(o.cpu, o.fifo);
    int64_t due = monotonic_ns() + kPeriodNs;
    for (std::size_t k = 0; k < ticks; ++k, due += kPeriodNs) {
        sleep_until(due);
        busy_for(static_cast<int64_t>(o.busy_us * 1e3));  // the step
        notified_ns.store(monotonic_ns());
        wakeup.notify();
    }
    stop.store(true);
    wakeup.notify();
    consumer.join();
    report("thread hand-off after a " + std::to_string(static_cast<int>(o.busy_us)) + " us step (" + placement(o) + ")",
           delay_us);
}

// ---- udp: raw multicast ping-pong ----------------------------------------------------------------
int multicast_socket(uint16_t listen_port) {
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    const int yes = 1;
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(listen_port);
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        std::perror("latency_parts: bind");
        std::exit(1);
    }
    ip_mreq membership{};
    inet_pton(AF_INET, kGroup, &membership.imr_multiaddr);
    membership.imr_interface.s_addr = htonl(INADDR_ANY);
    if (setsockopt(fd, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0) {
        std::perror("latency_parts: IP_ADD_MEMBERSHIP (inside a network namespace with the multicast route?)");
        std::exit(1);
    }
    const unsigned char ttl = 0, loop = 1;
    setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
    setsockopt(fd, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop);
    return fd;
}

void send_to(int fd, uint16_t port, const unsigned char* bytes) {
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    inet_pton(AF_INET, kGroup, &to.sin_addr);
    sendto(fd, bytes, kMessageBytes, 0, reinterpret_cast<sockaddr*>(&to), sizeof to);
}

void run_udp(const Options& o) {
    place_thread(o.cpu, o.fifo);
    const bool ping = o.role == "ping";
    const int fd = multicast_socket(ping ? kPongPort : kPingPort);
    unsigned char bytes[kMessageBytes] = {};
    const int64_t end = monotonic_ns() + static_cast<int64_t>(o.seconds * 1e9);
    if (!ping) {  // echo every ping until the end (plus a second, for the pinger's last ones)
        while (monotonic_ns() < end + 1000000000) {
            pollfd p{fd, POLLIN, 0};
            if (poll(&p, 1, 100) > 0 && recv(fd, bytes, sizeof bytes, 0) > 0) send_to(fd, kPongPort, bytes);
        }
        return;
    }
    usleep(200000);  // the pong side's socket joins the group
    std::vector<double> round_trip_us;
    int64_t due = monotonic_ns() + kPeriodNs;
    for (; due < end; due += kPeriodNs) {
        sleep_until(due);
        const int64_t sent = monotonic_ns();
        std::memcpy(bytes, &sent, sizeof sent);
        send_to(fd, kPingPort, bytes);
        // Read until this ping's echo (a late echo of an earlier one is dropped) or 5 ms.
        const int64_t give_up = sent + 5000000;
        for (int64_t now = sent; now < give_up; now = monotonic_ns()) {
            pollfd p{fd, POLLIN, 0};
            if (poll(&p, 1, static_cast<int>((give_up - now) / 1000000) + 1) <= 0) break;
            if (recv(fd, bytes, sizeof bytes, 0) <= 0) continue;
            int64_t echoed;
            std::memcpy(&echoed, bytes, sizeof echoed);
            if (echoed == sent) {
                round_trip_us.push_back(1e-3 * static_cast<double>(monotonic_ns() - sent));
                break;
            }
        }
    }
    report("raw UDP multicast round trip (" + placement(o) + ")", round_trip_us);
}

// ---- lcm: the same through LCM -------------------------------------------------------------------
struct LcmPong {
    lcm_t* lcm;
};

void run_lcm(const Options& o) {
    place_thread(o.cpu, o.fifo);
    const bool ping = o.role == "ping";
    lcm_t* lcm = lcm_create(o.lcm_url.c_str());
    if (lcm == nullptr) {
        std::fprintf(stderr, "latency_parts: lcm_create(%s) failed\n", o.lcm_url.c_str());
        std::exit(1);
    }
    const int64_t end = monotonic_ns() + static_cast<int64_t>(o.seconds * 1e9);
    if (!ping) {
        LcmPong pong{lcm};
        lcm_subscribe(
            lcm, "LATENCY_PING",
            [](const lcm_recv_buf_t* buffer, const char*, void* self) {
                lcm_publish(static_cast<LcmPong*>(self)->lcm, "LATENCY_PONG", buffer->data, buffer->data_size);
            },
            &pong);
        while (monotonic_ns() < end + 1000000000) lcm_handle_timeout(lcm, 100);
        lcm_destroy(lcm);
        return;
    }
    struct Pinger {
        int64_t sent = 0;
        bool back = false;
        int64_t arrived = 0;
    } pinger;
    lcm_subscribe(
        lcm, "LATENCY_PONG",
        [](const lcm_recv_buf_t* buffer, const char*, void* self) {
            auto* p = static_cast<Pinger*>(self);
            int64_t echoed = 0;
            if (buffer->data_size >= sizeof echoed) std::memcpy(&echoed, buffer->data, sizeof echoed);
            if (echoed == p->sent) {
                p->back = true;
                p->arrived = monotonic_ns();
            }
        },
        &pinger);
    usleep(200000);
    std::vector<double> round_trip_us;
    unsigned char bytes[kMessageBytes] = {};
    int64_t due = monotonic_ns() + kPeriodNs;
    for (; due < end; due += kPeriodNs) {
        sleep_until(due);
        pinger.sent = monotonic_ns();
        pinger.back = false;
        std::memcpy(bytes, &pinger.sent, sizeof pinger.sent);
        lcm_publish(lcm, "LATENCY_PING", bytes, sizeof bytes);
        const int64_t give_up = pinger.sent + 5000000;
        while (!pinger.back && monotonic_ns() < give_up) lcm_handle_timeout(lcm, 5);
        if (pinger.back) round_trip_us.push_back(1e-3 * static_cast<double>(pinger.arrived - pinger.sent));
    }
    lcm_destroy(lcm);
    report("LCM udpm round trip (" + placement(o) + ")", round_trip_us);
}

int usage() {
    std::fprintf(stderr,
                 "usage: enteron_lcm_latency_parts timer|handoff [--cpu C] [--peer-cpu C] [--fifo P] [--seconds S] "
                 "[--busy-us U]\n"
                 "       enteron_lcm_latency_parts udp|lcm --role ping|pong [--cpu C] [--fifo P] [--seconds S] "
                 "[--lcm-url URL]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage();
    Options o;
    o.part = argv[1];
    for (int i = 2; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) return usage();
        const char* value = argv[++i];
        if (flag == "--role") o.role = value;
        else if (flag == "--cpu") o.cpu = std::atoi(value);
        else if (flag == "--peer-cpu") o.peer_cpu = std::atoi(value);
        else if (flag == "--fifo") o.fifo = std::atoi(value);
        else if (flag == "--seconds") o.seconds = std::atof(value);
        else if (flag == "--busy-us") o.busy_us = std::atof(value);
        else if (flag == "--lcm-url") o.lcm_url = value;
        else return usage();
    }
    if (!(o.seconds > 0.0) || o.fifo < 0 || o.fifo > 99) return usage();
    if (o.part == "timer") run_timer(o);
    else if (o.part == "handoff") run_handoff(o);
    else if ((o.part == "udp" || o.part == "lcm") && (o.role == "ping" || o.role == "pong"))
        o.part == "udp" ? run_udp(o) : run_lcm(o);
    else return usage();
    return 0;
}
