#!/usr/bin/env python3
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
"""Refines a triangle mesh (OFF or OBJ with 'v' and 'f' lines) by 1-to-4 midpoint subdivision
LEVELS times (every edge split at its midpoint, every triangle into four) and writes it as OFF,
OBJ, ASCII or binary PLY or binary STL (by the extension of OUTPUT). Used to make the large
meshes of the input/output throughput measurements (hardening.md, "Reading and writing large
meshes"):

    python3 scripts/refine_mesh.py ../shared/data/meshes/bimba_i.obj 2 bimba_714k.obj
    python3 scripts/refine_mesh.py ../shared/data/meshes/mask.off 3 mask_2m.off

Coordinates are written with 9 significant digits (what a typical exporter writes).
"""
import struct
import sys


def read_mesh(path):
    pts, tris = [], []
    with open(path) as f:
        if path.lower().endswith(".off"):
            words = f.read().split()
            assert words[0] == "OFF"
            nv, nf = int(words[1]), int(words[2])
            at = 4
            for _ in range(nv):
                pts.append(tuple(float(w) for w in words[at:at + 3]))
                at += 3
            for _ in range(nf):
                n = int(words[at])
                face = [int(w) for w in words[at + 1:at + 1 + n]]
                at += 1 + n
                tris += [(face[0], face[k], face[k + 1]) for k in range(1, n - 1)]
        else:
            for line in f:
                w = line.split()
                if not w:
                    continue
                if w[0] == "v":
                    pts.append(tuple(float(x) for x in w[1:4]))
                elif w[0] == "f":
                    face = [int(c.split("/")[0]) for c in w[1:]]
                    face = [i - 1 if i > 0 else len(pts) + i for i in face]
                    tris += [(face[0], face[k], face[k + 1]) for k in range(1, len(face) - 1)]
    return pts, tris


def subdivide(pts, tris):
    mid = {}
    pts = list(pts)

    def midpoint(a, b):
        key = (a, b) if a < b else (b, a)
        m = mid.get(key)
        if m is None:
            p, q = pts[a], pts[b]
            m = len(pts)
            pts.append(((p[0] + q[0]) * 0.5, (p[1] + q[1]) * 0.5, (p[2] + q[2]) * 0.5))
            mid[key] = m
        return m

    out = []
    for a, b, c in tris:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return pts, out


def write_mesh(path, pts, tris):
    low = path.lower()
    fmt = "%.9g %.9g %.9g\n"
    if low.endswith(".off"):
        with open(path, "w") as f:
            f.write("OFF\n%d %d 0\n" % (len(pts), len(tris)))
            f.writelines(fmt % p for p in pts)
            f.writelines("3 %d %d %d\n" % t for t in tris)
    elif low.endswith(".obj"):
        with open(path, "w") as f:
            f.writelines("v " + fmt % p for p in pts)
            f.writelines("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1) for t in tris)
    elif low.endswith(".ply") and "binary" in low:
        with open(path, "wb") as f:
            f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\n"
                     "property float y\nproperty float z\nelement face %d\n"
                     "property list uchar int vertex_indices\nend_header\n" % (len(pts), len(tris))).encode())
            f.write(b"".join(struct.pack("<3f", *p) for p in pts))
            f.write(b"".join(struct.pack("<B3i", 3, *t) for t in tris))
    elif low.endswith(".ply"):
        with open(path, "w") as f:
            f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                    "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                    % (len(pts), len(tris)))
            f.writelines(fmt % p for p in pts)
            f.writelines("3 %d %d %d\n" % t for t in tris)
    elif low.endswith(".stl"):
        with open(path, "wb") as f:
            f.write(b"refine_mesh.py".ljust(80, b" ") + struct.pack("<I", len(tris)))
            f.write(b"".join(struct.pack("<3f", 0, 0, 0) + struct.pack("<3f", *pts[a]) + struct.pack("<3f", *pts[b]) +
                             struct.pack("<3f", *pts[c]) + b"\0\0" for a, b, c in tris))
    else:
        sys.exit("unsupported output extension: " + path)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    pts, tris = read_mesh(sys.argv[1])
    for _ in range(int(sys.argv[2])):
        pts, tris = subdivide(pts, tris)
    write_mesh(sys.argv[3], pts, tris)
    print("%s: %d vertices, %d triangles" % (sys.argv[3], len(pts), len(tris)))


if __name__ == "__main__":
    main()
