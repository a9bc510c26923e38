#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the organ meshes of examples/scenes/abdomen.json (examples/scenes/organs/*.obj).

The meshes are made here, not segmented from a scan: smooth closed surfaces with the
proportions of an adult abdomen, plausible rather than anatomical. Axes of the scene: the
patient lies supine on the table, so -z is posterior (gravity -z pulls the bowel onto the
posterior wall), +y is cranial and +x the patient's right.

- abdominal_wall.obj: the cavity, a rounded box (a superellipsoid of exponent 4) 34 x 42 x
  34 cm, normals facing in: the bowel is kept inside.
- liver.obj: under the right diaphragm (cranial, right), a flattened ellipsoid 15 x 7 x
  11 cm, thicker on the right, normals out; given in its own frame (origin at its centre)
  so that a retractor can move it (ent_obstacle_set_pose).
- stomach.obj: cranial left, an ellipsoid 10 x 7 x 9 cm, normals out.

Python 3's standard library only. Run from anywhere: python3 examples/scenes/make_abdomen.py
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def surface(point, rings, segments):
    """A closed surface from point(theta, phi) (theta 0 at the south pole .. pi), normals out
    when point is a star-shaped surface parametrised like a sphere."""
    vertices = [point(0.0, 0.0)]
    for i in range(1, rings):
        theta = math.pi * i / rings
        vertices += [point(theta, 2.0 * math.pi * j / segments) for j in range(segments)]
    vertices.append(point(math.pi, 0.0))
    north = len(vertices) - 1

    def at(ring, j):
        return 1 + (ring - 1) * segments + j % segments

    triangles = [(0, at(1, j + 1), at(1, j)) for j in range(segments)]
    for i in range(1, rings - 1):
        for j in range(segments):
            triangles += [(at(i, j), at(i, j + 1), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i + 1, j))]
    triangles += [(north, at(rings - 1, j), at(rings - 1, j + 1)) for j in range(segments)]
    return vertices, triangles


def signed_power(value, exponent):
    return math.copysign(abs(value) ** exponent, value)


def superellipsoid(half, exponent):
    """|x/a|^n + |y/b|^n + |z/c|^n = 1 (n = exponent), parametrised by angles."""
    e = 2.0 / exponent

    def point(theta, phi):
        s, c = math.sin(theta), -math.cos(theta)
        return (half[0] * signed_power(s, e) * signed_power(math.cos(phi), e),
                half[1] * signed_power(s, e) * signed_power(math.sin(phi), e),
                half[2] * signed_power(c, e))
    return point


def ellipsoid(half, right_thickening=0.0):
    """An ellipsoid; right_thickening > 0 makes it thicker (in z) toward +x, like a liver."""
    def point(theta, phi):
        x = half[0] * math.sin(theta) * math.cos(phi)
        y = half[1] * math.sin(theta) * math.sin(phi)
        z = -half[2] * math.cos(theta) * (1.0 + right_thickening * x / half[0])
        return (x, y, z)
    return point


def write_obj(name, description, vertices, triangles, inward=False):
    path = os.path.join(HERE, "organs", name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as obj:
        obj.write("# %s\n# Made by examples/scenes/make_abdomen.py; metres; %d triangles, %s.\n"
                  % (description, len(triangles), "normals in (a cavity)" if inward else "normals out"))
        for v in vertices:
            obj.write("v %.6f %.6f %.6f\n" % v)
        for a, b, c in triangles:
            if inward:
                b, c = c, b
            obj.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def main():
    write_obj("abdominal_wall.obj", "The abdominal cavity: a rounded box 34 x 42 x 34 cm",
              *surface(superellipsoid((0.17, 0.21, 0.17), 4.0), 60, 80), inward=True)
    write_obj("liver.obj", "A liver: a flattened ellipsoid 15 x 7 x 11 cm, thicker on the right",
              *surface(ellipsoid((0.075, 0.035, 0.055), right_thickening=0.3), 40, 60))
    write_obj("stomach.obj", "A stomach: an ellipsoid 10 x 7 x 9 cm",
              *surface(ellipsoid((0.05, 0.035, 0.045)), 30, 48))


if __name__ == "__main__":
    main()
