#!/usr/bin/env python3
"""Saddles cut from a lattice of equilateral triangles, ragged at the rim (issue 38, 2; numpy).

Unlike the grids, rows, rings, scatter, Delaunay and split fans of the other
bench/make_saddle_*.py: a lattice of equilateral triangles turned by a random angle is clipped
to an outline (a triangle's whole triangles only, so the rim is ragged as a scan's), holes are
cut by dropping the triangles near their centres, and the height is a cubic or a quadratic:
- monkey_saddle_scan: z = s (x^3 - 3 x y^2) / R^2 over a disk of radius R = 10 cm (three rising
  and three falling lobes; the rim's slope 3 s = 1.8), two holes, 0.4 mm of noise along z,
  tilted 25 degrees, in metres;
- monkey_saddle_triangle: the same cubic (3 s = 2.4) over an equilateral triangle whose corners
  lie on the falling lobes, in millimetres, turned and moved;
- steep_saddle_triangle: z = (x^2 - y^2) / 0.05 over an equilateral triangle of circumradius
  10 cm (slopes to 4 at its corners), one hole, 0.3 mm of noise, in millimetres, tilted 35
  degrees.

Usage: make_lattice_saddles.py OUT_DIR [--seed S]
Writes OUT_DIR/NAME.obj for the three.
"""
import math
import os

import numpy as np

from formula_meshes import folder_and_seed
from make_saddle_quadrics import rotation


def lattice(radius, spacing, turn):
    """Points of an equilateral lattice turned by `turn`, within 1.2 `radius` of the origin."""
    n = int(math.ceil(1.3 * radius / spacing)) + 2
    index, points = {}, []
    for j in range(-n, n + 1):
        for i in range(-n, n + 1):
            x, y = (i + 0.5 * j) * spacing, j * spacing * math.sqrt(3.0) / 2.0
            if x * x + y * y > (1.3 * radius) ** 2:
                continue
            c, s = math.cos(turn), math.sin(turn)
            index[(i, j)] = len(points)
            points.append((c * x - s * y, s * x + c * y))
    triangles = []
    for (i, j), a in index.items():
        for b, c in (((i + 1, j), (i, j + 1)), ((i + 1, j), (i + 1, j - 1))):
            if b in index and c in index:
                triangles.append((a, index[b], index[c]) if c[1] > j else (a, index[c], index[b]))
    return np.array(points), np.array(triangles)


def clip(points, triangles, inside, holes):
    """The triangles whose corners are all inside and whose centre is in no hole, reindexed."""
    keep = []
    for t in triangles:
        p = points[t]
        centre = p.mean(axis=0)
        if all(inside(q) for q in p) and all(np.linalg.norm(centre - h) > r for h, r in holes):
            keep.append(t)
    keep = np.array(keep)
    used = np.unique(keep)
    remap = -np.ones(len(points), int)
    remap[used] = np.arange(len(used))
    return points[used], remap[keep]


def in_triangle(circumradius, turn):
    corners = [circumradius * np.array([math.cos(turn + k * 2 * math.pi / 3),
                                        math.sin(turn + k * 2 * math.pi / 3)]) for k in range(3)]

    def inside(q):
        for k in range(3):
            a, b = corners[k], corners[(k + 1) % 3]
            if (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0]) < -1e-12:
                return False
        return True
    return inside


def write(path, vertices, triangles, note):
    with open(path, "w") as out:
        out.write(f"# {note}\n")
        for v in vertices:
            out.write(f"v {v[0]:.9g} {v[1]:.9g} {v[2]:.9g}\n")
        for t in triangles:
            out.write(f"f {t[0] + 1} {t[1] + 1} {t[2] + 1}\n")


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 19)
    R = 0.10

    # Monkey saddle over a disk, ragged rim, two holes, noise, tilted.
    p, t = lattice(R, R / 24, rng.uniform(0, math.pi))
    p, t = clip(p, t, lambda q: q @ q <= R * R,
                [(np.array([0.045, 0.02]), 0.012), (np.array([-0.03, -0.05]), 0.009)])
    s = 0.6
    z = s * (p[:, 0] ** 3 - 3 * p[:, 0] * p[:, 1] ** 2) / R ** 2
    z += rng.normal(0.0, 0.0004, len(z))
    v = np.column_stack([p, z]) @ rotation([1, 0.3, 0], math.radians(25)).T + [0.2, -0.1, 0.05]
    write(os.path.join(args.out, "monkey_saddle_scan.obj"), v, t,
          "monkey saddle z = 0.6 (x^3 - 3xy^2) / R^2, R 0.1 m, two holes, noise 0.4 mm, tilted 25")

    # Monkey saddle over a triangle whose corners lie on its falling lobes, in mm.
    p, t = lattice(R, R / 28, rng.uniform(0, math.pi))
    p, t = clip(p, t, in_triangle(R, math.pi / 3), [])
    s = 0.8
    z = s * (p[:, 0] ** 3 - 3 * p[:, 0] * p[:, 1] ** 2) / R ** 2
    v = np.column_stack([p, z]) @ rotation([0, 0, 1], math.radians(50)).T
    v = 1000.0 * (v + [-0.05, 0.12, 0.3])
    write(os.path.join(args.out, "monkey_saddle_triangle.obj"), v, t,
          "monkey saddle z = 0.8 (x^3 - 3xy^2) / R^2 over a triangle of circumradius 100 mm, mm")

    # A steep quadratic saddle over a triangle, one hole, noise, in mm, tilted.
    p, t = lattice(R, R / 30, rng.uniform(0, math.pi))
    p, t = clip(p, t, in_triangle(R, math.radians(20)), [(np.array([0.02, -0.025]), 0.01)])
    z = (p[:, 0] ** 2 - p[:, 1] ** 2) / 0.05
    z += rng.normal(0.0, 0.0003, len(z))
    v = np.column_stack([p, z]) @ rotation([0.2, 1, 0], math.radians(35)).T
    v = 1000.0 * (v + [0.1, 0.0, -0.2])
    write(os.path.join(args.out, "steep_saddle_triangle.obj"), v, t,
          "z = (x^2 - y^2) / 0.05 over a triangle of circumradius 100 mm, one hole, mm, tilted 35")


if __name__ == "__main__":
    main()
