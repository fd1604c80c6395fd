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
"""Writes the generated torus of the seam_parameterization example and its seams.

  make_torus.py [DIRECTORY]

torus.off: a torus of radii 2 and 0.7 (genus 1, closed), an N x M grid of vertices
(N = 24 around the axis, M = 12 around the tube), each quad split along its diagonal from
(i, j) to (i + 1, j + 1); vertex (i, j) has index i * M + j.

torus_cut_graph.selection.txt: the meridian i = 0 and the longitude j = 0, two loops through
vertex 0 that cut the torus into a disk.

torus_meridian_path.selection.txt: the meridian i = 0 without its last edge, a path that
closes no loop: the cut torus keeps its handle (ERROR_NO_TOPOLOGICAL_DISC).
"""

import math
import os
import sys

N, M = 24, 12


def vid(i, j):
    return (i % N) * M + (j % M)


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    lines = ['OFF', '%d %d 0' % (N * M, 2 * N * M)]
    for i in range(N):
        for j in range(M):
            u, v = 2 * math.pi * i / N, 2 * math.pi * j / M
            r = 2 + 0.7 * math.cos(v)
            lines.append('%.12g %.12g %.12g' % (r * math.cos(u), r * math.sin(u), 0.7 * math.sin(v)))
    for i in range(N):
        for j in range(M):
            lines.append('3 %d %d %d' % (vid(i, j), vid(i + 1, j), vid(i + 1, j + 1)))
            lines.append('3 %d %d %d' % (vid(i, j), vid(i + 1, j + 1), vid(i, j + 1)))
    with open(os.path.join(directory, 'torus.off'), 'w') as out:
        out.write('\n'.join(lines) + '\n')

    meridian = [(vid(0, j), vid(0, j + 1)) for j in range(M)]
    longitude = [(vid(i, 0), vid(i + 1, 0)) for i in range(N)]

    def write(name, edges):
        with open(os.path.join(directory, name), 'w') as out:
            out.write('\n\n' + ' '.join('%d %d' % e for e in edges) + '\n')

    write('torus_cut_graph.selection.txt', meridian + longitude)
    write('torus_meridian_path.selection.txt', meridian[:-1])


if __name__ == '__main__':
    main()
