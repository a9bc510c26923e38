# SPDX-License-Identifier: Apache-2.0
"""Exposure: how much of a target the bowel hides from a viewpoint (ent_scene_exposure).

    gallbladder = enteron.Exposure(scene, points, triangles)   # prepared once: it allocates
    seen = gallbladder.measure(scope_tip)                       # any thread, allocates nothing in C
    print(seen.visible_fraction, seen.spans)                    # spans (k, 2): u ranges that hide the rest

The target is a set of points, or a patch of triangles sampled at samples_per_edge^2
points each, in the world or in an obstacle's frame (obstacle=index: it moves with it).
Only the bowel hides (a tube of its radius around the published axis); docs/scoring-and-state.md.
"""
import ctypes
import dataclasses
import threading

import numpy as np

from . import _fields
from . import _structs as s
from ._errors import check
from ._handle import OwnedHandle
from ._library import lib


@dataclasses.dataclass(frozen=True)
class ExposureResult:
    """ent_exposure_result: visible_fraction (the target's weight seen over its total),
    spans (k, 2) [first u, last u] of each span of the bowel that hides part of the target,
    span_hidden_fractions (k,) the fraction of the target each hides, span_intestines (k,)
    their tubes, element_visible (E,) the fraction seen of each point or triangle;
    span_count may exceed k (= the span_capacity asked for)."""
    visible_fraction: float
    spans: np.ndarray
    span_hidden_fractions: np.ndarray
    span_intestines: np.ndarray
    element_visible: np.ndarray
    span_count: int
    samples: int
    hidden_samples: int
    time_s: float
    steps: int


class Exposure(OwnedHandle):
    """A target prepared for ent_scene_exposure on one scene (ent_exposure).

    Exposure(scene, points, triangles=None, weights=None, samples_per_edge=4,
             obstacle=enteron.NO_OBSTACLE, axis_chords_per_segment=4)
    points: (N, 3) m; triangles: (T, 3) indices into points, or None (the points are the
    target); weights: one per point (or per triangle: it multiplies the area), or None.
    Failures raise enteron.Error. Any thread, also while the scene steps; measures of one
    Exposure from several threads take turns (the C library would refuse the second as
    busy); close() from any thread: a measure running elsewhere finishes first.
    """

    def __init__(self, scene, points, triangles=None, weights=None, samples_per_edge=4, obstacle=-1,
                 axis_chords_per_segment=4):
        self._handle = None
        self._points = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3)
        self._triangles = None if triangles is None else np.ascontiguousarray(triangles, dtype=np.uint32).reshape(-1, 3)
        self._weights = None if weights is None else np.ascontiguousarray(weights, dtype=np.float64).reshape(-1)
        self.elements = len(self._points) if self._triangles is None else len(self._triangles)
        if self._weights is not None and len(self._weights) != self.elements:
            raise ValueError("weights: %d given for %d %s" % (len(self._weights), self.elements,
                                                               "points" if self._triangles is None else "triangles"))
        desc = s.ent_exposure_desc()
        check(lib.ent_exposure_desc_init(ctypes.byref(desc), ctypes.sizeof(desc)), "ent_exposure_desc_init")
        desc.points_xyz_m = self._points.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        desc.point_count = len(self._points)
        if self._triangles is not None:
            desc.triangles = self._triangles.ctypes.data_as(ctypes.POINTER(ctypes.c_uint32))
            desc.triangle_count = len(self._triangles)
        if self._weights is not None:
            desc.weights = self._weights.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        _fields.set_field(desc, "samples_per_edge", samples_per_edge)
        _fields.set_field(desc, "obstacle", obstacle)
        _fields.set_field(desc, "axis_chords_per_segment", axis_chords_per_segment)
        handle = ctypes.c_void_p()
        check(scene._call(lib.ent_exposure_create, ctypes.byref(desc), ctypes.byref(handle)), "ent_exposure_create")
        self._serial = threading.Lock()  # measures from several threads take turns
        self._own(handle, lib.ent_exposure_destroy)
        self._scene = scene

    def measure(self, viewpoint, span_capacity=16):
        """ent_scene_exposure from `viewpoint` (3,) m, on the scene's last published state:
        an ExposureResult with up to span_capacity spans."""
        eye = np.ascontiguousarray(viewpoint, dtype=np.float64).reshape(3)
        span_capacity = _fields.checked_integer(ctypes.c_uint32, span_capacity, "span_capacity")
        spans = np.zeros((span_capacity, 2))
        fractions = np.zeros(span_capacity)
        tubes = np.zeros(span_capacity, dtype=np.int32)
        elements = np.zeros(self.elements)
        raw = s.ent_exposure_result()
        raw.struct_size = ctypes.sizeof(raw)
        raw.span_capacity = span_capacity
        raw.spans_u = spans.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        raw.span_hidden_fractions = fractions.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        raw.span_intestines = tubes.ctypes.data_as(ctypes.POINTER(ctypes.c_int32))
        raw.element_visible = elements.ctypes.data_as(ctypes.POINTER(ctypes.c_double))
        with self._serial, self._using() as handle:
            check(self._scene._call(lib.ent_scene_exposure, handle, eye.ctypes.data_as(ctypes.POINTER(ctypes.c_double)),
                                    ctypes.byref(raw)), "ent_scene_exposure")
        k = min(raw.span_count, span_capacity)
        for array in (spans, fractions, tubes, elements):
            array.flags.writeable = False
        return ExposureResult(visible_fraction=raw.visible_fraction, spans=spans[:k], span_hidden_fractions=fractions[:k],
                              span_intestines=tubes[:k], element_visible=elements, span_count=raw.span_count,
                              samples=raw.samples, hidden_samples=raw.hidden_samples, time_s=raw.time_s,
                              steps=raw.steps)
