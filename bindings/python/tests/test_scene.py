# SPDX-License-Identifier: Apache-2.0
"""Scenes through the binding: the values are the C API's, errors raise, handles close."""
import ctypes
import threading
import unittest

import numpy as np

import enteron
from enteron import _library, _structs

G = (0.5, -1.0, -9.81)  # m/s^2, not along an axis: every coordinate moves
H = 1e-3                 # s

# A rigid free fall (gravity alone): every control point follows symplectic Euler's exact
# discrete solution dq = g (t^2 + h t) / 2 with t = k h.
FREE_FALL = {
    "intestine": {"length": 1.0, "control_points": 20, "linear_density": 0.3,
                  "stretch_stiffness": 0, "bend_stiffness": 0,  # a rigid fall: no elasticity
                  "shape": {"kind": "line", "center": [0.1, -0.2, 0.3], "direction": [1, 1, 0]}},
    "solver": {"integrator": "symplectic_euler", "timestep": H},
    "gravity": list(G),
}


def raw_axis(scene, count):
    """ent_scene_axis called directly through ctypes, bypassing the Scene class."""
    buffer = (ctypes.c_double * (3 * count))()
    assert _library.lib.ent_scene_axis(scene._handle, count, buffer) == 0
    return np.array(buffer[:]).reshape(count, 3)


class FreeFall(unittest.TestCase):
    def test_control_points_follow_the_exact_discrete_solution(self):
        with enteron.Scene(FREE_FALL) as scene:
            start = scene.control_points()
            self.assertEqual(start.shape, (20, 3))
            steps = 250
            for _ in range(steps):
                scene.step(H)
            t = steps * H
            expected = 0.5 * np.array(G) * (t * t + H * t)
            np.testing.assert_allclose(scene.control_points() - start, np.tile(expected, (20, 1)), atol=1e-12)

    def test_stats_and_effect_stats(self):
        with enteron.Scene(FREE_FALL) as scene:
            for _ in range(100):
                scene.step(H)
            stats = scene.stats()
            self.assertIsInstance(stats, enteron.Stats)
            self.assertEqual(stats.steps, 100)
            self.assertEqual(stats.substeps, 100)
            self.assertEqual(stats.control_points, 20)
            self.assertAlmostEqual(stats.time_s, 0.1, places=12)
            mass = 0.3 * 1.0
            speed2 = sum((g * 0.1) ** 2 for g in G)
            self.assertAlmostEqual(stats.kinetic_energy_J, 0.5 * mass * speed2, delta=1e-9)
            # What the last step did (the appended fields): one attempt of one substep, no
            # tool, no self-contact; the longest step at least the last.
            self.assertEqual((stats.last_step_attempts, stats.last_step_substeps), (1, 1))
            self.assertEqual(stats.subdivided_steps, 0)
            self.assertEqual(stats.last_step_proxy_iterations, 0)
            self.assertEqual(stats.proxy_unbalanced_solves, 0)
            self.assertGreaterEqual(stats.max_step_ns, stats.last_step_ns)
            self.assertLessEqual(stats.late_steps, stats.steps)
            gravity = scene.effect_stats("gravity")
            self.assertEqual(gravity, scene.effect_stats(enteron.EFFECT_GRAVITY))
            self.assertTrue(gravity.enabled)
            self.assertEqual(gravity.calls, 100)
            stretch = scene.effect_stats("stretch")
            self.assertFalse(stretch.enabled)
            self.assertEqual(stretch.calls, 0)
            self.assertEqual(set(scene.all_effect_stats()),
                             {"stretch", "bend", "damping", "gravity", "mesentery", "pinned", "environment",
                              "self_collision", "tools"})


