# SPDX-License-Identifier: Apache-2.0
"""An experiment: a scene, what the tools and obstacles do in it, what is measured, and
which of the scene's numbers a fit may change (docs/calibration.md, "The experiment file").

    {
      "name": "cantilever",
      "scene": {...} | "scene_file": "scene.json" | "journal": "session.journal",
      "step": 0.001, "duration": 1.0,
      "script": [{"at": 0.2, "tool": 0, "move_to": [0, 0, 0.05], "duration": 0.5}, ...],
      "measurements": {"tip_z": {"kind": "axis_point", "u": 1.0, "component": "z"}, ...},
      "parameters": [{"path": "intestine.bend_stiffness", "bounds": [1e-4, 1e-1]}],
      "fit": {"seed": 1, "max_evaluations": 400}
    }

Everything is checked when the experiment is loaded, and every refusal names the file
and the key: a JSON path the scene does not have, bounds the wrong way round, a scene the
library refuses at the start values or at a bound, a script action of an unknown kind.
"""
import copy
import json
import math
import numbers
import os

from . import json_path

KINDS = ("axis_point", "tool_force", "sag")
COMPONENTS = {"x": 0, "y": 1, "z": 2}
FORCE_COMPONENTS = dict(COMPONENTS, magnitude=3)
DEFAULT_STEP_S = 1e-3
DEFAULT_AXIS_SAMPLES = 201
_TOP_KEYS = ("name", "description", "source", "scene", "scene_file", "journal", "step", "duration", "script",
             "measurements", "parameters", "fit")
_FIT_KEYS = {"seed": int, "max_evaluations": int, "population": int, "sigma0": float, "local": bool,
             "tolerance": float}
#: What a fit does when the experiment's "fit" object says nothing (docs/calibration.md).
FIT_DEFAULTS = {"seed": 1, "max_evaluations": 600, "population": 0, "sigma0": 0.3, "local": True,
                "tolerance": 1e-3}


class CalibrationError(ValueError):
    """A bad experiment, data file or option: the message names the input and the key."""


class Parameter:
    """One constant to fit: a number of the scene named by a JSON path, its bounds, and the
    scale the search moves on ("log" for positive bounds spanning more than a decade, by
    default; "linear" otherwise). start: where the search starts, the scene's own value or
    the parameter's "start" (which also adds the key to a scene that lacks it), clamped
    into the bounds."""

    def __init__(self, path, lower, upper, scale, start, name):
        self.path = path
        self.parts = json_path.parse(path)
        self.lower = float(lower)
        self.upper = float(upper)
        self.scale = scale
        self.start = float(start)
        self.name = name

    def to_unit(self, value):
        """The value as a fraction of the bounds on the parameter's scale (0 at lower, 1 at upper)."""
        if self.scale == "log":
            return (math.log(value) - math.log(self.lower)) / (math.log(self.upper) - math.log(self.lower))
        return (value - self.lower) / (self.upper - self.lower)

    def from_unit(self, unit):
        """The inverse of to_unit."""
        if self.scale == "log":
            return math.exp(math.log(self.lower) + unit * (math.log(self.upper) - math.log(self.lower)))
        return self.lower + unit * (self.upper - self.lower)

    def value_per_unit(self, value):
        """d value / d unit at value: the chain rule from the search's coordinates to the constant's."""
        if self.scale == "log":
            return value * (math.log(self.upper) - math.log(self.lower))
        return self.upper - self.lower

    def describe(self):
        return {"name": self.name, "path": self.path, "bounds": [self.lower, self.upper], "scale": self.scale,
                "start": self.start}


class Measurement:
    """What one measured series is: kind (KINDS), with its keys (u, component, relative,
    tool, samples) and an optional sigma (the measurement's noise, in its unit)."""

    def __init__(self, name, kind, unit, sigma=None, **keys):
        self.name = name
        self.kind = kind
        self.unit = unit
        self.sigma = sigma
        self.keys = keys

    def describe(self):
        return dict({"kind": self.kind, "unit": self.unit, "sigma": self.sigma}, **self.keys)


