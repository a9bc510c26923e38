// SPDX-License-Identifier: Apache-2.0
// The accuracy study: what each accuracy knob of Enteron buys and what it costs in time.
// Writes CSV files into --out; bench/study/report.py turns them into plots, a markdown
// table and checks. scripts/study builds and runs both.
//
//   enteron_study [--fast | --full | --tiny] --out DIR [--part mechanics|collision|tool|skin|effects|peers ...]
//
// --fast (ctest) runs a small grid in a few minutes; --full (the default) is the grid
// whose results are committed in bench/results/study/; --tiny, the smallest grid of each
// part (seconds; what the distributed study's test compares with the serial study).
//
// The distributed study (study_runs.h; bench/study/distributed_study.py runs it on Dask):
//   enteron_study MODE --list-runs [--part ...]     the runs of the error part, one name a line
//   enteron_study MODE --run NAME                   computes that run (no timing), prints its record
//   enteron_study MODE --runs DIR --out DIR [--timing-steps N] [--part ...]
//                                                   reads the runs from DIR, measures the timings
//                                                   serially, writes the CSV files as usual
#include "collision_study.h"
#include "effects_study.h"
#include "mechanics_study.h"
#include "peers_study.h"
#include "skin_study.h"
#include "study_common.h"
#include "tool_push_study.h"

#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

namespace {

int usage(const char* message) {
    std::fprintf(stderr, "enteron_study: %s\nusage: enteron_study [--fast | --full | --tiny] --out DIR [--part NAME]...\n"
                 "         [--list-runs | --run NAME | --runs DIR [--timing-steps N]]\n"
                 "parts: mechanics, collision, tool, skin, effects, peers (default: all)\n", message);
    return 2;
}

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown";
}

}  // namespace

int main(int argc, char** argv) {
    study::Options options;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--fast")) options.fast = true, options.tiny = false;
        else if (!std::strcmp(argv[i], "--full")) options.fast = false, options.tiny = false;
        else if (!std::strcmp(argv[i], "--tiny")) options.fast = true, options.tiny = true;
        else if (!std::strcmp(argv[i], "--list-runs")) options.list_runs = true;
        else if (!std::strcmp(argv[i], "--run") && i + 1 < argc) options.run = argv[++i];
        else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) options.runs_dir = argv[++i];
        else if (!std::strcmp(argv[i], "--timing-steps") && i + 1 < argc) {
            options.timing_steps = std::strtol(argv[++i], nullptr, 10);
            if (options.timing_steps < 1) return usage("--timing-steps must be a positive integer");
        }
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) options.out_dir = argv[++i];
        else if (!std::strcmp(argv[i], "--part") && i + 1 < argc) options.parts.push_back(argv[++i]);
        else return usage((std::string("unknown argument ") + argv[i]).c_str());
    }
    if (options.list_runs + !options.run.empty() + !options.runs_dir.empty() > 1)
        return usage("--list-runs, --run and --runs go alone");
    const bool only_runs = options.list_runs || !options.run.empty();  // nothing written to --out
    if (options.out_dir.empty() && !only_runs) return usage("--out DIR is required");
    for (const std::string& part : options.parts)
        if (part != "mechanics" && part != "collision" && part != "tool" && part != "skin" && part != "effects" &&
            part != "peers")
            return usage(("unknown part " + part).c_str());
    if ((ent_version() >> 16) != ENT_VERSION_MAJOR) {
        std::fprintf(stderr, "enteron_study: libenteron major version %u, built for %d\n",
                     static_cast<unsigned>(ent_version() >> 16), ENT_VERSION_MAJOR);
        return 1;
    }
    try {
        if (!options.run.empty()) {
            if (study::print_mechanics_run(options, options.run) || study::print_collision_run(options, options.run) ||
                study::print_tool_run(options, options.run))
                return 0;
            return usage(("unknown run \"" + options.run + "\" (see --list-runs)").c_str());
        }
        if (options.list_runs) {  // the parts whose error part is distributed
            if (options.wants("mechanics")) study::run_mechanics_study(options);
            if (options.wants("collision")) study::run_collision_study(options);
            if (options.wants("tool")) study::run_tool_push_study(options);
            return 0;
        }
        std::filesystem::create_directories(options.out_dir);
        {
            study::Csv meta(options.out_dir + "/study_run.csv", {"mode", "date_utc", "cpu", "cpus", "library_version", "peers"});
            char date[32];
            const std::time_t now = std::time(nullptr);
            std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
            const uint32_t v = ent_version();
            meta.row({options.tiny ? "tiny" : options.fast ? "fast" : "full", date, "\"" + cpu_model() + "\"",
                      study::num(static_cast<int>(std::thread::hardware_concurrency())),
                      study::format("%u.%u.%u", v >> 16, (v >> 8) & 0xff, v & 0xff),
                      "\"" + study::peers_in_this_build() + "\""});
        }
        if (options.wants("mechanics")) study::run_mechanics_study(options);
        if (options.wants("collision")) study::run_collision_study(options);
        if (options.wants("tool")) study::run_tool_push_study(options);
        if (options.wants("skin")) study::run_skin_study(options);
        if (options.wants("effects")) study::run_effects_study(options);
        if (options.wants("peers")) study::run_peers_study(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "enteron_study: %s\n", error.what());
        return 1;
    }
    return 0;
}