class SameAsTheCApi(unittest.TestCase):
    def test_axis_equals_the_raw_c_call(self):
        with enteron.Scene(json_text()) as scene:
            for _ in range(20):
                scene.step(H)
            for count in (2, 7, 100):
                axis = scene.axis(count)
                self.assertEqual(axis.shape, (count, 3))
                self.assertEqual(axis.dtype, np.float64)
                np.testing.assert_array_equal(axis, raw_axis(scene, count))
            # The axis passes through the end control points.
            points = scene.control_points()
            np.testing.assert_allclose(scene.axis(50)[[0, -1]], points[[0, -1]], atol=1e-12)

    def test_desc_and_json_give_the_same_scene(self):
        desc = enteron.SceneDesc(effects={"gravity", "stretch", "bend"}, control_points=24, length_m=1.0,
                                 shape=enteron.SHAPE_LINE, shape_direction=(0, 1, 0),
                                 integrator=enteron.INTEGRATOR_RK4, gravity_m_per_s2=(0, 0, -9.81))
        text = {"intestine": {"length": 1.0, "control_points": 24, "stretch_stiffness": 100,
                              "bend_stiffness": 2.5e-3,
                              "shape": {"kind": "line", "direction": [0, 1, 0]}},
                "solver": {"integrator": "rk4"}, "gravity": [0, 0, -9.81]}
        with enteron.Scene(desc=desc) as a, enteron.Scene(text) as b:
            for _ in range(30):
                a.step(H)
                b.step(H)
            np.testing.assert_array_equal(a.control_points(), b.control_points())

    def test_desc_defaults_are_the_libraries(self):
        desc = enteron.SceneDesc()
        self.assertEqual(desc.control_points, 240)
        self.assertEqual(desc.length_m, 6.0)
        self.assertEqual(desc.gravity_m_per_s2, [0.0, 0.0, -9.81])
        self.assertEqual(desc.struct_size, ctypes.sizeof(_structs.ent_scene_desc))

    def test_points_shape_and_pinned_points(self):
        points = np.column_stack([np.linspace(0, 0.5, 11), np.zeros(11), np.zeros(11)])
        desc = enteron.SceneDesc(shape_points_xyz_m=points, effects={"gravity", "pinned"},
                                 pinned_points=[0, 10])
        with enteron.Scene(desc=desc) as scene:
            np.testing.assert_array_equal(scene.control_points(), points)
            for _ in range(10):
                scene.step(H)
            after = scene.control_points()
            np.testing.assert_array_equal(after[[0, 10]], points[[0, 10]])
            self.assertLess(after[5, 2], 0.0)  # the middle falls

    def test_bdf2_integrator_by_constant_and_by_name(self):
        # The same scene from SceneDesc(integrator=INTEGRATOR_BDF2) and JSON "bdf2", bit for bit;
        # a free fall follows bdf2's exact discrete solution g (t^2 / 2 + 3/4 h^2 (1 - 3^-k)).
        scenes = (enteron.Scene(dict(FREE_FALL, solver={"integrator": "bdf2", "timestep": H})),
                  enteron.Scene(desc=enteron.SceneDesc(
                      control_points=20, length_m=1.0, stretch_stiffness_N=0.0, bend_stiffness_N_m2=0.0,
                      effects={"gravity"}, shape=enteron.SHAPE_LINE, shape_center_m=(0.1, -0.2, 0.3),
                      shape_direction=(1, 1, 0), gravity_m_per_s2=G, integrator=enteron.INTEGRATOR_BDF2,
                      timestep_s=H)))
        results = []
        for scene in scenes:
            with scene:
                start = scene.control_points()
                k = 50
                for _ in range(k):
                    scene.step(H)
                t = k * H
                moved = scene.control_points() - start
                expected = np.array(G) * (t * t / 2 + 0.75 * H * H * (1 - 3.0 ** -k))
                np.testing.assert_allclose(moved, np.tile(expected, (20, 1)), rtol=0, atol=1e-12)
                results.append(moved)
        np.testing.assert_array_equal(results[0], results[1])

    def test_profiles_from_c_and_json_make_the_same_scene(self):
        # A tube narrowing from 3.5 to 1.3 cm and lighter towards its end, falling: the same
        # trajectory whether the profiles come through ent_scene_desc or JSON.
        radius = [[0.0, 0.035], [1.5, 0.013]]
        density = [[0.0, 0.6], [0.5, 0.4], [1.5, 0.3]]
        desc = enteron.SceneDesc(length_m=1.5, control_points=31, shape=enteron.SHAPE_LINE,
                                 radius_profile_m=radius, linear_density_profile_kg_per_m=density,
                                 effects={"gravity", "stretch", "bend", "damping"})
        text = {"intestine": {"length": 1.5, "control_points": 31, "shape": {"kind": "line"},
                              "radius_profile": radius, "linear_density_profile": density},
                "gravity": [0, 0, -9.81], "damping": {}}
        trajectories = []
        for scene in (enteron.Scene(desc=desc), enteron.Scene(text)):
            with scene:
                for _ in range(50):
                    scene.step(H)
                trajectories.append(scene.control_points())
        np.testing.assert_array_equal(trajectories[0], trajectories[1])
        self.assertLess(trajectories[0][-1, 2], -1e-3)  # it fell
        with self.assertRaisesRegex(ValueError, "radius_profile_m must be an \\(n, 2\\) array"):
            enteron.SceneDesc(radius_profile_m=[0.0, 0.035, 1.5])
        with self.assertRaises(enteron.Error) as caught:
            enteron.Scene(desc=enteron.SceneDesc(length_m=1.5, radius_profile_m=[[0, 0.03], [1, 0.02]]))
        self.assertEqual(caught.exception.status, enteron.ERROR_INVALID_ARGUMENT)
        self.assertIn("radius_profile_m[2] must be >= length_m", caught.exception.message)

    def test_fan_mesentery_and_spans_from_c_and_json_make_the_same_scene(self):
        # A root polyline, a mapping and a pinned span: the same trajectory whether they come
        # through ent_scene_desc or JSON; the span's points stay where they started.
        root = [[-0.072, 0.0, -0.1], [0.0, 0.021, -0.1], [0.072, 0.0, -0.1]]
        mapping = [[0.0, 0.0], [0.4, 0.3], [1.0, 1.0]]
        desc = enteron.SceneDesc(length_m=1.0, control_points=21, shape=enteron.SHAPE_LINE,
                                 shape_center_m=(-0.5, 0, 0), mesentery_attachments=10,
                                 mesentery_root_points_m=root, mesentery_root_mapping=mapping,
                                 pinned_spans_m=[[0.45, 0.55]],
                                 effects={"gravity", "stretch", "bend", "damping", "mesentery", "pinned"})
        text = {"intestine": {"length": 1.0, "control_points": 21,
                              "shape": {"kind": "line", "center": [-0.5, 0, 0]}},
                "gravity": [0, 0, -9.81], "damping": {},
                "mesentery": {"root": root, "root_mapping": mapping, "attachments": 10},
                "pinned": {"spans": [{"from": 0.45, "to": 0.55}]}}
        trajectories = []
        for scene in (enteron.Scene(desc=desc), enteron.Scene(text)):
            with scene:
                start = scene.control_points()
                for _ in range(50):
                    scene.step(H)
                trajectories.append(scene.control_points())
        np.testing.assert_array_equal(trajectories[0], trajectories[1])
        np.testing.assert_array_equal(trajectories[0][9:12], start[9:12])  # s = 0.45, 0.5, 0.55
        self.assertLess(trajectories[0][0, 2], -1e-3)  # the rest fell
        with self.assertRaisesRegex(ValueError, "mesentery_root_points_m must be an \\(n, 3\\) array"):
            enteron.SceneDesc(mesentery_root_points_m=[[0.0, 0.0], [1.0, 1.0]])
        with self.assertRaises(enteron.Error) as caught:
            enteron.Scene(desc=enteron.SceneDesc(effects={"pinned"}, pinned_spans_m=[[0.5, 0.2]]))
        self.assertIn("pinned_spans_m[0].to must be >= pinned_spans_m[0].from", caught.exception.message)

    def test_clamped_end_keeps_its_point_and_tangent(self):
        # A horizontal cantilever clamped at its first end sags, its end tangent
        # (4 q1 - 3 q0 - q2) / 2 staying horizontal; the same through JSON's pinned.clamped.
        points = np.column_stack([np.linspace(0, 0.5, 11), np.zeros(11), np.zeros(11)])
        desc = enteron.SceneDesc(shape_points_xyz_m=points, clamped_ends=enteron.PIN_FIRST,
                                 effects={"gravity", "stretch", "bend", "damping", "pinned"},
                                 integrator=enteron.INTEGRATOR_IMPLICIT_EULER)
        text = {"intestine": {"length": 0.5, "control_points": 11, "shape": {"kind": "line"}},
                "gravity": [0, 0, -9.81], "damping": {},
                "solver": {"integrator": "implicit_euler"}, "pinned": {"clamped": "first"}}
        for scene in (enteron.Scene(desc=desc), enteron.Scene(text)):
            with scene:
                start = scene.control_points()
                for _ in range(200):
                    scene.step(H)
                q = scene.control_points()
                np.testing.assert_array_equal(q[0], start[0])
                self.assertLess(q[-1, 2], start[-1, 2] - 1e-3)  # the tip sags
                tangent = (4 * q[1] - 3 * q[0] - q[2]) / 2
                direction = (4 * start[1] - 3 * start[0] - start[2]) / 2
                across = np.linalg.norm(np.cross(tangent, direction)) / np.dot(tangent, direction)
                self.assertLess(abs(across), 1e-9)


