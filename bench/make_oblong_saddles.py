#!/usr/bin/env python3
"""Steep saddles over oblong outlines, meshed in polar sectors (issue 38, 2; numpy).

Unlike the grids, rows, rings about the middle, scatter, Delaunay, split fans, lattices and
off-centre fans of the other bench/make_saddle_*.py, make_lattice_saddles.py and
make_fan_saddles.py: the outline is twice as long as it is wide or more, so a square that covers
its long arc carries over twice its paper, and the mesh is a polar grid of a fixed count of
sectors (the triangles grow toward the rim, long across the outline's narrow ends), each ring's
vertices jittered along their ring:
- oblong_saddle_ellipse: z = x^2 / 0.06 - y^2 / 0.09 over an ellipse of semi-axes 13 x 6 cm (slope
  4.3 at the rising ends), 0.2 mm of noise along z, in metres, turned 30 degrees about (0, 1, 1);
- oblong_saddle_stadium_mm: z = (0.9 x^2 - y^2) / 70 over |x / 130|^6 + |y / 55|^6 = 1 (a rounded
  rectangle 260 x 110 mm, slope 3.3 at its ends), in millimetres, turned about (1, -1, 2) by 50
  degrees and moved to (200, -80, 40).
Usage: make_oblong_saddles.py OUT_DIR [--seed S]
Writes OUT_DIR/NAME.obj for the two and OUT_DIR/targets.tsv (name, start kind).
"""
import math
import os

import numpy as np

from formula_meshes import folder_and_seed, write_kinds
from make_lattice_saddles import write
from make_saddle_quadrics import rotation


def polar_sectors(radius_at, rings, sectors, rng, jitter):
    """A centre vertex and `rings` rings of `sectors` vertices each, the k-th at k / rings of the
    outline's distance; quads between rings split along alternating diagonals."""
    points = [np.zeros(2)]
    for k in range(1, rings + 1):
        for j in range(sectors):
            a = (j + rng.uniform(-jitter, jitter)) * 2.0 * math.pi / sectors
            r = (k / rings) * radius_at(a)
            points.append(r * np.array([math.cos(a), math.sin(a)]))
    index = lambda k, j: 1 + (k - 1) * sectors + j % sectors  # noqa: E731
    triangles = [(0, index(1, j), index(1, j + 1)) for j in range(sectors)]
    for k in range(1, rings):
        for j in range(sectors):
            a, b, c, d = index(k, j), index(k, j + 1), index(k + 1, j + 1), index(k + 1, j)
            if (j + k) % 2:
                triangles += [(a, c, b), (a, d, c)]
            else:
                triangles += [(a, d, b), (b, d, c)]
    return np.array(points), np.array(triangles)


def superellipse(a, b, power):
    def radius_at(phi):
        c, s = abs(math.cos(phi)), abs(math.sin(phi))
        return 1.0 / ((c / a) ** power + (s / b) ** power) ** (1.0 / power)
    return radius_at


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 22)
    made = []

    # An ellipse 26 x 12 cm, in metres, noise along z, turned.
    p, t = polar_sectors(superellipse(0.13, 0.06, 2.0), 24, 72, rng, 0.3)
    z = p[:, 0] ** 2 / 0.06 - p[:, 1] ** 2 / 0.09 + rng.normal(0.0, 0.0002, len(p))
    v = np.column_stack([p, z]) @ rotation((0.0, 1.0, 1.0), math.radians(30)).T
    write(os.path.join(args.out, "oblong_saddle_ellipse.obj"), v, t,
          "z = x^2 / 0.06 - y^2 / 0.09 over an ellipse 13 x 6 cm, noise 0.2 mm, turned (metres)")
    made.append("oblong_saddle_ellipse")

    # A rounded rectangle 260 x 110 mm, in millimetres, turned and moved.
    p, t = polar_sectors(superellipse(130.0, 55.0, 6.0), 20, 96, rng, 0.25)
    z = (0.9 * p[:, 0] ** 2 - p[:, 1] ** 2) / 70.0
    v = np.column_stack([p, z]) @ rotation((1.0, -1.0, 2.0), math.radians(50)).T
    v += np.array([200.0, -80.0, 40.0])
    write(os.path.join(args.out, "oblong_saddle_stadium_mm.obj"), v, t,
          "z = (0.9 x^2 - y^2) / 70 over a rounded rectangle 260 x 110 mm, turned, moved (mm)")
    made.append("oblong_saddle_stadium_mm")

    write_kinds(args.out, made, "square")


if __name__ == "__main__":
    main()
