"""Contacts and save/restore through the binding: the contact array against the penalty law
the test works out itself, a tool's contacts against its wrench, and a restored scene that
continues bit for bit, a damaged state refused with the scene unchanged."""
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