class Errors(unittest.TestCase):
    def assertRaisesStatus(self, status, text, function, *args, **kwargs):
        with self.assertRaises(enteron.Error) as caught:
            function(*args, **kwargs)
        self.assertEqual(caught.exception.status, status)
        self.assertEqual(caught.exception.status_name, enteron.status_string(status))
        self.assertIn(text, caught.exception.message)
        self.assertIn(text, str(caught.exception))
        return caught.exception

    def test_creation_errors_carry_the_library_message(self):
        self.assertRaisesStatus(enteron.ERROR_PARSE, "byte", enteron.Scene, "{\"intestine\": ,}")
        self.assertRaisesStatus(enteron.ERROR_INVALID_SCENE, "intestine.radius must be > 0",
                                enteron.Scene, {"intestine": {"radius": -1}})
        self.assertRaisesStatus(enteron.ERROR_INVALID_SCENE, 'unknown key "lenght"',
                                enteron.Scene, {"intestine": {"lenght": 1}})
        self.assertRaisesStatus(enteron.ERROR_INVALID_ARGUMENT, "radius_m must be > 0",
                                enteron.Scene, desc={"radius_m": -1.0})
        self.assertRaisesStatus(enteron.ERROR_INVALID_ARGUMENT, "clamped_ends must be <= 3, got 7",
                                enteron.Scene, desc={"clamped_ends": 7, "effects": {"pinned"}})
        self.assertRaisesStatus(enteron.ERROR_INVALID_SCENE, 'pinned.clamped must be one of',
                                enteron.Scene, {"pinned": {"clamped": "middle"}})

    def test_call_errors(self):
        with enteron.Scene(FREE_FALL) as scene:
            self.assertRaisesStatus(enteron.ERROR_INVALID_ARGUMENT, "dt_s", scene.step, -1.0)
            self.assertRaisesStatus(enteron.ERROR_INVALID_ARGUMENT, "count must be >= 2", scene.axis, 1)
            self.assertRaisesStatus(enteron.ERROR_NOT_FOUND, "99", scene.effect_stats, 99)
            self.assertEqual(scene.stats().steps, 0)  # nothing changed
        with enteron.Scene(dict(FREE_FALL, solver={"integrator": "symplectic_euler", "max_speed": 1e-6})) as scene:
            self.assertRaisesStatus(enteron.ERROR_UNSTABLE, "unstable", scene.step, H)

    def test_python_level_mistakes(self):
        with self.assertRaises(AttributeError):
            enteron.SceneDesc(lenght_m=1.0)
        with self.assertRaises(ValueError):
            enteron.SceneDesc(effects={"gravitation"})
        with self.assertRaises(TypeError):
            enteron.Scene()
        with self.assertRaises(TypeError):
            enteron.Scene(FREE_FALL, desc={})


