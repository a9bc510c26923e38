# SPDX-License-Identifier: Apache-2.0
"""The replayed LCM journal: a session recorded by the bridge (enteron_record_journal: a
tool pushes aside the middle of a bowel held at both ends, pushed_bowel.json, for 1 s, one
command per 1 ms tick) is the script; the force on the tool made by the library with a
hidden bend stiffness is the data; the fit through the shipped lcm_journal experiment (the
command, --journal) recovers it within 2 %. Replaying the journal with the session's own
constants reproduces the scene's own run of the same calls bit for bit. About 15 s.

Environment: RECORD_JOURNAL (the recorder) and enteron_lcm on PYTHONPATH (bindings/lcm's
generated Python types)."""
import contextlib
import io
import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import calibrate_support as support
import enteron
from enteron import calibrate
from enteron.calibrate import cli

HIDDEN_BEND_STIFFNESS = 4.0e-3  # N m^2; the session's scene has 2.5e-3
SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pushed_bowel.json")


class Journal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp(prefix="calibrate-journal-")
        cls.journal = os.path.join(cls.directory, "session.journal")
        subprocess.run([os.environ["RECORD_JOURNAL"], SCENE, cls.journal, "1.0"], check=True,
                       stdout=subprocess.DEVNULL)
        with open(calibrate.experiment_path("lcm_journal"), encoding="utf-8") as file:
            document = json.load(file)
        document["journal"] = cls.journal
        document["fit"].update(tolerance=1e-2)
        cls.experiment = calibrate.experiment_from_dict(document, source_file=calibrate.experiment_path("lcm_journal"))
        cls.requests = support.requests(["force_y", "force_z"], 0.01, 1.0, start_s=0.5)

    def test_the_journal_is_the_session(self):
        journal = self.experiment.journal
        self.assertEqual(len(journal.steps_s), 1000)
        self.assertAlmostEqual(journal.duration_s, 1.0, places=12)
        with open(SCENE, encoding="utf-8") as file:
            self.assertEqual(journal.scene, json.load(file))
        # The replay makes the session's calls: the same as making them by hand.
        plan = calibrate.Plan(self.experiment, [("force_y", 1.0)])
        replayed = plan.predict([2.5e-3])[0]
        with enteron.Scene(journal.scene) as scene:
            tool = scene.tool(0)
            for tick, dt in enumerate(journal.steps_s):
                for _, tool_id, position, orientation, action in journal.tool_calls.get(tick, ()):
                    tool.set_pose(position, orientation)
                    if action == 1:
                        tool.grasp()
                    elif action == 2:
                        tool.release()
                scene.step(dt)
            by_hand = tool.wrench().force[1]
        self.assertEqual(np.float64(replayed).tobytes(), np.float64(by_hand).tobytes())
        self.assertGreater(abs(by_hand), 0.05, "the tool must push on the bowel")

    def test_the_command_recovers_a_hidden_bend_stiffness(self):
        data = calibrate.synthesize(self.experiment, self.requests, [HIDDEN_BEND_STIFFNESS])
        path = os.path.join(self.directory, "force.csv")
        calibrate.write_data(path, data)
        out = os.path.join(self.directory, "result.json")
        stdout = io.StringIO()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(io.StringIO()):
            status = cli.main(["lcm_journal", path, "--journal", self.journal, "--workers", "0", "--no-cache",
                               "--out", out])
        self.assertEqual(status, 0)
        with open(out, encoding="utf-8") as file:
            result = json.load(file)
        found = result["parameters"][0]["value"]
        support.print_table("Recovery through a replayed LCM journal", [
            ["constant", "hidden", "fitted", "error", "simulations"],
            ["intestine.bend_stiffness", "%g" % HIDDEN_BEND_STIFFNESS, "%.6g" % found,
             "%.3f %%" % (100 * support.relative_error(found, HIDDEN_BEND_STIFFNESS)),
             str(result["simulations"]["computed"])]])
        self.assertLess(support.relative_error(found, HIDDEN_BEND_STIFFNESS), 0.02)
        self.assertIn("intestine.bend_stiffness", stdout.getvalue())

    def test_a_file_that_is_not_a_journal(self):
        path = os.path.join(self.directory, "not_a_journal")
        with open(path, "wb") as file:
            file.write(b"\x00" * 64)
        with self.assertRaisesRegex(calibrate.CalibrationError, "lcm_journal.json: journal: .*not_a_journal is not a "
                                                                "readable journal: .*bad magic"):
            calibrate.load_experiment(calibrate.experiment_path("lcm_journal"), journal=path)


if __name__ == "__main__":
    unittest.main()
