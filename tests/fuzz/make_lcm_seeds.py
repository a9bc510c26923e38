#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed corpus of fuzz_lcm_command (tests/fuzz/corpus/lcm_command/).

The target reads its input front to back: a settings byte (bit 0: millimetres, 1: a turned
workspace, 2: a force scale, 3: a device limit, 4: a change limit per tick, 5: a ramp time,
6: a watchdog time; each set bit but bit 0 takes one more byte), then operations, each a
code byte (% 4): 0 raw bytes (a length byte, the bytes), 1 a well-formed command, 2 a
time step (a byte: 0.25 ms each) and a tick, 3 a tick 1 ms later. A command's fields: a seq
step byte (% 4 - 1), a tool byte (4 picks tool 1, which does not exist), then numbers for
the position (3), orientation (4) and velocity (3): a kind byte (0 NaN, 1 inf, 2 -1e300,
3 -0, 4 the smallest subnormal, else a little-endian int16 follows, times the unit), then
grasp (% 3), force_enable (% 3 == 0: off) and buttons bytes.
Run from the repository root: python3 tests/fuzz/make_lcm_seeds.py
"""
import os
import struct

RAW, COMMAND, WAIT, TICK = 0, 1, 2, 3


def number(value, unit):
    return bytes([8]) + struct.pack("<h", int(round(value / unit)))


def command(x, y, z, grasp=0, force=1, seq_step=2, tool=0, millimetres=False, w=1.0):
    unit = 0.1 if millimetres else 1e-4
    scale = 1000.0 if millimetres else 1.0
    body = bytes([COMMAND, seq_step, tool])
    body += b"".join(number(v * scale, unit) for v in (x, y, z))
    body += b"".join(number(v, 1.0 / 8192) for v in (w, 0.0, 0.0, 0.0))
    body += b"".join(number(0.0, 1e-3) for _ in range(3))
    return body + bytes([grasp, 1 if force else 0, 0])


def ticks(n):
    return bytes([TICK] * n)


def press(millimetres=False):
    return b"".join(command(-0.1, 0.0, 0.012, millimetres=millimetres) + ticks(2) for _ in range(60))


def grasp_and_lift():
    path = command(0.0, -0.02, 0.0125) + ticks(40)
    path += command(0.0, -0.02, 0.0125, grasp=1) + ticks(5)
    for i in range(40):
        path += command(0.0, -0.02, 0.0125 + 0.0015 * i, grasp=1) + ticks(1)
    return path + command(0.0, -0.02, 0.07, grasp=0) + ticks(10)


def watchdog():
    return press()[:400] + bytes([WAIT, 200]) + command(-0.07, 0.0, 0.012) + ticks(30)


def hostile():
    nan = bytes([COMMAND, 2, 0, 0]) + bytes(40)
    return (bytes([RAW, 12]) + bytes(range(12)) + nan + command(0, 0, 0.05, tool=4) + command(0, 0, 0.05, w=0.0)
            + command(0, 0, 0.05, seq_step=0) + command(0, 0, 0.05, grasp=2) + ticks(3) + command(0, 0, 0.05)
            + bytes([WAIT, 255]) + ticks(3))


SEEDS = {
    "press": bytes([0]) + press(),
    "press_mm_turned_limited": bytes([1 | 2 | 4 | 8 | 16, 1, 2, 40, 24, 20]) + press(millimetres=True),
    "grasp_and_lift": bytes([0]) + grasp_and_lift(),
    "watchdog_and_ramp": bytes([32 | 64, 51, 120]) + watchdog(),
    "hostile": bytes([0]) + hostile(),
}

if __name__ == "__main__":
    directory = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "lcm_command")
    os.makedirs(directory, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(directory, name), "wb") as seed:
            seed.write(data)
    print("wrote %d seeds to %s" % (len(SEEDS), directory))