class Descriptions(unittest.TestCase):
    """Issue 27, defects 3 and 4: a description says what was written, or is refused."""

    POINTS = np.column_stack([np.linspace(0, 0.45, 10), np.zeros(10), np.zeros(10)])

    def test_a_count_comes_from_its_array(self):
        desc = enteron.SceneDesc(shape_points_xyz_m=self.POINTS, pinned_points=[0, 9])
        self.assertEqual((desc.control_points, desc.struct.pinned_point_count), (10, 2))
        enteron.SceneDesc(control_points=10, shape_points_xyz_m=self.POINTS)  # agreeing: fine
        for fields in ({"shape_points_xyz_m": self.POINTS, "control_points": 100000},
                       {"control_points": 12, "shape_points_xyz_m": self.POINTS}):
            with self.subTest(order=list(fields)):
                with self.assertRaises(ValueError) as caught:
                    enteron.SceneDesc(**fields)
                self.assertIn("SceneDesc.control_points is", str(caught.exception))
                self.assertIn("shape_points_xyz_m holds 10 points", str(caught.exception))
        with self.assertRaises(ValueError) as caught:
            enteron.SceneDesc(shape_points_xyz_m=np.zeros(7))
        self.assertIn("shape_points_xyz_m must be an (n, 3) array", str(caught.exception))
        desc = enteron.SceneDesc(shape_points_xyz_m=self.POINTS, pinned_points=[0])
        desc.struct.pinned_point_count = 1000  # behind the description's back: refused at creation
        with self.assertRaises(ValueError) as caught:
            enteron.Scene(desc=desc)
        self.assertIn("pinned_point_count is 1000 but pinned_points holds 1 indices", str(caught.exception))

    def test_points_start_at_rest(self):
        # Issue 27, defect 5: without length_m the rest length is the spline's through the
        # points (a straight 0.45 m line here), not the 6 m default.
        desc = enteron.SceneDesc(shape_points_xyz_m=self.POINTS, effects={"stretch"})
        self.assertEqual(desc.length_m, 0.0)
        with enteron.Scene(desc=desc) as scene:
            self.assertLess(abs(scene.contact_summary().largest_stretch), 1e-9)
            self.assertLess(scene.stats().potential_energy_J, 1e-12)
        self.assertEqual(enteron.SceneDesc(length_m=1.0, shape_points_xyz_m=self.POINTS).length_m, 1.0)

    def test_integer_fields_do_not_wrap(self):
        cases = [(lambda: enteron.SceneDesc(control_points=2**32 + 10), "SceneDesc.control_points must fit uint32_t"),
                 (lambda: enteron.SceneDesc(control_points=2**40), "got 1099511627776"),
                 (lambda: enteron.SceneDesc(control_points=-1), "SceneDesc.control_points must fit uint32_t"),
                 (lambda: enteron.SceneDesc(integrator=2**31), "SceneDesc.integrator must fit int32_t"),
                 (lambda: enteron.SceneDesc(max_substeps=2**32), "SceneDesc.max_substeps"),
                 (lambda: enteron.SceneDesc(pinned_points=[1, 2**32]), "SceneDesc.pinned_points[1] must fit uint32_t"),
                 (lambda: enteron.SceneDesc(pinned_points=[-1]), "SceneDesc.pinned_points[0]")]
        for make, text in cases:
            with self.subTest(text=text):
                with self.assertRaises(OverflowError) as caught:
                    make()
                self.assertIn(text, str(caught.exception))
        with self.assertRaises(TypeError) as caught:
            enteron.SceneDesc(control_points=40.5)
        self.assertIn("SceneDesc.control_points must be an integer", str(caught.exception))
        with enteron.Scene(FREE_FALL) as scene:
            for knob, value in (("segments", 2**32 + 8), ("cap_rings", -1), ("stable_topology", 2**31)):
                with self.subTest(knob=knob):
                    with self.assertRaises(OverflowError) as caught:
                        enteron.Skin(scene, "tube", **{knob: value})
                    self.assertIn("ent_skin_desc.%s must fit" % knob, str(caught.exception))
            with enteron.Skin(scene, "tube", segments=8) as skin:  # in range: as before
                skin.update()
                self.assertGreater(skin.mesh().vertex_count, 0)


