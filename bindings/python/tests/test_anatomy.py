# SPDX-License-Identifier: Apache-2.0
"""Moving anatomy through the binding: a mesh obstacle holds the bowel as the analytic shape
does, an obstacle moved between steps carries a pin with it, gravity and friction change
between steps, obstacles are removed and counted, a scene file finds its mesh next to it,
and bad input raises naming the input and changes nothing."""
import ctypes
import os
import tempfile
import unittest

import numpy as np

import enteron

R = 0.0125  # the default intestine radius, m
H = 1e-3    # s

# A 0.3 m bowel along x from (-0.15, 0, R), resting on whatever is at z = 0.
BOWEL = {
    "intestine": {"length": 0.3, "control_points": 12, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                  "shape": {"kind": "line", "center": [-0.15, 0, R]}},
    "gravity": [0, 0, -9.81],
    "damping": {},
}


def slab(half=0.25, depth=0.05):
    """A closed box mesh, normals out, its top face at z = 0: a floor as a mesh."""
    corners = np.array([[x, y, z] for z in (-depth, 0.0) for y in (-half, half) for x in (-half, half)])
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return corners, np.array(triangles)


def settle(scene, steps=300):
    for _ in range(steps):
        scene.step(H)


class MeshObstacle(unittest.TestCase):
    def test_a_mesh_floor_holds_the_bowel_as_a_plane_does(self):
        vertices, triangles = slab()
        heights = []
        for kind, keys in (("plane", {}), ("mesh", {"vertices": vertices, "triangles": triangles})):
            with enteron.Scene(BOWEL) as scene:
                index = scene.add_obstacle(kind, **keys)
                self.assertEqual(index, 0)
                settle(scene)
                heights.append(scene.control_points()[:, 2])
        self.assertTrue(np.all(heights[1] > R - 0.002), heights[1])
        np.testing.assert_allclose(heights[1], heights[0], atol=2e-4)

    def test_the_mesh_comes_back_as_given(self):
        vertices, triangles = slab()
        with enteron.Scene(BOWEL) as scene:
            index = scene.add_obstacle("mesh", vertices=vertices, triangles=triangles, position=(0, 0, -0.01))
            back_vertices, back_triangles = scene.obstacle_mesh(index)
            np.testing.assert_array_equal(back_vertices, vertices)
            np.testing.assert_array_equal(back_triangles, triangles)
            position, orientation = scene.obstacle_pose(index)
            np.testing.assert_array_equal(position, [0, 0, -0.01])
            np.testing.assert_array_equal(orientation, [1, 0, 0, 0])

    def test_bad_meshes_raise_and_change_nothing(self):
        vertices, triangles = slab()
        with enteron.Scene(BOWEL) as scene:
            bad_index = triangles.copy()
            bad_index[3, 1] = 99
            with self.assertRaises(enteron.Error) as caught:
                scene.add_obstacle("mesh", vertices=vertices, triangles=bad_index)
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            self.assertIn("triangles[3]", caught.exception.message)
            nan = vertices.astype(float)
            nan[5, 2] = np.nan
            with self.assertRaises(enteron.Error) as caught:
                scene.add_obstacle("mesh", vertices=nan, triangles=triangles)
            self.assertIn("vertices[5]", caught.exception.message)
            with self.assertRaises(ValueError):
                scene.add_obstacle("mesh", vertices=vertices[:, :2], triangles=triangles)
            with self.assertRaises(TypeError):
                scene.add_obstacle("mesh", vertices=vertices)
            self.assertEqual(scene.obstacle_count, 0)
            self.assertFalse(scene.effect_stats("environment").enabled)

    def test_a_scene_file_finds_its_mesh_next_to_it(self):
        vertices, triangles = slab()
        with tempfile.TemporaryDirectory() as directory:
            os.mkdir(os.path.join(directory, "organs"))
            with open(os.path.join(directory, "organs", "slab.obj"), "w") as obj:
                obj.writelines("v %r %r %r\n" % tuple(v) for v in vertices)
                obj.writelines("f %d %d %d\n" % tuple(t + 1) for t in triangles)
            with open(os.path.join(directory, "scene.json"), "w") as scene_file:
                scene_file.write(
                    '{"intestine": {"length": 0.3, "control_points": 12, "shape": {"kind": "line",'
                    ' "center": [-0.15, 0, 0.0125]}}, "gravity": [0, 0, -9.81],'
                    ' "environment": [{"type": "mesh", "file": "organs/slab.obj"}]}')
            with enteron.Scene(file=os.path.join(directory, "scene.json")) as scene:
                self.assertEqual(scene.obstacle_count, 1)
                settle(scene, 200)
                self.assertTrue(np.all(scene.control_points()[:, 2] > R - 0.002))
            with self.assertRaises(enteron.Error) as caught:
                enteron.Scene(file=os.path.join(directory, "missing.json"))
            self.assertIn("missing.json", caught.exception.message)


