# SPDX-License-Identifier: Apache-2.0
"""Contacts and save/restore through the binding: the contact array against the penalty law
the test works out itself, a tool's contacts against its wrench, and a restored scene that
continues bit for bit; a damaged, forged, cut or foreign state refused with the library's
message and the scene unchanged (its saved state the same bytes)."""
import math
import struct
import unittest

import numpy as np

import enteron

R = 0.0125        # the default intestine radius, m
K = 500.0         # the default contact stiffness, N/m
H = 1e-3          # s


def pressed_into_floor(depth):
    """A straight bowel at rest whose axis lies R - depth above the floor z = 0, no gravity."""
    return enteron.Scene({
        "intestine": {"length": 0.3, "control_points": 13, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                      "shape": {"kind": "line", "center": [-0.15, 0, R - depth]}},
        "environment": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}]})


def pushed_by_a_tool():
    scene = enteron.Scene({
        "intestine": {"length": 0.4, "control_points": 17, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                      "shape": {"kind": "line", "center": [-0.2, 0, R]}},
        "gravity": [0, 0, -9.81], "damping": {},
        "environment": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}]})
    tool = scene.add_tool(position=(0.0, 0.05, R))
    return scene, tool


# The saved state's layout (docs/scoring-and-state.md, "The image"): a 48-byte header with
# the format version at byte 8, the total size at 16 and the body's checksum at 32; the first
# section (`scene`) after its 32-byte header holds the control point count (4 bytes), the
# time, then the positions.
VERSION_AT, SIZE_AT, CHECKSUM_AT, HEADER_SIZE, SECTION_HEADER_SIZE = 8, 16, 32, 48, 32
TIME_AT = HEADER_SIZE + SECTION_HEADER_SIZE + 4
POSITIONS_AT = TIME_AT + 8
MASK = (1 << 64) - 1
FNV_OFFSET, FNV_PRIME = 0xcbf29ce484222325, 0x100000001b3


def body_checksum(body):
    """64-bit FNV-1a over the body's little-endian 64-bit words with a shift, the last bytes one by one."""
    hash_ = FNV_OFFSET
    words = len(body) // 8
    for (word,) in struct.iter_unpack("<Q", body[: 8 * words]):
        hash_ = ((hash_ ^ word) * FNV_PRIME) & MASK
        hash_ ^= hash_ >> 29
    for byte in body[8 * words:]:
        hash_ = ((hash_ ^ byte) * FNV_PRIME) & MASK
    return hash_


def resealed(image):
    """The image with its size and checksum written as the library writes them on saving."""
    image = bytearray(image)
    struct.pack_into("<Q", image, SIZE_AT, len(image))
    struct.pack_into("<Q", image, CHECKSUM_AT, body_checksum(bytes(image[HEADER_SIZE:])))
    return bytes(image)


def patched(image, offset, value):
    """The image with the double at `offset` set to `value`, resealed."""
    image = bytearray(image)
    struct.pack_into("<d", image, offset, value)
    return resealed(image)


def push(scene, tool, first, last):
    for i in range(first, last):
        tool.set_pose((0.0, 0.05 - 1e-4 * i, R))
        scene.step(H)


class Contacts(unittest.TestCase):
    def test_a_bowel_pressed_into_the_floor_feels_k_times_the_depth(self):
        depth = 0.002
        with pressed_into_floor(depth) as scene:
            scene.step(1e-4)  # one evaluation, at rest: the spring alone
            contacts = scene.contacts()
            self.assertEqual(contacts.dtype, enteron.CONTACT_DTYPE)
            spheres = round(0.3 / (0.5 * R)) + 1
            self.assertEqual(len(contacts), spheres)
            self.assertTrue(np.all(contacts["kind"] == enteron.CONTACT_OBSTACLE))
            np.testing.assert_allclose(contacts["u"], np.linspace(0, 1, spheres), atol=1e-12)
            np.testing.assert_allclose(contacts["depth_m"], depth, atol=1e-12)
            np.testing.assert_allclose(contacts["force_N"][:, 2], K * depth, rtol=1e-9)
            np.testing.assert_allclose(contacts["point_m"][:, 2], 0.0, atol=1e-12)
            summary = scene.contact_summary()
            self.assertEqual(summary.obstacle_contacts, spheres)
            self.assertEqual(summary.found, summary.listed)
            self.assertAlmostEqual(summary.largest_force_N, K * depth, delta=1e-9)

    def test_a_tools_contacts_add_up_to_minus_its_wrench(self):
        scene, tool = pushed_by_a_tool()
        with scene:
            touching = 0
            for i in range(1, 500):
                push(scene, tool, i, i + 1)
                force, _ = tool.wrench()
                contacts = scene.contacts()
                mine = contacts[contacts["kind"] == enteron.CONTACT_TOOL]
                np.testing.assert_allclose(mine["force_N"].sum(axis=0), -force, atol=1e-12 * (1 + np.linalg.norm(force)))
                touched = tool.contacts()
                self.assertEqual(touched.contacts, len(mine))
                for u in mine["u"]:
                    self.assertTrue(np.any((touched.ranges[:, 0] <= u) & (u <= touched.ranges[:, 1])))
                touching += len(mine) > 0
            self.assertGreater(touching, 100)
            self.assertGreater(tool.contacts().contact_impulse_magnitude_Ns, 0.0)