class Experiment:
    """A loaded, checked experiment. scene: the JSON document (a dict) with the parameters at
    their start values; parameters, measurements ({name: Measurement}); step_s, duration_s;
    script: the checked actions; journal: a journal.Journal or None; fit_options; and the
    file's description and source (where its data come from)."""

    def __init__(self, name, source_file, scene, parameters, measurements, step_s, duration_s, script, journal,
                 fit_options, description="", data_source=""):
        self.name = name
        self.file = source_file
        self.scene = scene
        self.parameters = parameters
        self.measurements = measurements
        self.step_s = step_s
        self.duration_s = duration_s
        self.script = script
        self.journal = journal
        self.fit_options = fit_options
        self.description = description
        self.data_source = data_source

    def scene_with(self, values):
        """A copy of the scene with the parameters set to values (one per parameter)."""
        return json_path.with_numbers(self.scene, [p.parts for p in self.parameters], values)

    def identity(self):
        """What determines a simulation's result besides the parameter values, as canonical JSON:
        two experiments with the same identity give the same evaluations (the cache's key)."""
        return json.dumps({"scene": self.scene, "paths": [p.path for p in self.parameters],
                           "step": self.step_s, "script": self.script,
                           "journal": self.journal.identity() if self.journal is not None else None,
                           "measurements": {m.name: [m.kind, m.keys] for m in self.measurements.values()}},
                          sort_keys=True, separators=(",", ":"))


# ---- loading ------------------------------------------------------------------------------
def _refuse(where, message):
    raise CalibrationError("%s: %s" % (where, message))


def _number(value, where, low=None, high=None, low_open=False):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        _refuse(where, "must be a finite number, got %r" % (value,))
    if low is not None and (value < low or (low_open and value == low)):
        _refuse(where, "must be %s %g, got %r" % (">" if low_open else ">=", low, value))
    if high is not None and value > high:
        _refuse(where, "must be <= %g, got %r" % (high, value))
    return float(value)


def _vector(value, count, where):
    if not isinstance(value, list) or len(value) != count:
        _refuse(where, "must be an array of %d numbers, got %r" % (count, value))
    return [_number(v, "%s[%d]" % (where, i)) for i, v in enumerate(value)]


def _only_keys(spec, allowed, where):
    if not isinstance(spec, dict):
        _refuse(where, "must be an object, got %r" % (spec,))
    unknown = sorted(set(spec) - set(allowed))
    if unknown:
        _refuse(where, "unknown key %r (expected one of: %s)" % (unknown[0], ", ".join(allowed)))


def _fewest_samples(u):
    """The fewest axis samples (evenly spaced in arc length) with one exactly at u: reading
    the axis costs in proportion to its samples (u = 1: 2; u = 0.5: 3; else 201 and an
    interpolation between two)."""
    if isinstance(u, numbers.Real) and not isinstance(u, bool) and 0 <= u <= 1:
        for samples in range(2, DEFAULT_AXIS_SAMPLES + 1):
            if abs(u * (samples - 1) - round(u * (samples - 1))) < 1e-12:
                return samples
    return DEFAULT_AXIS_SAMPLES


def _measurement(name, spec, where):
    _only_keys(spec, ("kind", "u", "component", "relative", "tool", "samples", "sigma"), where)
    kind = spec.get("kind")
    if kind not in KINDS:
        _refuse(where + ".kind", "must be one of %s, got %r" % (", ".join(KINDS), kind))
    sigma = spec.get("sigma")
    if sigma is not None:
        sigma = _number(sigma, where + ".sigma", 0.0, low_open=True)
    samples = spec.get("samples", _fewest_samples(spec.get("u")) if kind == "axis_point" else DEFAULT_AXIS_SAMPLES)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 2 <= samples <= 100000:
        _refuse(where + ".samples", "must be an integer from 2 to 100000, got %r" % (samples,))
    allowed = {"axis_point": ("kind", "u", "component", "relative", "samples", "sigma"),
               "tool_force": ("kind", "tool", "component", "sigma"),
               "sag": ("kind", "samples", "sigma")}[kind]
    for key in spec:
        if key not in allowed:
            _refuse(where, "key %r does not apply to kind %r (its keys: %s)" % (key, kind, ", ".join(allowed)))
    if kind == "axis_point":
        component = spec.get("component")
        if component not in COMPONENTS:
            _refuse(where + ".component", "must be one of x, y, z, got %r" % (component,))
        relative = spec.get("relative", False)
        if not isinstance(relative, bool):
            _refuse(where + ".relative", "must be true or false, got %r" % (relative,))
        return Measurement(name, kind, "m", sigma, u=_number(spec.get("u"), where + ".u", 0.0, 1.0),
                           component=component, relative=relative, samples=samples)
    if kind == "tool_force":
        tool = spec.get("tool", 0)
        if isinstance(tool, bool) or not isinstance(tool, int) or tool < 0:
            _refuse(where + ".tool", "must be a tool id (an integer >= 0), got %r" % (tool,))
        component = spec.get("component")
        if component not in FORCE_COMPONENTS:
            _refuse(where + ".component", "must be one of x, y, z, magnitude, got %r" % (component,))
        return Measurement(name, kind, "N", sigma, tool=tool, component=component)
    return Measurement(name, kind, "m", sigma, samples=samples)


