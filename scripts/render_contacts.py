#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Draws a fold pressed into another (the meshes `enteron_skin_bench --contact_mesh_dir=DIR`
writes: two legs of a U-turn along x, the second pushed 0.3 R into the first at x = -0.1 m),
each skin without contact surfaces (before) and with them (after): the cross-sections
through the contact, the meshes cut by the plane x = -0.1 m. Without, the two legs'
sections overlap; with, they meet on a flat contact and swell beside it (the convolution),
or the union swells (the point skeleton); the tube has no contact surfaces.

    scripts/render_contacts.py DIR OUT.png

Debian packages only: python3-numpy, python3-matplotlib (scripts/install-deps).
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render_mesh  # noqa: E402

METHODS = ("tube", "point_skeleton", "convolution")
R = 0.0125  # m
CUT = -0.1  # m: the plane x = CUT


def section(positions, triangles, x):
    """The segments where the plane x cuts the triangles: (S, 2, 2) arrays of (y, z), m."""
    corners = positions[triangles]
    side = corners[:, :, 0] - x
    segments = []
    for tri, s in zip(corners, side):
        points = []
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if (s[a] < 0) != (s[b] < 0):
                w = s[a] / (s[a] - s[b])
                points.append(tri[a, 1:] + w * (tri[b, 1:] - tri[a, 1:]))
        if len(points) == 2:
            segments.append(points)
    return np.array(segments)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", help="where enteron_skin_bench wrote the meshes")
    parser.add_argument("png", help="the picture to write")
    args = parser.parse_args(argv)
    figure, axes = plt.subplots(1, len(METHODS), figsize=(5 * len(METHODS), 3.6), dpi=100)
    for column, method in enumerate(METHODS):
        top = axes[column]
        for suffix, style, label in (("through", "--", "before: contact_surfaces 0"), ("contacts", "-", "after: contact_surfaces 1")):
            positions, triangles = render_mesh.read_ply(os.path.join(args.dir, "%s_%s.ply" % (method, suffix)))
            for k, segment in enumerate(section(positions, triangles, CUT) / R):
                top.plot(segment[:, 0], segment[:, 1], style, color="C0" if suffix == "through" else "C3",
                         linewidth=1.2, label=label if k == 0 else None)
        top.set_aspect("equal")
        top.set_xlim(-2.7, 1.4)
        top.set_ylim(-1.25, 1.6)
        top.set_xlabel("y / R")
        top.set_ylabel("z / R")
        top.set_title("%s: section through the contact" % method, fontsize=10)
        top.legend(fontsize=8, loc="upper center", ncol=2, frameon=False)
    figure.tight_layout()
    figure.savefig(args.png)
    print("wrote %s" % args.png)


if __name__ == "__main__":
    main(sys.argv[1:])
