# SPDX-License-Identifier: Apache-2.0
"""Skins through the binding: the mesh arrays are the C API's buffers (no copy), a fresh
mesh() follows each update, errors raise enteron.Error, handles close safely."""
import ctypes
import gc
import unittest

import numpy as np

import enteron
from enteron import _library, _structs

H = 1e-3  # s

SCENE = {
    "intestine": {"length": 0.6, "control_points": 24, "stretch_stiffness": 100, "bend_stiffness": 2.5e-3,
                  "shape": {"kind": "serpentine", "leg_length": 0.15}},
    "gravity": [0, 0, -9.81],
    "damping": {},
}


def raw_mesh(skin):
    """ent_skin_mesh called directly, its buffers copied out byte for byte (not the binding's views)."""
    view = _structs.ent_mesh_view()
    view.struct_size = ctypes.sizeof(view)
    assert _library.lib.ent_skin_mesh(skin._handle, ctypes.byref(view)) == 0
    v, t = view.vertex_count, view.triangle_count

    def copy(address, count, dtype):
        return np.frombuffer(ctypes.string_at(address, count * np.dtype(dtype).itemsize), dtype=dtype).copy()

    return view, {"positions": copy(view.positions_xyz_m, 3 * v, np.float32).reshape(v, 3),
                  "normals": copy(view.normals_xyz, 3 * v, np.float32).reshape(v, 3),
                  "u": copy(view.axis_u, v, np.float32),
                  "indices": copy(view.indices, 3 * t, np.uint32).reshape(t, 3),
                  "v": copy(view.around_v, v, np.float32),
                  "tangents": copy(view.tangents_xyz, 3 * v, np.float32).reshape(v, 3)}


class MeshIsTheCApis(unittest.TestCase):
    def test_arrays_equal_the_c_buffers_for_every_method(self):
        with enteron.Scene(SCENE) as scene:
            for _ in range(10):
                scene.step(H)
            for method in ("tube", "point_skeleton", "convolution"):
                with self.subTest(method=method), enteron.Skin(scene, method) as skin:
                    empty = skin.mesh()
                    self.assertEqual((empty.vertex_count, empty.triangle_count, empty.updates), (0, 0, 0))
                    skin.update()
                    mesh = skin.mesh()
                    view, raw = raw_mesh(skin)
                    self.assertGreater(mesh.triangle_count, 100)
                    self.assertEqual(mesh.positions.shape, (view.vertex_count, 3))
                    self.assertEqual(mesh.normals.shape, (view.vertex_count, 3))
                    self.assertEqual(mesh.u.shape, (view.vertex_count,))
                    self.assertEqual(mesh.indices.shape, (view.triangle_count, 3))
                    self.assertEqual((mesh.positions.dtype, mesh.normals.dtype, mesh.u.dtype, mesh.indices.dtype),
                                     (np.float32, np.float32, np.float32, np.uint32))
                    for name, expected in raw.items():
                        np.testing.assert_array_equal(getattr(mesh, name), expected, err_msg=name)
                    self.assertEqual(mesh.updates, 1)
                    self.assertEqual(mesh.time_s, view.time_s)
                    self.assertAlmostEqual(mesh.time_s, 10 * H, places=12)
                    self.assertLess(int(mesh.indices.max()), mesh.vertex_count)
                    np.testing.assert_allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-4)

    def test_metrics_are_the_c_apis(self):
        with enteron.Scene(SCENE) as scene, enteron.Skin(scene, "convolution", segments=20) as skin:
            skin.update()
            metrics = skin.metrics()
            raw = _structs.ent_skin_metrics()
            raw.struct_size = ctypes.sizeof(raw)
            self.assertEqual(_library.lib.ent_skin_metrics(skin._handle, ctypes.byref(raw)), 0)
            self.assertIsInstance(metrics, enteron.SkinMetrics)
            for field in enteron.SkinMetrics.__dataclass_fields__:
                if field != "watertight":
                    self.assertEqual(getattr(metrics, field), getattr(raw, field), field)
            self.assertIs(metrics.watertight, bool(raw.watertight))
            self.assertTrue(metrics.watertight)
            mesh = skin.mesh()
            self.assertEqual((metrics.vertex_count, metrics.triangle_count), (mesh.vertex_count, mesh.triangle_count))
            self.assertEqual(mesh.vertex_count % 20, 2)  # rings of 20, plus the two cap tips
            self.assertLess(metrics.radius_error_rms, 0.05)
            self.assertAlmostEqual(metrics.axis_length_m, 0.6, delta=0.01)

    def test_knobs_reach_the_library(self):
        with enteron.Scene(SCENE) as scene:
            counts = {}
            for segments in (8, 32):
                with enteron.Skin(scene, "tube", segments=segments, cap_rings=0) as skin:
                    self.assertEqual(skin.method, enteron.SKIN_TUBE)
                    skin.update()
                    counts[segments] = skin.mesh().vertex_count
            self.assertEqual(counts[8] % 8, counts[32] % 32)
            self.assertEqual(counts[32] * 8 - counts[8] * 32, (counts[32] % 32) * 8 - (counts[8] % 8) * 32)
            self.assertGreater(counts[32], 3 * counts[8])

    def test_level_of_detail_adds_rings_where_the_axis_bends(self):
        # The serpentine's U-turns: adaptive rings (at most 2 R apart) add rings there, and
        # the facet error (the chord between rings) falls against even rings 2 R apart.
        with enteron.Scene(SCENE) as scene:
            results = {}
            for chord_error in (0.0, 0.005):
                with enteron.Skin(scene, "convolution", segments=32, ring_spacing_radii=2.0,
                                  ring_chord_error_radii=chord_error) as skin:
                    skin.update()
                    results[chord_error] = (skin.mesh().vertex_count, skin.metrics())
            (even_vertices, even), (lod_vertices, lod) = results[0.0], results[0.005]
            self.assertGreater(lod_vertices, even_vertices)
            self.assertLess(lod.facet_error_max, even.facet_error_max)
            self.assertTrue(lod.watertight)


