#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the adult patient's organs and layout (examples/scenes/patient/): an insufflated
abdomen as seen at laparoscopy, with the dimensions and landmarks of docs/anatomy.md
("The patient") and examples/scenes/patient/anatomy_sources.json.

The frame (metres): the patient lies supine. The origin is on the posterior parietal
peritoneum in the midline at the level of the umbilicus (over the lower body of L4 and the
aortic bifurcation, Nezhat et al. 1998: 0.1 +- 1.2 cm from the umbilicus in the supine
position). +x is the patient's right, +y cranial, +z anterior (up: gravity is -z).

Written here (deterministic: the same files on every run, on every machine):
- organs/abdominal_wall.obj: the peritoneal cavity insufflated to 12-15 mmHg, normals in
  (the bowel is kept inside): the anterior wall a dome 13 cm above the origin at the
  umbilicus, the posterior wall with the vertebral bodies in the midline and the
  paravertebral gutters beside them (where the ascending and descending colon lie), the
  diaphragm's domes, the pelvis narrower and deeper.
- organs/liver.obj, organs/gallbladder.obj, organs/stomach.obj: closed, normals out,
  each in its own frame (its centre; layout.json gives where it goes), so that a
  retractor can move it (ent_obstacle_set_pose).
- targets/right_colon_bed.obj, targets/pelvic_floor.obj, targets/gallbladder_fundus.obj:
  small open patches on those surfaces, targets for the exposure query (ent_scene_exposure),
  not obstacles.
- layout.json: the landmarks, the organs' positions, the mesenteric root, and the layout
  paths of the colon (caecum to the rectosigmoid junction, with its parts) and of the small
  bowel (duodenojejunal flexure to the ileocaecal junction, packed in loops in the
  infracolic compartment), each point with its radius: data for a scene to lay its tubes
  on.

Run from anywhere: /usr/bin/python3 examples/scenes/make_patient.py [output folder]
(Python 3 with numpy). tests/patient checks that the committed files are what this writes,
and that every dimension lies within the range its source gives.
"""
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

# ---- the cavity ------------------------------------------------------------------------------

CAVITY_TOP = 0.13        # m: the anterior wall above the origin (insufflated; docs/anatomy.md)
CAVITY_CRANIAL = 0.25    # the diaphragm's domes above the umbilicus
CAVITY_CAUDAL = -0.17    # the pelvic floor below it
CAVITY_HALF_WIDTH = 0.15  # flank to flank / 2 at the umbilicus
PELVIS_HALF_WIDTH = 0.065  # the pelvic inlet's transverse diameter / 2
GUTTER_DEPTH = 0.035     # the paravertebral gutters below the midline's vertebral bodies
SPINE_HALF_WIDTH = 0.045  # the vertebral bodies and psoas as a bump this wide (1/e)


def smoothstep(edge0, edge1, x):
    t = np.clip((x - edge0) / (edge1 - edge0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def half_width(y):
    """The cavity's half width at height y: the abdomen, narrowing to the pelvic inlet."""
    return PELVIS_HALF_WIDTH + (CAVITY_HALF_WIDTH - PELVIS_HALF_WIDTH) * smoothstep(-0.15, -0.075, y)


def posterior_wall(x, y):
    """z of the posterior parietal peritoneum: the vertebral bodies in the midline, the
    gutters beside them, the pelvis (below the sacral promontory) deeper."""
    spine = -GUTTER_DEPTH + GUTTER_DEPTH * np.exp(-(x / SPINE_HALF_WIDTH) ** 2)
    promontory = 0.012 * np.exp(-((y + 0.075) / 0.02) ** 2) * np.exp(-(x / 0.04) ** 2)
    sacral_hollow = -0.03 * smoothstep(-0.08, -0.14, y)
    diaphragm_rise = 0.06 * smoothstep(0.12, 0.24, y)  # the domes curve forward
    return spine + promontory + sacral_hollow + diaphragm_rise


