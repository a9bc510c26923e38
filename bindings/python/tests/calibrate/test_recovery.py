# SPDX-License-Identifier: Apache-2.0
"""Recovery: data made by the library with hidden constants (bend stiffness, stretch
stiffness, damping, friction), fitted from the shipped experiments' start values. Without
noise every constant comes back within 2 %; with Gaussian noise of a known sigma (given to
the fit in the data), within 3 reported standard deviations (a fixed seed, so the test is
deterministic; 3 standard deviations: 99.7 % of Gaussian draws). The table it prints is the
recovery table of docs/calibration.md.

Simulations in this process (the engine's workers=0): the Dask tests are test_engine.py and
test_dask_cluster.py. Each experiment is the shipped one, measured less often than its
file suggests, to keep the CI's time (about 40 s on the 2-core machine, loaded).
"""
import time
import unittest

import calibrate_support as support
from enteron import calibrate

# (what is recovered, experiment, hidden values, requests, noise sigma in the data's unit)
CASES = [
    ("bend stiffness and damping (drag)", "cantilever", [1.7e-3, 0.6],
     support.requests(["tip_z"], 0.02, 1.0), 5e-4),
    ("stretch stiffness", "hanging_sag", [160.0],
     support.requests(["sag"], 0.02, 0.6), 2e-4),
    ("friction", "drop_on_table", [0.12],
     support.requests(["middle_x", "middle_z"], 0.02, 0.5), 5e-4),
]
FIT = {"tolerance": 1e-2}  # the global search hands over to the local refinement at 1 % of the bounds


class Recovery(unittest.TestCase):
    rows = [["constant", "experiment", "hidden", "noise", "fitted", "error", "reported std", "error / std",
             "simulations", "wall s"]]

    @classmethod
    def tearDownClass(cls):
        support.print_table("Recovery (simulations in one process, machine loaded)", cls.rows)

    def fit(self, case, noise):
        label, name, hidden, requests, sigma = case
        experiment = support.experiment(name, fit=FIT)
        data = calibrate.synthesize(experiment, requests, hidden, noise=sigma if noise else 0.0, seed=7)
        started = time.monotonic()
        with calibrate.Engine(workers=0, progress=False) as engine:
            result = calibrate.fit(experiment, data, engine)
        wall = time.monotonic() - started
        for parameter, true in zip(result.parameters, hidden):
            error = support.relative_error(parameter["value"], true)
            self.rows.append([parameter["name"], name, "%g" % true, "%g" % sigma if noise else "none",
                              "%.6g" % parameter["value"], "%.3f %%" % (100 * error),
                              "%.3g" % parameter["std"], "%.2f" % (abs(parameter["value"] - true) / parameter["std"]),
                              "%d" % result.simulations["computed"], "%.1f" % wall])
        return result, hidden

    def test_without_noise_within_2_percent(self):
        for case in CASES:
            with self.subTest(case[0]):
                result, hidden = self.fit(case, noise=False)
                for parameter, true in zip(result.parameters, hidden):
                    self.assertLess(support.relative_error(parameter["value"], true), 0.02, parameter)
                    self.assertFalse(parameter["at_bound"])

    def test_with_noise_within_the_reported_uncertainty(self):
        for case in CASES:
            with self.subTest(case[0]):
                result, hidden = self.fit(case, noise=True)
                self.assertEqual(result.noise, "given")
                # The residual is the noise: chi2 per degree of freedom near 1.
                self.assertLess(abs(result.chi2 / result.dof - 1.0), 0.5, result.chi2 / result.dof)
                for parameter, true in zip(result.parameters, hidden):
                    self.assertGreater(parameter["std"], 0.0)
                    self.assertLess(parameter["relative_std"], 0.2, parameter)
                    self.assertLessEqual(abs(parameter["value"] - true), 3 * parameter["std"], parameter)
                    # The Hessian's prediction of the cost's rise holds within 20 %.
                    self.assertLess(abs(parameter["linearity"] - 1.0), 0.2, parameter)


if __name__ == "__main__":
    unittest.main()
