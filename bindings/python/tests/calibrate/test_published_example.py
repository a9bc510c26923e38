# SPDX-License-Identifier: Apache-2.0
"""The example of docs/calibration.md against a published measurement: the tensile test
fitted to examples/calibrate/tensile_test_terry2014.csv (the low-strain modulus of porcine
small intestine, Terry et al. 2014) with the command. The fitted EA must reproduce the
published force (E A, 34.03 N for the example's cross-section) within 2 %, with a standard
deviation within 10 % of the published one (3.29 N), and the command must write the fitted
scene. About 10 s."""
import contextlib
import io
import json
import os
import tempfile
import unittest

from enteron.calibrate import cli

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..")
DATA = os.path.join(ROOT, "examples", "calibrate", "tensile_test_terry2014.csv")
PUBLISHED_EA, PUBLISHED_SD = 307.25e3 * 1.10741e-4, 29.67e3 * 1.10741e-4  # N: E A and its SD, A of the data file


class PublishedExample(unittest.TestCase):
    def test_the_tensile_test_fits_the_published_modulus(self):
        directory = tempfile.mkdtemp(prefix="calibrate-published-")
        out, scene = os.path.join(directory, "result.json"), os.path.join(directory, "fitted.json")
        stdout = io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
            status = cli.main(["tensile_test", DATA, "--workers", "0", "--no-cache", "--out", out, "--scene-out", scene])
        self.assertEqual(status, 0)
        print(stdout.getvalue())
        with open(out, encoding="utf-8") as file:
            fitted = json.load(file)["parameters"][0]
        self.assertLess(abs(fitted["value"] / PUBLISHED_EA - 1.0), 0.02, fitted)
        self.assertLess(abs(fitted["std"] / PUBLISHED_SD - 1.0), 0.1, fitted)
        with open(scene, encoding="utf-8") as file:
            self.assertEqual(json.load(file)["intestine"]["stretch_stiffness"], fitted["value"])


if __name__ == "__main__":
    unittest.main()
