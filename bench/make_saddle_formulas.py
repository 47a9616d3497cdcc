#!/usr/bin/env python3
"""Saddle targets from formulas the other generators do not use (issue 38, 2; standard library).

Unlike the grids, lattices, scatter, Delaunay and row scans of the other saddle generators, the
first two targets here are meshed on a warped grid (every line bent by a sine, so no edge lies on a straight
line of the parameter plane) whose quads are each split into four triangles about a centre
vertex (vertices of degree 4 and 8 alternate), then moved off the origin.

  monkey_turned:  a monkey saddle z = (x^3 - 3 x y^2) / 0.06 over a 16 x 16 cm square (three
                  rises and three falls, heights to +-34 mm), 24 x 24 quads, turned 20 degrees
                  about z, centred at (0.2, 0.1, -0.05).
  saddle_rect_30: z = 0.9 x^2 - 1.6 y^2 over a 30 x 18 cm rectangle, tilted 30 degrees about x,
                  0.3 mm noise (seeded) along z before the tilt, 36 x 22 quads, centred at
                  (-0.1, 0.05, 0.2).
  torus_throat:   not a height formula: the inner band of a torus (tube radius 7 cm about a circle
                  of 12 cm), 50 degrees either way about its axis and 55 degrees either way over
                  the tube from its innermost line, a steep saddle (its normal turns 100 and
                  110 degrees across it, the band flaring from 4.4 to 7 cm half width); meshed in
                  rows along the axis' circles, each row's vertices as many as its length needs
                  (so rows differ in count) and zipped to the next, tilted 25 degrees about
                  (1, 1, 0) and centred near (0.3, -0.2, 0.1).

Usage: make_saddle_formulas.py OUT_DIR
"""
import math
import os
import random
import sys


def warped_grid(half_x, half_y, nx, ny, height, noise, rng):
    """Vertices (x, y, z) and triangles of the warped, centre-split grid."""
    positions, corner = [], {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            u, v = -1.0 + 2.0 * i / nx, -1.0 + 2.0 * j / ny
            # Bend the grid's lines, keeping the outline straight (the sine vanishes at +-1).
            du = 0.04 * math.sin(math.pi * u) * math.cos(0.5 * math.pi * v)
            dv = 0.04 * math.sin(math.pi * v) * math.cos(0.5 * math.pi * u)
            x, y = half_x * (u + du), half_y * (v + dv)
            corner[(i, j)] = len(positions)
            positions.append((x, y, height(x, y) + rng.gauss(0.0, noise)))
    triangles = []
    for j in range(ny):
        for i in range(nx):
            a, b = corner[(i, j)], corner[(i + 1, j)]
            c, d = corner[(i + 1, j + 1)], corner[(i, j + 1)]
            x = sum(positions[k][0] for k in (a, b, c, d)) / 4.0
            y = sum(positions[k][1] for k in (a, b, c, d)) / 4.0
            m = len(positions)
            positions.append((x, y, height(x, y) + rng.gauss(0.0, noise)))
            triangles += [(a, b, m), (b, c, m), (c, d, m), (d, a, m)]
    return positions, triangles


def torus_rows(big, tube, half_u, half_v, rows, spacing):
    """The torus band's vertices and triangles: rows over the tube, zipped (see the docstring)."""
    positions, row_ids, row_us = [], [], []
    for j in range(rows + 1):
        v = -half_v + 2.0 * half_v * j / rows
        rho = big - tube * math.cos(v)
        count = max(4, int(round(2.0 * half_u * rho / spacing)) + 1)
        ids, us = [], []
        for i in range(count):
            u = -half_u + 2.0 * half_u * i / (count - 1)
            ids.append(len(positions))
            us.append(u)
            positions.append((rho * math.cos(u), rho * math.sin(u), tube * math.sin(v)))
        row_ids.append(ids)
        row_us.append(us)
    return positions, zip_rows(list(zip(row_ids, row_us)))


def zip_rows(rows):
    """Triangles between consecutive rows, each (vertex ids, parameters) ordered along the row."""
    triangles = []
    for (a, ua), (b, ub) in zip(rows, rows[1:]):
        i = k = 0
        while i < len(a) - 1 or k < len(b) - 1:
            if k == len(b) - 1 or (i < len(a) - 1 and ua[i + 1] < ub[k + 1]):
                triangles.append((a[i], a[i + 1], b[k]))
                i += 1
            else:
                triangles.append((a[i], b[k + 1], b[k]))
                k += 1
    return triangles


def rotate_axis(p, axis, degrees):
    """Rodrigues' rotation of p about the unit-normalised axis."""
    n = math.sqrt(sum(a * a for a in axis))
    k = [a / n for a in axis]
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    dot = sum(a * b for a, b in zip(k, p))
    cross = (k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0])
    return tuple(p[i] * c + cross[i] * s + k[i] * dot * (1 - c) for i in range(3))


def rotate_z(p, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return (c * p[0] - s * p[1], s * p[0] + c * p[1], p[2])


def rotate_x(p, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return (p[0], c * p[1] - s * p[2], s * p[1] + c * p[2])


def write(path, positions, triangles):
    with open(path, "w") as out:
        for p in positions:
            out.write("v %.9g %.9g %.9g\n" % p)
        for t in triangles:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    rng = random.Random(1138)

    v, f = warped_grid(0.08, 0.08, 24, 24, lambda x, y: (x ** 3 - 3 * x * y * y) / 0.06, 0.0, rng)
    v = [tuple(a + b for a, b in zip(rotate_z(p, 20.0), (0.2, 0.1, -0.05))) for p in v]
    write(os.path.join(out, "monkey_turned.obj"), v, f)

    v, f = warped_grid(0.15, 0.09, 36, 22, lambda x, y: 0.9 * x * x - 1.6 * y * y, 0.0003, rng)
    v = [tuple(a + b for a, b in zip(rotate_x(p, 30.0), (-0.1, 0.05, 0.2))) for p in v]
    write(os.path.join(out, "saddle_rect_30.obj"), v, f)

    v, f = torus_rows(0.12, 0.07, math.radians(50.0), math.radians(55.0), 30, 0.004)
    # The band's middle (its innermost line at u = 0) to the origin, then tilted and moved.
    v = [rotate_axis((p[0] - 0.05, p[1], p[2]), (1.0, 1.0, 0.0), 25.0) for p in v]
    v = [tuple(a + b for a, b in zip(p, (0.3, -0.2, 0.1))) for p in v]
    write(os.path.join(out, "torus_throat.obj"), v, f)


if __name__ == "__main__":
    main()
