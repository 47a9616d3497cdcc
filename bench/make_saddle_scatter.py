#!/usr/bin/python3
"""Saddle targets for `curvefold fit` made apart from curvefold (issue 38, 2), in pure Python.

Unlike bench/make_saddle_targets.py (regular grids and polar rings) and
bench/make_saddle_lattice.awk (awk lattices, height along y): jittered grids, so no edge lies on
a straight line; a hypar z = k x y whose rulings run along a rectangle's edges; a monkey saddle
over a hexagon of a triangular lattice; a saddle scanned off centre, with noise along its normal,
three holes and a ragged rim, tilted and moved away from the origin.
Usage: bench/make_saddle_scatter.py OUTDIR (deterministic: a fixed seed).
"""
import math
import os
import random
import sys

from formula_meshes import place, write_obj


def jittered(width, depth, nx, ny, jitter, rng):
    """(nx+1) x (ny+1) points of a width x depth rectangle, inner ones moved up to `jitter` of a
    cell, and its triangles (each cell cut along the shorter diagonal)."""
    pts = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = width * (i / nx - 0.5), depth * (j / ny - 0.5)
            if 0 < i < nx:
                x += jitter * width / nx * (2 * rng.random() - 1)
            if 0 < j < ny:
                y += jitter * depth / ny * (2 * rng.random() - 1)
            pts.append((x, y))
    tris = []
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i
            b, c, d = a + 1, a + nx + 2, a + nx + 1
            if math.dist(pts[a], pts[c]) < math.dist(pts[b], pts[d]):
                tris += [(a, b, c), (a, c, d)]
            else:
                tris += [(a, b, d), (b, c, d)]
    return pts, tris


def hexagon(radius, n):
    """A triangular lattice clipped to a regular hexagon of `radius`, n rows from centre to rim."""
    index, pts, tris = {}, [], []
    h = radius / n
    for j in range(-n, n + 1):
        for i in range(-n, n + 1):
            if abs(i + j) <= n:  # axial coordinates inside the hexagon
                index[(i, j)] = len(pts)
                pts.append((h * (i + 0.5 * j), h * j * math.sqrt(3) / 2))
    for (i, j), a in index.items():
        for b, c in (((i + 1, j), (i, j + 1)), ((i + 1, j), (i + 1, j - 1))):
            if b in index and c in index:
                tris.append((a, index[b], index[c]) if c[1] > j else (a, index[c], index[b]))
    return pts, tris


def normal_at(f, x, y, e=1e-5):
    fx = (f(x + e, y) - f(x - e, y)) / (2 * e)
    fy = (f(x, y + e) - f(x, y - e)) / (2 * e)
    n = (-fx, -fy, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(c / length for c in n)


def write(path, comment, verts, tris):
    write_obj(path, comment, "bench/make_saddle_scatter.py", verts, tris)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_saddle_scatter.py OUTDIR")
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    rng = random.Random(20261205)

    # z = x y / 0.35 on a 36 x 22 cm rectangle, rulings along its edges, turned and moved.
    pts, tris = jittered(0.36, 0.22, 36, 22, 0.3, rng)
    verts = [place((x, y, x * y / 0.35), 40, 10, (0.3, -0.1, 0.05)) for x, y in pts]
    write(os.path.join(outdir, "hypar_rect.obj"), "z = xy/0.35 over 36 x 22 cm, jittered", verts, tris)

    # A monkey saddle over a hexagon of radius 12 cm, tilted 30 degrees.
    def monkey(x, y):
        return (x ** 3 - 3 * x * y * y) / 0.05
    pts, tris = hexagon(0.12, 16)
    verts = [place((x, y, monkey(x, y)), 15, 30, (0.0, 0.0, 0.2)) for x, y in pts]
    write(os.path.join(outdir, "monkey_hex.obj"), "monkey saddle over a hexagon r 12 cm", verts, tris)

    # A scanned saddle: z = x^2/0.4 - y^2/0.25 over an ellipse 32 x 24 cm off centre, jittered,
    # 0.6 mm noise along the normal, three holes, a ragged rim; tilted 35, turned 70.
    def saddle(x, y):
        return x * x / 0.4 - y * y / 0.25
    pts, tris = jittered(0.34, 0.26, 48, 36, 0.35, rng)
    verts = []
    for x, y in pts:
        n, d = normal_at(saddle, x, y), rng.gauss(0.0, 0.0006)
        verts.append(place((x + d * n[0], y + d * n[1], saddle(x, y) + d * n[2]), 70, 35, (-0.2, 0.4, 0.1)))
    holes = [((0.06, 0.03), 0.02), ((-0.09, -0.05), 0.015), ((0.02, -0.08), 0.012)]

    def kept(t):
        cx = sum(pts[v][0] for v in t) / 3
        cy = sum(pts[v][1] for v in t) / 3
        rim = 1.0 + 0.06 * math.sin(7 * math.atan2(cy, cx))
        if (cx / 0.16) ** 2 + (cy / 0.12) ** 2 > rim ** 2:
            return False
        return all(math.dist((cx, cy), c) > r for c, r in holes)
    write(os.path.join(outdir, "saddle_scan.obj"), "z = x^2/0.4 - y^2/0.25 scanned, holes",
          verts, [t for t in tris if kept(t)])


if __name__ == "__main__":
    main()