def _parameter(spec, scene, where):
    _only_keys(spec, ("path", "bounds", "scale", "name", "start"), where)
    path = spec.get("path")
    try:
        parts = json_path.parse(path)
        if "start" in spec:  # the scene may lack the key: it is added (docs/calibration.md)
            json_path.add_number(scene, parts, _number(spec["start"], where + ".start"))
        start = json_path.get(scene, parts)
    except json_path.PathError as error:
        _refuse(where + ".path", "%r does not name a number of the scene: %s" % (path, error))
    bounds = spec.get("bounds")
    if not isinstance(bounds, list) or len(bounds) != 2:
        _refuse(where + ".bounds", "must be [lower, upper], got %r" % (bounds,))
    lower = _number(bounds[0], where + ".bounds[0]")
    upper = _number(bounds[1], where + ".bounds[1]")
    if not lower < upper:
        _refuse(where + ".bounds", "the lower bound must be below the upper one, got [%r, %r]" % (lower, upper))
    scale = spec.get("scale", "log" if lower > 0 and upper > 10 * lower else "linear")
    if scale not in ("log", "linear"):
        _refuse(where + ".scale", "must be \"log\" or \"linear\", got %r" % (scale,))
    if scale == "log" and lower <= 0:
        _refuse(where + ".scale", "a log scale needs a positive lower bound, got %r" % (lower,))
    name = spec.get("name", json_path.spell(parts))
    return Parameter(path, lower, upper, scale, min(max(start, lower), upper), name)


def _action(spec, tools, obstacles, where):
    """One script action, checked, as a dict with "at" and one of: tool/obstacle + move_to
    (+ duration, orientation), tool + grasp, obstacle + velocity (+ angular_velocity),
    gravity."""
    _only_keys(spec, ("at", "tool", "obstacle", "move_to", "duration", "orientation", "grasp", "velocity",
                      "angular_velocity", "gravity"), where)
    at = _number(spec.get("at"), where + ".at", 0.0)
    action = {"at": at}
    actors = [key for key in ("tool", "obstacle") if key in spec]
    if len(actors) > 1:
        _refuse(where, "names both a tool and an obstacle: one action, one actor")
    verbs = [key for key in ("move_to", "grasp", "velocity", "gravity") if key in spec]
    if len(verbs) != 1:
        _refuse(where, "must do exactly one of move_to, grasp, velocity, gravity (got %s)"
                % (", ".join(verbs) or "none"))
    verb = verbs[0]
    if actors:
        actor = actors[0]
        number = spec[actor]
        count = tools if actor == "tool" else obstacles
        if isinstance(number, bool) or not isinstance(number, int) or not 0 <= number < count:
            _refuse(where + "." + actor, "must be an index below the scene's %d %s(s), got %r" % (count, actor, number))
        action[actor] = number
    actor = actors[0] if actors else None
    allowed = {"move_to": ("tool", "obstacle"), "grasp": ("tool",), "velocity": ("obstacle",), "gravity": (None,)}[verb]
    if actor not in allowed:
        _refuse(where, "%s is for %s, not %s" % (verb, " or ".join("a " + a if a else "the scene" for a in allowed),
                                                  "a " + actor if actor else "the scene"))
    for key in ("duration", "orientation"):
        if key in spec and verb != "move_to":
            _refuse(where + "." + key, "applies to move_to only")
    if "angular_velocity" in spec and verb != "velocity":
        _refuse(where + ".angular_velocity", "applies to velocity only")
    if verb == "move_to":
        action["move_to"] = _vector(spec["move_to"], 3, where + ".move_to")
        action["duration"] = _number(spec.get("duration", 0.0), where + ".duration", 0.0)
        if "orientation" in spec:
            orientation = _vector(spec["orientation"], 4, where + ".orientation")
            if not any(orientation):
                _refuse(where + ".orientation", "must be a non-zero quaternion (w x y z)")
            action["orientation"] = orientation
    elif verb == "grasp":
        if not isinstance(spec["grasp"], bool):
            _refuse(where + ".grasp", "must be true (grasp) or false (release), got %r" % (spec["grasp"],))
        action["grasp"] = spec["grasp"]
    elif verb == "velocity":
        action["velocity"] = _vector(spec["velocity"], 3, where + ".velocity")
        action["angular_velocity"] = _vector(spec.get("angular_velocity", [0, 0, 0]), 3, where + ".angular_velocity")
    else:
        action["gravity"] = _vector(spec["gravity"], 3, where + ".gravity")
    return action


