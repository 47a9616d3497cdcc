#!/usr/bin/env python3
"""Saddle targets scanned row by row (issue 38, 2; standard library only).

Unlike the other saddle generators (grids, lattices, scatter, Delaunay), each target here is
sampled as a line scanner sees it: rows across the shape, each row's points at their own uneven
spacing, neighbouring rows joined by a zipper triangulation (always advancing along the row whose
next point is nearer), noise added along the surface's normal.

  hypar_turned: z = (x^2 - y^2) / 0.32 over a 22 x 18 cm rectangle, turned 45 degrees about z
                (so z = 2 x'y' / 0.32 in the frame of its edges), centred at (0.04, -0.03, 0.01),
                40 rows, 0.3 mm noise.
  cosh_saddle:  z = 0.06 (cosh(x / 0.09) - cosh(y / 0.11)) over a 24 x 20 cm ellipse, tilted 12
                degrees about x, 36 rows, 0.2 mm noise.

Usage: make_saddle_rows.py OUT_DIR
"""
import math
import os
import random
import sys


def zipper(rows):
    """Triangles joining consecutive rows of vertex indices (each row ordered along it)."""
    triangles = []
    for a, b in zip(rows, rows[1:]):
        i = j = 0
        while i < len(a) - 1 or j < len(b) - 1:
            if j == len(b) - 1 or (i < len(a) - 1 and a[i + 1][1] <= b[j + 1][1]):
                triangles.append((a[i][0], a[i + 1][0], b[j][0]))
                i += 1
            else:
                triangles.append((a[i][0], b[j + 1][0], b[j][0]))
                j += 1
    return triangles


def scan(height, inside, half_x, half_y, rows, noise, seed):
    rng = random.Random(seed)
    positions, index_rows = [], []
    for r in range(rows):
        y = -half_y + 2.0 * half_y * r / (rows - 1)
        row, x = [], -half_x
        step = 2.0 * half_x / 45.0
        while x <= half_x + 1e-12:
            if inside(x, y):
                z = height(x, y)
                # Noise along the normal of the height field.
                hx = (height(x + 1e-5, y) - height(x - 1e-5, y)) / 2e-5
                hy = (height(x, y + 1e-5) - height(x, y - 1e-5)) / 2e-5
                n = math.sqrt(1.0 + hx * hx + hy * hy)
                e = rng.gauss(0.0, noise)
                row.append((len(positions), x))
                positions.append((x - e * hx / n, y - e * hy / n, z + e / n))
            x += step * rng.uniform(0.6, 1.4)
        if len(row) >= 2:
            index_rows.append(row)
    return positions, zipper(index_rows)


def write(path, positions, triangles):
    with open(path, "w") as f:
        for p in positions:
            f.write("v %.7f %.7f %.7f\n" % p)
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)

    positions, triangles = scan(lambda x, y: (x * x - y * y) / 0.32,
                                lambda x, y: True, 0.11, 0.09, 40, 0.0003, 7)
    c = s = math.sqrt(0.5)
    turned = [(c * x - s * y + 0.04, s * x + c * y - 0.03, z + 0.01) for x, y, z in positions]
    write(os.path.join(out, "hypar_turned.obj"), turned, triangles)

    positions, triangles = scan(
        lambda x, y: 0.06 * (math.cosh(x / 0.09) - math.cosh(y / 0.11)),
        lambda x, y: (x / 0.12) ** 2 + (y / 0.10) ** 2 <= 1.0, 0.12, 0.10, 36, 0.0002, 11)
    t = math.radians(12.0)
    tilted = [(x, math.cos(t) * y - math.sin(t) * z, math.sin(t) * y + math.cos(t) * z)
              for x, y, z in positions]
    write(os.path.join(out, "cosh_saddle.obj"), tilted, triangles)


if __name__ == "__main__":
    main()
