# SPDX-License-Identifier: Apache-2.0
"""Skins: the bowel's surface as a triangle mesh (ent_skin), for rendering.

    with enteron.Scene(...) as scene, enteron.Skin(scene, "convolution", segments=24) as skin:
        scene.step(0.001)
        skin.update()
        mesh = skin.mesh()        # numpy arrays of the mesh
        draw(mesh.positions, mesh.normals, mesh.indices)

The arrays of mesh() are copies of the skin's buffers (the C API's view is valid only
until the next update or destroy): read-only, and valid for as long as they live, after
the skin's next update(), its close() or its scene's close(). Copying costs a memcpy of
the mesh (27 us measured for the default convolution skin of the 6 m bowel, 15474
vertices, against milliseconds for its update); call mesh() once per update.
"""
import ctypes
import dataclasses
import threading

import numpy as np

from . import _buffers
from . import _fields
from . import _structs as s
from ._errors import check
from ._handle import OwnedHandle
from ._library import lib

SKIN_TUBE = 0
SKIN_POINT_SKELETON = 1
SKIN_CONVOLUTION = 2

_METHODS = {"tube": SKIN_TUBE, "point_skeleton": SKIN_POINT_SKELETON, "convolution": SKIN_CONVOLUTION}
_KNOBS = tuple(name for name, _ in s.ent_skin_desc._fields_ if name not in ("struct_size", "method"))


def skin_method(method):
    """A method given by name ('tube' | 'point_skeleton' | 'convolution') or number."""
    if isinstance(method, str):
        try:
            return _METHODS[method]
        except KeyError:
            raise ValueError("unknown skin method %r (expected one of: %s)"
                             % (method, ", ".join(_METHODS))) from None
    return int(method)


@dataclasses.dataclass(frozen=True)
class Mesh:
    """One ent_skin_mesh: positions (V, 3) float32 in m, normals (V, 3) float32 (unit,
    outward), u (V,) float32 (axis arc length / total length, in [0, 1]), indices (T, 3)
    uint32 (counter-clockwise seen from outside), v (V,) float32 (the angle around the
    axis / 2 pi in the rotation-minimising frame, in [0, 1)), tangents (V, 3) float32 (unit,
    perpendicular to the normal, along increasing u). The arrays are read-only copies that
    stay valid after the skin's next update() or close().
    Topology: topology_changed is True when the last update changed vertex_count or the
    indices (upload them again only then); topology_serial counts such updates (equal
    serials, the same indices); stable_topology says whether the skin keeps its topology
    while the bowel moves (tube and convolution by default; point_skeleton never)."""
    positions: np.ndarray
    normals: np.ndarray
    u: np.ndarray
    indices: np.ndarray
    time_s: float   # simulated time of the state the mesh was made from
    updates: int    # successful updates of the skin so far
    v: np.ndarray
    tangents: np.ndarray
    topology_serial: int
    topology_changed: bool
    stable_topology: bool

    @property
    def vertex_count(self):
        return len(self.positions)

    @property
    def triangle_count(self):
        return len(self.indices)


@dataclasses.dataclass(frozen=True)
class SkinMetrics:
    """struct ent_skin_metrics: how close the mesh is to the ideal tube of radius R."""
    vertex_count: int
    triangle_count: int
    watertight: bool
    open_edges: int
    nonmanifold_edges: int
    blended_vertices: int
    inverted_triangles: int
    radius_error_rms: float
    radius_error_max: float
    normal_deviation_rms_rad: float
    normal_deviation_max_rad: float
    volume_m3: float
    volume_error: float
    axis_length_m: float
    last_update_ns: int
    facet_error_rms: float
    facet_error_max: float
    # Where folds meet (in R, areas m^2) and motion since the update before (in R): see enteron.h.
    overlap_depth_max: float
    overlap_area_m2: float
    tube_overlap_depth_max: float
    tube_overlap_area_m2: float
    contact_gap_max: float
    shape_volume_error: float
    free_radius_error_rms: float
    vertex_motion_max: float
    vertex_excess_motion_max: float
    free_vertex_count: int
    has_previous_update: bool


class _Serialised:
    """A call's `with` block under the skin's lock, around its count in flight."""

    __slots__ = ("_lock", "_call")

    def __init__(self, lock, call):
        self._lock, self._call = lock, call

    def __enter__(self):
        self._lock.acquire()
        try:
            return self._call.__enter__()
        except BaseException:
            self._lock.release()
            raise

    def __exit__(self, *exc):
        try:
            return self._call.__exit__(*exc)
        finally:
            self._lock.release()