class SaveRestore(unittest.TestCase):
    def assert_refused(self, scene, image, status, words):
        """Restoring `image` raises enteron.Error with `status` and the library's message
        holding `words`, and changes nothing: the scene saves the same bytes afterwards."""
        before = scene.save_state()
        with self.assertRaises(enteron.Error) as caught:
            scene.restore_state(image)
        self.assertEqual(caught.exception.status, status, str(caught.exception))
        self.assertEqual(caught.exception.call, "ent_scene_restore_state")
        self.assertIn(words, caught.exception.message)
        self.assertIn(caught.exception.message, str(caught.exception))
        self.assertEqual(before, scene.save_state(), "a refused restore changed the scene")

    def test_the_checksum_written_here_is_the_librarys(self):
        # The forged images below rest on it: a resealed unchanged image is the same bytes.
        scene, tool = pushed_by_a_tool()
        with scene:
            push(scene, tool, 0, 30)
            state = scene.save_state()
            self.assertEqual(resealed(state), state)
            (time_s,) = struct.unpack_from("<d", state, TIME_AT)
            self.assertEqual(time_s, scene.stats().time_s)

    def test_refusals_carry_the_librarys_message_and_change_nothing(self):
        scene, tool = pushed_by_a_tool()
        with scene:
            push(scene, tool, 0, 40)
            good = scene.save_state()
            push(scene, tool, 40, 45)  # so that a wrongly applied restore would show
            self.assert_refused(scene, good[:-1], enteron.ERROR_INVALID_ARGUMENT, "truncated")
            self.assert_refused(scene, good[:20], enteron.ERROR_INVALID_ARGUMENT, "header")
            self.assert_refused(scene, b"X" + good[1:], enteron.ERROR_INVALID_ARGUMENT, "ENTSTATE")
            version_99 = bytearray(good)
            struct.pack_into("<I", version_99, VERSION_AT, 99)
            self.assert_refused(scene, bytes(version_99), enteron.ERROR_VERSION, "format version 99")
            self.assert_refused(scene, patched(good, TIME_AT, math.nan), enteron.ERROR_INVALID_ARGUMENT, "time")
            self.assert_refused(scene, patched(good, POSITIONS_AT + 8 * 5, math.inf),
                                enteron.ERROR_INVALID_ARGUMENT, "positions")
            self.assert_refused(scene, patched(good, POSITIONS_AT, -math.inf),
                                enteron.ERROR_INVALID_ARGUMENT, "positions")
            # Another scene's state: the same kind of scene, a longer bowel.
            with enteron.Scene({
                    "intestine": {"length": 0.5, "control_points": 17, "stretch_stiffness": 100,
                                  "bend_stiffness": 2.5e-3, "shape": {"kind": "line", "center": [-0.2, 0, R]}},
                    "gravity": [0, 0, -9.81], "damping": {},
                    "environment": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]}]}) as longer:
                longer.add_tool(position=(0.0, 0.05, R))
                self.assert_refused(scene, longer.save_state(), enteron.ERROR_INVALID_ARGUMENT, "another scene")
                self.assert_refused(longer, good, enteron.ERROR_INVALID_ARGUMENT, "another scene")
            # After all that the good state restores, and the scene saves it back unchanged.
            scene.restore_state(good)
            self.assertEqual(scene.save_state(), good)

    def test_a_fresh_scene_restored_continues_bit_for_bit(self):
        scene, tool = pushed_by_a_tool()
        with scene:
            push(scene, tool, 0, 200)
            state = scene.save_state()
            push(scene, tool, 200, 320)
            first = (scene.control_points().tobytes(), scene.contacts().tobytes(),
                     [f.tobytes() for f in tool.wrench()])
        fresh, fresh_tool = pushed_by_a_tool()
        with fresh:
            fresh.restore_state(bytearray(state))  # any bytes-like object
            self.assertEqual(fresh.save_state(), state)
            push(fresh, fresh_tool, 200, 320)
            again = (fresh.control_points().tobytes(), fresh.contacts().tobytes(),
                     [f.tobytes() for f in fresh_tool.wrench()])
            self.assertEqual(first, again)

    def test_a_restored_scene_continues_bit_for_bit(self):
        scene, tool = pushed_by_a_tool()
        with scene:
            push(scene, tool, 0, 250)
            state = scene.save_state()
            self.assertIsInstance(state, bytes)
            push(scene, tool, 250, 400)
            first = scene.control_points()
            first_contacts = scene.contacts()
            scene.restore_state(state)
            self.assertEqual(scene.stats().steps, 250)
            push(scene, tool, 250, 400)
            self.assertEqual(first.tobytes(), scene.control_points().tobytes())
            self.assertEqual(first_contacts.tobytes(), scene.contacts().tobytes())

    def test_a_damaged_state_is_refused_and_changes_nothing(self):
        scene, tool = pushed_by_a_tool()
        with scene:
            push(scene, tool, 0, 50)
            state = bytearray(scene.save_state())
            push(scene, tool, 50, 60)
            before = scene.control_points()
            state[len(state) // 2] ^= 0xFF
            with self.assertRaises(enteron.Error) as caught:
                scene.restore_state(state)
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            self.assertIn("checksum", str(caught.exception))
            self.assertEqual(before.tobytes(), scene.control_points().tobytes())
            with self.assertRaises(enteron.Error):
                scene.restore_state(b"ENTSTATE")
        another, _ = pushed_by_a_tool()
        with another:
            good = another.save_state()
        with pressed_into_floor(0.001) as other:
            with self.assertRaises(enteron.Error) as caught:
                other.restore_state(good)
            self.assertIn("another scene", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
