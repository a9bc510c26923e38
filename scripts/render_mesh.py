#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Renders a skin mesh (binary PLY as lib/skinning/mesh_writers writes it, or OBJ) to a PNG
with matplotlib: flat-shaded triangles lit from above and the front, seen from a fixed
direction, so that pictures of several methods of the same frame compare side by side.

    scripts/render_mesh.py MESH.ply OUT.png [--title TEXT] [--elevation DEG] [--azimuth DEG]
                                            [--size INCHES]

Debian packages only: python3-numpy, python3-matplotlib (scripts/install-deps).
"""
import argparse
import struct
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_ply(path):
    """Positions (V, 3) and triangles (T, 3) of a binary little-endian PLY with float
    vertex properties and uchar/uint32 face lists (what write_ply produces)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    if "format binary_little_endian 1.0" not in header:
        raise ValueError("%s: not a binary little-endian PLY" % path)
    vertices = faces = 0
    properties = []
    element = None
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            if element == "vertex":
                vertices = int(words[2])
            elif element == "face":
                faces = int(words[2])
        elif words[:1] == ["property"] and element == "vertex":
            if words[1] != "float":
                raise ValueError("%s: vertex property %s is not float" % (path, words[2]))
            properties.append(words[2])
    stride = 4 * len(properties)
    table = np.frombuffer(data, dtype="<f4", count=vertices * len(properties), offset=end)
    table = table.reshape(vertices, len(properties))
    columns = [properties.index(name) for name in ("x", "y", "z")]
    positions = table[:, columns].astype(np.float64)
    offset = end + vertices * stride
    # Each face: a uchar count (3) then three uint32: 13 bytes.
    record = np.dtype([("count", "u1"), ("index", "<u4", (3,))])
    records = np.frombuffer(data, dtype=record, count=faces, offset=offset)
    if faces and not np.all(records["count"] == 3):
        raise ValueError("%s: a face is not a triangle" % path)
    return positions, records["index"].astype(np.int64)


def read_obj(path):
    positions, triangles = [], []
    with open(path) as f:
        for line in f:
            words = line.split()
            if words[:1] == ["v"]:
                positions.append([float(w) for w in words[1:4]])
            elif words[:1] == ["f"]:
                triangles.append([int(w.split("/")[0]) - 1 for w in words[1:4]])
    return np.array(positions), np.array(triangles, dtype=np.int64)


def render(positions, triangles, out, title, elevation, azimuth, size):
    corners = positions[triangles]                       # (T, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    normals /= np.where(lengths > 0, lengths, 1.0)[:, None]
    # Two lights, Lambert, plus ambient; back faces (inside, seen through a gap) dimmed.
    key = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    fill = np.array([-0.6, 0.4, 0.3]) / np.linalg.norm([-0.6, 0.4, 0.3])
    shade = 0.25 + 0.6 * np.clip(normals @ key, 0, 1) + 0.25 * np.clip(normals @ fill, 0, 1)
    base = np.array([0.86, 0.52, 0.45])                  # a bowel pink
    colours = np.clip(shade[:, None] * base[None, :], 0, 1)

    figure = plt.figure(figsize=(size, size), dpi=100)
    axes = figure.add_subplot(projection="3d")
    collection = Poly3DCollection(corners, facecolors=colours, edgecolors="none", linewidths=0)
    axes.add_collection3d(collection)
    low, high = positions.min(axis=0), positions.max(axis=0)
    centre, half = (low + high) / 2, (high - low).max() / 2
    for setter, c in zip((axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
        setter(c - half, c + half)
    axes.set_box_aspect((1, 1, 1))
    axes.view_init(elev=elevation, azim=azimuth)
    axes.set_axis_off()
    if title:
        axes.set_title(title, fontsize=11)
    figure.tight_layout()
    figure.savefig(out)
    plt.close(figure)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", help="a .ply (binary) or .obj mesh")
    parser.add_argument("png", help="the picture to write")
    parser.add_argument("--title", default="")
    parser.add_argument("--elevation", type=float, default=35.0, help="degrees above the xy plane")
    parser.add_argument("--azimuth", type=float, default=-60.0, help="degrees about z")
    parser.add_argument("--size", type=float, default=7.0, help="picture side, inches at 100 dpi")
    args = parser.parse_args(argv)
    reader = read_ply if args.mesh.endswith(".ply") else read_obj
    positions, triangles = reader(args.mesh)
    if len(triangles) == 0:
        sys.exit("%s: no triangles" % args.mesh)
    render(positions, triangles, args.png, args.title, args.elevation, args.azimuth, args.size)
    print("wrote %s (%d triangles)" % (args.png, len(triangles)))


if __name__ == "__main__":
    main(sys.argv[1:])
