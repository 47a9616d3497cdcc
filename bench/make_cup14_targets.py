#!/usr/bin/python3
"""Steep cups and bowls for `fit` (issue 38, 2), as OBJ, made apart from curvefold.

Unlike the other bowl generators (hexagonal disks, lattices, polar grids, scan lines, rings
spaced by arc length): numpy only; the mesh is a square grid of (u, v) in [-1, 1]^2 mapped onto
the unit disk by the elliptical square-to-disk map (x = u sqrt(1 - v^2 / 2), y = v sqrt(1 - u^2 /
2)), each grid cell split along an alternating diagonal, and each disk point (angle phi, radius
rho) lifted onto the cup along its own meridian (so a cup need not be round: a leaning wall, an
oval rim). Wall angles are from the horizontal.

  leaning_cup       a cup whose rim stands off the bottom's axis: a flat bottom 5 cm across, the
                    rim 8.5 cm across 6.5 cm up, its centre 1 cm to one side (the wall 62-83
                    degrees mid-way), a rounded heel; turned 20 degrees, off the origin, metres.
  footed_bowl_scan  a steep bowl on a foot ring, as a scan: 11 cm across, 5.2 cm deep, the inside
                    of the foot raised 3 mm (a step 2.4-2.8 cm out), a wall steepening to about
                    68 degrees at the rim; noise 0.25 mm along z, four holes, tilted 35
                    degrees, millimetres.
  oval_cup          an oval cup, rim 9.5 x 7 cm, 5 cm deep, a flat oval bottom 5 x 3.7 cm (the wall
                    about 68-72 degrees mid-way), turned 50 degrees about an oblique axis, metres.

Usage: bench/make_cup14_targets.py OUTDIR
"""
import math
import os
import sys

import numpy as np


def square_disk(n):
    """Grid vertices mapped to the unit disk (phi, rho) and the grid's triangles."""
    u, v = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n), indexing="ij")
    x = u * np.sqrt(1 - v * v / 2)
    y = v * np.sqrt(1 - u * u / 2)
    tris = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            if (i + j) % 2:
                tris += [(a, b, c), (a, c, d)]
            else:
                tris += [(a, b, d), (b, c, d)]
    phi = np.arctan2(y, x).ravel()
    rho = np.hypot(x, y).ravel()
    return phi, rho, np.array(tris)


def lift(phi, rho, bottom, rim, height, heel, flat):
    """A cup point per disk point: the bottom (radius `bottom(phi)`) out to `flat` of rho, then a
    wall from the bottom's edge straight out to the rim point `rim(phi)` (x, y) at `height`, its
    height rising as t^heel along it (a rounded heel: level where it leaves the bottom)."""
    d = np.stack([np.cos(phi), np.sin(phi)], 1)
    b = bottom(phi)[:, None] * d
    pts = np.zeros((len(phi), 3))
    inner = rho <= flat
    pts[inner, :2] = b[inner] * (rho[inner] / flat)[:, None]
    t = (rho[~inner] - flat) / (1 - flat)
    r = rim(phi[~inner])
    pts[~inner, :2] = b[~inner] + (r - b[~inner]) * t[:, None]
    pts[~inner, 2] = height * t ** heel
    return pts


def turned(pts, axis, degrees, offset):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    a = math.radians(degrees)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    m = np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * k @ k
    return pts @ m.T + np.asarray(offset)


def write(path, comment, pts, tris):
    with open(path, "w") as f:
        f.write("# %s (bench/make_cup14_targets.py)\n" % comment)
        for p in pts:
            f.write("v %.7f %.7f %.7f\n" % tuple(p))
        for t in tris:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def drop_unused(pts, tris):
    used = np.unique(tris)
    index = -np.ones(len(pts), int)
    index[used] = np.arange(len(used))
    return pts[used], index[tris]


def main(out):
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(1438)
    phi, rho, tris = square_disk(61)

    def circle(radius, centre=(0.0, 0.0)):
        return lambda p: np.stack([centre[0] + radius * np.cos(p), centre[1] + radius * np.sin(p)], 1)

    # leaning_cup: the rim circle's centre off the bottom's; the bottom a circle of 2.5 cm
    pts = lift(phi, rho, lambda p: np.full_like(p, 0.025), circle(0.0425, (0.01, 0.0)), 0.065,
               1.6, 0.36)
    write(os.path.join(out, "leaning_cup.obj"),
          "a cup 8.5 cm across, 6.5 cm deep, its rim 1 cm off the bottom's axis",
          turned(pts, (0.3, 1.0, 0.4), 20.0, (-0.2, 0.07, 0.11)), tris)

    # footed_bowl_scan: a round profile z(r) with the foot's step, in millimetres
    r = np.linspace(0.0, 55.0, 2000)
    z = 52.0 * (r / 55.0) ** 2.9 + 3.0 / (1 + np.exp((r - 26.0) / 0.6)) - 3.0 / (1 + np.exp(26.0 / 0.6))
    arc = np.concatenate([[0], np.cumsum(np.hypot(np.diff(r), np.diff(z)))])
    s = rho * arc[-1]
    rr, zz = np.interp(s, arc, r), np.interp(s, arc, z)
    pts = np.stack([rr * np.cos(phi), rr * np.sin(phi), zz], 1)
    normal_noise = rng.normal(0.0, 0.25, len(pts))
    pts[:, 2] += normal_noise
    keep = np.ones(len(tris), bool)
    centroid = pts[tris].mean(1)
    for centre, radius in [((10, -8, 0), 6.0), ((-30, 25, 0), 7.0), ((38, 20, 0), 5.0),
                           ((-5, -44, 0), 6.5)]:
        keep &= np.hypot(centroid[:, 0] - centre[0], centroid[:, 1] - centre[1]) > radius
    pts, kept = drop_unused(pts, tris[keep])
    write(os.path.join(out, "footed_bowl_scan.obj"),
          "a steep bowl on a foot ring, 11 cm across, 5.2 cm deep, scanned (mm, noise, 4 holes)",
          turned(pts, (1.0, -0.4, 0.2), 35.0, (140.0, -60.0, 25.0)), kept)

    # oval_cup: an elliptic bottom and rim
    def ellipse(a, b):
        return lambda p: np.stack([a * np.cos(p), b * np.sin(p)], 1)

    pts = lift(phi, rho, lambda p: np.linalg.norm(ellipse(0.025, 0.0185)(p), axis=1),
               ellipse(0.0475, 0.035), 0.05, 1.5, 0.33)
    write(os.path.join(out, "oval_cup.obj"), "an oval cup 9.5 x 7 cm, 5 cm deep",
          turned(pts, (-0.5, 0.2, 1.0), 50.0, (0.05, 0.3, -0.1)), tris)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
