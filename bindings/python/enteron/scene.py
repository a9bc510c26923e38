# SPDX-License-Identifier: Apache-2.0
"""Scenes: create, step, query. A Scene owns its ent_scene handle; close it (or use it as a
context manager) to release it at a known time rather than at garbage collection."""
import ctypes
import dataclasses
import json
import weakref

import numpy as np

from . import _buffers
from . import _fields
from . import _structs as s
from ._errors import ERROR_BUFFER_TOO_SMALL, Error, check
from ._handle import OwnedHandle
from ._library import lib
from .tool import Tool, _numbers, tool_desc

EFFECT_STRETCH = 0
EFFECT_BEND = 1
EFFECT_DAMPING = 2
EFFECT_GRAVITY = 3
EFFECT_MESENTERY = 4
EFFECT_PINNED = 5
EFFECT_ENVIRONMENT = 6     # on with the first obstacle
EFFECT_SELF_COLLISION = 7
EFFECT_TOOLS = 8           # on with the first tool
EFFECT_COUNT = 9  # the effects this binding knows (a newer library may know more)

SHAPE_LINE = 0
SHAPE_SERPENTINE = 1
SHAPE_HELIX = 2
SHAPE_POINTS = 3

INTEGRATOR_RK4 = 0
INTEGRATOR_SYMPLECTIC_EULER = 1
INTEGRATOR_IMPLICIT_EULER = 2
INTEGRATOR_BDF2 = 3

PIN_NONE = 0
PIN_FIRST = 1
PIN_LAST = 2
PIN_BOTH = 3

OBSTACLE_BOX_INSIDE = 0
OBSTACLE_PLANE = 1
OBSTACLE_SPHERE = 2
OBSTACLE_CAPSULE = 3
OBSTACLE_MESH = 4          # a triangle mesh (an organ), met through its signed distance field

NO_OBSTACLE = -1           # the world, for pin_point and attach_mesentery

CONTACT_SELF = 0      # another fold of the bowel
CONTACT_OBSTACLE = 1  # an obstacle (index: its index)
CONTACT_TOOL = 2      # a tool (index: its id)

#: The numpy dtype of Scene.contacts(): ent_contact's fields (u in [0, 1] along the bowel; m, N).
CONTACT_DTYPE = np.dtype(s.ent_contact)

LOG_DEBUG = 0
LOG_INFO = 1
LOG_WARNING = 2
LOG_ERROR = 3


def effect_name(effect):
    """The JSON-style name of an effect number ("stretch", ...), or None if unknown."""
    name = lib.ent_effect_name(effect)
    return name.decode() if name is not None else None


def effect_number(effect):
    """An effect given by number or by name ("gravity") as its number."""
    if isinstance(effect, str):
        for number in range(EFFECT_COUNT):
            if effect_name(number) == effect:
                return number
        raise ValueError("unknown effect %r (expected one of: %s)"
                         % (effect, ", ".join(effect_name(n) for n in range(EFFECT_COUNT))))
    return int(effect)


# The obstacles of add_obstacle: kind, its number, and its keys (those of the JSON
# "environment" entries) with the ent_obstacle_desc field each sets. Every kind also takes
# _FRAME_KEYS; a mesh takes vertices and triangles (arrays, handled apart).
_OBSTACLES = {
    "box_inside": (OBSTACLE_BOX_INSIDE, {"center": "center_m", "half_extents": "half_extents_m"}),
    "plane": (OBSTACLE_PLANE, {"point": "center_m", "normal": "normal"}),
    "sphere": (OBSTACLE_SPHERE, {"center": "center_m", "radius": "radius_m"}),
    "capsule": (OBSTACLE_CAPSULE, {"start": "start_m", "end": "end_m", "radius": "radius_m"}),
    "mesh": (OBSTACLE_MESH, {"vertices": None, "triangles": None, "voxel_size": "mesh_voxel_size_m"}),
}
_FRAME_KEYS = {"position": "position_m", "orientation": "orientation_wxyz", "friction": "friction"}


