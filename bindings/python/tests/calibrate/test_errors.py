# SPDX-License-Identifier: Apache-2.0
"""Bad experiments, data and options: each is refused before any fit starts, with a message
that names the file and the key or line (a table, like tests/capi/test_bad_inputs.cpp), and
the command exits with status 2 and that message."""
import contextlib
import copy
import io
import json
import os
import tempfile
import unittest

import calibrate_support as support
from enteron import calibrate
from enteron.calibrate import cli

with open(calibrate.experiment_path("hanging_sag"), encoding="utf-8") as _file:
    GOOD = json.load(_file)


def changed(change):
    document = copy.deepcopy(GOOD)
    change(document)
    return document


def set_in(path, value):
    def change(document):
        node = document
        for part in path[:-1]:
            node = node[part]
        node[path[-1]] = value
    return change


def delete(path):
    def change(document):
        node = document
        for part in path[:-1]:
            node = node[part]
        del node[path[-1]]
    return change


# (what is wrong, how the experiment is changed, what the message must contain)
BAD_EXPERIMENTS = [
    ("unknown JSON path", set_in(["parameters", 0, "path"], "intestine.stretch_stifness"),
     ["bad.json: parameters[0].path", "'intestine.stretch_stifness'", "intestine has no key 'stretch_stifness'",
      "stretch_stiffness"]),
    ("path through a missing object", set_in(["parameters", 0, "path"], "collision.stiffness"),
     ["parameters[0].path", "the document has no key 'collision'"]),
    ("index past a list", set_in(["parameters", 0, "path"], "gravity[3]"),
     ["parameters[0].path", "gravity is a list of 3 element(s): no element 3"]),
    ("path to a non-number", set_in(["parameters", 0, "path"], "intestine.shape.kind"),
     ["parameters[0].path", "intestine.shape.kind is 'line', not a number"]),
    ("malformed path", set_in(["parameters", 0, "path"], "intestine..length"),
     ["parameters[0].path", "is not a path"]),
    ("bounds inverted", set_in(["parameters", 0, "bounds"], [1000, 10]),
     ["bad.json: parameters[0].bounds", "the lower bound must be below the upper one, got [1000.0, 10.0]"]),
    ("bounds not numbers", set_in(["parameters", 0, "bounds"], [10, "a lot"]),
     ["parameters[0].bounds[1]", "must be a finite number"]),
    ("a log scale with a zero bound", lambda d: d["parameters"][0].update(bounds=[0, 1000], scale="log"),
     ["bad.json: parameters[0].scale", "a log scale needs a positive lower bound, got 0"]),
    ("a scene the library refuses", set_in(["scene", "intestine", "radius"], -0.01),
     ["bad.json", "the library refuses the scene at the start values", "intestine.radius must be > 0, got -0.01"]),
    ("a bound the library refuses", set_in(["parameters", 0, "bounds"], [-50, 1000]),
     ["bad.json", "with parameters[0] (intestine.stretch_stiffness) at its lower bound -50",
      "intestine.stretch_stiffness must be >= 0"]),
    ("unknown key", set_in(["measurment"], {}), ["bad.json", "unknown key 'measurment'"]),
    ("no scene", delete(["scene"]), ["bad.json", "needs exactly one of \"scene\", \"scene_file\", \"journal\""]),
    ("unknown measurement kind", set_in(["measurements", "sag", "kind"], "droop"),
     ["bad.json: measurements.sag.kind", "must be one of axis_point, tool_force, sag, got 'droop'"]),
    ("a key of another kind", set_in(["measurements", "sag", "u"], 0.5),
     ["bad.json: measurements.sag", "key 'u' does not apply to kind 'sag'"]),
    ("a tool the scene lacks", set_in(["measurements", "force"], {"kind": "tool_force", "tool": 0, "component": "z"}),
     ["bad.json: measurements.force.tool", "the scene has 0 tool(s): no tool 0"]),
    ("an action for a missing obstacle", set_in(["script"], [{"at": 0.1, "obstacle": 2, "move_to": [0, 0, 0]}]),
     ["bad.json: script[0].obstacle", "must be an index below the scene's 0 obstacle(s), got 2"]),
    ("an action doing two things", set_in(["script"], [{"at": 0.1, "gravity": [0, 0, -9.81], "move_to": [0, 0, 0]}]),
     ["bad.json: script[0]", "must do exactly one of move_to, grasp, velocity, gravity (got move_to, gravity)"]),
    ("a negative step", set_in(["step"], -0.001), ["bad.json: step", "must be > 0"]),
    ("the same constant twice", lambda d: d["parameters"].append(dict(d["parameters"][0])),
     ["bad.json: parameters[1].path", "names intestine.stretch_stiffness a second time"]),
    ("an unknown fit option", set_in(["fit", "generations"], 5), ["bad.json: fit", "unknown key 'generations'"]),
]