class StableTopology(unittest.TestCase):
    """A mesh a GPU can keep: tube and convolution keep their indices while the bowel
    moves; v around the tube in [0, 1); unit tangents perpendicular to the normals."""

    def test_ring_skins_keep_their_indices_while_the_bowel_falls(self):
        with enteron.Scene(SCENE) as scene:
            for method in ("tube", "convolution"):
                with self.subTest(method=method), enteron.Skin(scene, method) as skin:
                    skin.update()
                    first = skin.mesh()
                    self.assertTrue(first.stable_topology)
                    self.assertTrue(first.topology_changed)
                    self.assertEqual(first.topology_serial, 1)
                    for _ in range(5):
                        for _ in range(40):
                            scene.step(H)
                        skin.update()
                        mesh = skin.mesh()
                        self.assertFalse(mesh.topology_changed)
                        self.assertEqual(mesh.topology_serial, 1)
                        np.testing.assert_array_equal(mesh.indices, first.indices)
                        np.testing.assert_array_equal(mesh.v, first.v)
                    self.assertGreater(np.abs(mesh.positions - first.positions).max(), 1e-3)  # it moved

    def test_v_and_tangents_for_every_method(self):
        with enteron.Scene(SCENE) as scene:
            for _ in range(10):
                scene.step(H)
            for method in ("tube", "point_skeleton", "convolution"):
                with self.subTest(method=method), enteron.Skin(scene, method) as skin:
                    skin.update()
                    mesh = skin.mesh()
                    _, raw = raw_mesh(skin)
                    np.testing.assert_array_equal(mesh.v, raw["v"])
                    np.testing.assert_array_equal(mesh.tangents, raw["tangents"])
                    self.assertEqual((mesh.v.shape, mesh.tangents.shape), ((mesh.vertex_count,), (mesh.vertex_count, 3)))
                    self.assertGreaterEqual(float(mesh.v.min()), 0.0)
                    self.assertLess(float(mesh.v.max()), 1.0)
                    np.testing.assert_allclose(np.linalg.norm(mesh.tangents, axis=1), 1.0, atol=1e-6)
                    self.assertLess(float(np.abs((mesh.tangents * mesh.normals).sum(axis=1)).max()), 1e-5)
                    self.assertEqual(mesh.stable_topology, method != "point_skeleton")

    def test_point_skeleton_and_stable_topology_off_say_when_indices_change(self):
        with enteron.Scene(SCENE) as scene, enteron.Skin(scene, "point_skeleton") as skin:
            for serial in (1, 2):
                scene.step(H)
                skin.update()
                mesh = skin.mesh()
                self.assertFalse(mesh.stable_topology)
                self.assertTrue(mesh.topology_changed)
                self.assertEqual(mesh.topology_serial, serial)
        with enteron.Scene(SCENE) as scene, enteron.Skin(scene, "tube", stable_topology=0) as skin:
            skin.update()
            self.assertFalse(skin.mesh().stable_topology)
        with enteron.Scene(SCENE) as scene, self.assertRaises(enteron.Error) as caught:
            enteron.Skin(scene, "tube", stable_topology=2)
        self.assertIn("stable_topology", str(caught.exception))


