// SPDX-License-Identifier: Apache-2.0
// enteron_stability: runs hard cases of the stability suite and prints their table.
//
//   enteron_stability CASE [--seconds S]   run one case for S simulated seconds (default 30)
//   enteron_stability all [--seconds S]    run every case
//   ... --hash                             also print each run's trajectory hash (the bits of
//                                          every published state: compares two library builds)
//   enteron_stability --list               print the case names, one per line
//   enteron_stability --expect-cases A,B   fail unless the cases are exactly A, B, ... (ctest
//                                          uses it to prove that every case is registered)
// Exit status: 0 if every case run passed, 1 if one failed, 2 on a bad command line.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "hard_cases.h"

namespace {

int usage() {
    std::fprintf(stderr, "usage: enteron_stability CASE|all [--seconds S] [--hash] | --list | --expect-cases A,B,...\n");
    return 2;
}

int expect_cases(const std::string& expected) {
    std::string actual;
    for (const stability::HardCase& c : stability::hard_cases()) actual += (actual.empty() ? "" : ",") + std::string(c.name);
    if (actual == expected) return 0;
    std::printf("the cases registered with ctest differ from the program's\n  ctest:   %s\n  program: %s\n",
                expected.c_str(), actual.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage();
    const std::string first = argv[1];
    if (first == "--list") {
        for (const stability::HardCase& c : stability::hard_cases()) std::printf("%s\n", c.name);
        return 0;
    }
    if (first == "--expect-cases") return argc == 3 ? expect_cases(argv[2]) : usage();
    double seconds = 30.0;
    bool hash = false;
    for (int i = 2; i < argc; ++i) {
        if (std::strcmp(argv[i], "--hash") == 0) {
            hash = true;
        } else if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            char* end = nullptr;
            seconds = std::strtod(argv[++i], &end);
            if (*end != '\0' || !(seconds > 0.0)) return usage();
        } else {
            return usage();
        }
    }
    int ran = 0, failed = 0;
    std::printf("%s\n", stability::table_header().c_str());
    std::fflush(stdout);
    for (const stability::HardCase& c : stability::hard_cases()) {
        if (first != "all" && first != c.name) continue;
        const stability::RunResult result = stability::run(c, seconds);
        std::printf("%s\n", stability::table_row(c, result).c_str());
        if (!result.passed) std::printf("  %s (%s): %s\n", c.name, c.what, result.failure.c_str());
        if (hash) std::printf("  %s: trajectory hash %016llx\n", c.name, static_cast<unsigned long long>(result.trajectory_hash));
        std::fflush(stdout);
        ++ran;
        failed += result.passed ? 0 : 1;
    }
    if (ran == 0) {
        std::fprintf(stderr, "enteron_stability: no case named \"%s\" (try --list)\n", first.c_str());
        return 2;
    }
    return failed == 0 ? 0 : 1;
}
