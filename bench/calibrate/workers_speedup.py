#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The speed-up of a fit from 1 to 2 (or more) local Dask workers (docs/calibration.md).

    PYTHONPATH=bindings/python bench/calibrate/workers_speedup.py [--rounds 3] [--workers 1 2]
                                                                   [--experiment cantilever]

The same fit (a shipped experiment, data made by the library, no cache) on a LocalCluster of
each size, alternated round by round so that every size sees the same load over the same
minutes; the fit's wall time excludes the cluster's start. Prints each round, the medians
and the speed-up of each size over the first, and the load average (a loaded machine shares
its cores with other work: say so when quoting the figures).
"""
import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bindings", "python"))

from enteron import calibrate  # noqa: E402 (after the path)

REQUESTS = {"cantilever": [("tip_z", round(0.02 * k, 9)) for k in range(1, 51)],
            "hanging_sag": [("sag", round(0.02 * k, 9)) for k in range(1, 51)]}
HIDDEN = {"cantilever": [1.7e-3, 0.6], "hanging_sag": [160.0]}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    p.add_argument("--experiment", choices=sorted(REQUESTS), default="cantilever")
    args = p.parse_args()
    experiment = calibrate.load_experiment(calibrate.experiment_path(args.experiment))
    data = calibrate.synthesize(experiment, REQUESTS[args.experiment], HIDDEN[args.experiment], noise=5e-4, seed=1)
    times = {w: [] for w in args.workers}
    loads = []
    for round_ in range(args.rounds):
        for workers in args.workers:
            with calibrate.Engine(workers=workers, progress=False) as engine:
                started = time.monotonic()
                result = calibrate.fit(experiment, data, engine)
                times[workers].append(time.monotonic() - started)
            loads.append(os.getloadavg()[0])
            print("round %d: %d worker(s): %.2f s, %d simulations" % (round_ + 1, workers, times[workers][-1],
                                                                      result.simulations["computed"]), flush=True)
    first = statistics.median(times[args.workers[0]])
    for workers in args.workers:
        median = statistics.median(times[workers])
        print("%d worker(s): median %.2f s, speed-up %.2f over %d" % (workers, median, first / median, args.workers[0]))
    print("load average during the runs: %.1f to %.1f on %d cores" % (min(loads), max(loads), os.cpu_count()))


if __name__ == "__main__":
    main()
