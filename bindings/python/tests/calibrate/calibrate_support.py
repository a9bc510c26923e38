# SPDX-License-Identifier: Apache-2.0
"""What the tests of enteron.calibrate share: the shipped experiments, made smaller where a
test needs it, and the times their data are measured at."""
import json
import os

import numpy as np

from enteron import calibrate


def experiment(name, fit=None, **top_level):
    """A shipped experiment, with some of its top-level keys replaced (duration, ...) and its
    "fit" object updated with fit."""
    path = calibrate.experiment_path(name)
    with open(path, encoding="utf-8") as file:
        document = json.load(file)
    document.update(top_level)
    document.setdefault("fit", {}).update(fit or {})
    return calibrate.experiment_from_dict(document, source_file=path)


def times(period_s, end_s, start_s=None):
    """period_s, 2 period_s, ... up to end_s (rounded to 1e-9 s so that they fall on steps)."""
    count = int(round(end_s / period_s))
    first = 1 if start_s is None else int(round(start_s / period_s))
    return [round(k * period_s, 9) for k in range(first, count + 1)]


def requests(measurements, period_s, end_s, start_s=None):
    """Every measurement at every time of times(...)."""
    return [(name, t) for name in measurements for t in times(period_s, end_s, start_s)]


def relative_error(found, true):
    return abs(found - true) / abs(true)


def print_table(title, rows):
    """A markdown table on stdout (ctest -V shows it; the figures in reports come from here)."""
    print("\n%s\n" % title)
    print("| " + " | ".join(rows[0]) + " |")
    print("|" + "---|" * len(rows[0]))
    for row in rows[1:]:
        print("| " + " | ".join(row) + " |")
    print(flush=True)


def environment_directory():
    """A scratch folder for a test (under the build tree when ctest gives one)."""
    base = os.environ.get("CALIBRATE_TEST_DIR") or os.path.join(os.getcwd(), "calibrate-test")
    os.makedirs(base, exist_ok=True)
    return base


SMALL_FIT_HIDDEN = [1.7e-3, 0.6]


def small_fit_problem():
    """The fit the engine tests run everywhere: the cantilever cut to 0.4 s (bend stiffness
    and drag, 20 noisy tip heights), about 150 simulations of 10 ms."""
    fitted = experiment("cantilever", fit={"tolerance": 1e-2, "max_evaluations": 120}, duration=0.4)
    data = calibrate.synthesize(fitted, requests(["tip_z"], 0.02, 0.4), SMALL_FIT_HIDDEN, noise=5e-4, seed=3)
    return fitted, data


def result_bits(result):
    """Everything a fit decided, as bytes: constants, covariance, cost, predictions."""
    return (np.array(result.values()).tobytes(), np.asarray(result.covariance).tobytes(),
            np.float64(result.cost).tobytes(), np.array(result.predictions).tobytes())