def _mesh_arrays(desc, vertices, triangles):
    """Points desc at C-contiguous copies of the mesh arrays, kept alive on desc (the library
    copies them during ent_scene_add_obstacle)."""
    if vertices is None or triangles is None:
        raise TypeError("a mesh obstacle needs both vertices= (n, 3) and triangles= (m, 3)")
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    t = np.asarray(triangles)
    if v.ndim != 2 or v.shape[1] != 3:
        raise ValueError("vertices must be an (n, 3) array of x y z in m, got shape %s" % (v.shape,))
    if t.ndim != 2 or t.shape[1] != 3:
        raise ValueError("triangles must be an (m, 3) array of vertex indices, got shape %s" % (t.shape,))
    if t.size and (not np.issubdtype(t.dtype, np.integer) or t.min() < 0 or t.max() > 0xFFFFFFFF):
        raise ValueError("triangles must hold vertex indices from 0 (integers that fit 32 bits)")
    t = np.ascontiguousarray(t, dtype=np.uint32)
    desc.mesh_vertices_xyz_m = v.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
    desc.mesh_vertex_count = _fields.checked_integer(ctypes.c_uint32, v.shape[0], "the vertex count of vertices")
    desc.mesh_triangles = t.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32))
    desc.mesh_triangle_count = _fields.checked_integer(ctypes.c_uint32, t.shape[0], "the triangle count of triangles")
    desc._arrays = (v, t)


def obstacle_desc(kind, **keys):
    """An ent_obstacle_desc with the library's defaults, then the kind (a name of _OBSTACLES
    or an OBSTACLE_* number) and its keys, named as in the JSON "environment" entries."""
    if not isinstance(kind, str):
        kind = {number: name for name, (number, _) in _OBSTACLES.items()}.get(kind, kind)
    if kind not in _OBSTACLES:
        raise ValueError("unknown obstacle kind %r (expected one of: %s)" % (kind, ", ".join(_OBSTACLES)))
    number, shape_keys = _OBSTACLES[kind]
    allowed = dict(shape_keys, **_FRAME_KEYS)
    desc = s.ent_obstacle_desc()
    check(lib.ent_obstacle_desc_init(ctypes.byref(desc), ctypes.sizeof(desc)), "ent_obstacle_desc_init")
    desc.kind = number
    for key, value in keys.items():
        if key not in allowed:
            raise TypeError("unknown key %r for a %s obstacle (expected one of: %s)"
                            % (key, kind, ", ".join(allowed)))
        if allowed[key] is None:
            continue
        target = getattr(desc, allowed[key])
        if isinstance(target, ctypes.Array):
            target[:] = list(_numbers(value, len(target), key))
        else:
            setattr(desc, allowed[key], float(value))
    if kind == "mesh":
        _mesh_arrays(desc, keys.get("vertices"), keys.get("triangles"))
    return desc


