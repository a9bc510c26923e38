// SPDX-License-Identifier: Apache-2.0
// The peers part in a build without MuJoCo (ENTERON_BENCH_MUJOCO off or libmujoco-dev
// missing): nothing to run. The study still succeeds; its report says the peers were skipped.
#include "peers_study.h"

#include <filesystem>

namespace study {

std::string peers_in_this_build() {
    return "none: this build has no MuJoCo (scripts/install-deps --with-peers; CMake option ENTERON_BENCH_MUJOCO)";
}

void run_peers_study(const Options& options) {
    std::filesystem::remove(options.out_dir + "/peers.csv");  // a stale one would be reported as this run's
    progress("peers: skipped, %s", peers_in_this_build().c_str());
}

}  // namespace study