class Contacts(unittest.TestCase):
    # Two legs of a U-turn 3 R apart, the middle of the second pushed 1.4 R towards the
    # first: their tubes press 0.4 R into each other there.
    R = 0.0125

    def scene(self):
        r = 1.5 * self.R

        def pushed(x):
            return 1.4 * self.R * np.cos(0.5 * np.pi * (x + 0.075) / 0.05) ** 2 if abs(x + 0.075) < 0.05 else 0.0

        leg = [[-0.15 + 0.15 * i / 48, -r, 0.0] for i in range(48)]
        turn = [[r * np.cos(a), r * np.sin(a), 0.0] for a in np.linspace(-np.pi / 2, np.pi / 2, 9)[:-1]]
        back = [[-0.15 * i / 48, r - pushed(-0.15 * i / 48), 0.0] for i in range(49)]
        points = leg + turn + back
        return enteron.Scene({"intestine": {"radius": self.R, "control_points": len(points),
                                            "shape": {"kind": "points", "points": points}}})

    def test_contact_surfaces_knob_and_measures(self):
        with self.scene() as scene:
            measures = {}
            for contacts in (1, 0):
                with enteron.Skin(scene, "convolution", contact_surfaces=contacts) as skin:
                    skin.update()
                    first = skin.metrics()
                    self.assertFalse(first.has_previous_update)
                    skin.update()
                    measures[contacts] = skin.metrics()
            met, through = measures[1], measures[0]
            self.assertTrue(met.has_previous_update)
            self.assertLess(met.vertex_excess_motion_max, 1e-6)  # the same state twice
            self.assertGreater(through.tube_overlap_depth_max, 0.15)
            self.assertGreater(through.overlap_depth_max, 0.15)
            self.assertLess(met.overlap_depth_max, 0.02)
            self.assertEqual(met.overlap_area_m2, 0.0)
            self.assertLess(abs(met.shape_volume_error), 0.005)
            self.assertEqual(met.inverted_triangles, 0)
            self.assertGreater(met.free_vertex_count, 0)
            with self.assertRaises(enteron.Error) as caught:
                enteron.Skin(scene, "convolution", contact_surfaces=2)
            self.assertIn("contact_surfaces", str(caught.exception))


class Copies(unittest.TestCase):
    def test_arrays_copy_the_librarys_mesh_and_outlive_updates(self):
        with enteron.Scene(SCENE) as scene, enteron.Skin(scene, "convolution") as skin:
            skin.update()
            first = skin.mesh()
            view, raw = raw_mesh(skin)
            np.testing.assert_array_equal(first.positions, raw["positions"])
            self.assertNotEqual(first.positions.ctypes.data, view.positions_xyz_m)
            self.assertTrue(first.positions.flags.owndata)
            self.assertFalse(first.positions.flags.writeable)
            before = np.array(first.positions)

            for _ in range(200):  # the bowel falls: every vertex moves
                scene.step(H)
            skin.update()
            second = skin.mesh()
            _, raw = raw_mesh(skin)
            self.assertEqual(second.updates, 2)
            np.testing.assert_array_equal(second.positions, raw["positions"])
            self.assertGreater(second.time_s, first.time_s)
            np.testing.assert_array_equal(first.positions, before)  # the first mesh keeps its state
            self.assertLess(second.positions[:, 2].mean(), before[:, 2].mean())  # fell under gravity

    def test_a_mesh_outlives_its_skin_and_scene(self):
        scene = enteron.Scene(SCENE)
        skin = enteron.Skin(scene, "tube")
        skin.update()
        mesh = skin.mesh()
        expected = np.array(mesh.positions)
        skin.close()
        scene.close()
        gc.collect()
        np.testing.assert_array_equal(mesh.positions, expected)


class Errors(unittest.TestCase):
    def test_bad_knob_raises_with_the_library_message(self):
        with enteron.Scene(SCENE) as scene:
            with self.assertRaises(enteron.Error) as caught:
                enteron.Skin(scene, "tube", segments=2)
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            self.assertIn("segments", caught.exception.message)
            self.assertEqual(caught.exception.call, "ent_skin_create")
            with self.assertRaises(enteron.Error) as caught:
                enteron.Skin(scene, "convolution", window_radii=5.0)
            self.assertIn("window_radii", caught.exception.message)
            with self.assertRaises(enteron.Error) as caught:
                enteron.Skin(scene, "convolution", ring_chord_error_radii=-0.5)
            self.assertIn("ring_chord_error_radii", caught.exception.message)
            with self.assertRaises(enteron.Error) as caught:
                enteron.Skin(scene, 7)
            self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
            self.assertIn("method", caught.exception.message)

    def test_python_side_mistakes(self):
        with enteron.Scene(SCENE) as scene:
            with self.assertRaises(ValueError):
                enteron.Skin(scene, "marching")
            with self.assertRaises(TypeError):
                enteron.Skin(scene, "tube", radius=1.0)


class Lifetime(unittest.TestCase):
    def test_closing_twice_is_safe(self):
        with enteron.Scene(SCENE) as scene:
            skin = enteron.Skin(scene, "tube")
            with skin:
                skin.update()
            self.assertTrue(skin.closed)
            skin.close()
            skin.close()
            for call in (skin.update, skin.mesh, skin.metrics):
                with self.assertRaises(ValueError):
                    call()

    def test_closing_the_scene_closes_its_skins_first(self):
        scene = enteron.Scene(SCENE)
        skin = enteron.Skin(scene, "convolution")
        skin.update()
        scene.close()
        self.assertTrue(skin.closed)
        skin.close()
        with self.assertRaises(ValueError):
            enteron.Skin(scene, "tube")


if __name__ == "__main__":
    unittest.main()