class Lifetime(unittest.TestCase):
    def test_context_manager_destroys_the_scene_once(self):
        destroyed = []
        original = _library.lib.ent_scene_destroy

        def counting_destroy(handle):
            destroyed.append(handle.value if isinstance(handle, ctypes.c_void_p) else handle)
            original(handle)

        _library.lib.ent_scene_destroy = counting_destroy
        try:
            with enteron.Scene(FREE_FALL) as scene:
                handle = scene._handle.value
                self.assertFalse(scene.closed)
            self.assertTrue(scene.closed)
            self.assertEqual(destroyed, [handle])
            scene.close()  # idempotent
            self.assertEqual(destroyed, [handle])
            with self.assertRaises(ValueError):
                scene.step(H)
            with self.assertRaises(ValueError):
                scene.axis(10)
            # An exception inside the block still releases the scene.
            with self.assertRaises(RuntimeError):
                with enteron.Scene(FREE_FALL) as other:
                    raise RuntimeError("boom")
            self.assertTrue(other.closed)
            self.assertEqual(len(destroyed), 2)
        finally:
            _library.lib.ent_scene_destroy = original

    def test_log_callback_receives_lines(self):
        lines = []
        with enteron.Scene(FREE_FALL, log=lambda level, message: lines.append((level, message))) as scene:
            scene.step(H)
        self.assertTrue(lines)
        self.assertTrue(all(enteron.LOG_DEBUG <= level <= enteron.LOG_ERROR and message for level, message in lines))


class Threads(unittest.TestCase):
    def test_queries_run_while_another_thread_steps(self):
        # ctypes releases the GIL during each call: a reader thread overlaps the stepping.
        with enteron.Scene(FREE_FALL) as scene:
            done = threading.Event()
            problems = []
            reads = [0]

            def reader():
                last = -1.0
                while not done.is_set():
                    stats = scene.stats()
                    axis = scene.axis(16)
                    if stats.time_s < last or not np.all(np.isfinite(axis)):
                        problems.append(stats)
                    last = stats.time_s
                    reads[0] += 1

            thread = threading.Thread(target=reader)
            thread.start()
            for _ in range(2000):
                scene.step(H)
            done.set()
            thread.join()
            self.assertEqual(problems, [])
            self.assertGreater(reads[0], 0)


def json_text():
    return ('{"intestine": {"length": 1.0, "control_points": 30, "stretch_stiffness": 100,'
            ' "bend_stiffness": 2.5e-3}, "gravity": [0, 0, -9.81], "damping": {}, "mesentery": {}}')


if __name__ == "__main__":
    unittest.main()
