# SPDX-License-Identifier: Apache-2.0
"""The engine: the same fit in this process, on a LocalCluster of 1 worker and of 2
workers gives the same constants, residual and covariance bit for bit; a fit interrupted
half-way resumes from the evaluations it had kept on disk and ends exactly where an
uninterrupted one does; the cache tells two parameter vectors apart by their last bit.
About 20 s on the 2-core machine (two LocalClusters start); the fit: calibrate_support.small_fit_problem."""
import io
import shutil
import tempfile
import unittest

import numpy as np

import calibrate_support as support
from enteron import calibrate
from enteron.calibrate.fit import Objective

HIDDEN = support.SMALL_FIT_HIDDEN
small_fit_problem = support.small_fit_problem
bits = support.result_bits


class Interrupt(Exception):
    pass


class Engine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.experiment, cls.data = small_fit_problem()
        with calibrate.Engine(workers=0, progress=False) as engine:
            cls.serial = calibrate.fit(cls.experiment, cls.data, engine)

    def test_the_same_bits_on_1_and_2_local_workers(self):
        for workers in (1, 2):
            with self.subTest(workers=workers):
                with calibrate.Engine(workers=workers, progress=False) as engine:
                    self.assertEqual(engine.worker_count, workers)
                    result = calibrate.fit(self.experiment, self.data, engine)
                    self.assertEqual(engine.tasks, result.simulations["computed"])
                self.assertEqual(bits(result), bits(self.serial))
                self.assertEqual(result.simulations, self.serial.simulations)

    def test_an_interrupted_fit_resumes_from_its_cache(self):
        directory = tempfile.mkdtemp(prefix="calibrate-resume-")
        self.addCleanup(shutil.rmtree, directory)
        kept = 40

        def stop_after(done, total):
            progress["done"] += 1
            if progress["done"] == kept:
                raise Interrupt()

        progress = {"done": 0}
        with calibrate.Engine(workers=0, on_progress=stop_after, stream=io.StringIO()) as engine:
            with self.assertRaises(Interrupt):
                calibrate.fit(self.experiment, self.data, engine, cache_directory=directory)
        with calibrate.Engine(workers=0, progress=False) as engine:
            resumed = calibrate.fit(self.experiment, self.data, engine, cache_directory=directory)
        self.assertEqual(bits(resumed), bits(self.serial))
        self.assertEqual(resumed.simulations["from_cache"], kept)
        self.assertEqual(resumed.simulations["computed"] + kept, self.serial.simulations["computed"])
        # Once more: everything from the disk, nothing computed.
        with calibrate.Engine(workers=0, progress=False) as engine:
            again = calibrate.fit(self.experiment, self.data, engine, cache_directory=directory)
        self.assertEqual(again.simulations["computed"], 0)
        self.assertEqual(bits(again), bits(self.serial))

    def test_the_cache_keys_are_the_vectors_bits(self):
        directory = tempfile.mkdtemp(prefix="calibrate-bits-")
        self.addCleanup(shutil.rmtree, directory)
        with calibrate.Engine(workers=0, progress=False) as engine:
            objective = Objective(self.experiment, self.data, engine, directory)
            values = np.array(HIDDEN)
            result = objective.plan.evaluate(values)
            objective.save(values, result)
            fresh = Objective(self.experiment, self.data, engine, directory)  # nothing in memory
            self.assertEqual(fresh.lookup(values).predictions.tobytes(), result.predictions.tobytes())
            self.assertIsNone(fresh.lookup(np.nextafter(values, 1.0)))
            self.assertIsNone(fresh.lookup(np.array([HIDDEN[0], np.nextafter(HIDDEN[1], 0.0)])))


if __name__ == "__main__":
    unittest.main()