class MovingAnatomy(unittest.TestCase):
    def test_a_pin_on_a_lifted_organ_follows_it_and_lets_go(self):
        with enteron.Scene(BOWEL) as scene:
            organ = scene.add_obstacle("sphere", center=(-0.2, 0, 0.05), radius=0.03)
            scene.pin_point(0, organ)
            start = scene.control_points()[0].copy()
            for i in range(1, 301):
                scene.set_obstacle_pose(organ, (0, 0, 0.1 * i / 300))
                scene.step(H)
            end = scene.control_points()[0]
            np.testing.assert_allclose(end, start + [0, 0, 0.1], atol=1e-6)
            position, _ = scene.obstacle_pose(organ)
            np.testing.assert_allclose(position, [0, 0, 0.1])
            scene.unpin_point(0)
            with self.assertRaises(enteron.Error) as caught:
                scene.unpin_point(0)
            self.assertEqual(caught.exception.status, enteron.ERROR_NOT_FOUND)
            settle(scene, 200)
            self.assertLess(scene.control_points()[0, 2], end[2] - 0.05)

    def test_a_clamped_end_on_a_lifted_organ_keeps_its_place_and_direction(self):
        with enteron.Scene(dict(BOWEL, pinned={"clamped": "first"})) as scene:
            organ = scene.add_obstacle("sphere", center=(-0.2, 0, 0.05), radius=0.03)
            with self.assertRaises(enteron.Error) as caught:
                scene.attach_clamped_end(enteron.PIN_LAST, organ)
            self.assertEqual(caught.exception.status, enteron.ERROR_NOT_FOUND)
            scene.attach_clamped_end(enteron.PIN_FIRST, organ)
            start = scene.axis(30001)[:2].copy()
            for i in range(1, 301):
                scene.set_obstacle_pose(organ, (0, 0, 0.1 * i / 300))
                scene.step(H)
            # The clamp carries the end point and the end's direction (the axis' first chord,
            # 0.01 mm long, is the tangent within the bend's curvature times its length).
            end = scene.axis(30001)[:2]
            np.testing.assert_allclose(end[0], start[0] + [0, 0, 0.1], atol=1e-6)
            direction, start_direction = (d / np.linalg.norm(d) for d in (end[1] - end[0], start[1] - start[0]))
            self.assertLess(np.arccos(min(1.0, direction @ start_direction)), 2e-4)

    def test_gravity_friction_and_removal_between_steps(self):
        with enteron.Scene(BOWEL) as scene:
            floor = scene.add_obstacle("plane", friction=0.0)
            scene.add_obstacle("plane", point=(0, 0, -1.0))
            self.assertEqual(scene.obstacle_count, 2)
            settle(scene, 100)
            # A table tilted by 20 degrees: on a frictionless floor the bowel slides along +x.
            angle = np.radians(20.0)
            scene.set_gravity((9.81 * np.sin(angle), 0.0, -9.81 * np.cos(angle)))
            before = scene.control_points()[:, 0].mean()
            settle(scene, 300)
            self.assertGreater(scene.control_points()[:, 0].mean(), before + 0.05)
            # With mu = 1 (above tan 20 degrees) it holds.
            scene.set_obstacle_friction(floor, 1.0)
            settle(scene, 300)
            held = scene.control_points()[:, 0].mean()
            settle(scene, 300)
            self.assertLess(abs(scene.control_points()[:, 0].mean() - held), 0.01)
            scene.remove_obstacle(floor)
            self.assertEqual(scene.obstacle_count, 1)
            with self.assertRaises(enteron.Error) as caught:
                scene.set_obstacle_pose(floor, (0, 0, 0))
            self.assertEqual(caught.exception.status, enteron.ERROR_NOT_FOUND)
            settle(scene, 200)
            self.assertLess(scene.control_points()[:, 2].max(), -0.05)

    def test_bad_run_time_input_raises_and_changes_nothing(self):
        with enteron.Scene(BOWEL) as scene:
            organ = scene.add_obstacle("sphere", center=(0, 0, -0.2))
            with self.assertRaises(enteron.Error) as caught:
                scene.set_obstacle_pose(organ, (0, 0, 0), (0, 0, 0, 0))
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            with self.assertRaises(enteron.Error):
                scene.set_gravity((0, float("nan"), 0))
            with self.assertRaises(enteron.Error):
                scene.pin_point(99)
            with self.assertRaises(enteron.Error) as caught:
                scene.attach_mesentery(organ)
            self.assertEqual(caught.exception.status, enteron.ERROR_NOT_FOUND)
            with self.assertRaises(ValueError):
                scene.set_obstacle_pose(organ, (0, 0))
            # An index beyond 32 bits is refused, not cut to its low bits (2**32 would be 0).
            for call in (lambda: scene.pin_point(2**32), lambda: scene.attach_mesentery(2**32 + organ),
                         lambda: scene.set_obstacle_pose(2**32 + organ, (0, 0, 1))):
                with self.assertRaises(ctypes.ArgumentError) as caught:
                    call()
                self.assertIn("out of range", str(caught.exception))
            position, orientation = scene.obstacle_pose(organ)
            np.testing.assert_array_equal(position, [0, 0, 0])
            np.testing.assert_array_equal(orientation, [1, 0, 0, 0])


if __name__ == "__main__":
    unittest.main()
