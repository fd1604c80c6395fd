#!/usr/bin/env python3
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
"""Writes the seed corpus of fuzz_mesh_input (test/fuzz/corpus/): tiny valid disks in OFF,
OBJ, PLY (ASCII and binary) and STL (ASCII and binary), and malformed or unsupported meshes
(NaN and infinite coordinates, out-of-range indices, non-triangle faces, empty and truncated
files, non-manifold edges and vertices, closed surfaces, two components, a handle, zero-area
faces, a face that uses a vertex twice, a header announcing a billion vertices).

    python3 test/fuzz/make_corpus.py          # rewrites test/fuzz/corpus/ (every file)
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus")


# Inputs the fuzzer found (rounds 1 to 4; hardening.md), kept byte for byte as seeds: each once
# crashed CGAL 5.5's readers or the program's pre-scan of them. Written by main() like the others.
FOUND = {
    "found_coff_color_out_of_range.off": (
        b'COFF\n16 18 0\n0.0 0.0 0.0 255 128 0 255\n0.3333333333333333 0.'
        b'0 0.0 255 128 0 r55\n0.6666666666666666 0.0 0.0 255 128 0 255'
        b'\n1.0 0.0 0.0 255 128 0 255\n0.0 0.3333333333333333 0.0 255 12'
        b'8 0 255\n0.3333333333333333 0.3333333333333333 0.224999999999'
        b'99998 255 128 0 255\n0.6666666666666666 0.3333333333333333 0.'
        b'225 255 128 0 255\n1.0 0.3333333333333333 3.1817257161747204e'
        b'-17 255 128 0 255\n0.0 0.6666666666666666 0.0 255 128 0 255\n0'
        b'.3333333333333333 0.6666666666666666 0.225 255 128 0 255\n0.6'
        b'666666666666666 0.6666666666666666 0.22500000000000003 255 1'
        b'205852\n  1.0 0.6666666666666666 3.181725716174721e-17 255 12'
        b'8 0 255\n0.0 1.0 0.0 255 128 0 255\n0.3333333333333333 1.0 3.1'
        b'817257161747204e-17 255 128 0 255\n0.6666666666666666 1.0 3.1'
        b'81725716174721e-17 255 128 0 255\n1.0 1.0 4.499279347985573e-'
        b'33 255 128 0 255\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2'
        b' 7 6\n3 4 5 9\n3 4 9 8\n3 5 6 10\n3 5 10 9\n3 6 7 11\n3 6 11 10\n3 '
        b'8 9 13\n3 8 13 12\n3 9 10 14\n3 9 14 13\n3 10 11 15\n3 10 15 14\n'
    ),
    "found_coff_counts_line_extra.off": (
        b'COFF\n1 0 66128 0 255\n0.0 0.6666666666666666 0.0 255 128 0 25'
        b'5\n0.3333333333333 0.6666666666666666 0.225 255 128 0 255\n0.6'
        b'666666666666666 0.6666666666666666 0.22500000000000003 255 1'
        b'205852\n  1.0 0.6666666666666666 3.18172575 11 15\n3 10 15 14\n'
    ),
    "found_coff_fewer_lines_than_counts.off": (
        b'COFF\n16 18 0\n0.0 0.0 066 00\n0 0 0\n1 0 0\n0 18 0\n0666 15 11 15'
        b'\n3 10 15 14\n'
    ),
    "found_coff_hash_in_keyword.off": (
        b'COFF#16 18 0\n0.0 0.0 0.0 2\xcb\xce 128 0 255\n0.q1_2333333333333 0.'
        b'0 0.0 255 128 0 255*0.6666255\n1.0 0.0 \xcb.0 255 128 0 255\n0.0 '
        b'0.3333333333333333 0.0 255 128 0 255\n0.3333333333333333 0.33'
        b'33333333333333 0.224999\xff99999999998\x01\x00\x00\x00\x00\x00\x00\x02 255 128 0 255\n0.'
        b'66666666666666o66 0.3333333333333333 0.225 255 14e-17 255 12'
        b'8 0 255\n0.66666614 1328 0 2\xff\xff\xff\xff\xff\n3 10 15 14\n'
    ),
    "found_coff_keyword_suffix.off": (
        b'COFF-\n16 18 0\n0.0 0.: 0.0 255 128 0 255\n0.3333333333333333 0'
        b'.0 0.0 255 128 0 255\n0.6666666666666666 0.0 0.0 255 128 0 25'
        b'5\n1.0 0.0 0.0 255 12855 2 0\n0.0 0.3333333333333333 0.0\xe0\xcd\xca\xca\xdf\xce'
        b'\xcd\xc7 0D\x00\x00\x00 255\n0.3333333333330.3333333333333333 0. 9\n3 6 7 11\n'
        b'3 6 11 10\n3 8 9 13\n3 8 13 12\n3 9 10 14\n3 9 14 13\n3 10 11 15\n'
        b'3 10 !5 14\n'
    ),
    "found_coff_short_vertex_line.off": (
        b'COFF\n16 18 0\n0.0 0\xc8.0 0.0 255 128 0 255\n0.3333333333333333 0'
        b'.0 0.0 255 128 0 255\n0.6666666666666666 0.0 0.0 255 128 0 25'
        b'5\n1.0 0.0 0.0 255 128 0 255\n0.0 0.3333333333333333 0.0 255 1'
        b'28 0 255\n0.3333333333333333 0.3333333333333333 0.22499999999'
        b'999998 255 128 0 255\n0.6666666666666666 0.3333333333333333 0'
        b'.225 255 128 0 255\n1.0 0.3333333333333333 3.1817257161747204'
        b'e-17 255 128 0 255\n0.0 0.6666666666666666 0.0 255 128 0 255\n'
        b'0.3333333333333333 0.6666666666666666 0.225 255 128 0 255\n0.'
        b'6666666666666666 0.6666666666666666 0.22500000000000003 255 '
        b'128 0 255\n1.0 0.6666666666666666 3.181725716174721e-17 255 1'
        b'28 0 255\n0.0 1.0 0.0 255 128 0 255\n0.3333333333333333 1.0 3.'
        b'1817257161747204e-17 255 128 0 255\n0.6666666666666666 1.0 3.'
        b'181725716174721e-17 255 128 0 255\n1.0 1.0 4.499279347985573e'
        b'-33 255 128 0 255\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 '
        b'2 7 6\n3 4 5 9\n3 4 9 8\n1 5 6 10\n3 5 10 9\n3 6 7 11\n3 6 11 10\n3'
        b' 8 9 13\n3 8 13 12\n3 9 10 14\n3 9 14 13\n3 10 11 15\n3 10 15 14\n'
    ),
    "found_off_face_size_with_suffix.off": (
        b'OFF\n 00\n3 0 66666666666z0\xff\xff\xff\xff\xff\xff\xff\t.0 0.0 /0.0\n0.\x83\x83\x83\x83\x83\x83\x83\x83\x83\x83\x83\x83\x83'
        b'\x83\x83\x83\x83\x83\x835 \x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x000.3333333333333333 0'
        b'.0\n0.3333333333333333 0.1666666666666666 0.22499999999999998'
        b'\n0.6.0 0.0 /0.0\n0.0 0.3333333333333333 0.0\n0.333333333333333'
        b'3 0.1666666660.3333333330 4 3\n3 1 2\x1854 7\n3 3 7 6\n3 4 5 8\n3 4'
        b'\n3 1.3333 8 7\n'
    ),
    "found_off_huge_face_size.off": (
        b'OFF\n 00\n3 0 66666666666 0\xff\xff\xff\xff\xff\xff\xff\t.0 0.0 /0.0\n0.0 0.333333333'
        b'3333333 0.0\n0.3333333333333333 0.1666666666666666 0.22499999'
        b'999999998\n0.666666666661 4\n3 0 4 3\n3 1 2 54 7\n3 3 7 6\n3 4 5 '
        b'8\n3 4\n3 1 5 4\n3 3 4 7\n\x00\n3 3 7 6\n3 4 5 8\n3 4 8 7\n'
    ),
    "found_off_keyword_glued_to_count.off": (
        b'COFF\x8a16 18 0mo cy0m\x00\x00\x00ent06\x00\x00\x02\x02 1\x01c'
    ),
    "found_ply_count_with_suffix.ply": (
        b'ply\nformat ascii 1.0\nelement vert\xff\xff 1y\nrorpepty float z\ne\nle'
        b'menatface 1\nproperty list uint int vertex_indices\ne\nproperty'
        b' float x\npropocale5 1 0\n4000000000\x01\x10 0 1 2\n'
    ),
    "found_ply_garbled_header.ply": (
        b'ply\nformat ascii 1.0\nelement vertex 3\npro(erty float x\nprope'
        b'rty float y\nproperty face 1ormat ascii 1.0\nelement vertex 3\n'
        b'pro(erty float x\nproperty float y\nproperty float z\nelement f'
        b'ace 1\nproperty list uint int vertex_indices\nend_header\n0 0 0'
        b'\n1 0 0\n0 1 0\n4000000000 0 1 2\n\nproperty list uint int vertex'
        b'_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n'
    ),
    "found_ply_integer_coordinate.ply": (
        b'ply\nformat binary_little_endian 1.0\nelement vertex 16\nproper'
        b'ty float x\nproperty int32 y\nproperty float z\nelement face 18'
        b'\nproperty list uchar int vertex_indices\nend_header\n\x00\x00\x00\x00\x00\x00\x00\x00\x00'
        b'\x00\x00\x00\xab\xaa\xaa>\x00\x00\x00\x00\x00\x00\x00\x00\xab\xaa*?\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x03\t\x00\x00\x00\n\x00\x00\x00\x0e\x00\x00\x00\x03\t\x00\x00\x00\x0e\x00\x00\x00\r\x00\x00\x00\x03\n\x00\x00\x00'
        b'\x0b\x00\x00\x00\x0f\x00\x00\x00\x03\n\x00\xaa\xaa\x0f'
    ),
    "found_ply_list_count_with_suffix.ply": (
        b'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nprope'
        b'rty float y\nproperty float z\nelement face 1\nproperty list ui'
        b'nt int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n400000000'
        b'0x 0 1 2\n'
    ),
    "found_ply_misspelled_format.ply": (
        b'ply\nformad ascii 1.0\nelement 6ertex 3\nproperty float x\nprope'
        b'rty float y\nproperty float z\nelement face 1\nproperty list ui'
        b'nt int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n400000000'
        b'0 0 1 2\n'
    ),
    "found_ply_property_before_element.ply": (
        b'ply\nformat ascii 1.0y\nproperty float z\nelement face 1\nproper'
        b'ty list uint int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0'
        b'\n4000000000 0 1 2\n'
    ),
}


def grid(n, bump=0.3):
    """(n+1)^2 vertices on [0,1]^2 lifted onto a bump, 2 n^2 triangles (counter-clockwise)."""
    pts = []
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i / n, j / n
            pts.append((x, y, bump * math.sin(math.pi * x) * math.sin(math.pi * y)))
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            tris += [(a, b, d), (a, d, c)]
    return pts, tris


def hexagon(rings):
    """hexagonal disk: 1 + 3 rings (rings + 1) vertices, on a paraboloid."""
    index, pts = {}, []
    def inside(q, r):
        return max(abs(q), abs(r), abs(q + r)) <= rings
    for q in range(-rings, rings + 1):
        for r in range(-rings, rings + 1):
            if inside(q, r):
                x, y = q + 0.5 * r, 0.5 * math.sqrt(3) * r
                index[(q, r)] = len(pts)
                pts.append((x, y, 0.05 * (x * x + y * y)))
    tris = []
    for (q, r), a in index.items():
        if (q + 1, r) in index and (q, r + 1) in index:
            tris.append((a, index[(q + 1, r)], index[(q, r + 1)]))
        if (q + 1, r) in index and (q + 1, r - 1) in index:
            tris.append((a, index[(q + 1, r - 1)], index[(q + 1, r)]))
    return pts, tris


def torus(n, m, R=2.0, r=0.7):
    pts, tris = [], []
    for i in range(n):
        for j in range(m):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
            pts.append(((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
    idx = lambda i, j: (i % n) * m + (j % m)
    for i in range(n):
        for j in range(m):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i, j + 1), idx(i + 1, j + 1)
            tris += [(a, b, d), (a, d, c)]
    return pts, tris


def c_shape():
    """a C-shaped (non star-shaped) planar strip, 4 x 12 cells bent around 300 degrees."""
    pts, tris = [], []
    nr, na = 3, 16
    for j in range(na + 1):
        t = math.radians(30 + 300 * j / na)
        for i in range(nr + 1):
            rad = 1.0 + 0.4 * i / nr
            pts.append((rad * math.cos(t), rad * math.sin(t), 0.0))
    for j in range(na):
        for i in range(nr):
            a = j * (nr + 1) + i
            b, c, d = a + 1, a + nr + 1, a + nr + 2
            tris += [(a, c, d), (a, d, b)]
    return pts, tris


def num(x):
    return repr(float(x)) if isinstance(x, float) else str(x)


def off(pts, faces, header="OFF"):
    s = "%s\n%d %d 0\n" % (header, len(pts), len(faces))
    s += "".join(" ".join(num(c) for c in p) + "\n" for p in pts)
    s += "".join("%d %s\n" % (len(f), " ".join(str(i) for i in f)) for f in faces)
    return s


def obj(pts, faces, comment=True):
    s = "# generated by make_corpus.py\n" if comment else ""
    s += "".join("v " + " ".join(num(c) for c in p) + "\n" for p in pts)
    s += "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)
    return s


def ply_ascii(pts, faces):
    s = "ply\nformat ascii 1.0\ncomment fuzz seed\nelement vertex %d\nproperty float x\nproperty float y\n" \
        "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(pts), len(faces))
    s += "".join(" ".join(num(c) for c in p) + "\n" for p in pts)
    s += "".join("%d %s\n" % (len(f), " ".join(str(i) for i in f)) for f in faces)
    return s


def ply_binary(pts, faces):
    s = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
         "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
         % (len(pts), len(faces))).encode()
    for p in pts:
        s += struct.pack("<3f", *p)
    for f in faces:
        s += struct.pack("<B", len(f)) + struct.pack("<%di" % len(f), *f)
    return s


def ply_binary_any(pts, faces, big_endian=False, coord="d", count="B", index="I"):
    """a binary PLY of any byte order and types (struct codes), with an extra property per
    vertex and an extra element, which the reader skips"""
    e = ">" if big_endian else "<"
    names = {"f": "float", "d": "double", "B": "uchar", "H": "ushort", "I": "uint", "i": "int", "b": "char"}
    s = ("ply\nformat %s 1.0\ncomment fuzz seed\nelement vertex %d\nproperty %s x\nproperty %s y\n"
         "property %s z\nproperty uchar red\nelement face %d\nproperty list %s %s vertex_indices\n"
         "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
         % ("binary_big_endian" if big_endian else "binary_little_endian", len(pts), names[coord], names[coord],
            names[coord], len(faces), names[count], names[index])).encode()
    for p in pts:
        s += struct.pack(e + "3" + coord, *p) + struct.pack("B", 7)
    for f in faces:
        s += struct.pack(e + count, len(f)) + struct.pack(e + "%d%s" % (len(f), index), *f)
    return s + struct.pack(e + "2i", 0, 1)


def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return [x / length for x in n]


def stl_ascii(pts, tris):
    s = "solid fuzz\n"
    for t in tris:
        p = [pts[i] for i in t]
        s += " facet normal %s\n  outer loop\n" % " ".join(num(x) for x in normal(*p))
        s += "".join("   vertex %s\n" % " ".join(num(c) for c in q) for q in p)
        s += "  endloop\n endfacet\n"
    return s + "endsolid fuzz\n"


def stl_binary(pts, tris):
    s = b"binary stl fuzz seed".ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        p = [pts[i] for i in t]
        s += struct.pack("<3f", *normal(*p))
        for q in p:
            s += struct.pack("<3f", *q)
        s += struct.pack("<H", 0)
    return s


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):  # every seed is written below: none is kept by hand
        os.remove(os.path.join(OUT, f))
    files = dict(FOUND)
    g2 = grid(2)
    g3 = grid(3)
    hx = hexagon(2)

    # valid disks, every reader
    files["grid_3x3.off"] = off(*g2)
    files["grid_4x4_coff.off"] = "COFF\n%d %d 0\n" % (len(g3[0]), len(g3[1])) + \
        "".join("%s 255 128 0 255\n" % " ".join(num(c) for c in p) for p in g3[0]) + \
        "".join("3 %d %d %d\n" % t for t in g3[1])
    files["hexagon.obj"] = obj(*hx)
    files["hexagon_vt_vn.obj"] = "".join("v %r %r %r\nvt 0 0\nvn 0 0 1\n" % p for p in hx[0]) + \
        "".join("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % tuple(i + 1 for i in t for _ in range(3)) for t in hx[1])
    files["grid_negative_indices.obj"] = "".join("v %r %r %r\n" % p for p in g2[0][:3]) + \
        "".join("v %r %r %r\n" % p for p in g2[0][3:]) + "f -9 -8 -4\nf -9 -4 -5\n"
    files["grid_ascii.ply"] = ply_ascii(*g3)
    files["grid_binary.ply"] = ply_binary(*g3)
    files["grid_ascii.stl"] = stl_ascii(*g2)
    files["hexagon_binary.stl"] = stl_binary(*hx)
    files["single_triangle.off"] = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    files["fan_one_interior.off"] = off([(0, 0, 0.2)] + [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3), 0.0)
                                                          for k in range(6)],
                                        [(0, 1 + k, 1 + (k + 1) % 6) for k in range(6)])
    files["annulus_two_borders.off"] = off(g3[0], [t for t in g3[1] if t not in [(5, 6, 10), (5, 10, 9)]])
    files["c_shape_folds.obj"] = obj(*c_shape())
    files["isolated_vertex.off"] = off(g2[0] + [(5.0, 5.0, 5.0)], g2[1])
    files["comments_and_blanks.off"] = "OFF\n# comment\n\n9 8 0\n" + "".join(
        " ".join(num(c) for c in p) + "  # v\n" for p in g2[0]) + "".join("3 %d %d %d\n" % t for t in g2[1])

    # malformed or unsupported
    nan_pts = list(g2[0]); nan_pts[4] = (float("nan"), 1.0, 0.3)
    files["nan.off"] = off(g2[0], g2[1]).replace(" ".join(num(c) for c in g2[0][4]), "nan 0.5 0.3")
    files["inf.obj"] = "v 0 0 0\nv 1 0 0\nv 0 1 inf\nv 1 1 0\nf 1 2 3\nf 2 4 3\n"
    files["nan_binary.ply"] = ply_binary(nan_pts, g2[1])
    files["nan_binary.stl"] = stl_binary(nan_pts, g2[1])
    files["index_out_of_range.off"] = off(*g2).replace("3 4 5 8", "3 4 5 9")
    files["index_out_of_range.obj"] = obj(*g2, comment=False).replace("f 5 6 9", "f 5 6 10")
    files["negative_index_out_of_range.obj"] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"
    files["index_out_of_range_binary.ply"] = ply_binary(g2[0], g2[1][:-1] + [(4, 8, 1000000)])
    files["quads.off"] = off(g2[0], [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)])
    files["mixed_triangle_quad.obj"] = obj(g2[0], [(0, 1, 4, 3), (1, 2, 5), (2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)])
    files["pentagon.ply"] = ply_ascii([(math.cos(k * 1.2566), math.sin(k * 1.2566), 0) for k in range(5)],
                                      [(0, 1, 2, 3, 4)])
    files["empty.off"] = ""
    files["header_only.off"] = "OFF\n"
    files["points_only.off"] = "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"
    files["truncated.off"] = off(*g2)[:60]
    files["truncated_binary.ply"] = ply_binary(*g3)[:-7]
    files["huge_vertex_count.off"] = "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    files["huge_face_count.ply"] = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 2000000000\n"
                                    "property list uchar int vertex_indices\nend_header\n").encode() + \
        struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    files["huge_list_size.ply"] = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 1\nproperty list uint int vertex_indices\n"
                                   "end_header\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n")
    files["huge_triangle_count.stl"] = b"x".ljust(80, b" ") + struct.pack("<I", 100000000) + b"\0" * 50
    files["not_a_mesh.obj"] = "hello world\n"
    files["edge_of_three_faces.off"] = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 -1 1\n3 0 1 2\n3 0 2 3\n3 0 2 4\n"
    files["bowtie_vertex.off"] = "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n"
    files["inconsistent_orientation.off"] = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n".replace(
        "3 0 2 3", "3 0 3 2")
    files["vertex_twice_in_face.off"] = "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 0 1\n"
    files["closed_tetrahedron.off"] = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    files["closed_octahedron.obj"] = obj([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)],
                                         [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5),
                                          (0, 3, 5)])
    tp, tt = torus(8, 6)
    files["punctured_torus.off"] = off(tp, tt[1:])
    files["closed_torus_binary.stl"] = stl_binary(tp, tt)
    files["two_components.off"] = off(g2[0] + [(5, 0, 0), (6, 0, 0), (5, 1, 0)], g2[1] + [(9, 10, 11)])
    zero = list(g2[0]); zero[4] = (0.5, 0.0, 0.0)
    files["zero_area_face.off"] = off(zero, g2[1])
    files["all_points_equal.off"] = off([(1.0, 1.0, 1.0)] * 9, g2[1])
    files["collinear_strip.obj"] = obj([(float(i), 0.0, 0.0) for i in range(4)] + [(0.5, 1e-300, 0.0)],
                                       [(0, 1, 4), (1, 2, 4), (2, 3, 4)])
    files["huge_coordinates.off"] = off([(p[0] * 1e300, p[1] * 1e300, p[2] * 1e300) for p in g2[0]], g2[1])
    files["tiny_coordinates.off"] = off([(p[0] * 1e-300, p[1] * 1e-300, p[2] * 1e-300) for p in g2[0]], g2[1])
    files["binary_garbage.stl"] = bytes(range(256)) * 2

    # the streaming readers (issue 14): every format variant, and the messages named there
    files["grid_binary_big_endian.ply"] = ply_binary_any(*g3, big_endian=True)
    files["grid_binary_float_ushort.ply"] = ply_binary_any(*g3, coord="f", count="H", index="i")
    files["grid_binary_big_endian_truncated.ply"] = ply_binary_any(*g3, big_endian=True)[:-20]
    files["grid_binary_solid_header.stl"] = b"solid" + stl_binary(*g2)[5:]  # binary, header starts with "solid"
    files["two_solids.stl"] = stl_ascii(*g2) + stl_ascii([(p[0] + 3, p[1], p[2]) for p in g2[0]], g2[1])
    files["truncated_ascii.stl"] = stl_ascii(*g2)[:-40]
    files["quad_loop.stl"] = "solid q\n facet normal 0 0 1\n  outer loop\n" + \
        "".join("   vertex %d %d 0\n" % v for v in [(0, 0), (1, 0), (1, 1), (0, 1)]) + "  endloop\n endfacet\nendsolid q\n"
    files["noff_dimension_3.off"] = "nOFF\n3\n9 8 0\n" + off(*g2)[len("OFF\n9 8 0\n"):]
    files["noff_dimension_4.off"] = "nOFF\n4\n3 1 0\n0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 2\n"
    files["stnoff_texture_normals.off"] = "STNOFF\n3 1 0\n" + "".join(
        "%d %d 0 0 0 1 0.5 0.5\n" % v for v in [(0, 0), (1, 0), (0, 1)]) + "3 0 1 2\n"
    files["off_counts_on_keyword_line.off"] = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    files["off_two_counts.off"] = "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    files["off_face_colors.off"] = off(*g2).replace("3 0 1 4\n", "3 0 1 4 255 0 0\n")
    files["off_binary.off"] = b"OFF BINARY\n" + struct.pack(">3i", 3, 1, 0) + b"\0" * 40
    files["off_trailing_data.off"] = off(*g2) + "3 0 1 2\n"
    files["obj_index_zero.obj"] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"
    files["obj_index_overflow.obj"] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n"
    files["obj_index_beyond_32_bits.obj"] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n"
    files["obj_forward_reference.obj"] = "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
    files["obj_groups_materials_lines.obj"] = "mtllib a.mtl\no thing\ng part\ns 1\nusemtl red\n" + \
        obj(*hx, comment=False) + "l 1 2 3\np 4\nvp 0.5\n"
    files["obj_vertex_colors_and_weight.obj"] = "".join(
        "v %r %r %r 0.5 0.25 1\n" % p for p in g2[0][:5]) + "".join("v %r %r %r 1\n" % p for p in g2[0][5:]) + \
        "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in g2[1])
    files["obj_free_form.obj"] = "cstype bezier\ndeg 3\ncurv 0 1 1 2 3 4\nend\n"
    files["obj_long_line.obj"] = "v " + "1" * 5000 + " 0 0\n"
    files["coincident_points.obj"] = obj([(2.0, 2.0, 2.0)] * 9, g2[1])
    files["huge_coordinates_mixed.obj"] = obj([(p[0] * 1e300, p[1] * 1e-10, p[2]) for p in g2[0]], g2[1])
    files["ply_element_without_properties.ply"] = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                                                   "property float x\nproperty float y\nproperty float z\n"
                                                   "element junk 4000000000\nelement face 1\n"
                                                   "property list uchar int vertex_indices\nend_header\n").encode() + \
        struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    files["coordinate_beyond_double.obj"] = "v 0 0 1e400\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"

    for name, content in sorted(files.items()):
        mode = "wb" if isinstance(content, bytes) else "w"
        with open(os.path.join(OUT, name), mode) as f:
            f.write(content)
    print("wrote %d seeds to %s" % (len(files), OUT))


if __name__ == "__main__":
    main()
