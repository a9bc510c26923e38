// SPDX-License-Identifier: Apache-2.0
// The stability suite's run loop: steps one hard case through the public C API for a given
// simulated time and checks, after every step, what "stays numerically stable" means:
//   - every step returns ENT_OK (the guard may roll back and subdivide, but must recover);
//   - every control point, the axis samples and the energies are finite;
//   - the total energy (kinetic + potential) never exceeds its initial value plus the work
//     done on the bowel from outside (by tools; zero without them) plus the case's allowance;
//   - the deepest contact stays within the case's penetration bound.
// It reports, for the table of the hard cases, the deepest penetration, the largest energy
// excess (drift), the guard's rollbacks and the substeps, and the wall time.
#pragma once

#include <enteron/enteron.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace stability {

// Moves the tools of one run (a fresh one per run: it keeps the run's state).
class ToolDriver {
public:
    virtual ~ToolDriver() = default;
    // Before each step: sets the tools' poses, grasps, releases. False if a call failed
    // (ent_last_error() says why).
    virtual bool before_step(ent_scene* scene, double time_s) = 0;
    // After the step: the work, in J, the tools did on the bowel during it (an estimate or
    // a bound, as the case explains); NaN if a call failed.
    virtual double work_of_step(const ent_scene* scene) = 0;
};

// One hard case. make() creates its scene (nullptr on failure, with ent_last_error set);
// driver(), if given, makes a fresh ToolDriver for each run (cases without tools have none,
// and nothing outside the bowel does work on them).
struct HardCase {
    const char* name;
    const char* what;                   // one line for the output
    double step_s;                      // dt of each ent_scene_step
    double max_penetration_m;           // bound on ent_stats.max_penetration_m at every step after settle_s
    double settle_s;                    // the start-up transient of a scene made overlapping
    double energy_allowance_J;          // tolerated energy from nothing over the whole run
    std::function<ent_scene*()> make;
    std::function<std::unique_ptr<ToolDriver>()> driver;
};

struct RunResult {
    bool passed = false;
    std::string failure;                 // why not, if not
    double simulated_s = 0.0;
    uint64_t steps = 0;
    uint64_t substeps = 0;
    uint64_t rollbacks = 0;
    double max_penetration_m = 0.0;      // after the case's settle_s
    double initial_energy_J = 0.0;
    double external_work_J = 0.0;        // work done by the tools on the bowel, summed (the driver's)
    double max_energy_excess_J = 0.0;    // max over steps of E - E0 - W (> 0: energy from nothing)
    double final_energy_J = 0.0;
    uint32_t max_contacts = 0;
    double wall_s = 0.0;
    // FNV-1a over the bits of the published control points and energies after every step:
    // equal hashes, the same trajectory to the last bit (comparing two builds of the library).
    uint64_t trajectory_hash = 14695981039346656037ull;
};

// Runs the case for `seconds` of simulated time. Never throws; a failure is in the result.
RunResult run(const HardCase& hard_case, double seconds);

// One line of the hard-case table (markdown), and its header.
std::string table_header();
std::string table_row(const HardCase& hard_case, const RunResult& result);

}  // namespace stability
