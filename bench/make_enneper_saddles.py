#!/usr/bin/python3
"""Enneper's minimal surfaces as steep and lobed saddles, for `curvefold fit` (issue 38, 2).

Unlike the other saddle generators (height fields z = f(x, y) over an outline: grids, rings,
lattices, fans, Delaunay meshes, polar sectors): a parametric minimal surface, not a graph over
any plane, from its Weierstrass data (f = 1, g = w^n over the complex disk |w| < r):
  X = Re(w - w^(2n+1) / (2n+1)),  Y = Im(w + w^(2n+1) / (2n+1)),  Z = Re(2 w^(n+1) / (n+1)),
so its n + 1 wings rise and fall ever more steeply toward the rim (the normal is g's stereographic
image: |w|^n = 1 would stand the rim on edge; r^n of 0.8-0.9 leaves it at 77-84 degrees, slopes
4 to 10), its outline is no polygon nor
ellipse but the rim's own curve, and its mean curvature is zero everywhere. Meshed on a square
grid of the parameter plane (w = u + iv), the triangles whose three corners lie in the disk kept
(a ragged rim; triangles of every size after the map, small at the middle, stretched at the rim),
each quad cut along a random diagonal; Gaussian noise along the normal; then scaled, turned about
a random axis and moved:
  enneper_k1.obj      n = 1 (a saddle of 2 wings up, 2 down), r = 0.9, 16 cm across, metres;
  enneper_k2_mm.obj   n = 2 (a monkey saddle), r = 0.92, 150 mm across, millimetres;
  enneper_k3.obj      n = 3 (4 wings each way), r = 0.93, 12 cm across, metres.
Usage: bench/make_enneper_saddles.py OUT_DIR [--seed S] (default seed 24; deterministic; the
standard library only).
"""
import cmath
import math
import os
import random
import sys


def enneper(w, n):
    p = w ** (2 * n + 1) / (2 * n + 1)
    return ((w - p).real, (w + p).imag, (2 * w ** (n + 1) / (n + 1)).real)


def rotation(axis, angle):
    x, y, z = axis
    length = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / length, y / length, z / length
    c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def surface(rng, n, r, across, noise, cells):
    """Vertices and triangles of Enneper's surface of order n over |w| < r, `across` wide."""
    h = 2 * r / cells
    index, vertices = {}, []
    for i in range(cells + 1):
        for j in range(cells + 1):
            w = complex(-r + i * h, -r + j * h)
            if abs(w) <= r * (1 + 1e-9):
                index[(i, j)] = len(vertices)
                vertices.append(enneper(w, n))
    triangles = []
    for i in range(cells):
        for j in range(cells):
            a, b, c, d = (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
            pairs = [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
            for t in pairs:
                if all(k in index for k in t):
                    triangles.append(tuple(index[k] for k in t))
    xs = [v[0] for v in vertices] + [v[1] for v in vertices]
    scale = across / (max(xs) - min(xs))
    out = []
    for (x, y, z) in vertices:
        # noise along the normal's main part (the surface's height near the middle)
        out.append([scale * x, scale * y, scale * z + rng.gauss(0.0, noise)])
    return out, triangles


def write(path, vertices, triangles, rng, offset):
    m = rotation([rng.uniform(-1, 1) for _ in range(3)], rng.uniform(0.3, 2.8))
    with open(path + ".tmp", "w") as f:
        f.write("# Enneper saddle (bench/make_enneper_saddles.py)\n")
        for v in vertices:
            p = [sum(m[i][k] * v[k] for k in range(3)) + offset[i] for i in range(3)]
            f.write("v %.7g %.7g %.7g\n" % tuple(p))
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))
    os.replace(path + ".tmp", path)


def main(argv):
    if len(argv) < 2 or argv[1].startswith("-"):
        sys.exit("usage: make_enneper_saddles.py OUT_DIR [--seed S]")
    out = argv[1]
    seed = int(argv[argv.index("--seed") + 1]) if "--seed" in argv else 24
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    for name, n, r, across, noise, cells, offset in [
        ("enneper_k1", 1, 0.9, 0.16, 0.0003, 44, [0.05, -0.02, 0.3]),
        ("enneper_k2_mm", 2, 0.92, 150.0, 0.3, 48, [40.0, 210.0, -75.0]),
        ("enneper_k3", 3, 0.93, 0.12, 0.0002, 52, [-0.1, 0.0, 0.02]),
    ]:
        vertices, triangles = surface(rng, n, r, across, noise, cells)
        write(os.path.join(out, name + ".obj"), vertices, triangles, rng, offset)
        print("%s: %d vertices, %d triangles" % (name, len(vertices), len(triangles)))


if __name__ == "__main__":
    main(sys.argv)
