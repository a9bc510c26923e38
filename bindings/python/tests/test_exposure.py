# SPDX-License-Identifier: Apache-2.0
"""The exposure query through the binding: a straight tube of radius R at height h above a
plane seen from an eye at height H above its axis hides the band |y| < w of the plane,
w = R H / sqrt((H - h)^2 - R^2): each point of a grid is seen exactly where the band says,
a disk on the band's edge is half seen, and bad input raises enteron.Error naming it."""
import math
import threading
import unittest

import numpy as np

import enteron

R, H, h = 0.0125, 0.30, 0.05


def straight_tube():
    return enteron.Scene({"intestine": {"length": 2.0, "control_points": 81, "radius": R,
                                        "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                                        "shape": {"kind": "line", "center": [-1.0, 0, h]}}})


class ExposureTest(unittest.TestCase):
    def test_each_point_is_seen_exactly_outside_the_band(self):
        with straight_tube() as scene:
            xs, ys = np.meshgrid(np.linspace(-0.04, 0.04, 9), np.linspace(-0.04, 0.04, 81) + 0.00037)
            points = np.stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)], axis=1)
            exposure = enteron.Exposure(scene, points)
            result = exposure.measure((0.0, 0.0, H))
            hidden = np.abs(points[:, 1]) * (H - h) / np.sqrt(points[:, 1] ** 2 + H ** 2) < R
            np.testing.assert_array_equal(result.element_visible, np.where(hidden, 0.0, 1.0))
            self.assertAlmostEqual(result.visible_fraction, 1.0 - hidden.mean(), places=12)
            self.assertEqual(result.hidden_samples, hidden.sum())
            self.assertEqual(result.span_count, 1)
            self.assertEqual(result.span_intestines.tolist(), [0])
            self.assertLess(result.spans[0, 0], 0.5)
            self.assertGreater(result.spans[0, 1], 0.5)
            exposure.close()
            exposure.close()  # idempotent
            with self.assertRaises(ValueError):
                exposure.measure((0.0, 0.0, H))

    def test_a_disk_on_the_bands_edge_is_half_seen(self):
        with straight_tube() as scene:
            w = R * H / math.sqrt((H - h) ** 2 - R ** 2)
            angles = 2 * math.pi * (np.arange(64) + 0.5) / 64
            rim = np.stack([0.01 * np.cos(angles), w + 0.01 * np.sin(angles), np.zeros(64)], axis=1)
            points = np.vstack([[0.0, w, 0.0], rim])
            triangles = [(0, 1 + k, 1 + (k + 1) % 64) for k in range(64)]
            with enteron.Exposure(scene, points, triangles, samples_per_edge=16) as disk:
                result = disk.measure((0.0, 0.0, H))
            self.assertAlmostEqual(result.visible_fraction, 0.5, delta=0.005)
            self.assertEqual(result.samples, 64 * 16 * 16)
            self.assertEqual(len(result.element_visible), 64)

    def test_bad_input_raises_naming_it(self):
        with straight_tube() as scene:
            with self.assertRaises(enteron.Error) as caught:
                enteron.Exposure(scene, [[0.0, float("nan"), 0.0]])
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            self.assertIn("points_xyz_m[0]", caught.exception.message)
            with self.assertRaises(enteron.Error) as caught:
                enteron.Exposure(scene, [[0.0, 0.0, 0.0]], obstacle=3)
            self.assertEqual(caught.exception.status, enteron.ERROR_NOT_FOUND)
            with self.assertRaises(ValueError):
                enteron.Exposure(scene, [[0.0, 0.0, 0.0]], weights=[1.0, 2.0])
            with enteron.Exposure(scene, [[0.0, 0.0, 0.0]]) as point:
                with self.assertRaises(enteron.Error) as caught:
                    point.measure((0.0, float("inf"), H))
                self.assertIn("viewpoint_m[1]", caught.exception.message)

    def test_measuring_from_another_thread_while_the_scene_steps(self):
        scene = enteron.Scene({"intestine": {"length": 1.0, "control_points": 40, "stretch_stiffness": 100,
                                             "bend_stiffness": 2.5e-3,
                                             "shape": {"kind": "line", "center": [-0.5, 0, h]}},
                               "gravity": [0, 0, -9.81]})
        exposure = enteron.Exposure(scene, [[0.0, 0.0, 0.0], [0.0, 0.1, 0.0]])
        fractions, errors = [], []
        done = threading.Event()

        def reader():
            while not done.is_set():
                try:
                    fractions.append(exposure.measure((0.0, 0.0, H)).visible_fraction)
                except Exception as error:  # noqa: BLE001 - reported below
                    errors.append(error)

        thread = threading.Thread(target=reader)
        thread.start()
        for _ in range(200):
            scene.step(0.001)
        done.set()
        thread.join()
        self.assertEqual(errors, [])
        self.assertTrue(fractions)
        self.assertTrue(all(0.0 <= f <= 1.0 for f in fractions))
        exposure.close()
        scene.close()


if __name__ == "__main__":
    unittest.main()
