#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The minimal example in Python: create a scene from a dict, step one simulated second,
read the axis and the stats, print one line.

    PYTHONPATH=bindings/python python3 examples/python/minimal.py
"""
import enteron

SCENE = {
    "intestine": {"length": 1.0, "control_points": 40, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3},
    "gravity": [0, 0, -9.81],
    "damping": {},
    "mesentery": {},
}

with enteron.Scene(SCENE) as scene:
    for _ in range(1000):  # one simulated second in 1 ms steps
        scene.step(0.001)
    axis = scene.axis(100)  # (100, 3) numpy array, m
    stats = scene.stats()
    print("minimal.py: libenteron %d.%d.%d, t = %.3f s, %d axis points, first end at (%.4f, %.4f, %.4f) m, "
          "lowest point z = %.4f m, kinetic energy %.3g J"
          % (*enteron.version, stats.time_s, len(axis), *axis[0], axis[:, 2].min(), stats.kinetic_energy_J))