class SceneDesc:
    """An ent_scene_desc filled with the library's defaults (ent_scene_desc_init), then with
    the keyword arguments, named as the C fields: SceneDesc(control_points=40, length_m=1.0,
    gravity_m_per_s2=(0, 0, -9.81), integrator=enteron.INTEGRATOR_RK4). Also:
      effects             a bit mask, or an iterable of effect numbers or names
                          ({"gravity", "stretch"}); default: stretch, bend, damping, gravity
      shape_points_xyz_m  an (n, 3) array-like (sets shape to SHAPE_POINTS, control_points to
                          n: a control_points given too must be n, and length_m to 0, the
                          length of the spline through them, unless length_m is given)
      pinned_points       an iterable of control point indices (sets pinned_point_count)
      radius_profile_m, linear_density_profile_kg_per_m, stretch_stiffness_profile_N,
      bend_stiffness_profile_N_m2
                          an (n, 2) array-like of pairs (s m, value): a property along the
                          length in place of its constant (sets its _count)
      mesentery_root_points_m
                          an (n, 3) array-like: the mesentery's root as a polyline of n >= 2
                          points (sets mesentery_root_point_count)
      mesentery_root_mapping, pinned_spans_m
                          an (n, 2) array-like of pairs: (s m, t) where along the root the
                          bowel at s is tied; (from m, to m) spans of the bowel held in place
    The arrays are copied and kept with the description until the scene is created. The
    count of an array always comes from the array; an integer field that its C type cannot
    hold (control_points=2**32 + 10) raises OverflowError naming the field, never wraps."""

    # Arrays of pairs (ent_scene_desc: a pointer to pairs, and their count), by pointer field:
    # the profiles, the mesentery's root mapping and the pinned spans.
    _PROFILES = {"radius_profile_m": "radius_profile_count",
                 "linear_density_profile_kg_per_m": "linear_density_profile_count",
                 "stretch_stiffness_profile_N": "stretch_stiffness_profile_count",
                 "bend_stiffness_profile_N_m2": "bend_stiffness_profile_count",
                 "mesentery_root_mapping": "mesentery_root_mapping_count",
                 "pinned_spans_m": "pinned_span_count"}
    # Arrays of points (x y z, m), by pointer field: the mesentery's root.
    _POINTS = {"mesentery_root_points_m": "mesentery_root_point_count"}
    _ARRAYS = ("shape_points_xyz_m", "pinned_points") + tuple(_PROFILES) + tuple(_POINTS)

    def __init__(self, **fields):
        self.struct = s.ent_scene_desc()
        check(lib.ent_scene_desc_init(ctypes.byref(self.struct), ctypes.sizeof(self.struct)),
              "ent_scene_desc_init")
        self._keep = {}
        self._given = set()
        for name, value in fields.items():
            setattr(self, name, value)

    def __setattr__(self, name, value):
        if name in ("struct", "_keep", "_given"):
            object.__setattr__(self, name, value)
            return
        known = ({field[0] for field in s.ent_scene_desc._fields_} - {"struct_size", "callbacks", "pinned_point_count"}
                 - set(self._PROFILES.values()) - set(self._POINTS.values()))
        if name not in known:
            raise AttributeError("ent_scene_desc has no settable field %r" % name)
        if name == "effects" and not isinstance(value, int):
            mask = 0
            for effect in value:
                mask |= 1 << effect_number(effect)
            value = mask
        if name == "shape_points_xyz_m":
            points = np.ascontiguousarray(value, dtype=np.float64)
            if points.ndim != 2 or points.shape[1] != 3:
                if points.ndim != 1 or points.size % 3:
                    raise ValueError("SceneDesc.shape_points_xyz_m must be an (n, 3) array of x y z in m, "
                                     "got shape %s" % (points.shape,))
                points = points.reshape(-1, 3)
            count = _fields.checked_integer(ctypes.c_uint32, len(points), "the point count of shape_points_xyz_m")
            if "control_points" in self._given and self.struct.control_points != count:
                raise ValueError(self._disagreement(self.struct.control_points, count))
            self._keep[name] = points
            self.struct.shape_points_xyz_m = points.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
            self.struct.shape = SHAPE_POINTS
            self.struct.control_points = count
            if "length_m" not in self._given:
                self.struct.length_m = 0.0  # the length of the spline through them: it starts at rest
            return
        if name in self._PROFILES or name in self._POINTS:
            width, looks = (3, "x y z in m") if name in self._POINTS else (2, "pairs (s in m, value)")
            rows = np.ascontiguousarray(value, dtype=np.float64)
            if rows.ndim != 2 or rows.shape[1] != width:
                raise ValueError("SceneDesc.%s must be an (n, %d) array of %s, got shape %s"
                                 % (name, width, looks, rows.shape))
            count = _fields.checked_integer(ctypes.c_uint32, len(rows), "the %s count of %s"
                                            % ("point" if width == 3 else "pair", name))
            self._keep[name] = rows
            setattr(self.struct, name, rows.ctypes.data_as(ctypes.POINTER(ctypes.c_double)))
            setattr(self.struct, {**self._PROFILES, **self._POINTS}[name], count)
            return
        if name == "pinned_points":
            indices = np.array([_fields.checked_integer(ctypes.c_uint32, index, "SceneDesc.pinned_points[%d]" % n)
                                for n, index in enumerate(value)], dtype=np.uint32)
            self._keep[name] = indices
            self.struct.pinned_points = indices.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32))
            self.struct.pinned_point_count = len(indices)
            return
        target = getattr(self.struct, name)
        if isinstance(target, ctypes.Array):
            if len(value) != len(target):
                raise ValueError("%s needs %d values, got %d" % (name, len(target), len(value)))
            target[:] = [float(v) for v in value]
            return
        if name == "control_points" and "shape_points_xyz_m" in self._keep:
            count = _fields.checked_integer(ctypes.c_uint32, value, "SceneDesc.control_points")
            if count != len(self._keep["shape_points_xyz_m"]):
                raise ValueError(self._disagreement(count, len(self._keep["shape_points_xyz_m"])))
        _fields.set_field(self.struct, name, value, "SceneDesc." + name)
        self._given.add(name)

    @staticmethod
    def _disagreement(control_points, points):
        return ("SceneDesc.control_points is %d but shape_points_xyz_m holds %d points: a points shape "
                "takes its count from its array (leave control_points out)" % (control_points, points))

    def _checked_struct(self):
        """The struct, once its (pointer, count) pairs are seen to match the arrays kept: a
        change made to .struct directly cannot make the library read past an array."""
        points = self._keep.get("shape_points_xyz_m")
        if self.struct.shape == SHAPE_POINTS and points is not None:
            if self.struct.control_points != len(points):
                raise ValueError(self._disagreement(self.struct.control_points, len(points)))
            if ctypes.cast(self.struct.shape_points_xyz_m, ctypes.c_void_p).value != points.ctypes.data:
                raise ValueError("SceneDesc.struct.shape_points_xyz_m was changed behind the description: "
                                 "set shape_points_xyz_m instead")
        indices = self._keep.get("pinned_points", np.zeros(0, dtype=np.uint32))
        pointer = ctypes.cast(self.struct.pinned_points, ctypes.c_void_p).value
        if self.struct.pinned_point_count != len(indices) or (len(indices) and pointer != indices.ctypes.data):
            raise ValueError("SceneDesc.pinned_point_count is %d but pinned_points holds %d indices: set "
                             "pinned_points instead" % (self.struct.pinned_point_count, len(indices)))
        for name, count_name in {**self._PROFILES, **self._POINTS}.items():
            rows = self._keep.get(name, np.zeros((0, 2)))
            pointer = ctypes.cast(getattr(self.struct, name), ctypes.c_void_p).value
            if getattr(self.struct, count_name) != len(rows) or (len(rows) and pointer != rows.ctypes.data):
                raise ValueError("SceneDesc.%s is %d but %s holds %d %s: set %s instead"
                                 % (count_name, getattr(self.struct, count_name), name, len(rows),
                                    "points" if name in self._POINTS else "pairs", name))
        return self.struct

    def __getattr__(self, name):
        if name.startswith("_") or name == "struct":
            raise AttributeError(name)
        value = getattr(self.struct, name)
        return list(value) if isinstance(value, ctypes.Array) else value


