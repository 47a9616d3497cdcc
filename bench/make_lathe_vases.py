#!/usr/bin/python3
"""A vase for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators
(awk grids, numpy grids, Catmull-Rom, Bezier, Hermite with bisection, elliptic fans, a helix):
the Python standard library only, a profile as a uniform cubic B-spline (it approximates its
control points, never passes through them) lathed on staggered rings (each ring of vertices
turned by half a step from the one below, so every quad is two triangles of an antiprism and no
edge runs along the axis), the ring's vertex count following the circumference, every vertex
jittered by a scan's noise, the axis tilted 35 degrees about (1, 0, 1) and moved off the origin.

Usage: bench/make_lathe_vases.py OUTDIR
Writes lathe_bulge_tilted.obj: 21 cm tall, a foot of 4.3 cm radius, a low bulge of 6.4 cm (at a
third of the height), a neck of 3.2 cm (at 88%) and a lip flaring to 3.9 cm; noise 0.4 mm
(seeded). The spline's radii are its control points smoothed, not the points themselves.
"""
import math
import os
import random
import sys

# (height, radius) control points of the B-spline, metres; the ends repeated so it starts and
# ends near them.
CONTROL = [(0.0, 0.040), (0.0, 0.040), (0.03, 0.058), (0.07, 0.068), (0.12, 0.055),
           (0.17, 0.030), (0.20, 0.032), (0.22, 0.040), (0.22, 0.040)]


def bspline(points, u):
    """The uniform cubic B-spline through `points` at u in [0, 1]."""
    segments = len(points) - 3
    x = min(u * segments, segments - 1e-12)
    i = int(x)
    t = x - i
    b = [(1 - t) ** 3 / 6, (3 * t ** 3 - 6 * t ** 2 + 4) / 6,
         (-3 * t ** 3 + 3 * t ** 2 + 3 * t + 1) / 6, t ** 3 / 6]
    h = sum(b[k] * points[i + k][0] for k in range(4))
    r = sum(b[k] * points[i + k][1] for k in range(4))
    return h, r


def rotation(axis, angle):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(angle), math.sin(angle)
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_lathe_vases.py OUTDIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    rng = random.Random(38)
    rings = 56
    around = 60  # the same on every ring (staggered rings need one count)
    noise = 0.0004
    turn = rotation((1.0, 0.0, 1.0), math.radians(35.0))
    offset = (0.13, -0.05, 0.21)
    verts = []
    for j in range(rings + 1):
        h, r = bspline(CONTROL, j / rings)
        for i in range(around):
            a = 2 * math.pi * (i + 0.5 * (j % 2)) / around
            p = [r * math.cos(a), h, r * math.sin(a)]
            p = [c + rng.gauss(0.0, noise) for c in p]
            q = [sum(turn[k][m] * p[m] for m in range(3)) + offset[k] for k in range(3)]
            verts.append(q)
    faces = []
    for j in range(rings):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = (j + 1) * around + i, (j + 1) * around + (i + 1) % around
            if j % 2 == 0:  # the ring above is turned by +half a step
                faces += [(a, b, c), (b, d, c)]
            else:
                faces += [(a, b, d), (a, d, c)]
    path = os.path.join(sys.argv[1], "lathe_bulge_tilted.obj")
    with open(path, "w") as out:
        out.write("# a B-spline lathe on staggered rings, tilted, noisy (bench/make_lathe_vases.py)\n")
        for p in verts:
            out.write(f"v {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
        for f in faces:
            out.write(f"f {f[0] + 1} {f[1] + 1} {f[2] + 1}\n")


if __name__ == "__main__":
    main()