GOOD_DATA = "measurement,t_s,value\nsag,0.1,0.012\nsag,0.2,0.011\n"
# (what is wrong, the data file's text, what the message must contain)
BAD_DATA = [
    ("a NaN value", "measurement,t_s,value\nsag,0.1,0.012\nsag,0.2,nan\n", ["data.csv line 3", "value is nan"]),
    ("an empty value", "measurement,t_s,value\nsag,0.1,\n", ["data.csv line 2", "value '' is not a number"]),
    ("an infinite time", "measurement,t_s,value\nsag,inf,0.01\n", ["data.csv line 2", "t_s is inf"]),
    ("a negative time", "measurement,t_s,value\nsag,-0.1,0.01\n", ["data.csv line 2", "t_s must be >= 0"]),
    ("a time past the end", "measurement,t_s,value\nsag,1.5,0.01\n",
     ["data.csv line 2", "t_s = 1.5 s is past the end of the experiment (1 s)"]),
    ("an unknown measurement", "measurement,t_s,value\ntip_z,0.1,0.01\n",
     ["data.csv line 2", "unknown measurement 'tip_z'", "measures: sag"]),
    ("a zero sigma", "measurement,t_s,value,sigma\nsag,0.1,0.01,0\n", ["data.csv line 2", "sigma must be > 0"]),
    ("a wrong header", "name,time,value\nsag,0.1,0.01\n", ["data.csv line 1", "the header must be measurement,t_s,value"]),
    ("a short row", "measurement,t_s,value\nsag,0.1\n", ["data.csv line 2", "2 field(s) for the 3 columns"]),
    ("a row twice", "measurement,t_s,value\nsag,0.1,0.01\n# again\nsag,0.1,0.02\n",
     ["data.csv line 4", "sag at t_s = 0.1 s is already on line 2"]),
    ("no rows", "measurement,t_s,value\n", ["data.csv", "a header but no data rows"]),
]


