#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Are the reported standard deviations right? A recovery case of test_recovery.py fitted
for 12 noise draws (seeds 1 to 12); prints each error divided by its reported standard
deviation and their RMS, which is 1 for an exact estimate (docs/calibration.md). Not a ctest
(a few minutes):

    PYTHONPATH=bindings/python bindings/python/tests/calibrate/coverage.py drop|sag
"""
import math
import sys

import calibrate_support as support
from enteron import calibrate

CASES = {"drop": ("drop_on_table", [0.12], support.requests(["middle_x", "middle_z"], 0.02, 0.5), 5e-4),
         "sag": ("hanging_sag", [160.0], support.requests(["sag"], 0.02, 0.6), 2e-4)}


def main():
    if len(sys.argv) != 2 or sys.argv[1] not in CASES:
        sys.exit("usage: coverage.py %s" % "|".join(CASES))
    name, hidden, requests, sigma = CASES[sys.argv[1]]
    experiment = support.experiment(name, fit={"tolerance": 1e-2})
    ratios = []
    with calibrate.Engine(workers=0, progress=False) as engine:
        for seed in range(1, 13):
            data = calibrate.synthesize(experiment, requests, hidden, noise=sigma, seed=seed)
            fitted = calibrate.fit(experiment, data, engine).parameters[0]
            ratios.append((fitted["value"] - hidden[0]) / fitted["std"])
            print("seed %2d: %.6g +- %.3g, error / std %+.2f" % (seed, fitted["value"], fitted["std"], ratios[-1]),
                  flush=True)
    print("RMS of error / std over %d draws: %.2f" % (len(ratios), math.sqrt(sum(r * r for r in ratios) / len(ratios))))


if __name__ == "__main__":
    main()