def _check_motions_do_not_overlap(script, where):
    ends = {}
    for index, action in sorted(enumerate(script), key=lambda item: item[1]["at"]):
        if "move_to" not in action:
            continue
        actor = ("tool", action["tool"]) if "tool" in action else ("obstacle", action["obstacle"])
        if actor in ends and action["at"] < ends[actor][0] - 1e-12:
            end, other = ends[actor]
            _refuse("%s: script[%d]" % (where, index), "starts at %g s while script[%d] still moves %s %d (until %g s)"
                    % (action["at"], other, actor[0], actor[1], end))
        ends[actor] = (action["at"] + action["duration"], index)


def load(path, journal=None):
    """Reads and checks an experiment file (JSON); journal, if given, replaces its "journal"."""
    try:
        with open(path, encoding="utf-8") as file:
            text = file.read()
    except OSError as error:
        raise CalibrationError("%s: cannot read the experiment: %s" % (path, error.strerror or error)) from None
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise CalibrationError("%s: not JSON: %s (line %d, column %d)"
                               % (path, error.msg, error.lineno, error.colno)) from None
    if journal is not None:
        if not isinstance(document, dict) or "journal" not in document:
            raise CalibrationError("%s: --journal applies to an experiment with a \"journal\"" % path)
        document["journal"] = os.path.abspath(journal)
    return from_dict(document, source_file=os.path.abspath(path))


