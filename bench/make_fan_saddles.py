#!/usr/bin/env python3
"""Lopsided saddles meshed in rings about an off-centre point (issue 38, 2; numpy).

Unlike the grids, rows, rings about the middle, scatter, Delaunay, split fans and lattices of the
other bench/make_saddle_*.py and make_lattice_saddles.py: the outline is star-shaped about a
point a third of the way out, its rings scaled from that point (so the triangles are long on one
side and short on the other), each ring with as many vertices as its length needs, zipped to the
next by angle; the height is no plain quadric but a saddle with a cubic lean, so its two wings
differ:
- lean_saddle_rect: z = (x^2 - 0.7 y^2) / 0.07 + x^3 / 0.4 over a rounded rectangle 24 x 16 cm
  (slopes to about 3.8 at the steep wing), in metres, turned 40 degrees about (1, 1, 0);
- lean_saddle_superellipse: z = (0.8 x^2 - y^2) / 0.05 - y^3 / 0.3 over |x/a|^4 + |y/b|^4 = 1,
  a = 9 cm, b = 7 cm, in millimetres, turned and moved;
- lean_saddle_lobes: z = (x^2 - y^2) / 0.06 + x y^2 / 0.3 over a three-lobed outline about 18 cm
  across, 0.3 mm of noise along z, one hole, in metres, tilted 20 degrees.
Usage: make_fan_saddles.py OUT_DIR [--seed S]
Writes OUT_DIR/NAME.obj for the three and OUT_DIR/targets.tsv (name, start kind).
"""
import math
import os

import numpy as np

from formula_meshes import folder_and_seed, write_kinds
from make_lattice_saddles import clip, write
from make_saddle_quadrics import rotation


def fan_rings(radius_at, centre, rings, step):
    """Rings about `centre`, the k-th at k / rings of the outline's distance `radius_at(phi)`,
    each with as many vertices as its length over `step`; zipped to the next by angle."""
    phis = np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)
    outline = np.array([radius_at(f) for f in phis])
    points = [np.array(centre, float)]
    ring_index = [[0]]
    ring_angles = [[0.0]]
    for k in range(1, rings + 1):
        length = (k / rings) * float(np.sum(outline)) * (2.0 * math.pi / len(phis))
        count = max(6, int(round(length / step)))
        # Every other ring turned by half a step, so no edge runs along a ray.
        angles = (np.arange(count) + 0.5 * (k % 2)) * 2.0 * math.pi / count
        index = []
        for a in angles:
            r = (k / rings) * radius_at(a)
            index.append(len(points))
            points.append(np.array(centre) + r * np.array([math.cos(a), math.sin(a)]))
        ring_index.append(index)
        ring_angles.append(list(angles))
    triangles = []
    inner = ring_index[1]
    for i in range(len(inner)):
        triangles.append((0, inner[i], inner[(i + 1) % len(inner)]))
    for k in range(1, rings):
        a, b = ring_index[k], ring_angles[k]
        c, d = ring_index[k + 1], ring_angles[k + 1]
        i = j = 0
        # Walk both rings by angle, one triangle per step of the one behind.
        while i < len(a) or j < len(c):
            ai_next = b[i + 1] if i + 1 < len(a) else b[0] + 2 * math.pi
            cj_next = d[j + 1] if j + 1 < len(c) else d[0] + 2 * math.pi
            if j >= len(c) or (i < len(a) and ai_next <= cj_next):
                triangles.append((a[i % len(a)], c[j % len(c)], a[(i + 1) % len(a)]))
                i += 1
            else:
                triangles.append((a[i % len(a)], c[j % len(c)], c[(j + 1) % len(c)]))
                j += 1
    return np.array(points), np.array(triangles)


