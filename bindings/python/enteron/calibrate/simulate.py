# SPDX-License-Identifier: Apache-2.0
"""One evaluation: the experiment's scene with one set of constants, stepped through its
script, measured where the data was measured. This is what runs on the Dask workers.

    plan = Plan(experiment, data.requests())     # on the client, once
    predictions = plan.predict(values)           # anywhere: numpy array, one per request

A simulation is a pure function of the plan and the values (the library is deterministic),
so its result does not depend on the worker, the process or the order: that is what makes
the fit bit-identical on any number of workers, and its results cacheable on disk.

The schedule. The experiment steps with dt (its "step"; a journal's own dt per tick) from
t = 0. Before the step from T[k] to T[k+1], every action with T[k] <= at < T[k+1] is
applied (grasp, release, gravity, an obstacle's velocity, which lasts until the next), and
every tool or obstacle in motion is sent the pose it has at T[k+1] on its move: linear in
position from where it was at "at" to move_to over duration, and normalised linear in
orientation (the library moves it continuously within the step). A measurement at a time
between two steps is interpolated linearly between them.
"""
import hashlib
import math

import numpy as np

from . import json_path
from .experiment import COMPONENTS, FORCE_COMPONENTS

_SNAP_S = 1e-9  # a request this close to a step's time is that step's value, not an interpolation


class SimulationFailed(Exception):
    """The library refused the scene or a step for these values (an unstable step, ...)."""


class Result:
    """What an evaluation gives back: predictions (float64, one per request) or failure (the
    library's message), and the sha256 of the library that computed it."""

    __slots__ = ("predictions", "failure", "library_sha256")

    def __init__(self, predictions, failure, library_sha256):
        self.predictions = predictions
        self.failure = failure
        self.library_sha256 = library_sha256

    def to_bytes(self):
        """The cache's record: 1 byte kind, then the float64 predictions or the UTF-8 message."""
        if self.failure is not None:
            return b"F" + self.failure.encode()
        return b"P" + np.ascontiguousarray(self.predictions, dtype="<f8").tobytes()

    @classmethod
    def from_bytes(cls, record, library_sha256):
        if record[:1] == b"F":
            return cls(None, record[1:].decode(), library_sha256)
        return cls(np.frombuffer(record[1:], dtype="<f8").copy(), None, library_sha256)


_library_digest = None


def library_sha256():
    """The sha256 of the libenteron this process loaded (computed once per process)."""
    global _library_digest
    if _library_digest is None:
        import enteron
        with open(enteron.library_path, "rb") as file:
            _library_digest = hashlib.sha256(file.read()).hexdigest()
    return _library_digest


def _nlerp(q0, q1, a):
    if float(np.dot(q0, q1)) < 0.0:
        q1 = -q1
    q = (1.0 - a) * q0 + a * q1
    return q / np.linalg.norm(q)


class _Timeline:
    """The commanded pose of one tool or obstacle over time: where it starts, then its moves."""

    def __init__(self, position, orientation):
        self.start = (np.asarray(position, dtype=np.float64), self._unit(orientation))
        self.moves = []  # (at, duration, from position, to position, from orientation, to orientation)

    @staticmethod
    def _unit(q):
        q = np.asarray(q, dtype=np.float64)
        return q / np.linalg.norm(q)

    def add_move(self, at, duration, to_position, to_orientation):
        position, orientation = self.pose(at)
        target_orientation = orientation if to_orientation is None else self._unit(to_orientation)
        self.moves.append((at, duration, position, np.asarray(to_position, dtype=np.float64), orientation,
                           target_orientation))

    def pose(self, t):
        position, orientation = self.start
        for at, duration, p0, p1, q0, q1 in self.moves:
            if t < at:
                break
            a = 1.0 if duration <= 0.0 else min(1.0, (t - at) / duration)
            position, orientation = p0 + a * (p1 - p0), _nlerp(q0, q1, a)
        return position, orientation

    def first_move(self):
        return self.moves[0][0] if self.moves else math.inf


