# SPDX-License-Identifier: Apache-2.0
"""Tests of enteron-viewer (docs/viewer.md), run by ctest (label "viewer").

The window tests run the viewer under an Xvfb server of their own (software rendering
with Mesa's llvmpipe); the --headless tests need no display (EGL, Mesa's surfaceless
platform). Each test runs the viewer as a user would and looks at what it wrote: the
pictures' pixels, the video's frames, the summary lines, the exit status.

    ENTERON_VIEWER=build/examples/viewer/enteron-viewer python3 -m unittest viewer_test
"""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import numpy
from PIL import Image

VIEWER = os.environ.get("ENTERON_VIEWER", "enteron-viewer")
WIDTH, HEIGHT = 1280, 720
ABDOMEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples", "scenes", "abdomen.json")


def colour_classes(path):
    """The picture's pixels as boolean masks: the bowel's pink, the tools' blue steel,
    and the reds of an error message."""
    rgb = numpy.asarray(Image.open(path).convert("RGB"), dtype=numpy.float64) / 255.0
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    high, low = rgb.max(axis=2), rgb.min(axis=2)
    saturation = numpy.where(high > 0, (high - low) / numpy.maximum(high, 1e-9), 0.0)
    pink = (r == high) & (saturation > 0.25) & (high > 0.35) & (g >= b * 0.8) & (g < r * 0.85)
    blue = (b == high) & (saturation > 0.2) & (high > 0.2) & (b > r * 1.15)
    error_red = (r > 0.8) & (g < 0.55) & (b < 0.5)
    return rgb, pink, blue, error_red


def organ_classes(path):
    """The abdomen scene's organ colours (renderer.cpp, organ_mesh_material) as masks: the
    liver's red-brown (red, and blue well under green where the bowel's pink has them
    about equal), the stomach's bright pale orange (green near red, blue under green)."""
    rgb = numpy.asarray(Image.open(path).convert("RGB"), dtype=numpy.float64) / 255.0
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    liver = (r > 0.2) & (g < 0.55 * r) & (b < 0.8 * g)
    stomach = (r > 0.6) & (g > 0.7 * r) & (g < 0.92 * r) & (b < 0.88 * g)
    return liver, stomach


class ViewerTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="enteron_viewer_test_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)
        return self.path(name)

    def run_viewer(self, args, window, timeout=240):
        """Runs the viewer (in a window on a private Xvfb, or as given) and returns
        (exit status, stdout, stderr)."""
        environment = dict(os.environ)
        xvfb = None
        if window:
            # -displayfd: Xvfb picks a free display itself, so tests may run side by side.
            read_end, write_end = os.pipe()
            xvfb = subprocess.Popen(
                ["Xvfb", "-displayfd", str(write_end), "-screen", "0", "%dx%dx24" % (WIDTH + 64, HEIGHT + 64),
                 "-nolisten", "tcp"],
                pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            os.close(write_end)
            with os.fdopen(read_end) as numbers:
                display = numbers.readline().strip()
            self.assertTrue(display, "Xvfb did not start")
            environment["DISPLAY"] = ":" + display
            args = args + ["--size", "%dx%d" % (WIDTH, HEIGHT)]
        else:
            environment.pop("DISPLAY", None)  # headless must need no display
        try:
            done = subprocess.run([VIEWER] + args, cwd=self.dir, env=environment, stdin=subprocess.DEVNULL,
                                  capture_output=True, text=True, timeout=timeout)
        finally:
            if xvfb is not None:
                xvfb.terminate()
                xvfb.wait(timeout=30)
        return done.returncode, done.stdout, done.stderr

    def summary(self, stdout):
        """The numbers of the viewer's summary lines."""
        plot = re.search(r"force plot: (\d+) samples, (\d+) non-zero, largest \|F\| ([0-9.]+) N"
                         r"(?:, first contact at t = ([0-9.]+) s)?", stdout)
        self.assertIsNotNone(plot, stdout)
        return {"samples": int(plot.group(1)), "nonzero": int(plot.group(2)), "largest_N": float(plot.group(3)),
                "first_contact_s": float(plot.group(4)) if plot.group(4) else None,
                "failures": int(re.search(r"(\d+) failed calls", stdout).group(1))}

    def test_window_shows_the_bowel(self):
        """With no scene the viewer opens the demo scene; its frame shows the bowel: the
        bowel's pink covers a plausible share of the picture, among many colours."""
        status, out, err = self.run_viewer(["--seconds", "1.5", "--screenshot", "shot.png"], window=True)
        self.assertEqual(status, 0, err)
        rgb, pink, _, _ = colour_classes(self.path("shot.png"))
        self.assertEqual(rgb.shape, (HEIGHT, WIDTH, 3))
        share = pink.mean()
        self.assertGreater(share, 0.03, "too little of the bowel's pink: %.3f" % share)
        self.assertLess(share, 0.60, "the picture is nearly all pink: %.3f" % share)
        colours = len(numpy.unique((rgb * 255).astype(numpy.uint32) @ numpy.array([65536, 256, 1])))
        self.assertGreater(colours, 1000, "a flat picture: %d colours" % colours)
        # The pink is a shaded tube, not a flat fill: its brightness varies.
        self.assertGreater(rgb[pink].max(axis=1).std(), 0.05)
        self.assertEqual(self.summary(out)["failures"], 0)

    def test_drag_moves_the_tool(self):
        """A scripted drag (the left button, through the same code as the mouse) brings the
        tool under the pointer: its steel blue appears where the drag ends and was not
        there before, and the picture changes there."""
        x, y = 900, 420
        script = self.write("drag.txt", "\n".join([
            "0.4 screenshot before.png",
            "0.5 mouse 640 300 down",
            "1.5 mouse %d %d down" % (x, y),
            "2.3 mouse %d %d up" % (x, y),
            "2.3 screenshot after.png", ""]))
        status, out, err = self.run_viewer(["--seconds", "2.4", "--script", script, "--ui", "none"], window=True)
        self.assertEqual(status, 0, err)
        before_rgb, _, before_blue, _ = colour_classes(self.path("before.png"))
        after_rgb, _, after_blue, _ = colour_classes(self.path("after.png"))
        window = (slice(y - 40, y + 41), slice(x - 40, x + 41))
        self.assertLess(before_blue[window].sum(), 20, "the tool was already at the end of the drag")
        self.assertGreater(after_blue[window].sum(), 150, "the tool did not follow the drag")
        # The tool's tip ends under the pointer: the lowest of its pixels is near (x, y).
        rows, columns = numpy.nonzero(after_blue[window])
        tip = numpy.argmax(rows)
        self.assertLess(abs(rows[tip] - 40) + abs(columns[tip] - 40), 20)
        changed = numpy.abs(after_rgb - before_rgb).max(axis=2) > 0.1
        self.assertGreater(changed[window].mean(), 0.05)

    def test_force_plot_receives_the_forces(self):
        """The tool waits above the bowel, then goes down into it: the force plot gets a
        sample for every step, all zero until the tool reaches the bowel, then forces."""
        script = self.write("path.txt", "0 tool -0.1 0 0.3\n1.0 tool -0.1 0 0.3\n2.0 tool 0.05 0 -0.08\n")
        status, out, err = self.run_viewer(["--headless", "--seconds", "2.5", "--fps", "4", "--size", "320x180",
                                            "--script", script], window=False)
        self.assertEqual(status, 0, err)
        plot = self.summary(out)
        self.assertEqual(plot["samples"], 2500, "every 1 ms step is plotted")
        self.assertGreater(plot["nonzero"], 50)
        self.assertGreater(plot["largest_N"], 0.1)
        self.assertLessEqual(plot["largest_N"], 5.0 + 1e-9, "beyond the tool's max_force")
        self.assertIsNotNone(plot["first_contact_s"])
        self.assertGreater(plot["first_contact_s"], 1.0, "a force while the tool was in the air")

    def test_headless_writes_frames_and_video(self):
        """--headless writes the frames asked for, a PNG each, of the size asked, that change
        as the bowel falls, and the same frames as a video (MP4 and GIF)."""
        for video in ("run.mp4", "run.gif"):
            with self.subTest(video=video):
                frames = self.path("frames_" + video[-3:])
                status, out, err = self.run_viewer(["--headless", "--seconds", "1", "--fps", "10", "--size", "320x180",
                                                    "--frames", frames, "--video", video], window=False)
                self.assertEqual(status, 0, err)
                names = sorted(os.listdir(frames))
                self.assertEqual(names, ["frame_%05d.png" % k for k in range(1, 11)])
                first = numpy.asarray(Image.open(os.path.join(frames, names[0])).convert("RGB"), dtype=float)
                last = numpy.asarray(Image.open(os.path.join(frames, names[-1])).convert("RGB"), dtype=float)
                self.assertEqual(first.shape, (180, 320, 3))
                self.assertGreater(numpy.abs(last - first).max(axis=2).__gt__(25).mean(), 0.005, "nothing moved")
                probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                                        "-show_entries", "stream=width,height,nb_read_frames", "-of", "csv=p=0",
                                        self.path(video)], capture_output=True, text=True, check=True)
                self.assertEqual(probe.stdout.strip().split(",")[:3], ["320", "180", "10"], probe.stdout)

    def test_headless_abdomen_scene(self):
        """The abdomen scene (organ meshes) headless, with its motion: the liver, the
        stomach and the bowel are all in the picture, and the liver is drawn where it is
        now: after the retractor lifted it 4 cm (1 to 1.5 s) its pixels are higher up."""
        frames = self.path("frames")
        status, out, err = self.run_viewer([ABDOMEN, "--headless", "--seconds", "2", "--fps", "5", "--size", "640x360",
                                            "--ui", "none", "--frames", frames], window=False)
        self.assertEqual(status, 0, err)
        self.assertEqual(self.summary(out)["failures"], 0)
        before, after = (os.path.join(frames, "frame_%05d.png" % k) for k in (4, 10))  # t = 0.8 s, 2.0 s
        _, pink, _, _ = colour_classes(after)
        self.assertGreater(pink.mean(), 0.02, "too little of the bowel's pink")
        top = {}
        for name, frame in (("before", before), ("after", after)):
            liver, stomach = organ_classes(frame)
            self.assertGreater(liver.sum(), 300, "no liver in the %s frame" % name)
            self.assertGreater(stomach.sum(), 300, "no stomach in the %s frame" % name)
            top[name] = numpy.percentile(numpy.nonzero(liver)[0], 2)  # its top edge (the bowel may hide its foot)
        # 4 cm up is about 20 pixels at this distance and size; the image's rows grow downwards.
        self.assertGreater(top["before"] - top["after"], 8.0, "the liver did not move up: top rows %s" % top)

    def test_headless_laparoscope(self):
        """--laparoscope (and key V) look through the 30-degree scope from the umbilical port:
        a round field on black, the bowel's pink inside it, lit from the tip; V goes back to
        the orbit camera (the grey background again) and forward to the scope."""
        script = self.write("scope.txt", "\n".join([
            "0.5 screenshot scope.png", "0.6 key V", "1.0 screenshot orbit.png", "1.1 key V",
            "1.5 screenshot scope_again.png", ""]))
        status, out, err = self.run_viewer([ABDOMEN, "--headless", "--laparoscope", "--seconds", "1.6", "--fps", "10",
                                            "--size", "640x360", "--ui", "none", "--script", script], window=False)
        self.assertEqual(status, 0, err)
        height, width = 360, 640
        rows, columns = numpy.mgrid[0:height, 0:width]
        outside = numpy.hypot(columns + 0.5 - width / 2, rows + 0.5 - height / 2) > 0.55 * height + 2
        for name in ("scope.png", "scope_again.png"):
            rgb, pink, _, _ = colour_classes(self.path(name))
            self.assertLess(rgb[outside].max(), 0.02, "%s: not black outside the scope's round field" % name)
            self.assertGreater(pink[~outside].mean(), 0.15, "%s: too little bowel in the scope's field" % name)
        rgb, _, _, _ = colour_classes(self.path("orbit.png"))
        self.assertGreater(rgb[:20, :20].mean(), 0.03, "key V did not go back to the orbit camera")

    def test_bad_scene_headless(self):
        """A scene file the library refuses: the message naming the key, exit status 1,
        nothing written."""
        scene = self.write("bad.json", '{"intestine": {"radius": -1}}')
        status, out, err = self.run_viewer([scene, "--headless", "--seconds", "1", "--screenshot", "x.png"],
                                           window=False)
        self.assertEqual(status, 1)
        self.assertIn("intestine.radius must be > 0, got -1", err)
        self.assertIn("ENT_ERROR_INVALID_SCENE", err)
        self.assertFalse(os.path.exists(self.path("x.png")))
        # A script that moves an obstacle the scene does not have (the abdomen's liver on
        # the demo scene, whose one obstacle is the cavity): refused when the scene opens.
        status, out, err = self.run_viewer(["--script", "abdomen", "--headless", "--seconds", "1"], window=False)
        self.assertEqual(status, 1)
        self.assertIn("the script moves obstacle 1, the scene has 1", err)

    def test_bad_scene_window(self):
        """In a window the same error is on the screen: the status line's red text along the
        bottom of the picture, and the panel's; exit status 1 when the window closes."""
        scene = self.write("bad.json", '{"intestine": {"lenght": 2}}')
        status, out, err = self.run_viewer([scene, "--seconds", "1", "--screenshot", "shot.png"], window=True)
        self.assertEqual(status, 1)
        self.assertIn('unknown key "lenght" in intestine', err)
        _, pink, _, red = colour_classes(self.path("shot.png"))
        self.assertGreater(red[HEIGHT - 30:, :].sum(), 200, "no error text on the status line")
        scene_area = pink[:HEIGHT - 40, 420:]  # right of the panel, above the status line
        self.assertLess(scene_area.mean(), 0.001, "a bowel drawn from a scene that did not load")

    def test_library_error_reported(self):
        """A call the library refuses during the run (here every step: the explicit
        integrator would need more substeps than the scene allows) is reported with its
        ENT_ERROR_* name and message, the simulation pauses, and --headless exits 1."""
        scene = self.write("refused.json", """{
            "intestine": {"length": 1.0, "control_points": 40, "stretch_stiffness": 1e5,
                          "shape": {"kind": "line", "center": [-0.5, 0, 0]}},
            "solver": {"integrator": "symplectic_euler", "timestep": 0.01, "max_substeps": 1}}""")
        status, out, err = self.run_viewer([scene, "--headless", "--seconds", "0.5", "--fps", "10", "--size",
                                            "320x180"], window=False)
        self.assertEqual(status, 1)
        self.assertIn("ENT_ERROR_INVALID_ARGUMENT from ent_scene_step at t = 0.000 s", err)
        self.assertIn("more than max_substeps (1)", err)
        self.assertEqual(err.count("ENT_ERROR_"), 1, "reported once, not once a frame")
        self.assertEqual(self.summary(out)["failures"], 1, "paused after the failure")

    def test_bad_command_line(self):
        """Mistakes on the command line or in a script: a message naming them, status 2."""
        script = self.write("bad_script.txt", "0.5 mouse 10 20\n")
        obstacle_script = self.write("bad_obstacle.txt", "0.5 obstacle 1 0 0\n")
        for args, message in ((["--seconds", "x"], "--seconds wants a number"),
                              (["--headless"], "--headless needs --seconds"),
                              (["--video", "a.avi", "--headless", "--seconds", "1"], "--video wants a .mp4 or .gif"),
                              (["--script", script], "bad_script.txt:1: mouse wants X Y down|up"),
                              (["--script", obstacle_script], "bad_obstacle.txt:1: obstacle wants an obstacle number"),
                              (["--lcm", "memq://", "scene.json"], "--lcm shows the server's scene"),
                              (["--channel-suffix", "_A"], "--channel-suffix goes with --lcm"),
                              (["--lcm", "memq://", "--script", "demo"], "mouse lines, not tool lines")):
            with self.subTest(args=args):
                status, out, err = self.run_viewer(args, window=False)
                self.assertIn(message, err)
                self.assertEqual(status, 2)


if __name__ == "__main__":
    unittest.main()