class BadInput(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix="calibrate-errors-")

    def write(self, name, text):
        path = os.path.join(self.directory, name)
        with open(path, "w", encoding="utf-8") as file:
            file.write(text)
        return path

    def command(self, *args):
        """cli.main's status and what it wrote to stderr."""
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(list(args) + ["--workers", "0", "--no-cache", "--quiet"])
        return status, err.getvalue()

    def test_bad_experiments_are_refused_naming_the_key(self):
        data = self.write("data.csv", GOOD_DATA)
        for what, change, expected in BAD_EXPERIMENTS:
            with self.subTest(what):
                path = self.write("bad.json", json.dumps(changed(change)))
                with self.assertRaises(calibrate.CalibrationError) as caught:
                    calibrate.load_experiment(path)
                for text in expected:
                    self.assertIn(text, str(caught.exception))
                status, message = self.command(path, data)
                self.assertEqual(status, 2, message)
                self.assertIn(expected[0], message)

    def test_bad_data_are_refused_naming_the_line(self):
        experiment = calibrate.load_experiment(self.write("good.json", json.dumps(GOOD)))
        for what, text, expected in BAD_DATA:
            with self.subTest(what):
                path = self.write("data.csv", text)
                with self.assertRaises(calibrate.CalibrationError) as caught:
                    calibrate.load_data(path, experiment)
                for part in expected:
                    self.assertIn(part, str(caught.exception))
                status, message = self.command(os.path.join(self.directory, "good.json"), path)
                self.assertEqual(status, 2, message)

    def test_files_that_cannot_be_read(self):
        data = self.write("data.csv", GOOD_DATA)
        for args, expected in (([os.path.join(self.directory, "missing.json"), data], "missing.json: cannot read"),
                               ([self.write("broken.json", "{\"scene\": "), data], "broken.json: not JSON"),
                               (["hanging_sag", os.path.join(self.directory, "none.csv")], "none.csv: cannot read")):
            with self.subTest(expected):
                status, message = self.command(*args)
                self.assertEqual(status, 2)
                self.assertIn(expected, message)

    def test_a_sigma_for_some_measurements_only(self):
        document = changed(lambda d: d["measurements"].update(
            sag={"kind": "sag", "samples": 41, "sigma": 0.001},
            middle={"kind": "axis_point", "u": 0.5, "component": "z"}))
        experiment = calibrate.load_experiment(self.write("two.json", json.dumps(document)))
        path = self.write("data.csv", "measurement,t_s,value\nsag,0.1,0.01\nmiddle,0.1,-0.01\n")
        with self.assertRaisesRegex(calibrate.CalibrationError, "data.csv: no sigma column.*not to middle"):
            calibrate.load_data(path, experiment)

    def test_bad_options(self):
        data = self.write("data.csv", GOOD_DATA)
        status, message = self.command("hanging_sag", data, "--max-evaluations", "-1")
        self.assertEqual(status, 2)
        self.assertIn("--max-evaluations must be >= 0", message)
        with self.assertRaisesRegex(calibrate.CalibrationError, "unknown fit option 'generations'"):
            experiment = calibrate.load_experiment(calibrate.experiment_path("hanging_sag"))
            calibrate.fit(experiment, calibrate.load_data(data, experiment), calibrate.Engine(workers=0),
                          generations=3)
        with self.assertRaisesRegex(calibrate.CalibrationError, "no shipped experiment 'cantilevre'"):
            calibrate.experiment_path("cantilevre")

    def test_every_shipped_experiment_loads_and_simulates(self):
        import math
        for name in calibrate.EXPERIMENTS:
            with self.subTest(name):
                if name == "lcm_journal":  # its journal is the user's recording (test_journal.py makes one)
                    with self.assertRaisesRegex(calibrate.CalibrationError, "lcm_journal.json: journal: cannot read "
                                                                            "the journal .*session.journal"):
                        calibrate.load_experiment(calibrate.experiment_path(name))
                    continue
                experiment = calibrate.load_experiment(calibrate.experiment_path(name))
                end = experiment.duration_s
                requests = [(measurement, round(end * k / 4, 9)) for measurement in experiment.measurements
                            for k in range(1, 5)]
                predictions = calibrate.Plan(experiment, requests).predict([p.start for p in experiment.parameters])
                self.assertTrue(all(math.isfinite(v) for v in predictions), predictions)

    def test_a_simulation_that_fails_during_the_fit_is_ranked_last_not_fatal(self):
        # symplectic Euler held to 6 substeps per 1 ms step: its stability limit needs more
        # above a stretch stiffness of about 300 N. Those simulations fail with the library's
        # message; the fit ranks them last and goes on.
        experiment = support.experiment("hanging_sag", fit={"max_evaluations": 30, "local": False}, duration=0.2)
        experiment.scene["solver"].update(integrator="symplectic_euler", max_substeps=6)
        plan = calibrate.Plan(experiment, [("sag", 0.1)])
        failed = plan.evaluate([1000.0])
        self.assertIn("at t = ", failed.failure)
        self.assertIsNone(plan.evaluate([10.0]).failure)
        data = calibrate.synthesize(experiment, support.requests(["sag"], 0.02, 0.2), [12.0])
        with calibrate.Engine(workers=0, progress=False) as engine:
            result = calibrate.fit(experiment, data, engine, sigma0=0.6)
        self.assertGreater(result.simulations["failed"], 0)
        self.assertLess(support.relative_error(result.parameters[0]["value"], 12.0), 0.05)

if __name__ == "__main__":
    unittest.main()