def star_radius(outline, centre):
    """The distance from `centre` to the outline `outline(t) -> (x, y)` along each ray,
    interpolated from 4000 of its points by their angle about `centre` (the outlines here are
    star-shaped about it)."""
    samples = np.array([outline(t) for t in np.linspace(0.0, 2 * math.pi, 4000, endpoint=False)])
    rel = samples - np.array(centre)
    ang = np.mod(np.arctan2(rel[:, 1], rel[:, 0]), 2 * math.pi)
    dist = np.linalg.norm(rel, axis=1)
    order = np.argsort(ang)
    ang, dist = ang[order], dist[order]

    def radius_at(phi):
        return float(np.interp(np.mod(phi, 2 * math.pi), ang, dist, period=2 * math.pi))

    return radius_at


def main():
    args, rng = folder_and_seed(__doc__.splitlines()[0], 20)
    names = []

    # A rounded rectangle 24 x 16 cm (a superellipse of power 8), rings about (4, -2.5) cm.
    def rounded(t, a=0.12, b=0.08, p=8.0):
        c, s = math.cos(t), math.sin(t)
        return (a * math.copysign(abs(c) ** (2 / p), c), b * math.copysign(abs(s) ** (2 / p), s))

    centre = (0.04, -0.025)
    p, t = fan_rings(star_radius(rounded, centre), centre, 22, 0.007)
    x, y = p[:, 0], p[:, 1]
    z = (x ** 2 - 0.7 * y ** 2) / 0.07 + x ** 3 / 0.4
    v = np.column_stack([p, z]) @ rotation([1, 1, 0], math.radians(40)).T + [0.3, 0.1, -0.2]
    write(os.path.join(args.out, "lean_saddle_rect.obj"), v, t,
          "z = (x^2 - 0.7 y^2) / 0.07 + x^3 / 0.4 over a rounded rectangle 24 x 16 cm, rings "
          "about (4, -2.5) cm, turned 40 degrees about (1, 1, 0), m")
    names.append("lean_saddle_rect")

    # A superellipse |x/a|^4 + |y/b|^4 = 1, rings about (-3, 2) cm, in mm.
    def squircle(t, a=0.09, b=0.07):
        c, s = math.cos(t), math.sin(t)
        return (a * math.copysign(abs(c) ** 0.5, c), b * math.copysign(abs(s) ** 0.5, s))

    centre = (-0.03, 0.02)
    p, t = fan_rings(star_radius(squircle, centre), centre, 20, 0.006)
    x, y = p[:, 0], p[:, 1]
    z = (0.8 * x ** 2 - y ** 2) / 0.05 - y ** 3 / 0.3
    v = np.column_stack([p, z]) @ rotation([0.3, -1, 0.5], math.radians(65)).T
    v = 1000.0 * (v + [-0.1, 0.25, 0.05])
    write(os.path.join(args.out, "lean_saddle_superellipse.obj"), v, t,
          "z = (0.8 x^2 - y^2) / 0.05 - y^3 / 0.3 over |x/9cm|^4 + |y/7cm|^4 = 1, rings about "
          "(-3, 2) cm, mm")
    names.append("lean_saddle_superellipse")

    # Three lobes about 18 cm across, rings about (2, 2) cm, noise, a hole, tilted.
    def lobes(t):
        r = 0.075 * (1.0 + 0.22 * math.cos(3 * t + 0.4))
        return (r * math.cos(t), r * math.sin(t))

    centre = (0.02, 0.02)
    p, t = fan_rings(star_radius(lobes, centre), centre, 22, 0.0065)
    p, t = clip(p, t, lambda q: True, [(np.array([-0.03, -0.02]), 0.011)])
    x, y = p[:, 0], p[:, 1]
    z = (x ** 2 - y ** 2) / 0.06 + x * y ** 2 / 0.3
    z += rng.normal(0.0, 0.0003, len(z))
    v = np.column_stack([p, z]) @ rotation([0, 1, 0.2], math.radians(20)).T + [-0.05, 0.0, 0.4]
    write(os.path.join(args.out, "lean_saddle_lobes.obj"), v, t,
          "z = (x^2 - y^2) / 0.06 + x y^2 / 0.3 over three lobes 18 cm across, rings about "
          "(2, 2) cm, noise 0.3 mm, a hole, tilted 20, m")
    names.append("lean_saddle_lobes")

    write_kinds(args.out, names, "square")


if __name__ == "__main__":
    main()
