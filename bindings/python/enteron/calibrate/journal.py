# SPDX-License-Identifier: Apache-2.0
"""A recorded LCM session as an experiment's script: the journal that enteron-lcm-server
writes with --journal (docs/lcm.md, "Journal and replay").

The journal holds the session's scene (its session_t, first), then for every tick what the
scene was given: one journal_tool_t per tool (the pose passed to ent_tool_set_pose, then
the grasp action) and one journal_step_t (the dt given to ent_scene_step). Replaying those
calls on the same scene gives the session back bit for bit (enteron-lcm-replay); replaying
them on the scene with other constants gives what the session would have been with them,
which a fit compares with what was measured during the session (a force sensor's trace).

The journal is read with enteron_lcm.log, the reader of bindings/lcm (built with the LCM
bridge: build/bindings/lcm/generated/python in a build tree; installed next to enteron).
"""
import glob
import hashlib
import json
import os
import sys

import numpy as np

from .experiment import CalibrationError

_SOURCE_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))))  # bindings/python/enteron/calibrate -> the checkout


def _log_reader():
    try:
        from enteron_lcm import log
        return log
    except ImportError:
        pass
    for folder in sorted(glob.glob(os.path.join(_SOURCE_ROOT, "build", "bindings", "lcm", "generated", "python")) +
                         glob.glob(os.path.join(_SOURCE_ROOT, "build", "*", "bindings", "lcm", "generated", "python"))):
        if os.path.isdir(os.path.join(folder, "enteron_lcm")):
            sys.path.append(folder)
            from enteron_lcm import log
            return log
    raise CalibrationError("reading an LCM journal needs the Python LCM types enteron_lcm (built with the LCM bridge, "
                           "ENTERON_WITH_LCM: build/bindings/lcm/generated/python in a build tree, or installed with "
                           "the library); add their folder to PYTHONPATH")


class Journal:
    """scene (the session's JSON, a dict), steps_s (the dt of every tick), tool_calls
    ({tick: [("journal_tool", tool, position, orientation, grasp action), ...]}),
    duration_s (the simulated time it covers), step_s (its first dt), path, sha256."""

    def __init__(self, path, scene, steps_s, tool_calls, sha256):
        self.path = path
        self.scene = scene
        self.steps_s = steps_s
        self.tool_calls = tool_calls
        self.sha256 = sha256
        self.duration_s = float(np.sum(steps_s))
        self.step_s = float(steps_s[0])

    def identity(self):
        return self.sha256


def load(path, where):
    """Reads a journal; CalibrationError (naming where and the tick) for a file that is not a
    complete, successful session."""
    try:
        with open(path, "rb") as file:
            sha256 = hashlib.sha256(file.read()).hexdigest()
    except OSError as error:
        raise CalibrationError("%s: cannot read the journal %s: %s" % (where, path, error.strerror or error)) from None
    log = _log_reader()
    scene, steps, calls = None, [], {}
    try:
        for event, message in log.messages(path):
            name = type(message).__name__
            if name == "session_t" and scene is None:
                try:
                    scene = json.loads(message.scene_json)
                except json.JSONDecodeError as error:
                    raise CalibrationError("%s: the journal's session holds a scene that is not JSON: %s" % (where, error))
            elif name == "journal_tool_t":
                calls.setdefault(len(steps), []).append(
                    ("journal_tool", int(message.tool), tuple(message.position_m), tuple(message.orientation_wxyz),
                     int(message.grasp_action)))
            elif name == "journal_step_t" and event.channel == "ENTERON_JOURNAL_STEP":
                if message.step_status != 0:
                    raise CalibrationError("%s: %s, tick %d: the recorded step failed (status %d); a fit replays "
                                           "sessions whose steps all succeeded" % (where, path, message.tick,
                                                                                   message.step_status))
                steps.append(float(message.dt_s))
    except (log.LogError, ValueError) as error:
        if isinstance(error, CalibrationError):
            raise
        raise CalibrationError("%s: %s is not a readable journal: %s" % (where, path, error)) from None
    if scene is None:
        raise CalibrationError("%s: %s has no session_t: not a journal of enteron-lcm-server" % (where, path))
    if not steps:
        raise CalibrationError("%s: %s holds no tick" % (where, path))
    return Journal(os.path.abspath(path), scene, np.array(steps), calls, sha256)
