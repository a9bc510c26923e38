#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The distributed study gives the serial study's numbers: enteron_study --tiny on the
mechanics, collision and tool parts, once serially and once through distributed_study.py
(the error part on a LocalCluster of 2 workers, the timing part pinned to one core); every
column of every CSV file is the same string in both, except the timings (us_per_ms, and the
reference's wall time), which must be positive numbers. A second distributed run takes every
run from its cache. About 30 s on the 2-core machine.

    test_distributed_study.py ENTERON_STUDY SCRATCH_DIR"""
import csv
import os
import shutil
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TIMINGS = {"us_per_ms", "reference_wall_s"}
PARTS = ["--part", "mechanics", "--part", "collision", "--part", "tool"]
FILES = ("mechanics.csv", "mechanics_reference.csv", "mechanics_reference_axes.csv", "collision_pile.csv",
         "collision_pile_integrators.csv", "collision_tool.csv")


def rows(path):
    with open(path, newline="") as file:
        return list(csv.DictReader(file))


class DistributedStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.program, cls.scratch = sys.argv[1], sys.argv[2]
        shutil.rmtree(cls.scratch, ignore_errors=True)
        cls.serial = os.path.join(cls.scratch, "serial")
        cls.distributed = os.path.join(cls.scratch, "distributed")
        subprocess.run([cls.program, "--tiny", "--out", cls.serial] + PARTS, check=True, stdin=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        cls.driver = [sys.executable, os.path.join(HERE, "distributed_study.py"), cls.program, cls.distributed,
                      "--grid", "tiny", "--workers", "2", "--quiet"] + PARTS
        cls.first = subprocess.run(cls.driver, capture_output=True, text=True, stdin=subprocess.DEVNULL)

    def test_the_same_numbers_as_the_serial_study(self):
        self.assertEqual(self.first.returncode, 0, self.first.stderr[-3000:])
        compared = 0
        for name in FILES:
            serial, distributed = rows(os.path.join(self.serial, name)), rows(os.path.join(self.distributed, name))
            self.assertEqual(len(serial), len(distributed), name)
            self.assertGreater(len(serial), 0, name)
            for line, (a, b) in enumerate(zip(serial, distributed), start=2):
                self.assertEqual(list(a), list(b), name)
                for column in a:
                    if column in TIMINGS:
                        self.assertGreater(float(b[column]), 0.0, "%s line %d: %s" % (name, line, column))
                    else:
                        self.assertEqual(a[column], b[column], "%s line %d: %s" % (name, line, column))
                        compared += 1
        self.assertGreater(compared, 1000)
        print("\n%d values compared, all identical; runs of the error part: %d" % (
            compared, len(os.listdir(os.path.join(self.distributed, "runs")))))

    def test_a_second_run_takes_every_run_from_its_cache(self):
        self.assertEqual(self.first.returncode, 0)
        again = subprocess.run(self.driver, capture_output=True, text=True, stdin=subprocess.DEVNULL)
        self.assertEqual(again.returncode, 0, again.stderr[-3000:])
        runs = len(os.listdir(os.path.join(self.distributed, "runs")))
        self.assertIn("(%d from the cache)" % runs, again.stderr)

    def test_the_timing_part_was_pinned_to_one_core(self):
        self.assertRegex(self.first.stderr, r"timing part on CPU \d+ .*taskset --cpu-list \d+ ")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
