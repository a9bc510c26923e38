#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Skins in Python: step a scene, update a convolution skin, read its mesh as numpy arrays
copied from the library's buffers (they stay valid after the next update) and measure it
against the ideal tube.

    PYTHONPATH=bindings/python python3 examples/python/skin.py
"""
import numpy as np

import enteron

SCENE = {
    "intestine": {"length": 1.0, "control_points": 40, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3},
    "gravity": [0, 0, -9.81],
    "damping": {},
    "mesentery": {},
}

with enteron.Scene(SCENE) as scene, enteron.Skin(scene, "convolution", segments=16) as skin:
    for _ in range(500):  # half a simulated second in 1 ms steps
        scene.step(0.001)
    skin.update()
    mesh = skin.mesh()  # views, valid until the next skin.update(): draw them now, or copy
    assert mesh.triangle_count > 0 and int(mesh.indices.max()) < mesh.vertex_count
    assert np.isfinite(mesh.positions).all()
    metrics = skin.metrics()
    print("skin.py: convolution skin at t = %.3f s: %d triangles, %d vertices, radius error %.3f %% RMS "
          "(%.3f %% max), %s, lowest vertex z = %.4f m"
          % (mesh.time_s, mesh.triangle_count, mesh.vertex_count, 100 * metrics.radius_error_rms,
             100 * metrics.radius_error_max, "watertight" if metrics.watertight else "NOT watertight",
             mesh.positions[:, 2].min()))
    if not metrics.watertight:
        raise SystemExit(1)
