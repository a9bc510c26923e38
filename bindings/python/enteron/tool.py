# SPDX-License-Identifier: Apache-2.0
"""Surgical tools: rigid capsules driven by the caller (a haptic device, a script) that push
and grasp the bowel (ent_tool_*).

    with enteron.Scene(...) as scene:
        tool = scene.add_tool(radius=0.005, max_force=5.0, position=(0.0, 0.05, 0.0125))
        for i in range(1, 501):
            tool.set_pose((0.0, 0.05 - 1e-4 * i, 0.0125))   # where the tip is at the end of the step
            scene.step(0.001)
            force, torque = tool.wrench()   # on the tool: N, and N m about the tip (render it)
        tool.grasp()                        # taken by the next step
        scene.step(0.001)
        if tool.grasping:                   # something was within reach
            ...
        tool.release()

The tip is at the pose's position; the shaft runs from the tip back along the
orientation's local +z axis (w x y z; identity: a vertical tool, tip lowest).
Threads, as in C: set_pose, grasp and release post to the tool's mailbox, which the next
step takes, and wrench, grasping and feedback read the last published state; all of them
are safe from any thread (a haptic thread) while another steps, and never wait for it.
scene.add_tool is a driving call: from the thread that steps.
"""
import ctypes
import typing

import numpy as np

from . import _structs as s
from ._errors import check
from ._library import lib

#: add_tool's keyword arguments and the ent_tool_desc fields they set (units in the names).
SETTINGS = {
    "radius": "radius_m",
    "length": "length_m",
    "max_force": "max_force_N",
    "grasp_margin": "grasp_margin_m",
    "grasp_stiffness": "grasp_stiffness_N_per_m",
    "grasp_damping": "grasp_damping_N_s_per_m",
    "coupling_stiffness": "coupling_stiffness_N_per_m",
    "coupling_damping": "coupling_damping_N_s_per_m",
    "friction": "friction",
    "jaw_length": "jaw_length_m",
    "jaw_opening": "jaw_opening_m",
    "blade_width": "blade_width_m",
    "blade_length": "blade_length_m",
}

#: ENT_TOOL_MODE_*: how a tool meets the bowel (docs/haptics.md).
TOOL_MODE_PROXY = 0
TOOL_MODE_DIRECT = 1

#: add_tool's mode= values (ent_tool_desc.mode).
MODES = {"proxy": TOOL_MODE_PROXY, "direct": TOOL_MODE_DIRECT}

IDENTITY = (1.0, 0.0, 0.0, 0.0)


class ToolFeedback(typing.NamedTuple):
    """ent_tool_feedback: what a tool felt and did in the last published step. force (3,)
    in N and torque (3,) about the tip in N m on the tool, bounded by its max_force;
    grasping; contacts (collision spheres touching it); time_s and steps of that state;
    stiffness (3, 3) dF/dx in N/m (as Tool.stiffness); proxy_position (3,), the tip of the
    tool in the scene, and commanded_position (3,), the tip asked for, in m; saturated: True
    when max_force bounded the force in that step (the force is the bound)."""
    force: np.ndarray
    torque: np.ndarray
    grasping: bool
    contacts: int
    time_s: float
    steps: int
    stiffness: np.ndarray
    proxy_position: np.ndarray
    commanded_position: np.ndarray
    saturated: bool


class ToolStats(typing.NamedTuple):
    """ent_tool_stats: the tool's passivity observer since it was added. energy_in and
    energy_out in J (the work the device put in and was given back; passive while
    energy_in - energy_out >= 0), limiter_energy in J, largest_force_change in N."""
    grasping: bool
    contacts: int
    energy_in: float
    energy_out: float
    limiter_energy: float
    largest_force_change: float
    steps: int


class ToolContacts(typing.NamedTuple):
    """ent_tool_read_contacts: what a tool touched and held in the last published step.
    ranges: (k, 2) array of [first u, last u] of each run of the bowel it touches (u in
    [0, 1]); contacts (collision spheres touching it); grasping, grasp_u (where the grasp took
    hold, -1 when not grasping); largest_force_N of one contact; contact_impulse_Ns (3,) and
    contact_impulse_magnitude_Ns since it was added (how hard for how long); time_s, steps."""
    ranges: np.ndarray
    contacts: int
    grasping: bool
    grasp_u: float
    largest_force_N: float
    contact_impulse_Ns: np.ndarray
    contact_impulse_magnitude_Ns: float
    time_s: float
    steps: int


