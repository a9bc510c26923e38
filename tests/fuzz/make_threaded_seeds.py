#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed corpus of fuzz_threaded_api (tests/fuzz/corpus/threaded_api/).

The driving thread reads the input front to back: one byte picks the base scene (0-2) and,
divided by 3, the render thread's skin method; then each operation is a code byte (modulo 6:
0 a step of a given dt, 1 or 2 a step of 1 ms, 3 an obstacle, 4 a tool, 5 a tool command)
followed by its arguments. A number is one byte: below 128 it scales the typical value by
0.25 + b / 64 (b = 48 gives exactly 1x). Adding an obstacle or a tool logs, and so makes the
second driver call during the driving call. Run from the repository root:
python3 tests/fuzz/make_threaded_seeds.py
"""
import os

ONE = 48
STEP_DT, STEP, OBSTACLE, TOOL, COMMAND = 0, 1, 3, 4, 5


def steps(n):
    return bytes([STEP] * n)


def obstacle(kind, center=ONE, half=ONE, normal=ONE, radius=ONE):
    return bytes([OBSTACLE, kind] + [center, half, normal] * 3 + [radius])


def tool(radius=ONE, force=ONE, position=ONE):
    return bytes([TOOL, radius, force, position, position, position])


def command(tool_id, grasp):
    return bytes([COMMAND, tool_id, ONE, ONE, ONE, 0 if grasp else 1])


SEEDS = {
    "pile_steps": bytes([0]) + steps(30),
    "pile_tools_and_walls": bytes([3]) + steps(5) + tool() + steps(5) + obstacle(1) + steps(10) + command(2, True) +
                            steps(10),
    "line_rk4_grasp": bytes([1]) + steps(3) + command(0, True) + steps(10) + command(0, False) + steps(10),
    "helix_odd_steps": bytes([2 + 3 * 2]) + bytes([STEP_DT, 128 + 4, STEP_DT, 128 + 0, STEP_DT, 100]) + steps(10) +
                       tool(position=ONE) + steps(10) + obstacle(2, half=ONE, radius=20),
    "busy_everywhere": bytes([4]) + (obstacle(1, center=ONE) + tool() + steps(3)) * 4,
}


def main():
    directory = os.path.join("tests", "fuzz", "corpus", "threaded_api")
    os.makedirs(directory, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(directory, name), "wb") as file:
            file.write(data)


if __name__ == "__main__":
    main()
