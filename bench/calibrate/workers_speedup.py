#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The speed-up of a fit from 1 to 2 (or more) local Dask workers (docs/calibration.md).

    PYTHONPATH=bindings/python bench/calibrate/workers_speedup.py [--rounds 3] [--workers 1 2]
                                                                   [--experiment cantilever]

Two figures per LocalCluster size, alternated round by round so that every size sees the
same load over the same minutes, the cluster's start excluded: the wall time of the same fit
(a shipped experiment, data made by the library, no cache: its generations of 6 and its
local refinement wait for each batch), and of one batch of --batch independent simulations
(the throughput when nothing waits). Prints each round, the medians, the speed-ups over the
first size and the load average (a loaded machine shares its cores with other work: say so
when quoting the figures).
"""
import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

from enteron import calibrate  # noqa: E402 (after the path)
import enteron.calibrate.simulate  # noqa: E402,F401 (calibrate.simulate.evaluate)

REQUESTS = {"cantilever": [("tip_z", round(0.02 * k, 9)) for k in range(1, 51)],
            "hanging_sag": [("sag", round(0.02 * k, 9)) for k in range(1, 51)]}
HIDDEN = {"cantilever": [1.7e-3, 0.6], "hanging_sag": [160.0]}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    p.add_argument("--experiment", choices=sorted(REQUESTS), default="cantilever")
    p.add_argument("--batch", type=int, default=48, help="simulations of the throughput batch")
    args = p.parse_args()
    experiment = calibrate.load_experiment(calibrate.experiment_path(args.experiment))
    data = calibrate.synthesize(experiment, REQUESTS[args.experiment], HIDDEN[args.experiment], noise=5e-4, seed=1)
    plan = calibrate.Plan(experiment, REQUESTS[args.experiment])
    batch = [[v * (1.0 + 0.01 * k) for v in HIDDEN[args.experiment]] for k in range(args.batch)]
    fits = {w: [] for w in args.workers}
    batches = {w: [] for w in args.workers}
    loads = []
    for round_ in range(args.rounds):
        for workers in args.workers:
            with calibrate.Engine(workers=workers, progress=False) as engine:
                started = time.monotonic()
                result = calibrate.fit(experiment, data, engine)
                fits[workers].append(time.monotonic() - started)
                started = time.monotonic()
                engine.map(calibrate.simulate.evaluate, plan, batch)
                batches[workers].append(time.monotonic() - started)
            loads.append(os.getloadavg()[0])
            print("round %d: %d worker(s): fit %.2f s (%d simulations), batch of %d %.2f s"
                  % (round_ + 1, workers, fits[workers][-1], result.simulations["computed"], len(batch),
                     batches[workers][-1]), flush=True)
    for label, times in (("fit", fits), ("batch", batches)):
        first = statistics.median(times[args.workers[0]])
        for workers in args.workers:
            median = statistics.median(times[workers])
            print("%s, %d worker(s): median %.2f s, speed-up %.2f over %d" % (label, workers, median, first / median,
                                                                              args.workers[0]))
    print("load average during the runs: %.1f to %.1f on %d cores" % (min(loads), max(loads), os.cpu_count()))

if __name__ == "__main__":
    main()
