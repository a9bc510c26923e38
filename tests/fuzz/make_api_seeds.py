#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed corpus of fuzz_api_sequence (tests/fuzz/corpus/api_sequence/).

The target reads its input front to back: one byte picks the base scene (0-3, or 4 for an
ent_scene_desc of arbitrary numbers), then each operation is one code byte followed by its
arguments. A number is one byte: below 128 it scales the typical value by 0.25 + b / 64
(b = 48 gives exactly 1x). Run from the repository root: python3 tests/fuzz/make_api_seeds.py
"""
import os

ONE = 48  # a number byte meaning "exactly the typical value"
STEP, OBSTACLE, SKIN, UPDATE, DESTROY, QUERY, TOOL, ANATOMY = (0 << 1), (3 << 1), (4 << 1), (5 << 1), (6 << 1), \
    (7 << 1), (8 << 1), (9 << 1)
# anatomy calls (| 0x10 * (k + 1): obstacle k; 0x00: no obstacle)
SET_POSE, SET_VELOCITY, SET_FRICTION, REMOVE, GRAVITY, PIN, UNPIN, ATTACH, POSE_QUERY, MESH_QUERY = range(10)
POSE, GRASP, RELEASE, WRENCH, STATE, ADD_TOOL = 0x00, 0x01, 0x02, 0x03, 0x04, 0x05  # tool 0 (| 0x08: tool 1)


def steps(n):
    return bytes([STEP, ONE] * n)


def skin(method):
    # method, "modest segments" flag, segments, ring spacing, cap rings, skeleton, voxel, window, no size change
    return bytes([SKIN, method, 0, 13, ONE, 4, ONE, ONE, ONE, 0])


def desc_scene():
    # effects (u32), then the numbers and small integers of create_from_desc, all typical
    return bytes([4, 0xff, 0, 0, 0]) + bytes([ONE] * 2) + bytes([20]) + bytes([ONE] * 3) + bytes([2]) + \
        bytes([ONE] * 2) + bytes([ONE] * 3 * 24) + bytes([2, ONE, 100, 4, ONE, ONE, ONE, 8, ONE, 3]) + \
        bytes([ONE] * 4)


SEEDS = {
    "line_steps": bytes([0]) + steps(20),
    "box_pile_skin": bytes([1]) + steps(30) + skin(2) + bytes([UPDATE]) + bytes([QUERY, 4]) + steps(5) + bytes([UPDATE]),
    "helix_obstacles": bytes([2]) + bytes([OBSTACLE, 2] + [ONE] * 16 + [0, ONE, 0]) + steps(10) +
                       bytes([QUERY, 0, 20]),
    "degenerate_skins": bytes([3]) + skin(0) + skin(1) + bytes([UPDATE, UPDATE | 1]) + steps(10) +
                        bytes([UPDATE, DESTROY, QUERY, 2, 0]),
    "bad_dt": bytes([1, STEP, 128 + 11, STEP, 128 + 12, STEP, 128 + 8, STEP, 128 + 0, STEP, ONE]),
    "desc_scene": desc_scene() + steps(10) + skin(0) + bytes([UPDATE]),
    # the box pile's tool 0 grasps, is pulled up (a pose 2.2 x 5 cm above), stepped, released
    "tool_grasp_pull": bytes([1]) + steps(20) + bytes([TOOL, GRASP]) + steps(5) +
                       bytes([TOOL, POSE, ONE, ONE, 127, 0]) + steps(20) + bytes([TOOL, WRENCH, TOOL, STATE]) +
                       bytes([TOOL, RELEASE]) + steps(5),
    # a tool added to the line, then put through it within one step
    "tool_teleport": bytes([0, TOOL, ADD_TOOL] + [ONE] * 9 + [0, 0]) + steps(3) +
                     bytes([TOOL, POSE | 0x08, 16, ONE, 40, 0]) + steps(5),
    # the helix on its mesentery: a tetrahedron mesh (4 vertices, 4 triangles) under it, moved up
    # through it, the mesentery and a pin on it, gravity tilted, the mesh read back, removed
    "moving_mesh": bytes([2, OBSTACLE, 4] + [ONE] * 13 + [4, 0, 0, 0, 127, 0, 0, 0, 127, 0, 0, 0, 127] +
                         [4, 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3] +
                         [ONE, 0, 0] + [ONE] * 3 + [0, ONE, 0]) + steps(3) +
                   bytes([ANATOMY, ATTACH | 0x10, ANATOMY, PIN | 0x10, 3]) +
                   b"".join(bytes([ANATOMY, SET_POSE | 0x10, ONE, ONE, 60 + i, 0, STEP, ONE]) for i in range(10)) +
                   bytes([ANATOMY, GRAVITY, 80, ONE, ONE, ANATOMY, MESH_QUERY | 0x10, ANATOMY, POSE_QUERY | 0x10,
                          ANATOMY, SET_FRICTION | 0x10, ONE, ANATOMY, UNPIN, 3]) + steps(3) +
                   bytes([ANATOMY, REMOVE | 0x10]) + steps(3),
    # a mesh whose indices run past its vertices, and one claiming a billion triangles
    "bad_meshes": bytes([0, OBSTACLE, 4] + [ONE] * 13 + [3] + [ONE] * 9 + [1, 0, 1, 9] + [ONE, 0, 0] + [ONE] * 3 +
                        [0, ONE, 0]) +
                  bytes([OBSTACLE, 4] + [ONE] * 13 + [3] + [ONE] * 9 + [1, 0, 1, 2] + [ONE, 255, 0, 0x0a, 0x3b, 0] +
                        [0] + [ONE] * 3 + [0, ONE, 0]) + steps(3),
}

if __name__ == "__main__":
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "api_sequence")
    os.makedirs(here, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(here, name), "wb") as f:
            f.write(data)