class Skin(OwnedHandle):
    """A skin of a scene (ent_skin).

    Skin(scene, "convolution", segments=24, ring_spacing_radii=0.5)
    method: 'tube' | 'point_skeleton' | 'convolution' (or enteron.SKIN_*); default the
    library's (convolution). The keyword arguments are the knobs of ent_skin_desc, named as
    its fields (segments, ring_spacing_radii, cap_rings, skeleton_spacing_radii,
    voxel_size_radii, window_radii, ring_chord_error_radii: the convolution's level of
    detail, rings closer where the axis bends; stable_topology: 1 (default) keeps the
    vertex count and indices of tube and convolution while the bowel moves;
    contact_surfaces: 1 (default) makes touching folds meet on contact surfaces with a
    bulge; skeleton_chord_error_radii: a skeleton that follows the curvature); the others
    keep the library's defaults.
    The mesh is empty until the first update(). Failures raise enteron.Error.
    The skin keeps its Scene alive; closing the Scene closes its skins first.
    Threads: any, also another than the one that steps the scene. Calls on one skin from
    several threads take turns (the C library would refuse the second as busy); close() from
    any thread: an update running elsewhere finishes, and the skin goes as it returns.
    """

    def __init__(self, scene, method=None, **knobs):
        self._handle = None
        desc = s.ent_skin_desc()
        check(lib.ent_skin_desc_init(ctypes.byref(desc), ctypes.sizeof(desc)), "ent_skin_desc_init")
        if method is not None:
            desc.method = skin_method(method)
        for name, value in knobs.items():
            if name not in _KNOBS:
                raise TypeError("ent_skin_desc has no knob %r (knobs: %s)" % (name, ", ".join(_KNOBS)))
            _fields.set_field(desc, name, value)
        handle = ctypes.c_void_p()
        check(scene._call(lib.ent_skin_create, ctypes.byref(desc), ctypes.byref(handle)), "ent_skin_create")
        self._serial = threading.Lock()
        self._own(handle, lib.ent_skin_destroy)
        self._scene = scene
        self.method = desc.method
        if not scene._adopt(self):  # the scene was closed on another thread meanwhile
            self.close()
            raise ValueError("operation on a closed enteron.Scene")

    # ---- lifetime -----------------------------------------------------------------------
    def close(self):
        """Destroys the skin (ent_skin_destroy); meshes already taken stay valid (copies).
        Idempotent; later calls of other methods raise ValueError. Any thread: an update
        running on another thread finishes first, and the skin goes as it returns."""
        super().close()

    def _using(self):
        # One call at a time per skin, whatever the threads: the C library refuses a second
        # one as busy; here the second waits for the first (and mesh() copies under it).
        return _Serialised(self._serial, super()._using())

    # ---- the mesh -------------------------------------------------------------------------
    def update(self):
        """Rebuilds the mesh from the scene's last published state (ent_skin_update).
        The arrays of earlier mesh() calls keep the mesh they copied."""
        check(self._call(lib.ent_skin_update), "ent_skin_update")

    def mesh(self):
        """The current mesh (ent_skin_mesh) as a Mesh of numpy arrays copied out of the
        library's buffers, which the next update() may reuse and close() frees."""
        raw = s.ent_mesh_view()
        raw.struct_size = ctypes.sizeof(raw)
        with self._using() as handle:  # the copies too: the view is the skin's memory
            check(lib.ent_skin_mesh(handle, ctypes.byref(raw)), "ent_skin_mesh")
            v, t = raw.vertex_count, raw.triangle_count
            return Mesh(positions=_buffers.copy(raw.positions_xyz_m, (v, 3), ctypes.c_float),
                        normals=_buffers.copy(raw.normals_xyz, (v, 3), ctypes.c_float),
                        u=_buffers.copy(raw.axis_u, (v,), ctypes.c_float),
                        indices=_buffers.copy(raw.indices, (t, 3), ctypes.c_uint32),
                        time_s=raw.time_s, updates=raw.updates,
                        v=_buffers.copy(raw.around_v, (v,), ctypes.c_float),
                        tangents=_buffers.copy(raw.tangents_xyz, (v, 3), ctypes.c_float),
                        topology_serial=raw.topology_serial, topology_changed=bool(raw.topology_changed),
                        stable_topology=bool(raw.stable_topology))

    def metrics(self):
        """ent_skin_metrics as a SkinMetrics (costs more than an update: not every frame)."""
        raw = s.ent_skin_metrics()
        raw.struct_size = ctypes.sizeof(raw)
        check(self._call(lib.ent_skin_metrics, ctypes.byref(raw)), "ent_skin_metrics")
        values = {field: getattr(raw, field) for field in SkinMetrics.__dataclass_fields__}
        values["watertight"] = bool(values["watertight"])
        values["has_previous_update"] = bool(values["has_previous_update"])
        return SkinMetrics(**values)
