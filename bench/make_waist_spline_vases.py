#!/usr/bin/env python3
"""Vases with a waist at different heights for `fit` (issue 38, 2; branch vase19).

Usage: bench/make_waist_spline_vases.py OUT [--seed N]
Writes OUT/<name>.obj and OUT/targets.tsv (name, file, the start to fit from).

Unlike the other vase generators: the profile is a monotone piecewise-cubic Hermite curve
(Fritsch-Carlson slopes, so no overshoot between control radii) through a foot, a belly, a waist
and a lip whose heights are drawn per vase (the waist at 0.45, 0.62 or 0.85 of the height); the
rows are spaced unevenly (denser near the waist, by the profile's curvature) and each row is
turned by a random angle, its quads split along the shorter diagonal; open at both ends, in
centimetres, the axis drawn at random and the centre off the origin. Manifold and consistently
oriented (checked here with numpy).
"""
import os

import numpy as np

from formula_meshes import folder_and_seed


def pchip(xs, ys, x):
    """Monotone cubic Hermite interpolation (Fritsch-Carlson) of (xs, ys) at x."""
    xs, ys = np.asarray(xs, float), np.asarray(ys, float)
    h = np.diff(xs)
    delta = np.diff(ys) / h
    m = np.zeros_like(ys)
    for k in range(1, len(xs) - 1):
        if delta[k - 1] * delta[k] > 0:
            w1, w2 = 2 * h[k] + h[k - 1], h[k] + 2 * h[k - 1]
            m[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k])
    m[0], m[-1] = delta[0], delta[-1]
    k = np.clip(np.searchsorted(xs, x) - 1, 0, len(xs) - 2)
    t = (x - xs[k]) / h[k]
    h00, h10 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t
    h01, h11 = -2 * t**3 + 3 * t**2, t**3 - t**2
    return h00 * ys[k] + h10 * h[k] * m[k] + h01 * ys[k + 1] + h11 * h[k] * m[k + 1]


def vase(rng, height, knots, columns=72, rows=90):
    hs, rs = zip(*knots)
    # Row heights denser where the profile bends: arc length of (t, 4 r'') as the measure.
    fine = np.linspace(0.0, 1.0, 2001)
    r = pchip(hs, rs, fine)
    bend = np.abs(np.gradient(np.gradient(r, fine), fine))
    density = 1.0 + 3.0 * bend / bend.max()
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (density[1:] + density[:-1]) * np.diff(fine))])
    t = np.interp(np.linspace(0.0, cdf[-1], rows), cdf, fine)
    radius = pchip(hs, rs, t) * height
    turn = rng.uniform(0.0, 2 * np.pi / columns, rows)
    angle = turn[:, None] + 2 * np.pi * np.arange(columns)[None, :] / columns
    v = np.stack([radius[:, None] * np.cos(angle), radius[:, None] * np.sin(angle),
                  np.broadcast_to(t[:, None] * height, angle.shape)], axis=-1).reshape(-1, 3)
    faces = []
    idx = lambda i, j: i * columns + j % columns
    for i in range(rows - 1):
        for j in range(columns):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
            if np.linalg.norm(v[a] - v[c]) < np.linalg.norm(v[b] - v[d]):
                faces += [(a, b, c), (a, c, d)]
            else:
                faces += [(a, b, d), (b, c, d)]
    return v, np.array(faces)


def check(v, f):
    edges = {}
    for tri in f:
        for k in range(3):
            e = (tri[k], tri[(k + 1) % 3])
            assert e not in edges, "an edge used twice in one direction: not oriented"
            edges[e] = True
    count = {}
    for (a, b) in edges:
        key = (min(a, b), max(a, b))
        count[key] = count.get(key, 0) + 1
    assert max(count.values()) <= 2, "not manifold"
    areas = np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1)
    assert areas.min() > 1e-9 * areas.max(), "a degenerate triangle"


def placed(rng, v):
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(helper, axis)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    frame = np.stack([e1, e2, axis], axis=1)
    return v @ frame.T + rng.uniform(-10.0, 10.0, 3)


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 19)
    jitter = lambda x: x * rng.uniform(0.92, 1.08)
    # (name, height cm, knots as (height fraction, radius over height)).
    shapes = [
        ("waist_low_trumpet_cm", 24.0,
         [(0.0, jitter(0.16)), (0.18, jitter(0.22)), (0.45, jitter(0.075)), (0.75, jitter(0.13)),
          (1.0, jitter(0.21))]),
        ("bulge_then_neck_cm", 30.0,
         [(0.0, jitter(0.12)), (0.3, jitter(0.25)), (0.62, jitter(0.06)), (0.85, jitter(0.1)),
          (1.0, jitter(0.16))]),
        ("waist_high_lip_cm", 26.0,
         [(0.0, jitter(0.15)), (0.4, jitter(0.26)), (0.7, jitter(0.17)), (0.85, jitter(0.07)),
          (1.0, jitter(0.15))]),
    ]
    with open(os.path.join(args.out, "targets.tsv"), "w") as tsv:
        for name, height, knots in shapes:
            v, f = vase(rng, height, knots)
            check(v, f)
            v = placed(rng, v)
            path = os.path.join(args.out, name + ".obj")
            with open(path, "w") as out:
                out.write("# %s: bench/make_waist_spline_vases.py, centimetres\n" % name)
                for p in v:
                    out.write("v %.6f %.6f %.6f\n" % tuple(p))
                for tri in f:
                    out.write("f %d %d %d\n" % tuple(tri + 1))
            tsv.write("%s\t%s\tcylinder\n" % (name, path))
            print(name, len(v), "vertices", len(f), "triangles")


if __name__ == "__main__":
    main()