class Wrench(typing.NamedTuple):
    """What the bowel exerted on a tool in the last step: force (3,) in N and torque (3,)
    about the tip in N m, both bounded by the tool's max_force. Unpacks as (force, torque)."""
    force: np.ndarray
    torque: np.ndarray


def _numbers(value, count, name):
    """`value` as a ctypes array of `count` doubles; ValueError naming `name` if the count is
    wrong. Non-finite numbers go through: the library refuses them with its own message."""
    try:
        numbers = [float(v) for v in value]
    except TypeError:
        raise TypeError("%s must be %d numbers, got %r" % (name, count, value)) from None
    if len(numbers) != count:
        raise ValueError("%s must be %d numbers, got %d" % (name, count, len(numbers)))
    return (ctypes.c_double * count)(*numbers)


def tool_desc(position=(0.0, 0.0, 0.0), orientation=IDENTITY, mode=None, passivity_limiter=None, **settings):
    """An ent_tool_desc with the library's defaults (ent_tool_desc_init), then the given
    pose and settings (the keys of SETTINGS, in SI units; mode "proxy" or "direct";
    passivity_limiter True or False)."""
    desc = s.ent_tool_desc()
    check(lib.ent_tool_desc_init(ctypes.byref(desc), ctypes.sizeof(desc)), "ent_tool_desc_init")
    if mode is not None:
        if mode not in MODES:
            raise ValueError("mode must be one of %s, got %r" % (", ".join(MODES), mode))
        desc.mode = MODES[mode]
    if passivity_limiter is not None:
        if not isinstance(passivity_limiter, bool):
            raise TypeError("passivity_limiter must be True or False, got %r" % (passivity_limiter,))
        desc.passivity_limiter = int(passivity_limiter)
    for name, value in settings.items():
        if name not in SETTINGS:
            raise TypeError("unknown tool setting %r (expected one of: %s, position, orientation)"
                            % (name, ", ".join(SETTINGS)))
        setattr(desc, SETTINGS[name], float(value))
    desc.position_m[:] = list(_numbers(position, 3, "position"))
    desc.orientation_wxyz[:] = list(_numbers(orientation, 4, "orientation"))
    return desc


