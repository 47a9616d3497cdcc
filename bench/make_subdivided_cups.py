#!/usr/bin/python3
"""Steep cups made by Loop subdivision of a coarse cage, for `curvefold fit` (issue 38, 2), numpy.
Usage: bench/make_subdivided_cups.py OUTDIR [--seed N] (deterministic for a seed).

Unlike the other cup generators (profiles of revolution meshed in rings or lattices, or solids
marched on a grid), each cup here is a coarse polyhedral cage (a prism of k sides with a floor and
no lid: a few dozen triangles) smoothed by Loop subdivision (Loop 1987: each triangle split in
four, every vertex moved to a weighted mean of its neighbours; the rim a boundary, smoothed as a
cubic B-spline curve), so no formula gives the surface: its floor is flat only near the middle,
its heel is rounded by the cage's coarseness, its sides are k-fold, not round, and its
triangles come in the cage's valence pattern (valence-k vertex at the floor's centre).
- subdiv_hex_cup (metres): a hexagonal cage 3.6 cm across the floor, 4.2 cm at the rim, 6 cm
  tall, 3 subdivisions, tilted 30 degrees.
- subdiv_oct_beaker_mm (mm): an octagonal cage 50 mm -> 64 mm across, 70 mm tall, its cage's
  vertices jittered by 1.5 mm, 3 subdivisions, tilted 100 degrees (upside down and leaning).
- subdiv_pent_tumbler (metres): a pentagonal cage turned by 8 degrees a ring (a twisted wall),
  3 cm -> 3.8 cm across, 7 cm tall, 3 subdivisions, tilted 55 degrees.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from formula_meshes import folder_and_seed, place, write_obj  # noqa: E402


def cage(k, floor_radius, rim_radius, height, rings, twist_degrees, jitter, rng):
    """A k-sided prism cage: a floor (a centre and a ring of k) and `rings` rings of the wall up
    to the rim, each turned by `twist_degrees` from the one below; triangles outward (floor
    facing -z)."""
    verts = [(0.0, 0.0, 0.0)]
    for j in range(rings + 1):
        h = height * j / rings
        r = floor_radius + (rim_radius - floor_radius) * j / rings
        turn = math.radians(twist_degrees * j)
        for i in range(k):
            a = 2.0 * math.pi * i / k + turn
            verts.append((r * math.cos(a), r * math.sin(a), h))
    verts = np.array(verts)
    if jitter > 0.0:
        verts[1:] += rng.normal(0.0, jitter, verts[1:].shape)
        verts[0, 2] = 0.0
    tris = []
    ring = lambda j, i: 1 + j * k + (i % k)  # noqa: E731
    for i in range(k):
        tris.append((0, ring(0, i + 1), ring(0, i)))  # the floor, seen from below
    for j in range(rings):
        for i in range(k):
            tris.append((ring(j, i), ring(j, i + 1), ring(j + 1, i + 1)))
            tris.append((ring(j, i), ring(j + 1, i + 1), ring(j + 1, i)))
    return verts, tris


def loop_subdivide(verts, tris):
    """One step of Loop subdivision with boundary rules (boundary edges and vertices smoothed as a
    cubic B-spline: 1/2 1/2 for an edge point, 1/8 3/4 1/8 for a vertex)."""
    edge_faces = {}
    for t in tris:
        for a, b, c in ((t[0], t[1], t[2]), (t[1], t[2], t[0]), (t[2], t[0], t[1])):
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(c)
    neighbours = [set() for _ in verts]
    boundary_neighbours = [[] for _ in verts]
    for (a, b), opposite in edge_faces.items():
        neighbours[a].add(b)
        neighbours[b].add(a)
        if len(opposite) == 1:
            boundary_neighbours[a].append(b)
            boundary_neighbours[b].append(a)
    new_verts = []
    for v, p in enumerate(verts):
        if boundary_neighbours[v]:
            a, b = boundary_neighbours[v][:2]
            new_verts.append(0.75 * p + 0.125 * (verts[a] + verts[b]))
        else:
            n = len(neighbours[v])
            beta = (0.625 - (0.375 + 0.25 * math.cos(2.0 * math.pi / n)) ** 2) / n
            new_verts.append((1.0 - n * beta) * p + beta * sum(verts[u] for u in neighbours[v]))
    edge_point = {}
    for (a, b), opposite in edge_faces.items():
        if len(opposite) == 1:
            q = 0.5 * (verts[a] + verts[b])
        else:
            q = 0.375 * (verts[a] + verts[b]) + 0.125 * (verts[opposite[0]] + verts[opposite[1]])
        edge_point[(a, b)] = len(new_verts)
        new_verts.append(q)
    mid = lambda a, b: edge_point[(min(a, b), max(a, b))]  # noqa: E731
    new_tris = []
    for a, b, c in tris:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        new_tris += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return np.array(new_verts), new_tris


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 24)
    cups = [
        ("subdiv_hex_cup", "metres", (6, 0.018, 0.021, 0.06, 3, 0.0, 0.0), 3, 20.0, 30.0,
         (0.1, -0.05, 0.02), "%.8f"),
        ("subdiv_oct_beaker_mm", "mm", (8, 25.0, 32.0, 70.0, 4, 0.0, 1.5), 3, 65.0, 100.0,
         (12.0, 40.0, -7.0), "%.5f"),
        ("subdiv_pent_tumbler", "metres", (5, 0.015, 0.019, 0.07, 4, 8.0, 0.0), 3, -40.0, 55.0,
         (-0.02, 0.03, 0.3), "%.8f"),
    ]
    for name, units, shape, steps, yaw, tilt, shift, number in cups:
        verts, tris = cage(*shape, rng)
        for _ in range(steps):
            verts, tris = loop_subdivide(verts, tris)
        placed = [place(tuple(p), yaw, tilt, shift) for p in verts]
        comment = "%s: Loop-subdivided %d-sided cup cage, %d steps, %s, %d triangles" % (
            name, shape[0], steps, units, len(tris))
        write_obj(os.path.join(args.out, name + ".obj"), comment, os.path.basename(__file__),
                  placed, tris, number)
        print(comment)


if __name__ == "__main__":
    main()
