#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The patient's anatomy (examples/scenes/patient/, docs/anatomy.md "The patient"):
- the generator (examples/scenes/make_patient.py) writes exactly the committed files;
- each dimension of the layout lies within the range its source gives
  (examples/scenes/patient/anatomy_sources.json), or is listed as a departure with its reason;
- each derived tissue constant is its formula of its inputs, within its source's range;
- the layout can start a scene: the small bowel and the colon inside the cavity, out of the
  organs, clear of each other and of themselves (apart from the ileocaecal junction);
- the meshes are closed (organs and cavity) and modest (under 10000 triangles).
Run: /usr/bin/python3 tests/patient/test_patient.py [-v]   (Python 3 with numpy)."""
import filecmp
import json
import math
import os
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENES = os.path.join(ROOT, "examples", "scenes")
PATIENT = os.path.join(SCENES, "patient")
sys.path.insert(0, SCENES)
import make_patient  # noqa: E402

GENERATED = ["layout.json", "organs/abdominal_wall.obj", "organs/liver.obj", "organs/gallbladder.obj",
             "organs/stomach.obj", "targets/right_colon_bed.obj", "targets/pelvic_floor.obj"]


def load_layout():
    with open(os.path.join(PATIENT, "layout.json")) as f:
        return json.load(f)


def polyline_length(points):
    return float(np.sum(np.linalg.norm(np.diff(np.asarray(points), axis=0), axis=1)))


def measure(layout, name):
    """The layout's value of a named dimension (anatomy_sources.json, "measure")."""
    bowel, colon = layout["small_bowel"], layout["colon"]
    landmarks = layout["landmarks"]
    root = np.asarray(layout["mesenteric_root"])
    kind, _, part = name.partition(":")
    if kind == "small_bowel_length_m":
        return polyline_length(bowel["points"])
    if kind == "small_bowel_first_radius_m":
        return bowel["radii"][0]
    if kind == "small_bowel_last_radius_m":
        return bowel["radii"][-1]
    if kind == "mesenteric_root_length_m":
        return float(np.linalg.norm(root[1] - root[0]))
    if kind == "mesenteric_root_slope_deg":
        d = root[1] - root[0]
        return math.degrees(math.atan2(abs(d[1]), abs(d[0])))
    if kind == "duodenojejunal_flexure_x_m":
        return landmarks["duodenojejunal_flexure"][0]
    if kind == "ileocaecal_junction_right_and_below":
        return int(landmarks["ileocaecal_junction"][0] > 0 and landmarks["ileocaecal_junction"][1] < 0)
    if kind == "aortic_bifurcation_y_m":
        return landmarks["aortic_bifurcation"][1] - landmarks["umbilicus_inner"][1]
    if kind == "splenic_above_hepatic":
        return int(landmarks["splenic_flexure"][1] > landmarks["hepatic_flexure"][1])
    if kind == "colon_length_m":
        return polyline_length(colon["points"])
    if kind in ("colon_part_length_m", "colon_part_largest_radius_m"):
        start, end = colon["parts_arc_length_m"][part]
        if kind == "colon_part_length_m":
            return end - start
        arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(np.asarray(colon["points"]), axis=0), axis=1))])
        inside = (arc >= start - 1e-9) & (arc <= end + 1e-9)
        return float(np.max(np.asarray(colon["radii"])[inside]))
    raise KeyError("no measurement named %r" % name)


def clearance(points, radii, others, other_radii, skip=None):
    """The smallest gap between the tubes' surfaces (axis distance minus both radii), m;
    `skip`: leave out samples within this many of each other (one tube against itself)."""
    p, q = np.asarray(points), np.asarray(others)
    worst = math.inf
    for i in range(len(p)):
        gaps = np.linalg.norm(q - p[i], axis=1) - radii[i] - np.asarray(other_radii)
        if skip is not None:
            gaps[max(0, i - skip):i + skip + 1] = math.inf
        worst = min(worst, float(gaps.min()))
    return worst


class PatientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.layout = load_layout()
        with open(os.path.join(PATIENT, "anatomy_sources.json")) as f:
            cls.sources = json.load(f)

    def test_the_generator_writes_the_committed_files(self):
        with tempfile.TemporaryDirectory() as out:
            make_patient.main(out)
            for name in GENERATED:
                self.assertTrue(filecmp.cmp(os.path.join(out, name), os.path.join(PATIENT, name), shallow=False),
                                "%s differs from what examples/scenes/make_patient.py writes: run it and commit" % name)

    def test_each_dimension_lies_within_its_sources_range(self):
        for entry in self.sources["dimensions"]:
            self.assertIn(entry["source"], self.sources["sources"], entry["name"])
            value = measure(self.layout, entry["measure"])
            low, high = entry["range"]
            if "departs" in entry:
                # A known departure: outside its source's range, with the reason written down.
                self.assertFalse(low <= value <= high, "%s is within its range now: drop 'departs'" % entry["name"])
                self.assertGreater(len(entry["departs"]), 40, entry["name"])
                continue
            self.assertTrue(low <= value <= high,
                            "%s: %.4g %s outside [%g, %g] (%s)" % (entry["name"], value, entry["unit"], low, high,
                                                                   entry["source"]))

    def test_each_constant_follows_from_its_inputs_and_its_source(self):
        formulas = {"E * 2 pi r t": lambda i: i["E"] * 2 * math.pi * i["r"] * i["t"],
                    "E * pi r^3 t": lambda i: i["E"] * math.pi * i["r"] ** 3 * i["t"],
                    "rho * 2 pi r t": lambda i: i["rho"] * 2 * math.pi * i["r"] * i["t"],
                    "E * w * h / L": lambda i: i["E"] * i["w"] * i["h"] / i["L"]}
        for entry in self.sources["constants"]:
            self.assertIn(entry["source"], self.sources["sources"], entry["name"])
            self.assertTrue(entry["derivation"], entry["name"])
            if "derived" in entry:
                expected = formulas[entry["derived"]](entry["inputs"])
                self.assertAlmostEqual(entry["value"] / expected, 1.0, delta=0.01, msg=entry["name"])
            if "range" in entry:
                low, high = entry["range"]
                self.assertTrue(low <= entry["value"] <= high, entry["name"])

    def test_the_tubes_start_inside_the_cavity_clear_of_organs_and_of_each_other(self):
        bowel = (np.asarray(self.layout["small_bowel"]["points"]), np.asarray(self.layout["small_bowel"]["radii"]))
        colon = (np.asarray(self.layout["colon"]["points"]), np.asarray(self.layout["colon"]["radii"]))
        for name, (points, radii) in (("small bowel", bowel), ("colon", colon)):
            free = np.array([make_patient.clear_of(points[i:i + 1], radii[i], [])[0] for i in range(len(points))])
            self.assertTrue(free.all(), "%s: %d points outside the cavity or in an organ, first %s"
                            % (name, (~free).sum(), points[~free][:1]))
        self.assertGreaterEqual(clearance(*bowel, *bowel, skip=6), 0.0, "the small bowel's loops overlap")
        self.assertGreaterEqual(clearance(*colon, *colon, skip=8), 0.0, "the colon overlaps itself")
        # The ileum joins the caecum at the ileocaecal junction: its last 3 cm may touch it.
        self.assertGreaterEqual(clearance(bowel[0][:-3], bowel[1][:-3], *colon), 0.0, "the small bowel overlaps the colon")
        # The ends are the landmarks.
        np.testing.assert_allclose(bowel[0][0], self.layout["landmarks"]["duodenojejunal_flexure"], atol=1e-6)
        np.testing.assert_allclose(bowel[0][-1], self.layout["landmarks"]["ileocaecal_junction"], atol=1e-6)
        np.testing.assert_allclose(colon[0][-1], self.layout["landmarks"]["rectosigmoid_junction"], atol=1e-6)

    def test_the_meshes_are_closed_oriented_and_modest(self):
        for name in GENERATED[1:]:
            vertices, triangles = [], []
            with open(os.path.join(PATIENT, name)) as f:
                for line in f:
                    if line.startswith("v "):
                        vertices.append([float(c) for c in line.split()[1:]])
                    elif line.startswith("f "):
                        triangles.append([int(c) - 1 for c in line.split()[1:]])
            self.assertLess(len(triangles), 10000, name)
            edges = {}
            for a, b, c in triangles:
                for e in ((a, b), (b, c), (c, a)):
                    edges[e] = edges.get(e, 0) + 1
            closed = all(edges.get((b, a), 0) == 1 and n == 1 for (a, b), n in edges.items())
            if name.startswith("organs/"):
                self.assertTrue(closed, "%s is not closed and consistently oriented" % name)
                # Signed volume: positive for normals out (organs), negative for the cavity (normals in).
                v = np.asarray(vertices)
                t = np.asarray(triangles)
                volume = float(np.sum(np.einsum("ij,ij->i", v[t[:, 0]], np.cross(v[t[:, 1]], v[t[:, 2]])))) / 6.0
                if name == "organs/abdominal_wall.obj":
                    self.assertLess(volume, -0.005, "the cavity's normals must face in (%.4f m^3)" % volume)
                else:
                    self.assertGreater(volume, 0.0, "%s's normals must face out" % name)


if __name__ == "__main__":
    unittest.main()