class Plan:
    """Everything a worker needs to evaluate one set of values: the scene, the parameters'
    paths, the schedule (time steps and actions) and where to measure. Plain data, so it
    pickles by value to any worker that can import enteron."""

    def __init__(self, experiment, requests):
        self.scene = experiment.scene
        self.parameter_parts = [p.parts for p in experiment.parameters]
        self.measurements = {name: (m.kind, dict(m.keys)) for name, m in experiment.measurements.items()}
        self.script = sorted(experiment.script, key=lambda action: action["at"])  # stable: file order at equal times
        last = max(t for _, t in requests)
        if experiment.journal is not None:
            self.steps_s = experiment.journal.steps_s
            self.tool_calls = experiment.journal.tool_calls
        else:
            count = int(math.ceil(last / experiment.step_s - _SNAP_S / experiment.step_s))
            self.steps_s = np.full(max(count, 0), experiment.step_s)
            self.tool_calls = None
        self.times_s = np.concatenate([[0.0], np.cumsum(self.steps_s)])
        if last > self.times_s[-1] + _SNAP_S:
            raise ValueError("a request at %g s is past the schedule's end (%g s)" % (last, self.times_s[-1]))
        self.requests = list(requests)
        # Each request as (measurement, step k, weight of step k + 1): value = (1 - w) v[k] + w v[k + 1].
        self._reads = []
        needed = {name: set() for name in self.measurements}
        for name, t in self.requests:
            k = int(np.searchsorted(self.times_s, t, side="right")) - 1
            k = min(max(k, 0), len(self.times_s) - 1)
            if k + 1 < len(self.times_s) and abs(self.times_s[k + 1] - t) <= _SNAP_S:
                k += 1
            if abs(self.times_s[k] - t) <= _SNAP_S or k + 1 == len(self.times_s):
                weight = 0.0
            else:
                weight = (t - self.times_s[k]) / (self.times_s[k + 1] - self.times_s[k])
            self._reads.append((name, k, weight))
            needed[name].add(k)
            if weight:
                needed[name].add(k + 1)
            if self.measurements[name][1].get("relative"):
                needed[name].add(0)
        self._needed = {name: sorted(steps) for name, steps in needed.items() if steps}
        self.last_step = max(max(steps) for steps in self._needed.values())

    # ---- running -------------------------------------------------------------------------
    def predict(self, values):
        """The predictions for these values (numpy float64, one per request); raises
        SimulationFailed with the library's message when it refuses the scene or a step."""
        import enteron
        document = json_path.with_numbers(self.scene, self.parameter_parts, values)
        try:
            scene = enteron.Scene(document)
        except enteron.Error as error:
            raise SimulationFailed("the library refuses the scene: %s" % error.message) from None
        with scene:
            recorded = {name: {} for name in self._needed}
            wanted = {}
            for name, steps in self._needed.items():
                for k in steps:
                    wanted.setdefault(k, []).append(name)
            tools = {}
            events = self._events(document)
            self._record(scene, tools, 0, wanted, recorded)
            for k in range(self.last_step):
                try:
                    for call in events.get(k, ()):
                        self._apply(scene, tools, call)
                    scene.step(float(self.steps_s[k]))
                except enteron.Error as error:
                    raise SimulationFailed("at t = %.6g s: %s" % (self.times_s[k], error.message)) from None
                if k + 1 in wanted:
                    self._record(scene, tools, k + 1, wanted, recorded)
        predictions = np.empty(len(self._reads))
        for i, (name, k, weight) in enumerate(self._reads):
            series = recorded[name]
            value = series[k] if not weight else (1.0 - weight) * series[k] + weight * series[k + 1]
            if self.measurements[name][1].get("relative"):
                value -= series[0]
            predictions[i] = value
        return predictions

    def evaluate(self, values):
        """predict, as a Result (a failure is a result too: the search ranks it last)."""
        try:
            return Result(self.predict(values), None, library_sha256())
        except SimulationFailed as failure:
            return Result(None, str(failure), library_sha256())

    def _events(self, document):
        """{step k: [call, ...]}: what to do before step k (see the module's comment)."""
        if self.tool_calls is not None:
            return self.tool_calls
        timelines = {}
        for index, tool in enumerate(document.get("tools", []) or []):
            timelines[("tool", index)] = _Timeline(tool.get("position", (0, 0, 0)), tool.get("orientation", (1, 0, 0, 0)))
        for index, obstacle in enumerate(document.get("environment", []) or []):
            timelines[("obstacle", index)] = _Timeline(obstacle.get("position", (0, 0, 0)),
                                                       obstacle.get("orientation", (1, 0, 0, 0)))
        events = {}

        def step_of(t):
            k = int(np.searchsorted(self.times_s, t + _SNAP_S, side="right")) - 1
            return max(k, 0)

        velocities = []
        for action in self.script:
            k = step_of(action["at"])
            if "move_to" in action:
                actor = ("tool", action["tool"]) if "tool" in action else ("obstacle", action["obstacle"])
                timelines[actor].add_move(action["at"], action["duration"], action["move_to"], action.get("orientation"))
            elif "grasp" in action:
                events.setdefault(k, []).append(("grasp" if action["grasp"] else "release", action["tool"]))
            elif "gravity" in action:
                events.setdefault(k, []).append(("gravity", tuple(action["gravity"])))
            else:
                velocities.append((k, action["obstacle"], tuple(action["velocity"]), tuple(action["angular_velocity"])))
        # A velocity holds from its step until the obstacle's next velocity.
        for i, (k, obstacle, linear, angular) in enumerate(velocities):
            later = [v[0] for v in velocities[i + 1:] if v[1] == obstacle]
            for step in range(k, min(later[0] if later else self.last_step, self.last_step)):
                events.setdefault(step, []).append(("velocity", obstacle, linear, angular))
        for (kind, index), timeline in timelines.items():
            if not timeline.moves:
                continue
            last_sent = None
            for k in range(step_of(timeline.first_move()), self.last_step):
                position, orientation = timeline.pose(self.times_s[k + 1])
                pose = (tuple(position), tuple(orientation))
                if pose != last_sent:
                    events.setdefault(k, []).append(("pose_" + kind, index) + pose)
                    last_sent = pose
        return events

    @staticmethod
    def _apply(scene, tools, call):
        kind = call[0]
        if kind == "pose_tool":
            _tool(scene, tools, call[1]).set_pose(call[2], call[3])
        elif kind == "pose_obstacle":
            scene.set_obstacle_pose(call[1], call[2], call[3])
        elif kind == "grasp":
            _tool(scene, tools, call[1]).grasp()
        elif kind == "release":
            _tool(scene, tools, call[1]).release()
        elif kind == "gravity":
            scene.set_gravity(call[1])
        elif kind == "velocity":
            scene.set_obstacle_velocity(call[1], call[2], call[3])
        else:  # "journal_tool": a journal's tick, the pose then the grasp action (0 none, 1 grasp, 2 release)
            tool = _tool(scene, tools, call[1])
            tool.set_pose(call[2], call[3])
            if call[4] == 1:
                tool.grasp()
            elif call[4] == 2:
                tool.release()

    def _record(self, scene, tools, k, wanted, recorded):
        axes = {}
        for name in wanted.get(k, ()):
            kind, keys = self.measurements[name]
            if kind == "tool_force":
                force = _tool(scene, tools, keys["tool"]).wrench().force
                component = FORCE_COMPONENTS[keys["component"]]
                recorded[name][k] = float(np.linalg.norm(force)) if component == 3 else float(force[component])
                continue
            samples = keys["samples"]
            if samples not in axes:
                axes[samples] = scene.axis(samples)
            axis = axes[samples]
            if kind == "sag":
                recorded[name][k] = float(0.5 * (axis[0, 2] + axis[-1, 2]) - axis[:, 2].min())
            else:  # axis_point: linear between the two samples around u
                position = keys["u"] * (samples - 1)
                i = min(int(position), samples - 2)
                a = position - i
                c = COMPONENTS[keys["component"]]
                recorded[name][k] = float((1.0 - a) * axis[i, c] + a * axis[i + 1, c]) if a else float(axis[i, c])


def _tool(scene, tools, tool_id):
    if tool_id not in tools:
        tools[tool_id] = scene.tool(tool_id)
    return tools[tool_id]


def evaluate(plan, values):
    """The function the engine sends to the workers: plan.evaluate(values)."""
    return plan.evaluate(values)
