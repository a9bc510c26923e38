# SPDX-License-Identifier: Apache-2.0
"""A Python user can never crash the interpreter through the package (issue 16, defect 1).

Each pattern that crashed or read freed memory runs in its own interpreter, so that a crash
fails its test instead of the whole run: the child must exit with status 0 and print "ok".
"""
import os
import subprocess
import sys
import textwrap
import unittest

PRELUDE = """
import gc, threading
import numpy as np
import enteron
SCENE = {"intestine": {"length": 0.6, "control_points": 24, "shape": {"kind": "line"}},
         "gravity": [0, 0, -9.81], "damping": {}}
"""

PATTERNS = {
    # The issue's: SIGSEGV in 4 of 4 runs.
    "mesh after its scene closed": """
        scene = enteron.Scene({}); skin = enteron.Skin(scene, "tube"); skin.update()
        mesh = skin.mesh(); scene.close(); total = mesh.positions.sum()
        assert np.isfinite(total) and mesh.positions.shape[0] > 0
    """,
    # No crash, but valgrind saw reads of memory ent_skin_destroy had freed.
    "mesh after its skin's with block": """
        with enteron.Scene(SCENE) as scene:
            with enteron.Skin(scene, "convolution") as skin:
                skin.update()
                mesh = skin.mesh()
                expected = np.array(mesh.positions)
            gc.collect()
            assert (mesh.positions == expected).all() and (mesh.indices < mesh.vertex_count).all()
    """,
    "mesh after its skin was collected": """
        scene = enteron.Scene(SCENE)
        skin = enteron.Skin(scene, "point_skeleton"); skin.update(); mesh = skin.mesh()
        expected = np.array(mesh.normals)
        del skin; gc.collect()
        assert (mesh.normals == expected).all()
    """,
    # An update may grow (reallocate) the skin's buffers under an older mesh.
    "old mesh after updates that grow the mesh": """
        scene = enteron.Scene(SCENE)
        skin = enteron.Skin(scene, "convolution", ring_chord_error_radii=0.01)
        skin.update(); first = skin.mesh(); expected = np.array(first.positions)
        for _ in range(300):
            scene.step(0.001)
        for _ in range(5):
            skin.update()
        assert (first.positions == expected).all() and skin.mesh().updates == 6
    """,
    "handles used after close raise": """
        scene = enteron.Scene(SCENE); tool = scene.add_tool(position=(0, 0, 0.1))
        skin = enteron.Skin(scene, "tube"); skin.update(); mesh = skin.mesh()
        scene.close()
        for call in (lambda: scene.step(0.001), tool.wrench, tool.feedback, lambda: tool.set_pose((0, 0, 0)),
                     skin.update, skin.mesh, skin.metrics, lambda: enteron.Skin(scene, "tube")):
            try:
                call()
            except ValueError:
                continue
            raise AssertionError("no ValueError from a closed handle")
        assert np.isfinite(mesh.positions).all()
    """,
    # Two threads stepping one scene used to hang (self-collision) or publish garbage.
    "two threads stepping one scene": """
        scene = enteron.Scene({"intestine": {"length": 1.0, "control_points": 40}, "gravity": [0, 0, -9.81],
                               "self_collision": {}})
        outcomes = []
        def drive():
            for _ in range(300):
                try:
                    scene.step(0.001); outcomes.append("ok")
                except enteron.Error as error:
                    assert error.status == enteron.ERROR_BUSY, error
                    outcomes.append("busy")
        threads = [threading.Thread(target=drive) for _ in range(2)]
        for t in threads: t.start()
        for t in threads: t.join()
        assert scene.stats().steps == outcomes.count("ok")
        assert np.isfinite(scene.control_points()).all()
    """,
    "a haptic thread beside the stepping thread": """
        scene = enteron.Scene(SCENE); tool = scene.add_tool(position=(0.3, 0, 0.03))
        done = threading.Event()
        def haptic():
            i = 0
            while not done.is_set():
                tool.set_pose((0.3, 0.0, 0.03 - 1e-5 * (i % 100))); tool.feedback(); i += 1
        t = threading.Thread(target=haptic); t.start()
        for _ in range(300):
            scene.step(0.001)
        done.set(); t.join()
        assert tool.feedback().steps == 300
    """,
}


class NoCrash(unittest.TestCase):
    def run_pattern(self, code):
        program = PRELUDE + textwrap.dedent(code) + "\nprint('ok')\n"
        result = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=120,
                                env=dict(os.environ))
        return result

    def test_every_crashing_pattern_now_exits_cleanly(self):
        for name, code in PATTERNS.items():
            with self.subTest(pattern=name):
                result = self.run_pattern(code)
                self.assertEqual(result.returncode, 0, "%s: exit status %d\n%s" % (name, result.returncode,
                                                                                   result.stderr[-2000:]))
                self.assertEqual(result.stdout.strip(), "ok", result.stderr[-2000:])


if __name__ == "__main__":
    unittest.main()