@dataclasses.dataclass(frozen=True)
class Stats:
    """ent_stats: counters and energies of the last published state (SI units), and what the
    last step did (last_step_*) and the slow steps so far (max_step_ns, late_steps,
    subdivided_steps, proxy_unbalanced_solves, full_contact_searches): include/enteron/enteron.h
    says what each counts."""
    control_points: int
    time_s: float
    steps: int
    substeps: int
    rollbacks: int
    kinetic_energy_J: float
    potential_energy_J: float
    contacts: int
    max_penetration_m: float
    last_step_ns: int
    last_step_attempts: int
    last_step_substeps: int
    last_step_proxy_iterations: int
    last_step_proxy_evaluations: int
    max_step_ns: int
    late_steps: int
    subdivided_steps: int
    proxy_unbalanced_solves: int
    full_contact_searches: int


@dataclasses.dataclass(frozen=True)
class ContactSummary:
    """ent_contact_summary: the bowel's contacts and stretch in the last published step (what
    a trainer scores as tissue stress). capacity: the most contacts a step lists; listed,
    found (found > listed: the list was full); self_, obstacle_ and tool_contacts found;
    largest_force_N and where (largest_force_u in [0, 1]); largest_stretch of a segment (0.05:
    5 % longer than at rest) and where; time_s and steps of that state."""
    capacity: int
    listed: int
    found: int
    self_contacts: int
    obstacle_contacts: int
    tool_contacts: int
    largest_force_N: float
    largest_force_u: float
    largest_stretch: float
    largest_stretch_u: float
    time_s: float
    steps: int


@dataclasses.dataclass(frozen=True)
class EffectStats:
    """ent_effect_stats: what one effect cost so far."""
    effect: int
    name: str
    enabled: bool
    calls: int
    total_time_ns: int