class Tool:
    """A tool of a scene, named by its id (0, 1, ... in order of addition; the tools of the
    JSON description come first). Made by Scene.add_tool, Scene.tool(id) or Scene.tools.
    It keeps its scene alive; once the scene is closed its calls raise ValueError.
    Failures raise enteron.Error with the library's message."""

    def __init__(self, scene, tool_id):
        self._scene = scene
        self._id = int(tool_id)
        self._grasping_flag = ctypes.c_int32()
        self._force = (ctypes.c_double * 3)()
        self._torque = (ctypes.c_double * 3)()
        # Refuses an id the scene does not have (ENT_ERROR_NOT_FOUND, "tool 5 does not exist ...").
        check(scene._call(lib.ent_tool_state, self._id, ctypes.byref(self._grasping_flag)), "ent_tool_state")

    @property
    def id(self):
        """The tool's id in its scene (the int32_t of the C API)."""
        return self._id

    @property
    def scene(self):
        return self._scene

    def set_pose(self, position, orientation=IDENTITY):
        """Sets where the tool is at the end of the next step (ent_tool_set_pose): the tip's
        position (3 numbers, m) and the orientation (w, x, y, z; normalised by the library).
        The tool moves continuously there across the step's substeps. Any thread: the
        library takes it without a lock, and the last pose set before a step wins."""
        check(self._scene._call(lib.ent_tool_set_pose, self._id, _numbers(position, 3, "position"),
                                    _numbers(orientation, 4, "orientation")), "ent_tool_set_pose")

    def wrench(self):
        """The force (N) and the torque about the tip (N m) the bowel exerted on the tool in
        the last published step (ent_tool_wrench), as a Wrench of two new (3,) float64
        arrays. Zero before the first step; |force| never exceeds max_force. Any thread."""
        check(self._scene._call(lib.ent_tool_wrench, self._id, self._force, self._torque), "ent_tool_wrench")
        return Wrench(np.array(self._force[:]), np.array(self._torque[:]))

    def feedback(self):
        """ent_tool_read_feedback as a ToolFeedback: wrench, grasp and contacts of the last
        published step, with its time and step count, read at once. Any thread."""
        raw = s.ent_tool_feedback()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._scene._call(lib.ent_tool_read_feedback, self._id, ctypes.byref(raw)),
              "ent_tool_read_feedback")
        return ToolFeedback(np.array(raw.force_N[:]), np.array(raw.torque_Nm[:]), bool(raw.grasping),
                            raw.contacts, raw.time_s, raw.steps, np.array(raw.stiffness_N_per_m[:]).reshape(3, 3),
                            np.array(raw.proxy_position_m[:]), np.array(raw.commanded_position_m[:]),
                            bool(raw.saturated))

    def stiffness(self):
        """The tool's local stiffness at the last published step (ent_tool_stiffness): a new
        (3, 3) float64 array K = dF/dx in N/m (K[i, j] = dF_i/dx_j), the bowel and the
        velocities held. A device loop faster than the physics renders F + K (x - x_k).
        Any thread."""
        k = (ctypes.c_double * 9)()
        check(self._scene._call(lib.ent_tool_stiffness, self._id, k), "ent_tool_stiffness")
        return np.array(k[:]).reshape(3, 3)

    def stats(self):
        """The tool's passivity observer and counters (ent_tool_read_stats) as a ToolStats.
        Any thread."""
        raw = s.ent_tool_stats()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._scene._call(lib.ent_tool_read_stats, self._id, ctypes.byref(raw)), "ent_tool_read_stats")
        return ToolStats(bool(raw.grasping), raw.contacts, raw.energy_in_J, raw.energy_out_J, raw.limiter_energy_J,
                         raw.largest_force_change_N, raw.steps)

    def remove(self):
        """Removes the tool from its scene (ent_tool_remove): from the next step it touches
        nothing and lets go; its calls then raise enteron.Error (ERROR_NOT_FOUND). A driving
        call: from the thread that steps."""
        check(self._scene._call(lib.ent_tool_remove, self._id), "ent_tool_remove")

    def contacts(self):
        """ent_tool_read_contacts as a ToolContacts, from one snapshot. Any thread."""
        ranges = np.zeros((8, 2))
        while True:
            raw = s.ent_tool_contacts()
            raw.struct_size = ctypes.sizeof(raw)
            raw.range_capacity = len(ranges)
            raw.ranges_u = ranges.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
            check(self._scene._call(lib.ent_tool_read_contacts, self._id, ctypes.byref(raw)),
                  "ent_tool_read_contacts")
            if raw.range_count <= len(ranges):
                break
            ranges = np.zeros((raw.range_count, 2))
        return ToolContacts(ranges[: raw.range_count].copy(), raw.contacts, bool(raw.grasping), raw.grasp_u,
                            raw.largest_force_N, np.array(raw.contact_impulse_Ns[:]),
                            raw.contact_impulse_magnitude_Ns, raw.time_s, raw.steps)

    def grasp(self):
        """Grasps, at the start of the next step, the collision sphere nearest the tip if it
        is within reach (ent_tool_grasp); grasping shows whether it holds once that step is
        done. Grasping again picks anew. Any thread."""
        check(self._scene._call(lib.ent_tool_grasp, self._id), "ent_tool_grasp")

    def release(self):
        """Releases what the tool holds at the start of the next step (ent_tool_release);
        nothing held: no effect. Any thread."""
        check(self._scene._call(lib.ent_tool_release, self._id), "ent_tool_release")

    @property
    def grasping(self):
        """True while a grasp holds in the last published state; False after a release, a
        grasp with nothing in reach, or a slip (a hold that needed more than max_force)
        (ent_tool_state). Any thread."""
        check(self._scene._call(lib.ent_tool_state, self._id, ctypes.byref(self._grasping_flag)),
              "ent_tool_state")
        return bool(self._grasping_flag.value)

    def __eq__(self, other):
        return isinstance(other, Tool) and other._scene is self._scene and other._id == self._id

    def __hash__(self):
        return hash((id(self._scene), self._id))

    def __repr__(self):
        return "<enteron.Tool %d of %r>" % (self._id, self._scene)
