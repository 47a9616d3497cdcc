#!/usr/bin/python3
"""A vase for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators (awk
grids, numpy grids, splines, Bezier, Hermite, elliptic fans, a helix, staggered B-spline rings,
arc-length rows zipped, Cauchy bumps): the Python standard library only.

square_bottle_z: 28 cm tall, a rounded-square cross-section (a superellipse |x|^3 + |y|^3 = r^3,
so its radius varies by about 12% around), a straight body tapering from 6.0 to 5.6 cm, a
shoulder as a quarter ellipse from 5.6 cm down to a long straight neck of 1.6 cm (a third of the
height), a bead at the lip (a half torus of 0.5 cm standing out of the neck); the axis along +z
tilted 15 degrees about x and moved to (0.1, -0.05, 0.3). Its mesh: a grid of 40 around by 44
along (rows spaced by the profile's arc length) with a centre vertex in every quad (four
triangles a quad), so half its vertices have valence 4 and half valence 8.

Usage: bench/make_square_bottle_vases.py OUTDIR
"""
import math
import os
import sys

from make_amphora_vases import rows_by_arc_length


def profile(t):
    """Radius (m) at t in [0, 1] along the 28 cm height."""
    if t < 0.45:  # body, a slight taper
        return 0.060 - 0.004 * t / 0.45
    if t < 0.62:  # shoulder: a quarter ellipse from 5.6 cm down to the neck
        u = (t - 0.45) / 0.17
        return 0.016 + 0.040 * math.sqrt(max(0.0, 1.0 - u * u))
    if t < 0.94:  # neck
        return 0.016
    u = (t - 0.94) / 0.06  # bead: a half circle standing 5 mm out
    return 0.016 + 0.005 * math.sqrt(max(0.0, 1.0 - (2.0 * u - 1.0) ** 2))


def squircle(r, a):
    """The point at angle a on |x|^3 + |y|^3 = r^3."""
    c, s = math.cos(a), math.sin(a)
    k = r / (abs(c) ** 3 + abs(s) ** 3) ** (1.0 / 3.0)
    return k * c, k * s


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    height, around, along = 0.28, 40, 44
    ts = rows_by_arc_length(profile, height, along, fine=4000)
    verts = []
    for t in ts:
        for i in range(around):
            x, y = squircle(profile(t), 2.0 * math.pi * i / around)
            verts.append((x, y, height * t))
    grid = len(verts)
    faces = []
    for k in range(along):
        for i in range(around):
            a, b = k * around + i, k * around + (i + 1) % around
            c, d = a + around, b + around
            centre = [sum(verts[v][j] for v in (a, b, c, d)) / 4.0 for j in range(3)]
            # The centre on the surface: its radius at its height along its own direction.
            tm = (ts[k] + ts[k + 1]) / 2.0
            ang = math.atan2(centre[1], centre[0])
            x, y = squircle(profile(tm), ang)
            verts.append((x, y, height * tm))
            m = len(verts) - 1
            faces += [(a, b, m), (b, d, m), (d, c, m), (c, a, m)]
    assert len(verts) == grid + along * around
    tilt = math.radians(15.0)
    ct, st = math.cos(tilt), math.sin(tilt)
    path = os.path.join(out, "square_bottle_z.obj")
    with open(path, "w") as f:
        f.write("# square_bottle_z: bench/make_square_bottle_vases.py (rounded-square bottle, "
                "shoulder, long neck, bead lip; axis +z tilted 15 degrees about x)\n")
        for x, y, z in verts:
            y2, z2 = y * ct - z * st, y * st + z * ct
            f.write("v %.7f %.7f %.7f\n" % (x + 0.1, y2 - 0.05, z2 + 0.3))
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    print(path)


if __name__ == "__main__":
    main()
