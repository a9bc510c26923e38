#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Tools in Python: a surgical tool pushes a bowel lying on the floor aside, and the force
the bowel exerts on it is read back after every step, as a haptic device would render it.

    PYTHONPATH=bindings/python python3 examples/python/tools.py
"""
import numpy as np

import enteron

R = 0.0125  # intestine radius, m
SCENE = {
    # A 0.4 m bowel along x, centred on the origin, lying on the floor z = 0.
    "intestine": {"length": 0.4, "control_points": 17, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                  "shape": {"kind": "line", "center": [-0.2, 0, R]}},
    "gravity": [0, 0, -9.81],
    "damping": {},
    "environment": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}],
}
MAX_FORCE = 5.0  # N

with enteron.Scene(SCENE) as scene:
    # A vertical tool (the identity orientation: shaft up, tip down) beside the bowel.
    tool = scene.add_tool(radius=0.005, max_force=MAX_FORCE, position=(0.0, 0.05, R))
    start_y = scene.axis(101)[50, 1]
    largest = 0.0
    for i in range(1, 801):  # 8 cm along -y at 0.1 m/s, in 1 ms steps
        tool.set_pose((0.0, 0.05 - 1e-4 * i, R))  # where the tip is at the end of the step
        scene.step(0.001)
        force, torque = tool.wrench()  # on the tool: N, and N m about the tip
        largest = max(largest, np.linalg.norm(force))
        if i % 200 == 0:
            print("tools.py: t = %.1f s, tip at y = %+.3f m, F = (%+.3f, %+.3f, %+.3f) N"
                  % (scene.stats().time_s, 0.05 - 1e-4 * i, *np.where(abs(force) < 5e-4, 0.0, force)))
    moved = start_y - scene.axis(101)[50, 1]
    print("tools.py: pushed the bowel %.1f cm aside, largest |F| %.3f N (max_force %.1f N)"
          % (100 * moved, largest, MAX_FORCE))
    if not (moved > 0.01 and 0.0 < largest <= MAX_FORCE * (1 + 1e-12)):
        raise SystemExit("tools.py: the push did not behave as expected")
