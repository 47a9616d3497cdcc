#!/usr/bin/env python3
"""Saddles from random quadratics, meshed by splitting a fan (issue 38, 2; numpy).

Unlike the grids, lattices, scatter, Delaunay, row scans, warped grids and rings of the other
bench/make_saddle_*.py: the outline is a random star polygon (5-9 corners at random radii and
turns), fanned from its centre and each triangle split into four at its edges' midpoints five
times (so the vertices have valence 6 but the centre's and the corners', and every edge of the
fan's spokes runs straight through the mesh); the height is a random quadratic form
z = k1 u^2 + k2 v^2 with k1 > 0 > k2 (opposite-sign curvatures, |k2| / k1 drawn in [0.35, 2.5])
along principal directions at a random turn, scaled so the steepest slope on the rim is drawn in
[0.8, 3.2]; the sheet's size is drawn in [8, 40] cm, the whole tilted about a random horizontal
axis by up to 50 degrees, turned about z, moved off the origin, written in metres or millimetres
(drawn), with noise along z of up to 0.2% of the size on some.

Usage: make_saddle_quadrics.py OUT_DIR [--count N] [--seed S]
Writes OUT_DIR/quadric_saddle_K.obj and OUT_DIR/quadrics.tsv (each target's draw).
"""
import argparse
import math
import os

import numpy as np


def star_outline(rng, corners):
    # Keep the corners apart (no sliver of the fan).
    turns = np.linspace(0.0, 2.0 * math.pi, corners, endpoint=False) + rng.uniform(
        -0.25, 0.25, corners) * (2.0 * math.pi / corners)
    radii = rng.uniform(0.7, 1.0, corners)
    return np.stack([radii * np.cos(turns), radii * np.sin(turns)], axis=1)


def fan_split(outline, splits):
    """A fan from the origin over `outline`, each triangle split into four `splits` times."""
    points = [(0.0, 0.0)] + [tuple(p) for p in outline]
    n = len(outline)
    triangles = [(0, 1 + i, 1 + (i + 1) % n) for i in range(n)]
    for _ in range(splits):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                pa, pb = points[a], points[b]
                points.append((0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])))
                middle[key] = len(points) - 1
            return middle[key]

        nxt = []
        for a, b, c in triangles:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nxt += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        triangles = nxt
    return np.array(points), np.array(triangles)


def rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
                     [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
                     [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]])


def make(rng):
    corners = int(rng.integers(5, 10))
    outline = star_outline(rng, corners)
    uv, triangles = fan_split(outline, 5)
    size = rng.uniform(0.08, 0.40)  # across, metres
    half = 0.5 * size
    uv = uv * half
    ratio = rng.uniform(0.35, 2.5)  # |k2| / k1
    phi = rng.uniform(0.0, math.pi)
    c, s = math.cos(phi), math.sin(phi)
    u = c * uv[:, 0] + s * uv[:, 1]
    v = -s * uv[:, 0] + c * uv[:, 1]
    # Slope of k1 u^2 - k1 ratio v^2 is 2 k1 (u, -ratio v); its largest on the rim sets k1.
    slope = rng.uniform(0.8, 3.2)
    rim = 2.0 * np.hypot(u, ratio * v).max()
    k1 = slope / rim
    z = k1 * u * u - k1 * ratio * v * v
    noise = rng.uniform(0.0, 0.002 * size) if rng.random() < 0.5 else 0.0
    z = z + rng.normal(0.0, noise, z.shape) if noise > 0 else z
    points = np.stack([uv[:, 0], uv[:, 1], z], axis=1)
    tilt_axis = (math.cos(rng.uniform(0, 2 * math.pi)), math.sin(rng.uniform(0, 2 * math.pi)), 0.0)
    tilt = math.radians(rng.uniform(0.0, 50.0))
    turn = rng.uniform(0.0, 2.0 * math.pi)
    r = rotation((0, 0, 1), turn) @ rotation(tilt_axis, tilt)
    points = points @ r.T + rng.uniform(-0.5, 0.5, 3)
    unit = "mm" if rng.random() < 0.4 else "m"
    if unit == "mm":
        points *= 1000.0
    draw = dict(corners=corners, size_m=round(size, 4), ratio=round(ratio, 3),
                phi_deg=round(math.degrees(phi), 1), rim_slope=round(slope, 2),
                tilt_deg=round(math.degrees(tilt), 1), unit=unit, noise_m=round(noise, 5))
    return points, triangles, draw


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--count", type=int, default=4)
    parser.add_argument("--seed", type=int, default=16)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = np.random.default_rng(args.seed)
    with open(os.path.join(args.out, "quadrics.tsv"), "w") as table:
        for k in range(args.count):
            points, triangles, draw = make(rng)
            name = f"quadric_saddle_{k}"
            with open(os.path.join(args.out, name + ".obj"), "w") as obj:
                obj.write(f"# {name}: {draw}\n")
                for p in points:
                    obj.write(f"v {p[0]:.7g} {p[1]:.7g} {p[2]:.7g}\n")
                for a, b, c in triangles:
                    obj.write(f"f {a + 1} {b + 1} {c + 1}\n")
            table.write(name + "\t" + "\t".join(f"{k}={v}" for k, v in draw.items()) + "\n")
            print(name, draw)


if __name__ == "__main__":
    main()