def cavity_inside(p):
    """< 0 inside the cavity, > 0 outside (the sign is what counts; the magnitude is about
    a distance in m near the surface)."""
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    center_y = 0.5 * (CAVITY_CRANIAL + CAVITY_CAUDAL)
    half_y = 0.5 * (CAVITY_CRANIAL - CAVITY_CAUDAL)
    bottom = posterior_wall(x, y)
    across = np.abs(x) / half_width(y)    # 1 at the flanks
    along = np.abs(y - center_y) / half_y  # 1 at the diaphragm and the pelvic floor
    # The anterior dome: a superellipse across (exponent 3), flatter along (exponent 4).
    dome = np.clip(1.0 - across ** 3, 0.0, None) ** (1.0 / 3.0) * np.clip(1.0 - along ** 4, 0.0, None) ** 0.25
    top = bottom + (CAVITY_TOP - bottom) * dome
    outside_xy = np.maximum(across - 1.0, along - 1.0) * 0.1
    return np.maximum(np.maximum(bottom - z, z - top), outside_xy)


def radial_surface(inside, center, rings, segments, reach=0.5):
    """The surface where inside() changes sign, found along rays from center (the surface
    must be star-shaped about it), parametrised like a sphere (theta from -z to +z)."""
    directions = [np.array([0.0, 0.0, -1.0])]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2.0 * math.pi * j / segments
            directions.append(np.array([math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                                        -math.cos(theta)]))
    directions.append(np.array([0.0, 0.0, 1.0]))
    d = np.array(directions)
    # March out in steps of 2 mm to the first crossing, then bisect.
    steps = np.arange(1, int(reach / 0.002) + 1) * 0.002
    pts = center[None, None, :] + steps[None, :, None] * d[:, None, :]
    values = inside(pts)
    first_out = np.argmax(values > 0.0, axis=1)
    lo = np.where(first_out > 0, steps[np.maximum(first_out - 1, 0)], 0.0)
    hi = steps[first_out]
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        out = inside(center[None, :] + mid[:, None] * d) > 0.0
        hi = np.where(out, mid, hi)
        lo = np.where(out, lo, mid)
    vertices = center[None, :] + (0.5 * (lo + hi))[:, None] * d
    return vertices, sphere_triangles(rings, segments)