class Scene(OwnedHandle):
    """A simulated intestine (ent_scene).

    Scene('{"intestine": {...}}')       from JSON text (str or bytes)
    Scene({"intestine": {...}})         from a dict, given to the library as JSON
    Scene(desc=SceneDesc(...))          from a C description (or desc={field: value})
    Scene(file="abdomen.json")          from a JSON file; its mesh files are found next to it
    log=callable(level, message)        optional: receives the scene's log lines
    add_tool(...) -> enteron.Tool, tool(id), tools; add_obstacle(kind, ...) -> index, then
    set_obstacle_pose, set_obstacle_velocity, set_obstacle_friction, remove_obstacle,
    obstacle_mesh; set_gravity, pin_point, unpin_point, attach_mesentery, attach_clamped_end (moving
    anatomy).
    Failures raise enteron.Error. Threads: as in C, one thread drives (step, add_*, the
    moving anatomy's calls, every Tool call) while others query (axis, control_points,
    stats, effect_stats, obstacle_pose, obstacle_count); close() may come from any thread at
    any time (the calls in flight finish, later ones raise ValueError).
    """

    def __init__(self, description=None, *, desc=None, file=None, log=None):
        if [description is None, desc is None, file is None].count(False) != 1:
            raise TypeError("give one of a JSON description (text or dict), desc= or file=")
        self._handle = None
        self._skins = weakref.WeakSet()  # closed before the scene: a skin must not outlive it
        self._callbacks = None
        self._log_function = None
        if log is not None:
            self._log_function = s.LOG_FUNCTION(
                lambda _user, level, message: log(level, message.decode(errors="replace")))
            self._callbacks = s.ent_callbacks()
            check(lib.ent_callbacks_init(ctypes.byref(self._callbacks), ctypes.sizeof(self._callbacks)),
                  "ent_callbacks_init")
            self._callbacks.log = self._log_function
        handle = ctypes.c_void_p()
        if desc is not None:
            if not isinstance(desc, SceneDesc):
                desc = SceneDesc(**desc)
            struct = desc._checked_struct()
            struct.callbacks = ctypes.pointer(self._callbacks) if self._callbacks is not None else None
            check(lib.ent_scene_create(ctypes.byref(struct), ctypes.byref(handle)), "ent_scene_create")
        elif file is not None:
            callbacks = ctypes.byref(self._callbacks) if self._callbacks is not None else None
            check(lib.ent_scene_create_json_file(str(file).encode(), callbacks, ctypes.byref(handle)),
                  "ent_scene_create_json_file")
        else:
            if isinstance(description, dict):
                description = json.dumps(description)
            text = description.encode() if isinstance(description, str) else bytes(description)
            callbacks = ctypes.byref(self._callbacks) if self._callbacks is not None else None
            check(lib.ent_scene_create_json_with(text, len(text), callbacks, ctypes.byref(handle)),
                  "ent_scene_create_json")
        self._own(handle, lib.ent_scene_destroy)
        self._count = self._control_point_count()
        self._tool_count = self._count_tools() if desc is None else 0

    # ---- lifetime -----------------------------------------------------------------------
    def close(self):
        """Destroys the scene (ent_scene_destroy) and closes its skins. Idempotent; later
        calls raise ValueError. Any thread: calls running on other threads (a step, a query,
        a save) finish, the scene goes as the last of them returns, and their next calls
        raise ValueError."""
        super().close()  # first: a skin made from now on is refused (_adopt)
        lock = getattr(self, "_lock", None)
        if lock is None:
            return
        with lock:
            skins = list(self._skins)
        for skin in skins:
            skin.close()

    def _adopt(self, skin):
        """Keeps a new skin, to be closed with the scene; False if the scene was closed
        while the skin was being made (another thread's close)."""
        with self._lock:
            if not self._handle:
                return False
            self._skins.add(skin)
            return True

    # ---- driving --------------------------------------------------------------------------
    def step(self, dt_s):
        """Advances by dt_s seconds (ent_scene_step)."""
        check(self._call(lib.ent_scene_step, dt_s), "ent_scene_step")

    def add_obstacle(self, kind, **keys):
        """Adds a rigid obstacle (ent_scene_add_obstacle) and returns its index. kind (a name
        or enteron.OBSTACLE_*) and keys are those of a JSON "environment" entry: add_obstacle("box_inside", center=(0, 0, 0),
        half_extents=(0.12, 0.12, 0.12)), ("plane", point=, normal=), ("sphere", center=,
        radius=), ("capsule", start=, end=, radius=), ("mesh", vertices=(n, 3) array in m,
        triangles=(m, 3) vertex indices, voxel_size=); every kind also takes position=,
        orientation= (w, x, y, z: its frame) and friction=. The first obstacle turns the
        environment effect on. Allocates (a mesh's distance field is built here): call it
        between steps."""
        desc = obstacle_desc(kind, **keys)
        index = ctypes.c_int32(-1)
        check(self._call(lib.ent_scene_add_obstacle, ctypes.byref(desc), ctypes.byref(index)),
              "ent_scene_add_obstacle")
        return index.value

    def remove_obstacle(self, obstacle):
        """Removes an obstacle from the next step on (ent_scene_remove_obstacle); the others
        keep their indices."""
        check(self._call(lib.ent_scene_remove_obstacle, obstacle), "ent_scene_remove_obstacle")

    def set_obstacle_pose(self, obstacle, position, orientation=(1.0, 0.0, 0.0, 0.0)):
        """Moves an obstacle's frame (ent_obstacle_set_pose): reached at the end of the next
        step, moving within it; position in m, orientation (w, x, y, z)."""
        check(self._call(lib.ent_obstacle_set_pose, obstacle, _numbers(position, 3, "position"),
                                        _numbers(orientation, 4, "orientation")), "ent_obstacle_set_pose")

    def set_obstacle_velocity(self, obstacle, linear, angular=(0.0, 0.0, 0.0)):
        """The velocity the obstacle's contacts see in the next step (ent_obstacle_set_velocity):
        linear of its origin in m/s, angular in rad/s."""
        check(self._call(lib.ent_obstacle_set_velocity, obstacle, _numbers(linear, 3, "linear"),
                                            _numbers(angular, 3, "angular")), "ent_obstacle_set_velocity")

    def set_obstacle_friction(self, obstacle, friction):
        """An obstacle's Coulomb friction coefficient (>= 0; negative: the scene's)."""
        check(self._call(lib.ent_obstacle_set_friction, obstacle, float(friction)), "ent_obstacle_set_friction")

    def obstacle_mesh(self, obstacle):
        """A mesh obstacle's (vertices (n, 3) in m in its frame, triangles (m, 3) uint32):
        copies (ent_obstacle_mesh). Between steps, from the driving thread."""
        vertex_count, triangle_count = ctypes.c_uint32(), ctypes.c_uint32()
        check(self._call(lib.ent_obstacle_mesh, obstacle, 0, None, ctypes.byref(vertex_count), 0, None,
                                    ctypes.byref(triangle_count)), "ent_obstacle_mesh")
        vertices, vertex_pointer = _buffers.new_array(vertex_count.value, 3)
        triangles = np.zeros((triangle_count.value, 3), dtype=np.uint32)
        check(self._call(lib.ent_obstacle_mesh, obstacle, vertex_count.value, vertex_pointer,
                                    ctypes.byref(vertex_count), triangle_count.value,
                                    triangles.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32)),
                                    ctypes.byref(triangle_count)), "ent_obstacle_mesh")
        return vertices, triangles

    def set_gravity(self, gravity_m_per_s2):
        """Gravity from the next step on, m/s^2 (ent_scene_set_gravity): a table tilt."""
        check(self._call(lib.ent_scene_set_gravity, _numbers(gravity_m_per_s2, 3, "gravity")),
              "ent_scene_set_gravity")

    def pin_point(self, control_point, obstacle=NO_OBSTACLE):
        """Holds a control point where it is, in the world or on an obstacle's frame
        (ent_scene_pin_point)."""
        check(self._call(lib.ent_scene_pin_point, control_point, obstacle), "ent_scene_pin_point")

    def unpin_point(self, control_point):
        """Lets a pinned control point go (ent_scene_unpin_point)."""
        check(self._call(lib.ent_scene_unpin_point, control_point), "ent_scene_unpin_point")

    def attach_mesentery(self, obstacle=NO_OBSTACLE):
        """Fixes the mesentery's root to an obstacle's frame, or to the world
        (ent_scene_attach_mesentery)."""
        check(self._call(lib.ent_scene_attach_mesentery, obstacle), "ent_scene_attach_mesentery")

    def attach_clamped_end(self, ends, obstacle=NO_OBSTACLE):
        """Fixes clamped ends (PIN_FIRST, PIN_LAST or PIN_BOTH; the scene's clamped_ends) to
        an obstacle's frame, or to the world: the end point and its tangent's direction move
        with the obstacle from where they are now (ent_scene_attach_clamped_end)."""
        check(self._call(lib.ent_scene_attach_clamped_end, ends, obstacle), "ent_scene_attach_clamped_end")

    def add_tool(self, *, position=(0.0, 0.0, 0.0), orientation=(1.0, 0.0, 0.0, 0.0), **settings):
        """Adds a surgical tool (ent_tool_add) and returns its enteron.Tool. Keywords, SI
        units, library defaults for those not given: radius (m, shaft radius), length (m, of
        the shaft from the tip along local +z), max_force (N, bound of the force it exerts
        and reports), grasp_margin (m), grasp_stiffness (N/m), grasp_damping (N s/m),
        position (m, of the tip), orientation (w, x, y, z; identity: vertical, tip lowest),
        mode ("proxy", the default, or "direct"), coupling_stiffness (N/m), coupling_damping
        (N s/m), friction (its contacts' Coulomb coefficient; < 0: the scene's),
        passivity_limiter (True or False), jaw_length and jaw_opening (m: a grasper's jaws,
        whose grasp takes what lies between them), blade_width and blade_length (m: a
        retractor's blade at the tip) (docs/haptics.md).
        The first tool turns the tools effect on. Allocates: call it between steps."""
        desc = tool_desc(position, orientation, **settings)
        index = ctypes.c_int32(-1)
        check(self._call(lib.ent_tool_add, ctypes.byref(desc), ctypes.byref(index)), "ent_tool_add")
        self._tool_count = index.value + 1
        return Tool(self, index.value)

    def tool(self, tool_id):
        """The Tool with this id (0, 1, ...; the JSON description's tools come first).
        An id the scene does not have raises enteron.Error (ERROR_NOT_FOUND)."""
        return Tool(self, tool_id)

    @property
    def tools(self):
        """The scene's tools, in id order (a tuple of Tool), without the removed ones."""
        grasping = ctypes.c_int32()
        return tuple(Tool(self, n) for n in range(self._tool_count)
                     if self._call(lib.ent_tool_state, n, ctypes.byref(grasping)) == 0)

    @property
    def tool_count(self):
        """The number of tools added and not removed (ent_scene_tool_count)."""
        count = ctypes.c_int32()
        check(self._call(lib.ent_scene_tool_count, ctypes.byref(count)), "ent_scene_tool_count")
        return count.value

    def _count_tools(self):
        # The C API has no tool count: the JSON tools are ids 0..n-1, so ask for each until
        # one is not found.
        grasping = ctypes.c_int32()
        count = 0
        while self._call(lib.ent_tool_state, count, ctypes.byref(grasping)) == 0:
            count += 1
        return count

    # ---- queries of the last published state (any thread) ---------------------------------
    @property
    def control_point_count(self):
        return self._count

    def _control_point_count(self):
        count = ctypes.c_uint32()
        check(self._call(lib.ent_scene_control_points, 0, None, ctypes.byref(count)), "ent_scene_control_points")
        return count.value

    def axis(self, count=100):
        """count points evenly spaced along the axis, as a (count, 3) float64 array in m."""
        array, pointer = _buffers.new_array(count, 3)
        check(self._call(lib.ent_scene_axis, count, pointer), "ent_scene_axis")
        return array

    def control_points(self):
        """The control points, as an (n, 3) float64 array in m (a copy: the C API copies)."""
        array, pointer = _buffers.new_array(self._count, 3)
        count = ctypes.c_uint32()
        status = self._call(lib.ent_scene_control_points, self._count, pointer, ctypes.byref(count))
        if status == ERROR_BUFFER_TOO_SMALL:  # cannot happen today: the count is fixed
            self._count = count.value
            return self.control_points()
        check(status, "ent_scene_control_points")
        return array[: count.value]

    @property
    def obstacle_count(self):
        """Obstacles in the last published state, removed ones not counted."""
        count = ctypes.c_uint32()
        check(self._call(lib.ent_scene_obstacle_count, ctypes.byref(count)), "ent_scene_obstacle_count")
        return count.value

    def obstacle_pose(self, obstacle):
        """Where an obstacle's frame rests in the last published state: (position (3,) in m,
        orientation (4,) w x y z), numpy arrays."""
        position, orientation = np.zeros(3), np.zeros(4)
        check(self._call(lib.ent_obstacle_pose, obstacle, position.ctypes.data_as(ctypes.POINTER(ctypes.c_double)),
                                    orientation.ctypes.data_as(ctypes.POINTER(ctypes.c_double))),
              "ent_obstacle_pose")
        return position, orientation

    def stats(self):
        """ent_scene_stats as a Stats dataclass."""
        raw = s.ent_stats()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._call(lib.ent_scene_stats, ctypes.byref(raw)), "ent_scene_stats")
        return Stats(**{field: getattr(raw, field) for field in Stats.__dataclass_fields__})

    def effect_stats(self, effect):
        """ent_scene_effect_stats of one effect, by number (enteron.EFFECT_*) or name."""
        number = effect_number(effect)
        raw = s.ent_effect_stats()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._call(lib.ent_scene_effect_stats, number, ctypes.byref(raw)), "ent_scene_effect_stats")
        return EffectStats(number, effect_name(number), bool(raw.enabled), raw.calls, raw.total_time_ns)

    def all_effect_stats(self):
        """{name: EffectStats} for every effect this binding knows."""
        return {effect_name(n): self.effect_stats(n) for n in range(EFFECT_COUNT)}

    # ---- contacts (any thread) ---------------------------------------------------------------
    def contacts(self):
        """The contacts of the last published step (ent_scene_contacts) as a numpy structured
        array of CONTACT_DTYPE, one row per contact: kind (CONTACT_*), index (the obstacle's
        index or the tool's id; -1 for a self-contact), u and other_u (where on the bowel, in
        [0, 1]; other_u: the other fold, -1 unless a self-contact), point_m (3,), normal (3,),
        depth_m, force_N (3,) on the bowel at u. The tools' come first, then the obstacles',
        then the self-contacts'."""
        while True:
            count = ctypes.c_uint32()
            check(self._call(lib.ent_scene_contacts, 0, None, ctypes.byref(count)), "ent_scene_contacts")
            array = np.zeros(max(count.value, 1), dtype=CONTACT_DTYPE)
            array["struct_size"][0] = CONTACT_DTYPE.itemsize
            status = self._call(lib.ent_scene_contacts, len(array), array.ctypes.data, ctypes.byref(count))
            if status == ERROR_BUFFER_TOO_SMALL:  # another thread's step listed more meanwhile
                continue
            check(status, "ent_scene_contacts")
            return array[: count.value]

    def contact_summary(self):
        """ent_scene_contact_summary as a ContactSummary."""
        raw = s.ent_contact_summary()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._call(lib.ent_scene_contact_summary, ctypes.byref(raw)), "ent_scene_contact_summary")
        return ContactSummary(**{field: getattr(raw, field) for field in ContactSummary.__dataclass_fields__})

    # ---- save and restore (driving calls) ----------------------------------------------------
    def save_state(self):
        """The whole state of the scene as bytes (ent_scene_save_state; docs/scoring-and-state.md):
        restore_state(state), into this scene or one made from the same description, continues
        bit for bit as this one would."""
        size = ctypes.c_size_t()
        check(self._call(lib.ent_scene_save_state, None, 0, ctypes.byref(size)), "ent_scene_save_state")
        buffer = ctypes.create_string_buffer(size.value)
        check(self._call(lib.ent_scene_save_state, buffer, size.value, ctypes.byref(size)), "ent_scene_save_state")
        return buffer.raw[: size.value]

    def restore_state(self, state):
        """Back to a state from save_state (bytes or any bytes-like object)
        (ent_scene_restore_state). A state that is damaged, of another version or of another
        scene raises enteron.Error naming the problem, and the scene is unchanged."""
        data = bytes(state)
        check(self._call(lib.ent_scene_restore_state, data, len(data)), "ent_scene_restore_state")
