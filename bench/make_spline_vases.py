#!/usr/bin/python3
"""Vases with a neck for `fit` (issue 38, 2), made apart from curvefold and unlike the other
generators: each profile is a natural cubic spline (solved here with numpy) through control radii
drawn at random (`--seed`) at even heights, with a neck forced at a random height under a lip
that flares again, so the waist's depth and place differ from draw to draw; the surface is a
twisted quad grid (each column of vertices winds a quarter to half a turn along the height, and
each row's height waves around the axis, so no row is a circle and no column a meridian), written
as quads; then turned onto its axis and moved off the origin.

spline_vase_mm_x: 260 mm tall in millimetres, axis along +x, belly 55-75 mm, neck 0.25-0.35 of
the belly, open ends.
spline_bottle_tilted: 0.3 m tall, axis tilted (0.3, 0.8, 0.5), belly 6-8 cm, a long neck of
0.2-0.3 of the belly, open ends.
spline_urn_down_small: 9 cm tall, axis along -y, belly 3-4 cm, neck 0.4-0.5 of the belly, a wide
lip, open ends.

Also writes OUTDIR/targets.tsv (name, start kind, description, vertices, faces), the table
bench/run_judge_shapes.sh reads.

Usage: bench/make_spline_vases.py OUTDIR [--seed N]
"""
import argparse
import os

import numpy as np

from make_meridian_vases import place, write  # +z turned onto an axis; an OBJ of polygons


def natural_spline(x, y, at):
    """The natural cubic spline through (x, y), x increasing, evaluated at `at`."""
    n = len(x) - 1
    h = np.diff(x)
    a = np.zeros((n + 1, n + 1))
    b = np.zeros(n + 1)
    a[0, 0] = a[n, n] = 1.0  # second derivative 0 at both ends
    for i in range(1, n):
        a[i, i - 1], a[i, i], a[i, i + 1] = h[i - 1], 2 * (h[i - 1] + h[i]), h[i]
        b[i] = 6 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1])
    m = np.linalg.solve(a, b)
    k = np.clip(np.searchsorted(x, at) - 1, 0, n - 1)
    t0, t1 = at - x[k], x[k + 1] - at
    return (m[k] * t1 ** 3 + m[k + 1] * t0 ** 3) / (6 * h[k]) + (y[k] / h[k] - m[k] * h[k] / 6) * t1 + (
        y[k + 1] / h[k] - m[k + 1] * h[k] / 6) * t0


def profile(rng, belly, neck_share, lip_share):
    """Control heights and radii: a foot, a belly, a neck, a lip (radii as shares of 1)."""
    neck_at = rng.uniform(0.68, 0.82)
    belly_at = rng.uniform(0.3, 0.45)
    xs = [0.0, belly_at * 0.5, belly_at, 0.5 * (belly_at + neck_at), neck_at, 0.5 * (neck_at + 1.0), 1.0]
    rs = [rng.uniform(0.5, 0.75), rng.uniform(0.75, 0.95), 1.0, rng.uniform(0.55, 0.75), neck_share,
          0.5 * (neck_share + lip_share), lip_share]
    return np.array(xs), belly * np.array(rs)


def twisted_grid(radius, height, rows, around, twist, wave, rng):
    """Vertices about +z and quads: column j at angle 2 pi j / around + twist t, row i at height
    t height plus a wave of `wave` around the axis (none at the two ends)."""
    verts = []
    phase = rng.uniform(0, 2 * np.pi)
    for i in range(rows + 1):
        t = i / rows
        a = 2 * np.pi * np.arange(around) / around + twist * t
        lift = 0.0 if i in (0, rows) else wave * np.sin(3 * a + phase)
        tt = np.clip(t + lift + np.zeros(around), 0.0, 1.0)
        r = radius(tt)
        verts.extend(zip(r * np.cos(a), r * np.sin(a), height * tt))
    quads = []
    for i in range(rows):
        for j in range(around):
            p, q = i * around + j, i * around + (j + 1) % around
            quads.append((p, q, q + around, p + around))
    return np.array(verts), quads


def main():
    ap = argparse.ArgumentParser(description="Vases with a spline profile and a neck (issue 38, 2).")
    ap.add_argument("dir", help="where the OBJ files and targets.tsv go")
    ap.add_argument("--seed", type=int, default=16, help="draws the control radii")
    args = ap.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    # name, height, belly range, neck share range, lip share range, rows, around, twist, wave,
    # axis, place
    shapes = [
        ("spline_vase_mm_x", 260.0, (55.0, 75.0), (0.25, 0.35), (0.55, 0.75), 44, 60, 0.5 * np.pi, 0.004,
         (1.0, 0.0, 0.0), (120.0, -40.0, 15.0)),
        ("spline_bottle_tilted", 0.3, (0.06, 0.08), (0.2, 0.3), (0.3, 0.45), 56, 48, np.pi, 0.003,
         (0.3, 0.8, 0.5), (0.1, 0.05, -0.2)),
        ("spline_urn_down_small", 0.09, (0.03, 0.04), (0.4, 0.5), (0.8, 1.0), 36, 52, 0.6 * np.pi, 0.005,
         (0.0, -1.0, 0.0), (0.0, 0.3, 0.02)),
    ]
    table = []
    for name, height, belly, neck, lip, rows, around, twist, wave, axis, at in shapes:
        xs, rs = profile(rng, rng.uniform(*belly), rng.uniform(*neck), rng.uniform(*lip))
        verts, quads = twisted_grid(lambda t: natural_spline(xs, rs, t), height, rows, around, twist,
                                    wave, rng)
        what = (f"spline through radii {', '.join('%.3g' % r for r in rs)} at heights "
                f"{', '.join('%.2f' % x for x in xs)} of {height:g}, twisted quads")
        write(os.path.join(args.dir, name + ".obj"), f"{name}: {what} (bench/make_spline_vases.py)",
              place(verts, axis, at), quads)
        table.append((name, "cylinder", what, len(verts), len(quads)))
    with open(os.path.join(args.dir, "targets.tsv"), "w") as out:
        for row in table:
            out.write("\t".join(str(c) for c in row) + "\n")


if __name__ == "__main__":
    main()
