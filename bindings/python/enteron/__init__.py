# SPDX-License-Identifier: Apache-2.0
"""Enteron: a real-time model of the human small intestine, from Python.

A ctypes binding of the C API of libenteron (no compile step). Quick start:

    import enteron
    with enteron.Scene({"intestine": {"length": 1.0, "control_points": 40,
                                      "stretch_stiffness": 100, "bend_stiffness": 2.5e-3},
                        "gravity": [0, 0, -9.81]}) as scene:
        for _ in range(1000):
            scene.step(0.001)
        axis = scene.axis(100)          # (100, 3) numpy array, m
        tool = scene.add_tool(radius=0.005, max_force=5.0, position=(0.0, 0.1, 0.0))
        tool.set_pose((0.0, 0.0, 0.0))  # reached at the end of the next step; from any thread
        scene.step(0.001)
        force, torque = tool.wrench()   # what the bowel exerts on the tool, N and N m
        touched = scene.contacts()      # numpy structured array: kind, index, u, point_m, force_N, ...
        state = scene.save_state()      # bytes; scene.restore_state(state) goes back to this instant
        with enteron.Skin(scene, "convolution", segments=24) as skin:
            skin.update()
            mesh = skin.mesh()          # numpy arrays of the mesh (copies: they stay valid)
            print(mesh.triangle_count, skin.metrics().radius_error_rms)

Failures raise enteron.Error (status, status_name, message from ent_last_error). The
library is found through ENTERON_LIBRARY, next to the installed package, in the source
checkout's build tree, or on the system; see _library.py.
"""
from ._library import SUPPORTED_MAJOR
from ._library import path as _path
from ._library import version as _version
from ._errors import (ERROR_BUFFER_TOO_SMALL, ERROR_BUSY, ERROR_INTERNAL, ERROR_INVALID_ARGUMENT,
                      ERROR_INVALID_SCENE, ERROR_NOT_FOUND, ERROR_OUT_OF_MEMORY, ERROR_PARSE, ERROR_UNSTABLE,
                      ERROR_VERSION, OK, Error, status_string)
from .scene import (CONTACT_DTYPE, CONTACT_OBSTACLE, CONTACT_SELF, CONTACT_TOOL, ContactSummary, EFFECT_BEND, EFFECT_COUNT, EFFECT_DAMPING, EFFECT_ENVIRONMENT, EFFECT_GRAVITY,
                    EFFECT_MESENTERY, EFFECT_PINNED, EFFECT_SELF_COLLISION, EFFECT_STRETCH, EFFECT_TOOLS,
                    INTEGRATOR_BDF2, INTEGRATOR_IMPLICIT_EULER, INTEGRATOR_RK4, INTEGRATOR_SYMPLECTIC_EULER, LOG_DEBUG,
                    LOG_ERROR, LOG_INFO, LOG_WARNING, NO_OBSTACLE, OBSTACLE_BOX_INSIDE, OBSTACLE_CAPSULE, OBSTACLE_MESH,
                    OBSTACLE_PLANE, OBSTACLE_SPHERE,
                    PIN_BOTH, PIN_FIRST, PIN_LAST, PIN_NONE, SHAPE_HELIX, SHAPE_LINE, SHAPE_POINTS, SHAPE_SERPENTINE,
                    EffectStats, Scene, SceneDesc, Stats, effect_name)
from .exposure import Exposure, ExposureResult
from .skin import SKIN_CONVOLUTION, SKIN_POINT_SKELETON, SKIN_TUBE, Mesh, Skin, SkinMetrics
from .tool import TOOL_MODE_DIRECT, TOOL_MODE_PROXY, Tool, ToolContacts, ToolFeedback, ToolStats, Wrench

#: The loaded library's version, (major, minor, patch).
version = (_version >> 16, (_version >> 8) & 0xFF, _version & 0xFF)
#: The path the library was loaded from.
library_path = _path

__all__ = [name for name in dir() if not name.startswith("_")]
