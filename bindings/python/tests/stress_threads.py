# SPDX-License-Identifier: Apache-2.0
"""Random call sequences on one scene from several threads, closes included: no death by
signal (issue 27, "Also").

    stress_threads.py [--seeds N] [--first SEED] [--seconds S]    the driver (ctest)
    stress_threads.py --child SEED [--seconds S]                  one run

Each seed runs in its own interpreter, so that a crash fails that seed instead of the whole
run. A run makes a scene (one of three bases), a skin or two and a tool, then four threads
draw calls from a generator seeded by the run's seed: steps, queries (axis, control points,
stats, contacts), tool commands and reads, skin updates, meshes and metrics, save and
restore, a new skin, and, at random moments, the close of a skin or of the scene. Each call
may raise only what the package documents for misuse: ValueError (a closed handle) or
enteron.Error (busy, not found, unstable, ...); anything else, or a death by signal, or a
sanitizer's report, fails the seed. The driver prints the seeds, the runs and the time.
Under AddressSanitizer the library's runtime is preloaded (LD_PRELOAD, bindings/python/
CMakeLists.txt) and its report fails the run (non-zero exit).
"""
import argparse
import os
import random
import subprocess
import sys
import threading
import time

BASES = [
    # a serpentine pile in a box, self-colliding, a tool
    {"intestine": {"length": 1.0, "control_points": 24,
                   "shape": {"kind": "serpentine", "leg_length": 0.12, "center": [0, 0, -0.05]}},
     "solver": {"max_substeps": 100}, "gravity": [0, 0, -9.81], "damping": {},
     "environment": [{"type": "box_inside", "half_extents": [0.1, 0.1, 0.1]}], "self_collision": {},
     "tools": [{"position": [0, 0, -0.03]}]},
    # a line on a floor, rk4
    {"intestine": {"length": 0.4, "control_points": 12, "shape": {"kind": "line", "center": [-0.2, 0, 0.0125]}},
     "solver": {"integrator": "rk4", "max_substeps": 100}, "gravity": [0, 0, -9.81],
     "environment": [{"type": "plane"}], "tools": [{"position": [0, 0, 0.03]}]},
    # a helix on its mesentery, bdf2
    {"intestine": {"length": 1.0, "control_points": 16, "shape": {"helix_radius": 0.05}},
     "solver": {"integrator": "bdf2", "max_substeps": 100}, "gravity": [0, 0, -9.81],
     "damping": {}, "mesentery": {"attachments": 8}, "pinned": {"ends": "first"}},
]


def child(seed, seconds):
    import numpy as np

    import enteron

    rng = random.Random(seed)
    scene = enteron.Scene(BASES[seed % len(BASES)])
    if not scene.tools:
        scene.add_tool(position=(0.0, 0.0, 0.08))
    tool = scene.tools[0]
    skins = [enteron.Skin(scene, rng.choice(["tube", "point_skeleton", "convolution"]))]
    saved = [scene.save_state()]
    lock = threading.Lock()  # guards the lists above, not the library's calls
    calls = {"ok": 0, "closed": 0, "error": 0}
    failures = []

    def a_skin(r):
        with lock:
            return r.choice(skins) if skins else None

    def new_skin(r):
        skin = enteron.Skin(scene, r.choice(["tube", "convolution"]))
        with lock:
            skins.append(skin)

    def close_skin(r):
        skin = a_skin(r)
        if skin is not None:
            skin.close()

    def save(r):
        state = scene.save_state()
        with lock:
            saved.append(state)

    def restore(r):
        with lock:
            state = r.choice(saved)
        scene.restore_state(state)

    def pose(r):
        tool.set_pose((r.uniform(-0.05, 0.05), r.uniform(-0.05, 0.05), r.uniform(-0.04, 0.06)))

    def skin_call(name):
        def call(r):
            skin = a_skin(r)
            if skin is not None:
                result = getattr(skin, name)()
                if name == "mesh" and result.vertex_count:
                    assert np.isfinite(result.positions).all() and (result.indices < result.vertex_count).all()
        return call

    menu = [
        (30, lambda r: scene.step(0.001)),
        (8, lambda r: scene.axis(r.randint(2, 64))),
        (8, lambda r: scene.control_points()),
        (6, lambda r: scene.stats()),
        (4, lambda r: scene.contacts()),
        (3, lambda r: scene.contact_summary()),
        (12, pose),
        (6, lambda r: tool.feedback()),
        (4, lambda r: tool.wrench()),
        (2, lambda r: tool.grasp()),
        (2, lambda r: tool.release()),
        (10, skin_call("update")),
        (8, skin_call("mesh")),
        (1, skin_call("metrics")),
        (3, save),
        (3, restore),
        (2, new_skin),
        (1, close_skin),
        (1, lambda r: scene.close() if r.random() < 0.05 else None),
    ]
    weights = [w for w, _ in menu]
    functions = [f for _, f in menu]
    end = time.monotonic() + seconds

    def worker(index):
        r = random.Random(seed * 1000 + index)
        while time.monotonic() < end:
            call = r.choices(functions, weights)[0]
            try:
                call(r)
                outcome = "ok"
            except ValueError as error:
                if "closed" not in str(error):
                    failures.append("thread %d: ValueError not of a closed handle: %s" % (index, error))
                    return
                outcome = "closed"
            except enteron.Error:
                outcome = "error"
            except BaseException as error:  # noqa: B902: anything else is a failure of the seed
                failures.append("thread %d: %s: %s" % (index, type(error).__name__, error))
                return
            with lock:
                calls[outcome] += 1

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    scene.close()
    if failures:
        for line in failures:
            print("stress_threads: seed %d: %s" % (seed, line), file=sys.stderr)
        return 1
    print("stress_threads: seed %d: %d calls (%d raised closed, %d enteron.Error)"
          % (seed, sum(calls.values()), calls["closed"], calls["error"]))
    return 0


def driver(first, seeds, seconds):
    start = time.monotonic()
    failed = []
    for seed in range(first, first + seeds):
        result = subprocess.run([sys.executable, os.path.abspath(__file__), "--child", str(seed),
                                 "--seconds", str(seconds)], capture_output=True, text=True, timeout=300)
        if result.returncode != 0:
            how = ("killed by signal %d" % -result.returncode if result.returncode < 0
                   else "exit status %d" % result.returncode)
            failed.append(seed)
            print("stress_threads: seed %d FAILED (%s)\n%s%s" % (seed, how, result.stdout[-2000:],
                                                                result.stderr[-4000:]))
        else:
            sys.stdout.write(result.stdout)
    elapsed = time.monotonic() - start
    print("stress_threads: %d runs (seeds %d to %d), %.1f s of calls each, %d failed, %.1f s in all"
          % (seeds, first, first + seeds - 1, seconds, len(failed), elapsed))
    return 1 if failed else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--child", type=int)
    parser.add_argument("--seeds", type=int, default=40)
    parser.add_argument("--first", type=int, default=1)
    parser.add_argument("--seconds", type=float, default=0.3)
    args = parser.parse_args()
    if args.child is not None:
        return child(args.child, args.seconds)
    return driver(args.first, args.seeds, args.seconds)


if __name__ == "__main__":
    sys.exit(main())
