#!/usr/bin/python3
"""Four vases for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators:
each is a meridian curve given by a closed formula in its own parameter (not a radius against
height, so a shoulder may run level and a bottom may close on the axis), sampled evenly by arc
length with numpy, swept about its axis on rows staggered by half a step (every other row turned by half a vertex
spacing, so the triangles point alternately up and down the axis), then turned and moved off the
world's axes.

lampshade_bulge_oblique: 20 cm tall, open at both ends, a radius widening downward from 4.5 cm
at the top to 8.5 cm at the bottom with a bulge of 1.8 cm at 0.55 of the height (a Gaussian);
the axis along (0.35, 0.55, -0.76), moved to (0.2, -0.1, 0.3).

bottle_short_neck: 25 cm, a closed flat bottom rounded into a straight body of 4.5 cm, a shoulder
that runs nearly level (a quarter ellipse, 3.1 cm in, 4.5 cm up) into a short neck of 1.4 cm
(3 cm long) with a bead at the open lip; lying along (0.96, 0, 0.28), moved to (-0.1, 0.2, 0).

cone_vase_flared: 22 cm in millimetres (220 units), a foot of 6 cm tapering as a cone to a waist
of 2.8 cm at 0.82 of the height, then a lip flaring to 4.2 cm; axis along -z, moved to
(40, -25, 300) mm.

jar_closed: 8 cm tall, a closed flat bottom of 4.5 cm (a fifth of its area) under a wall with a
belly of 1.2 cm, narrowing by 1 cm to the open rim; axis along (0.2, 0.9, -0.4), moved to
(0.05, 0.1, -0.02).

Usage: bench/make_meridian_vases.py OUTDIR
"""
import math
import os
import sys

import numpy as np


def by_arc_length(curve, count, fine=4000):
    """`count` + 1 points (r, h) of curve(u), u in [0, 1], spaced evenly along it."""
    u = np.linspace(0.0, 1.0, fine + 1)
    r, h = curve(u)
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(r), np.diff(h)))])
    even = np.interp(np.linspace(0.0, s[-1], count + 1), s, u)
    return curve(even)


def sweep(r, h, around):
    """Vertices (about +z) and triangles; rows staggered by half a step, a row on the axis one vertex."""
    verts, rows = [], []
    for k, (rk, hk) in enumerate(zip(r, h)):
        if rk < 1e-9:
            rows.append([len(verts)])
            verts.append((0.0, 0.0, hk))
            continue
        a = 2 * math.pi * (np.arange(around) + 0.5 * (k % 2)) / around
        rows.append(list(range(len(verts), len(verts) + around)))
        verts.extend(zip(rk * np.cos(a), rk * np.sin(a), np.full(around, hk)))
    faces = []
    for k in range(len(rows) - 1):
        lo, hi = rows[k], rows[k + 1]
        if len(lo) == 1 or len(hi) == 1:
            ring, tip = (hi, lo[0]) if len(lo) == 1 else (lo, hi[0])
            for i in range(around):
                f = (tip, ring[i], ring[(i + 1) % around])
                faces.append(f[::-1] if len(lo) == 1 else f)
            continue
        shift = k % 2  # odd rows sit half a step ahead
        for i in range(around):
            a, b = lo[i], lo[(i + 1) % around]
            c, d = hi[(i + shift) % around], hi[(i + shift - 1) % around]
            faces += [(a, b, c), (a, c, d)]
    return np.array(verts), faces


def place(verts, axis, at):
    """Turn +z onto `axis` (Rodrigues) and move the result to `at`."""
    z = np.array([0.0, 0.0, 1.0])
    n = np.asarray(axis, float) / np.linalg.norm(axis)
    v, c = np.cross(z, n), float(z @ n)
    if np.linalg.norm(v) < 1e-12:
        turn = np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    else:
        k = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
        turn = np.eye(3) + k + k @ k / (1 + c)
    return verts @ turn.T + np.asarray(at, float)


def lampshade(u):
    t = u
    return 0.085 - 0.04 * t + 0.018 * np.exp(-((t - 0.55) / 0.2) ** 2), 0.20 * t


def bottle(u):
    # pieces by the parameter: bottom 0-0.15, rounded foot 0.15-0.2, body 0.2-0.55,
    # shoulder 0.55-0.8, neck 0.8-0.95, bead 0.95-1
    r, h = np.empty_like(u), np.empty_like(u)
    for i, x in enumerate(u):
        if x < 0.15:
            r[i], h[i] = 0.037 * x / 0.15, 0.0
        elif x < 0.2:
            a = 0.5 * math.pi * (x - 0.15) / 0.05
            r[i], h[i] = 0.037 + 0.008 * math.sin(a), 0.008 * (1 - math.cos(a))
        elif x < 0.55:
            r[i], h[i] = 0.045, 0.008 + 0.162 * (x - 0.2) / 0.35
        elif x < 0.8:
            a = 0.5 * math.pi * (x - 0.55) / 0.25
            r[i], h[i] = 0.014 + 0.031 * math.cos(a), 0.17 + 0.045 * math.sin(a)
        else:
            s = (x - 0.8) / 0.2
            r[i] = 0.014 + 0.003 * math.exp(-((s - 0.85) / 0.08) ** 2)
            h[i] = 0.215 + 0.035 * s
    return r, h


def cone_vase(u):
    t = u
    waist = 60.0 - (60.0 - 28.0) * np.minimum(t, 0.82) / 0.82
    return waist + 14.0 * np.clip((t - 0.82) / 0.18, 0, None) ** 1.5, 220.0 * t


def jar(u):
    r, h = np.empty_like(u), np.empty_like(u)
    bottom = u < 0.3
    r[bottom], h[bottom] = 0.045 * u[bottom] / 0.3, 0.0
    t = (u[~bottom] - 0.3) / 0.7
    r[~bottom] = 0.045 + 0.012 * np.sin(np.pi * t) - 0.01 * t
    h[~bottom] = 0.08 * t
    return r, h


def write(path, comment, verts, faces):
    with open(path, "w") as out:
        out.write("# " + comment + "\n")
        for v in verts:
            out.write("v %.7g %.7g %.7g\n" % tuple(v))
        for f in faces:
            out.write("f " + " ".join(str(i + 1) for i in f) + "\n")  # any polygon


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_meridian_vases.py OUTDIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    shapes = [
        ("lampshade_bulge_oblique", lampshade, 30, 64, (0.35, 0.55, -0.76), (0.2, -0.1, 0.3)),
        ("bottle_short_neck", bottle, 70, 48, (0.96, 0.0, 0.28), (-0.1, 0.2, 0.0)),
        ("cone_vase_flared", cone_vase, 36, 56, (0.0, 0.0, -1.0), (40.0, -25.0, 300.0)),
        ("jar_closed", jar, 40, 56, (0.2, 0.9, -0.4), (0.05, 0.1, -0.02)),
    ]
    for name, curve, rows, around, axis, at in shapes:
        r, h = by_arc_length(curve, rows)
        verts, faces = sweep(r, h, around)
        write(os.path.join(sys.argv[1], name + ".obj"),
              f"{name}: bench/make_meridian_vases.py (meridian by arc length, staggered rows)",
              place(verts, axis, at), faces)


if __name__ == "__main__":
    main()
