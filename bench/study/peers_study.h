// SPDX-License-Identifier: Apache-2.0
// Peers in the same run: other engines on the mechanics study's swing, at the study's N
// and time steps, timed in the same process, so that report.py can put their error
// (against the same reference) and their cost next to ours.
//
// Two implementations, picked by CMake: peers_study.cpp (MuJoCo found, ENTERON_BENCH_MUJOCO)
// and peers_absent.cpp (no peer in this build: nothing runs and the study says so).
#pragma once

#include "study_common.h"

namespace study {

// The peers this build can run ("MuJoCo 2.2.2"), or "none" and why.
std::string peers_in_this_build();

// Writes peers.csv into options.out_dir (columns: see report.py). Without a peer, removes
// a stale peers.csv and says so on stderr.
void run_peers_study(const Options& options);

}  // namespace study
