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
"""Writes a CGAL selection file (*.selection.txt) of seam edges that cut a closed genus-0
triangle mesh (OFF) into a topological disk: a tree of shortest edge paths through
`terminals` far-apart vertices.

  make_seam_selection.py MESH.off OUT.selection.txt [TERMINALS]

Edge lengths are Euclidean. The terminals are chosen by farthest-point sampling of the
shortest-path distance: the first is the vertex farthest from vertex 0, each next one the
vertex farthest from the ones chosen so far. The tree starts at the first terminal; each
next terminal is joined to the tree by its shortest edge path to the nearest tree vertex.
With TERMINALS = 2 (the default) the cut is the shortest edge path between two far-apart
vertices. The output is deterministic (vertices are visited in index order).

Output: line 1 (selected vertices) and line 2 (selected faces) are empty, line 3 lists the
seam edges as pairs of 0-based vertex indices in file order, each pair in path order.
"""

import heapq
import math
import sys


def read_off(path):
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split('#', 1)[0]
            tokens.extend(line.split())
    if tokens[0] != 'OFF':
        raise SystemExit(path + ': not an OFF file')
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    points = []
    for _ in range(nv):
        points.append(tuple(float(t) for t in tokens[at:at + 3]))
        at += 3
    faces = []
    for _ in range(nf):
        n = int(tokens[at])
        faces.append([int(t) for t in tokens[at + 1:at + 1 + n]])
        at += 1 + n
    return points, faces


def adjacency(points, faces):
    neighbours = [dict() for _ in points]
    for f in faces:
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            d = math.dist(points[a], points[b])
            neighbours[a][b] = d
            neighbours[b][a] = d
    return neighbours


def dijkstra(neighbours, sources):
    """distances and predecessors from the nearest source"""
    dist = [math.inf] * len(neighbours)
    pred = [-1] * len(neighbours)
    heap = []
    for s in sources:
        dist[s] = 0.
        heap.append((0., s))
    heapq.heapify(heap)
    while heap:
        d, v = heapq.heappop(heap)
        if d > dist[v]:
            continue
        for w in sorted(neighbours[v]):
            nd = d + neighbours[v][w]
            if nd < dist[w]:
                dist[w] = nd
                pred[w] = v
                heapq.heappush(heap, (nd, w))
    return dist, pred


def farthest(dist):
    best = max(d for d in dist if d < math.inf)
    return min(v for v, d in enumerate(dist) if d == best)


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    points, faces = read_off(sys.argv[1])
    count = int(sys.argv[3]) if len(sys.argv) == 4 else 2
    neighbours = adjacency(points, faces)

    terminals = [farthest(dijkstra(neighbours, [0])[0])]
    while len(terminals) < count:
        terminals.append(farthest(dijkstra(neighbours, terminals)[0]))

    tree = {terminals[0]}
    edges = []
    for t in terminals[1:]:
        dist, pred = dijkstra(neighbours, sorted(tree))
        path = [t]
        while path[-1] not in tree:
            path.append(pred[path[-1]])
        path.reverse()  # from the tree to the terminal
        edges.extend(zip(path[:-1], path[1:]))
        tree.update(path)

    with open(sys.argv[2], 'w') as out:
        out.write('\n\n' + ' '.join('%d %d' % e for e in edges) + '\n')
    print('%s: terminals %s, %d seam edges' % (sys.argv[2], ' '.join(map(str, terminals)), len(edges)))


if __name__ == '__main__':
    main()