def sphere_triangles(rings, segments):
    def at(ring, j):
        return 1 + (ring - 1) * segments + j % segments
    north = 1 + (rings - 1) * segments
    triangles = [(0, at(1, j + 1), at(1, j)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            triangles += [(at(i, j), at(i, j + 1), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i + 1, j))]
    triangles += [(north, at(rings - 1, j), at(rings - 1, j + 1)) for j in range(segments)]
    return triangles


def ellipsoid(half, rings, segments, right_thickening=0.0):
    """An ellipsoid about the origin, normals out; right_thickening > 0 makes it thicker in
    z toward +x (a liver's right lobe)."""
    vertices = [(0.0, 0.0, -half[2])]
    for i in range(1, rings):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2.0 * math.pi * j / segments
            x = half[0] * math.sin(theta) * math.cos(phi)
            y = half[1] * math.sin(theta) * math.sin(phi)
            z = -half[2] * math.cos(theta) * (1.0 + right_thickening * x / half[0])
            vertices.append((x, y, z))
    vertices.append((0.0, 0.0, half[2]))
    return np.array(vertices), sphere_triangles(rings, segments)


def rotate(vertices, axis, degrees):
    """Turns the vertices about a unit axis through the origin (Rodrigues)."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    a = math.radians(degrees)
    v = np.asarray(vertices)
    return (v * math.cos(a) + np.cross(k, v) * math.sin(a) + np.outer(v @ k, k) * (1.0 - math.cos(a)))


def patch_on_wall(x_range, y_range, cells):
    """An open patch of the posterior wall (its triangles facing +z, into the cavity)."""
    xs = np.linspace(x_range[0], x_range[1], cells[0] + 1)
    ys = np.linspace(y_range[0], y_range[1], cells[1] + 1)
    vertices = [(x, y, float(posterior_wall(x, y))) for y in ys for x in xs]
    row = cells[0] + 1
    triangles = []
    for j in range(cells[1]):
        for i in range(cells[0]):
            a = j * row + i
            triangles += [(a, a + 1, a + row + 1), (a, a + row + 1, a + row)]
    return np.array(vertices), triangles


def write_obj(root, name, description, vertices, triangles, inward=False):
    path = os.path.join(root, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as obj:
        obj.write("# %s\n# Made by examples/scenes/make_patient.py; metres; %d triangles, %s.\n"
                  % (description, len(triangles), "normals in (a cavity)" if inward else "facing out"))
        for v in vertices:
            obj.write("v %.5f %.5f %.5f\n" % (v[0] + 0.0, v[1] + 0.0, v[2] + 0.0))
        for a, b, c in triangles:
            if inward:
                b, c = c, b
            obj.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


# The small bowel's outer radius, jejunum to terminal ileum (docs/anatomy.md).
SMALL_BOWEL_RADII = (0.011, 0.009)

# ---- the layout ------------------------------------------------------------------------------

# Landmarks (m, the frame above); docs/anatomy.md gives each one's source.
LANDMARKS = {
    "umbilicus_inner": [0.0, 0.0, CAVITY_TOP],
    "umbilical_port": [0.0, 0.0, CAVITY_TOP + 0.03],       # the skin, 3 cm of wall above the peritoneum
    "aortic_bifurcation": [0.0, 0.0, 0.0],
    "duodenojejunal_flexure": [-0.025, 0.075, 0.02],        # left of L2
    "ileocaecal_junction": [0.05, -0.055, 0.02],             # right iliac fossa, at the right sacroiliac joint
    "sacral_promontory": [0.0, -0.075, 0.012],
    "hepatic_flexure": [0.11, 0.11, 0.035],
    "splenic_flexure": [-0.112, 0.14, 0.03],
    "rectosigmoid_junction": [0.0, -0.13, -0.005],
}

# Organ frames: centre (m) and orientation (w x y z) of each closed organ mesh.
ORGANS = {
    "liver": {"position": [0.055, 0.2, 0.06], "orientation": [1.0, 0.0, 0.0, 0.0]},
    "gallbladder": {"position": [0.055, 0.16, 0.07], "orientation": [1.0, 0.0, 0.0, 0.0]},
    "stomach": {"position": [-0.05, 0.205, 0.07], "orientation": [1.0, 0.0, 0.0, 0.0]},
}
# Their shapes in their frames: half axes (m), thickening toward +x, then a turn (axis, degrees).
ORGAN_SHAPES = {
    "liver": ((0.10, 0.075, 0.06), 0.35, ([1, 0, 0], -20.0), "A liver: 20 x 15 x 12 cm, thicker on the right"),
    "gallbladder": ((0.015, 0.045, 0.015), 0.0, ([1, 0, 0], 35.0), "A gallbladder: 9 x 3 x 3 cm, fundus forward"),
    "stomach": ((0.06, 0.075, 0.045), 0.0, ([0, 0, 1], -30.0), "A stomach: 12 x 15 x 9 cm"),
}


def inside_organs(points):
    """Whether each point (n x 3, the patient's frame) lies inside an organ."""
    inside = np.zeros(len(points), dtype=bool)
    for name, (half, thickening, (axis, degrees), _) in ORGAN_SHAPES.items():
        local = rotate(np.asarray(points) - np.asarray(ORGANS[name]["position"]), axis, -degrees)
        x, y, z = local[:, 0] / half[0], local[:, 1] / half[1], local[:, 2]
        z = z / (half[2] * np.maximum(1.0 + thickening * x, 0.1))
        inside |= x * x + y * y + z * z < 1.0
    return inside


def resample(points, spacing):
    """The polyline through `points` (its corners rounded by a Catmull-Rom spline through
    them) at even arc length `spacing`; returns the points and their arc lengths."""
    p = np.asarray(points, dtype=float)
    ext = np.vstack([2 * p[0] - p[1], p, 2 * p[-1] - p[-2]])
    dense = []
    for i in range(1, len(ext) - 2):
        for t in np.linspace(0.0, 1.0, 40, endpoint=False):
            a, b, c, d = ext[i - 1], ext[i], ext[i + 1], ext[i + 2]
            dense.append(0.5 * ((-t**3 + 2 * t**2 - t) * a + (3 * t**3 - 5 * t**2 + 2) * b
                                + (-3 * t**3 + 4 * t**2 + t) * c + (t**3 - t**2) * d))
    dense.append(p[-1])
    dense = np.array(dense)
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
    count = int(round(arc[-1] / spacing)) + 1
    targets = np.linspace(0.0, arc[-1], count)
    out = np.stack([np.interp(targets, arc, dense[:, k]) for k in range(3)], axis=1)
    return out, targets


# The colon's path through its parts, caecum to rectosigmoid; its radius at each corner (m).
COLON_PARTS = [
    # (part, corners, radii at the corners)
    ("caecum", [[0.085, -0.09, 0.02], [0.09, -0.065, 0.018]], [0.034, 0.032]),
    ("ascending", [[0.095, -0.035, 0.005], [0.102, 0.02, 0.0], [0.105, 0.08, 0.015]], [0.03, 0.027, 0.025]),
    ("transverse", [LANDMARKS["hepatic_flexure"], [0.07, 0.08, 0.07], [0.035, 0.07, 0.095], [0.01, 0.095, 0.1],
                    [-0.02, 0.07, 0.1], [-0.06, 0.075, 0.09], [-0.097, 0.105, 0.055]],
     [0.024, 0.023, 0.022, 0.022, 0.021, 0.021, 0.02]),
    ("descending", [LANDMARKS["splenic_flexure"], [-0.112, 0.09, 0.0], [-0.113, 0.01, -0.01],
                    [-0.108, -0.07, -0.005]], [0.019, 0.018, 0.017, 0.016]),
    ("sigmoid", [[-0.09, -0.1, 0.01], [-0.055, -0.122, 0.03], [-0.015, -0.132, 0.055], [0.025, -0.125, 0.058],
                 [0.035, -0.142, 0.035], [0.015, -0.148, 0.012], LANDMARKS["rectosigmoid_junction"]],
     [0.016, 0.015, 0.014, 0.014, 0.014, 0.013, 0.013]),
]


def colon_path(spacing):
    corners, radii, part_of = [], [], []
    for part, points, part_radii in COLON_PARTS:
        corners += points
        radii += part_radii
        part_of += [part] * len(points)
    points, arc = resample(corners, spacing)
    # Radius and part along the arc: interpolated between the corners' arc positions.
    corner_arc = [float(arc[np.argmin(np.linalg.norm(points - np.asarray(c), axis=1))]) for c in corners]
    corner_arc = np.maximum.accumulate(np.array(corner_arc))
    r = np.interp(arc, corner_arc, radii)
    first_corner = {}
    for k, part in enumerate(part_of):
        first_corner.setdefault(part, corner_arc[k])
    # A part runs from its first corner to the next part's first corner.
    names = [p[0] for p in COLON_PARTS]
    spans = {}
    for i, name in enumerate(names):
        start = 0.0 if i == 0 else first_corner[name]
        end = arc[-1] if i + 1 == len(names) else first_corner[names[i + 1]]
        spans[name] = [round(float(start), 4), round(float(end), 4)]
    return points, r, spans


def clear_of(points, radius, obstacles):
    """Whether spheres of `radius` at `points` (n x 3) stay inside the cavity and clear of
    the tubes in `obstacles` ((points, radii) pairs): by probing the cavity at 14
    directions and the tubes' distances."""
    probes = [np.array(d, dtype=float) / np.linalg.norm(d) for d in
              [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1), (1, 1, 1), (1, 1, -1),
               (1, -1, 1), (1, -1, -1), (-1, 1, 1), (-1, 1, -1), (-1, -1, 1), (-1, -1, -1)]]
    ok = np.ones(len(points), dtype=bool)
    for d in probes:
        ok &= (cavity_inside(points + radius * d) < 0.0) & ~inside_organs(points + radius * d)
    for tube, tube_radii in obstacles:
        gaps = np.linalg.norm(points[:, None, :] - tube[None, :, :], axis=2) - tube_radii[None, :] - radius
        ok &= gaps.min(axis=1) > 0.0
    return ok


def small_bowel_path(spacing, root_start, root_end, r_jejunum, r_ileum, colon, colon_radii):
    """Loops packed in the infracolic compartment, duodenojejunal flexure to ileocaecal
    junction, in levels of back-and-forth legs along x: the jejunum in the upper band (below
    the transverse colon) on the three lower levels, up; the ileum in the lower band and the
    pelvic inlet on all four levels, down, its last leg ending at the ileocaecal junction.
    Each leg runs as far as the cavity and the colon leave room along it; legs are a pitch
    apart in y and levels in z, so no two loops cross (tests/patient measures the
    clearance). Returns the points and their radii."""
    gap = 0.003
    xs = np.arange(-0.14, 0.1401, 0.002)

    def leg_ends(y, z, radius, x_limit):
        """The free run of x around the middle of x_limit at (y, z)."""
        points = np.stack([xs, np.full_like(xs, y), np.full_like(xs, z)], axis=1)
        free = clear_of(points, radius + gap, [(colon, colon_radii)]) & (xs >= x_limit[0]) & (xs <= x_limit[1])
        middle = int(np.argmin(np.abs(xs - 0.5 * (x_limit[0] + x_limit[1]))))
        if not free[middle]:
            return None
        lo = hi = middle
        while lo > 0 and free[lo - 1]:
            lo -= 1
        while hi + 1 < len(xs) and free[hi + 1]:
            hi += 1
        return xs[lo], xs[hi]

    jejunum_pitch, ileum_pitch = 2 * r_jejunum + gap, 2 * r_ileum + gap
    jejunum_rows = np.arange(0.05, -0.045 - 1e-9, -jejunum_pitch)
    ileum_rows = np.arange(jejunum_rows[-1] - 0.5 * (jejunum_pitch + ileum_pitch), -0.13 - 1e-9, -ileum_pitch)
    levels = [0.018 + k * jejunum_pitch for k in range(4)]
    def band(rows, band_levels, radius, x_limit):
        """The rows free on every level of the band (so that each level turns into the next
        at the same row), and each row's free run of x on each level."""
        ends = {y: [leg_ends(y, z, radius, x_limit(z)) for z in band_levels] for y in rows}
        return [y for y in rows if all(e is not None and e[1] - e[0] > 0.05 for e in ends[y])], ends

    # The jejunum on the three lower levels, up (the first row left out on the first level,
    # where the flexure comes down); the ileum on all four, down, ending on its first row,
    # which runs to the ileocaecal junction.
    jejunum_levels, ileum_levels = levels[:3], levels[::-1]
    j_rows, j_ends = band(jejunum_rows, jejunum_levels, r_jejunum, lambda z: (-0.14, 0.14))
    i_rows, i_ends = band(ileum_rows, ileum_levels, r_ileum,
                          lambda z: (-0.14, root_end[0] - 0.02 if z == levels[0] else 0.14))
    legs = []  # (y, z, x_from, x_to)
    rightward = True
    for k, z in enumerate(jejunum_levels):
        for y in (j_rows[1:] if k == 0 else j_rows[::-1] if k % 2 else j_rows):
            lo, hi = j_ends[y][k]
            legs.append((y, z, lo, hi) if rightward else (y, z, hi, lo))
            rightward = not rightward
    for k, z in enumerate(ileum_levels):
        for y in (i_rows[::-1] if k % 2 else i_rows):
            lo, hi = i_ends[y][k]
            legs.append((y, z, lo, hi) if rightward else (y, z, hi, lo))
            rightward = not rightward
    if legs[-1][3] < legs[-1][2]:
        legs.pop()  # the last leg runs toward the ileocaecal junction (+x)
    # Each leg turns into the next (a pitch away in y, or in z between levels) by a half
    # circle: both end at the inner of their two ends, shortened by the half circle's bulge.
    for i in range(len(legs) - 1):
        (ya, za, a0, a1), (yb, zb, b0, b1) = legs[i], legs[i + 1]
        bulge = 0.5 * math.hypot(yb - ya, zb - za)
        inner = min(a1, b0) - bulge if a1 > a0 else max(a1, b0) + bulge
        legs[i] = (ya, za, a0, inner)
        legs[i + 1] = (yb, zb, inner, b1)
    # The flexure comes down along the first level's empty first row, then turns into it.
    dense = [np.asarray(root_start, dtype=float), np.array([legs[0][2], j_rows[0], legs[0][1]])]
    for i, (y, z, x0, x1) in enumerate(legs):
        dense += [np.array([x, y, z]) for x in np.linspace(x0, x1, 12)]
        if i + 1 < len(legs):
            yb, zb = legs[i + 1][0], legs[i + 1][1]
            end, nxt = np.array([x1, y, z]), np.array([x1, yb, zb])
            center, half = 0.5 * (end + nxt), 0.5 * (nxt - end)
            outward = np.array([1.0 if x1 > x0 else -1.0, 0.0, 0.0]) * np.linalg.norm(half)
            for a in np.linspace(0.0, math.pi, 10)[1:-1]:
                dense.append(center - math.cos(a) * half + math.sin(a) * outward)
    dense.append(np.asarray(root_end, dtype=float))
    dense = np.array(dense)
    arc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
    targets = np.linspace(0.0, arc[-1], int(round(arc[-1] / spacing)) + 1)
    points = np.stack([np.interp(targets, arc, dense[:, k]) for k in range(3)], axis=1)
    radius = r_jejunum + (r_ileum - r_jejunum) * targets / targets[-1]
    return points, radius


def polyline_length(points):
    return float(np.sum(np.linalg.norm(np.diff(np.asarray(points), axis=0), axis=1)))


def rounded(values, digits=5):
    return [[round(float(c) + 0.0, digits) for c in p] for p in values]


def main(root):
    # Organs.
    wall_v, wall_t = radial_surface(cavity_inside, np.array([0.0, 0.04, 0.06]), 50, 72)
    write_obj(root, "organs/abdominal_wall.obj",
              "The peritoneal cavity of an adult insufflated to 12-15 mmHg (the patient's frame)", wall_v, wall_t,
              inward=True)
    for name, (half, thickening, (axis, degrees), description) in ORGAN_SHAPES.items():
        vertices, triangles = ellipsoid(half, 32 if name == "liver" else 24, 48 if name == "liver" else 36,
                                        right_thickening=thickening)
        write_obj(root, "organs/%s.obj" % name, description + ", in its own frame", rotate(vertices, axis, degrees),
                  triangles)
    # Targets (exposure patches), in the world frame.
    bed_v, bed_t = patch_on_wall((0.065, 0.125), (-0.04, 0.08), (6, 12))
    write_obj(root, "targets/right_colon_bed.obj", "The right colon's bed on the posterior wall: a target patch",
              bed_v, bed_t)
    pelvis_v, pelvis_t = patch_on_wall((-0.045, 0.045), (-0.155, -0.105), (9, 5))
    write_obj(root, "targets/pelvic_floor.obj", "The pelvic floor (pouch of Douglas): a target patch",
              pelvis_v, pelvis_t)

    # Paths.
    root_start = LANDMARKS["duodenojejunal_flexure"]
    root_end = LANDMARKS["ileocaecal_junction"]
    colon, colon_r, colon_parts = colon_path(0.01)
    bowel, bowel_r = small_bowel_path(0.01, root_start, root_end, SMALL_BOWEL_RADII[0], SMALL_BOWEL_RADII[1], colon, colon_r)
    layout = {
        "description": "The patient's layout (docs/anatomy.md, The patient): m, the patient's frame; "
                       "made by examples/scenes/make_patient.py",
        "frame": {"origin": "posterior parietal peritoneum, midline, at the level of the umbilicus (L4)",
                  "x": "patient's right", "y": "cranial", "z": "anterior (gravity -z, supine)"},
        "landmarks": {k: [round(c, 5) for c in v] for k, v in LANDMARKS.items()},
        "organs": {name: dict(ORGANS[name], mesh="organs/%s.obj" % name) for name in ORGANS},
        "cavity": {"mesh": "organs/abdominal_wall.obj", "anterior_wall_at_umbilicus_m": CAVITY_TOP,
                   "cranial_m": CAVITY_CRANIAL, "caudal_m": CAVITY_CAUDAL,
                   "half_width_at_umbilicus_m": CAVITY_HALF_WIDTH,
                   "pelvic_inlet_half_width_m": PELVIS_HALF_WIDTH},
        "targets": {"right_colon_bed": "targets/right_colon_bed.obj", "pelvic_floor": "targets/pelvic_floor.obj"},
        "mesenteric_root": rounded([root_start, root_end]),
        "colon": {"points": rounded(colon), "radii": [round(float(r), 5) for r in colon_r],
                  "parts_arc_length_m": colon_parts,
                  "fixed_parts": ["ascending", "descending"], "free_parts": ["transverse", "sigmoid"]},
        "small_bowel": {"points": rounded(bowel), "radii": [round(float(r), 5) for r in bowel_r]},
    }
    with open(os.path.join(root, "layout.json"), "w") as f:
        json.dump(layout, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "patient"))