def from_dict(document, source_file="<experiment>"):
    """Checks an experiment given as a dict (relative files are found next to source_file)."""
    where = os.path.basename(source_file)
    base = os.path.dirname(source_file) if source_file != "<experiment>" else os.getcwd()
    _only_keys(document, _TOP_KEYS, where)
    sources = [key for key in ("scene", "scene_file", "journal") if key in document]
    if len(sources) != 1:
        _refuse(where, "needs exactly one of \"scene\", \"scene_file\", \"journal\" (got %s)"
                % (", ".join(sources) or "none"))
    journal = None
    if "scene" in document:
        scene = document["scene"]
        if not isinstance(scene, dict):
            _refuse(where + ": scene", "must be a JSON object (a scene description), got %r" % (scene,))
        scene = copy.deepcopy(scene)
    elif "scene_file" in document:
        scene_path = os.path.join(base, document["scene_file"])
        try:
            with open(scene_path, encoding="utf-8") as file:
                scene = json.load(file)
        except (OSError, json.JSONDecodeError) as error:
            _refuse(where + ": scene_file", "cannot read %s: %s" % (scene_path, error))
        _absolute_mesh_files(scene, os.path.dirname(scene_path))
    else:
        from . import journal as journal_module
        journal = journal_module.load(os.path.join(base, document["journal"]), where + ": journal")
        scene = copy.deepcopy(journal.scene)
    if not isinstance(scene, dict):
        _refuse(where + ": scene", "must be a JSON object")

    if journal is not None:
        for key in ("step", "script"):
            if key in document:
                _refuse(where + ": " + key, "does not apply to a journal: its ticks give the steps and the tools' poses")
        step = journal.step_s
    else:
        step = _number(document.get("step", DEFAULT_STEP_S), where + ": step", 0.0, 1.0, low_open=True)
    duration = document.get("duration")
    if duration is not None:
        duration = _number(duration, where + ": duration", 0.0, low_open=True)
        if journal is not None and duration > journal.duration_s + 1e-9:
            _refuse(where + ": duration", "is %g s but the journal holds %g s" % (duration, journal.duration_s))

    measurements_spec = document.get("measurements")
    if not isinstance(measurements_spec, dict) or not measurements_spec:
        _refuse(where + ": measurements", "must be an object naming at least one measurement")
    measurements = {name: _measurement(name, spec, "%s: measurements.%s" % (where, name))
                    for name, spec in measurements_spec.items()}

    tools = len(scene.get("tools", []) or [])
    obstacles = len(scene.get("environment", []) or [])
    for measurement in measurements.values():
        if measurement.kind == "tool_force" and measurement.keys["tool"] >= tools:
            _refuse("%s: measurements.%s.tool" % (where, measurement.name),
                    "the scene has %d tool(s): no tool %d" % (tools, measurement.keys["tool"]))
    script_spec = document.get("script", [])
    if not isinstance(script_spec, list):
        _refuse(where + ": script", "must be an array of actions, got %r" % (script_spec,))
    script = [_action(spec, tools, obstacles, "%s: script[%d]" % (where, i)) for i, spec in enumerate(script_spec)]
    _check_motions_do_not_overlap(script, where)

    parameters_spec = document.get("parameters")
    if not isinstance(parameters_spec, list) or not parameters_spec:
        _refuse(where + ": parameters", "must be an array of at least one {\"path\", \"bounds\"}")
    parameters = [_parameter(spec, scene, "%s: parameters[%d]" % (where, i)) for i, spec in enumerate(parameters_spec)]
    paths = [p.parts for p in parameters]
    for i, parts in enumerate(paths):
        if parts in paths[:i]:
            _refuse("%s: parameters[%d].path" % (where, i), "names %s a second time" % json_path.spell(parts))

    fit_spec = document.get("fit", {})
    _only_keys(fit_spec, tuple(_FIT_KEYS), where + ": fit")
    fit_options = dict(FIT_DEFAULTS)
    for key, value in fit_spec.items():
        kind = _FIT_KEYS[key]
        if kind is bool and not isinstance(value, bool):
            _refuse("%s: fit.%s" % (where, key), "must be true or false, got %r" % (value,))
        if kind is int and (isinstance(value, bool) or not isinstance(value, int) or value < 0):
            _refuse("%s: fit.%s" % (where, key), "must be an integer >= 0, got %r" % (value,))
        if kind is float:
            value = _number(value, "%s: fit.%s" % (where, key), 0.0, low_open=True)
        fit_options[key] = value

    name = document.get("name", os.path.splitext(where)[0])
    experiment = Experiment(name, source_file, scene, parameters, measurements, step, duration, script, journal,
                            fit_options, document.get("description", ""), document.get("source", ""))
    _check_scene_is_accepted(experiment, where)
    return experiment


def _absolute_mesh_files(scene, directory):
    """Mesh files of a scene file are relative to it; the experiment hands the scene to the
    library as text, so they become absolute."""
    for obstacle in scene.get("environment", []) or []:
        if isinstance(obstacle, dict) and isinstance(obstacle.get("file"), str):
            obstacle["file"] = os.path.join(directory, obstacle["file"])


def _check_scene_is_accepted(experiment, where):
    """The library must accept the scene at the start values and at every bound (one
    parameter at a time): a scene it refuses is named with the library's own message."""
    import enteron
    start = [p.start for p in experiment.parameters]
    trials = [("at the start values", start)]
    for i, parameter in enumerate(experiment.parameters):
        for label, value in (("lower", parameter.lower), ("upper", parameter.upper)):
            values = list(start)
            values[i] = value
            trials.append(("with parameters[%d] (%s) at its %s bound %g" % (i, parameter.name, label, value), values))
    for label, values in trials:
        try:
            enteron.Scene(experiment.scene_with(values)).close()
        except enteron.Error as error:
            _refuse(where, "the library refuses the scene %s: %s" % (label, error.message))
