#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the seed corpus of fuzz_mesh_file (tests/fuzz/corpus/mesh_file/).

An input is a format byte (% 4: 0 OBJ, 1 PLY, 2 OFF, 3 STL) and the file's bytes: a small
closed mesh (a tetrahedron with a quad-split side) in every variant the readers know, and a
few broken ones for the fuzzer to start from.
Run from the repository root: python3 tests/fuzz/make_mesh_seeds.py
"""
import os
import struct

OBJ, PLY, OFF, STL = 0, 1, 2, 3
V = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0), (0.5, 0.5, 0.0)]
F = [(0, 2, 4, 1), (0, 1, 3), (1, 4, 2, 3), (2, 0, 3)]


def triangles():
    for f in F:
        for k in range(2, len(f)):
            yield (f[0], f[k - 1], f[k])


def obj(negative=False):
    lines = ["# a seed", "o tetra", "mtllib none.mtl"] + ["v %g %g %g" % v for v in V] + ["vn 0 0 1", "vt 0 0"]
    for i, f in enumerate(F):
        if negative:
            lines.append("f " + " ".join(str(k - len(V)) for k in f))
        else:
            forms = ["%d", "%d/1", "%d//1", "%d/1/1"]
            lines.append("f " + " ".join(forms[(i + j) % 4] % (k + 1) for j, k in enumerate(f)))
    return ("\r\n" if negative else "\n").join(lines).encode() + b"\n"


def ply(encoding, real="float", index="int"):
    head = ("ply\nformat %s 1.0\ncomment a seed\nelement vertex %d\nproperty %s x\nproperty %s y\n"
            "property uchar red\nproperty %s z\nelement face %d\nproperty list uchar %s vertex_indices\n"
            "element edge 1\nproperty list uchar int ends\nend_header\n"
            % (encoding, len(V), real, real, real, len(F), index)).encode()
    if encoding == "ascii":
        body = "".join("%g %g 9 %g\n" % (x, y, z) for x, y, z in V)
        body += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in F) + "2 0 1\n"
        return head + body.encode()
    order = "<" if encoding == "binary_little_endian" else ">"
    r = {"float": "f", "double": "d"}[real]
    i = {"int": "i", "uint": "I", "ushort": "H"}[index]
    body = b"".join(struct.pack(order + r + r + "B" + r, x, y, 9, z) for x, y, z in V)
    body += b"".join(struct.pack(order + "B" + i * len(f), len(f), *f) for f in F)
    body += struct.pack(order + "Bii", 2, 0, 1)
    return head + body


def off(prefix="OFF", same_line=False):
    counts = "%d %d 0" % (len(V), len(F))
    lines = [prefix + " " + counts] if same_line else [prefix, "# a seed", counts]
    lines += ["%g %g %g 0.5 0.5 0.5" % v for v in V] + ["%d %s 255 0 0" % (len(f), " ".join(map(str, f))) for f in F]
    return "\n".join(lines).encode() + b"\n"


def stl_ascii():
    out = "solid seed\n"
    for t in triangles():
        out += " facet normal 0 0 1\n  outer loop\n"
        out += "".join("   vertex %g %g %g\n" % V[k] for k in t)
        out += "  endloop\n endfacet\n"
    return (out + "endsolid seed\n").encode()


def stl_binary(header=b"a seed"):
    ts = list(triangles())
    out = header.ljust(80, b" ") + struct.pack("<I", len(ts))
    for t in ts:
        out += struct.pack("<3f", 0, 0, 1) + b"".join(struct.pack("<3f", *V[k]) for k in t) + b"\0\0"
    return out


SEEDS = {
    "obj": (OBJ, obj()),
    "obj_negative_crlf": (OBJ, obj(negative=True)),
    "obj_broken_index": (OBJ, obj().replace(b"f 1 ", b"f 9 ")),
    "ply_ascii": (PLY, ply("ascii")),
    "ply_ascii_double": (PLY, ply("ascii", "double", "uint")),
    "ply_little": (PLY, ply("binary_little_endian")),
    "ply_big_double": (PLY, ply("binary_big_endian", "double", "ushort")),
    "ply_cut": (PLY, ply("binary_little_endian")[:-11]),
    "off": (OFF, off()),
    "off_counts_same_line": (OFF, off("CNOFF", same_line=True)),
    "stl_ascii": (STL, stl_ascii()),
    "stl_binary": (STL, stl_binary()),
    "stl_binary_solid_header": (STL, stl_binary(b"solid but binary")),
    "stl_wrong_count": (STL, stl_binary()[:-50]),
}


def main():
    directory = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "mesh_file")
    os.makedirs(directory, exist_ok=True)
    for name, (fmt, data) in SEEDS.items():
        with open(os.path.join(directory, name), "wb") as f:
            f.write(bytes([fmt]) + data)
    print("wrote %d seeds to %s" % (len(SEEDS), directory))


if __name__ == "__main__":
    main()
