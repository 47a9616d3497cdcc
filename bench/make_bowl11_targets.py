#!/usr/bin/python3
"""Two bowls unlike the other generators' for `fit --from disk` (issue 38, 2), as OBJ.

Unlike make_bowl_targets.py, make_footed_bowls.py, make_smooth_targets.py,
make_revolution_targets.py, make_scanline_bowls.py and make_judge_shapes.py (bowls of revolution
or an ellipse stretched from one, profiles as formulas of the radius or tables):
- squircle_bowl: a bowl over a rounded square (the superellipse |x|^4 + |y|^4 = a^4, 18 cm
  across), its depth a power of the superellipse's own radius (no axis of revolution: four-fold,
  its corners deeper-walled than its sides), on a grid of that radius by angle, in metres,
  opening +z, off the origin;
- drain_dish_scan: a shallow dish with a flat foot (12 cm across) and a wall that steepens to
  about 65 degrees at its rim (22 cm across, 4.5 cm deep), tilted 25 degrees, scanned: noise
  0.3 mm along the normal, a drain hole off the centre, a jittered polar grid, units of mm.
Usage: bench/make_bowl11_targets.py OUTDIR   (numpy)
"""
import math
import os
import sys

import numpy as np

rng = np.random.default_rng(38_211)


def grid_faces(rings, around):
    """Faces of a centre vertex (0) and `rings` closed rings of `around` vertices."""
    faces = []
    for j in range(around):
        faces.append((0, 1 + j, 1 + (j + 1) % around))
    for i in range(rings - 1):
        for j in range(around):
            a = 1 + i * around + j
            b = 1 + i * around + (j + 1) % around
            c, d = a + around, b + around
            # alternate diagonals so no direction is favoured
            faces += [(a, c, d), (a, d, b)] if (i + j) % 2 else [(a, c, b), (b, c, d)]
    return faces


def write(path, v, faces):
    with open(path, "w") as f:
        for p in v:
            f.write("v %.7g %.7g %.7g\n" % tuple(p))
        for t in faces:
            f.write("f %d %d %d\n" % tuple(k + 1 for k in t))


def squircle_bowl(path):
    a, depth, p = 0.09, 0.065, 4.0
    rings, around = 26, 112
    v = [(0.0, 0.0, 0.0)]
    for i in range(1, rings + 1):
        rho = i / rings
        for j in range(around):
            t = 2 * math.pi * j / around
            c, s = math.cos(t), math.sin(t)
            # the superellipse's radius in direction t
            edge = a / (abs(c) ** p + abs(s) ** p) ** (1 / p)
            v.append((rho * edge * c, rho * edge * s, depth * rho ** 1.7))
    v = np.array(v) + np.array([0.2, -0.05, 0.03])
    write(path, v, grid_faces(rings, around))


def drain_dish_scan(path):
    foot, rim, depth = 60.0, 110.0, 45.0  # mm

    def height(r):
        u = np.clip((r - foot) / (rim - foot), 0.0, 1.0)
        return depth * u ** 2.3

    rings, around = 30, 120
    v = [(0.0, 0.0, 0.0)]
    for i in range(1, rings + 1):
        for j in range(around):
            r = rim * (i + (rng.uniform(-0.3, 0.3) if i < rings else 0.0)) / rings
            t = 2 * math.pi * (j + rng.uniform(-0.3, 0.3)) / around
            v.append((r * math.cos(t), r * math.sin(t), height(r)))
    v = np.array(v)
    faces = grid_faces(rings, around)
    # the drain: faces whose centroid lies within 12 mm of (25, 12)
    hole = np.array([25.0, 12.0])
    faces = [f for f in faces if np.linalg.norm(v[list(f), :2].mean(axis=0) - hole) > 12.0]
    # noise along the surface's normal (of the height field z = h(r))
    r = np.linalg.norm(v[:, :2], axis=1)
    slope = (height(r + 0.01) - height(r - 0.01)) / 0.02
    radial = v[:, :2] / np.maximum(r, 1e-9)[:, None]
    n = np.column_stack([-slope[:, None] * radial, np.ones(len(v))])
    n /= np.linalg.norm(n, axis=1)[:, None]
    v = v + rng.normal(0.0, 0.3, len(v))[:, None] * n
    # tilted 25 degrees about (1, 0.4, 0), moved off the origin
    axis = np.array([1.0, 0.4, 0.0])
    axis /= np.linalg.norm(axis)
    angle = math.radians(25.0)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    rot = np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k
    v = v @ rot.T + np.array([150.0, 40.0, -20.0])
    write(path, v, faces)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    squircle_bowl(os.path.join(out, "squircle_bowl.obj"))
    drain_dish_scan(os.path.join(out, "drain_dish_scan.obj"))


if __name__ == "__main__":
    main()
