#!/usr/bin/env python3
"""Lobed saddles over regular polygons whose corners lie on the falling lobes (issue 38, item 2).

Unlike the other saddle makers (grids, lattices, Delaunay, parameter disks): each surface is a
height field z = a rho^k cos(k t) over a regular k-gon (k = 3, 4, 5) or a lens (k = 2), meshed
as concentric rings drawn out to the outline (ring j of 6 j points at the share j / n of the
outline's reach in each direction, neighbouring rings stitched by walking both at once), so its
triangles fan out from the middle and its rim is the polygon itself. Near its rim such a saddle
holds nearly one height at each distance from its middle (every corner falls alike), as a dish
does; inside the polygon's inner circle its height swings with the turn. A dish over the same
square (z = c rho^2) is written beside them as a surface that does turn about its axis.

- polygon_saddle_k2_lens: z = 1.6 rho^2 / R cos(2 t) over a lens (two circular arcs) whose tips
  lie on the falling lobes, R = 9 cm, in centimetres, tilted 20 degrees;
- polygon_saddle_k3: a monkey saddle, slope 2.1 at the corners, over a triangle of circumradius
  11 cm, in centimetres, 0.3 mm of noise, turned and moved;
- polygon_saddle_k4: four lobes, slope 1.8 at the corners, over a square of circumradius 12 cm,
  in metres, two holes (triangles dropped), tilted 30 degrees;
- polygon_saddle_k5: five lobes, slope 1.5 at the corners, over a pentagon of circumradius
  10 cm, in millimetres;
- polygon_dish_k4: the dish z = 2 rho^2 over the square of the k4 saddle, in metres (the control).

Usage: make_polygon_saddles.py OUT_DIR [--seed S]  (standard library only; default seed 25)
"""
import argparse
import math
import os
import random


def outline_reach(kind, k, radius, t):
    """Distance from the middle to the outline in direction t (corners at the falling lobes)."""
    if kind == "lens":
        # Two arcs through the tips (0, +-R) whose half-width is 0.6 R at the middle.
        w = 0.6 * radius
        c = (radius * radius - w * w) / (2.0 * w)  # arc centre at (-c, 0) and (c, 0), radius c + w
        rr = c + w
        best = 0.0
        for sx in (-1.0, 1.0):
            # The ray s (cos t, sin t) meets the arc centred at (-sx c, 0) on its far side.
            ux, uy = math.cos(t), math.sin(t)
            cx = -sx * c
            b = ux * cx
            disc = b * b - (cx * cx - rr * rr)
            s = b + math.sqrt(disc)
            if sx * ux >= 0.0:
                best = s
        return best
    # A regular k-gon with its corners at the falling lobes: cos(k t) = -1 at t = (2 i + 1) pi / k.
    apothem = radius * math.cos(math.pi / k)
    best = float("inf")
    for i in range(k):
        edge = 2.0 * math.pi * i / k  # edge midpoints at the rising lobes
        c = math.cos(t - edge)
        if c > 1e-12:
            best = min(best, apothem / c)
    return best


def rings_mesh(kind, k, radius, rings):
    """Concentric rings drawn out to the outline, stitched ring to ring."""
    points = [(0.0, 0.0)]
    starts = [0]
    counts = [1]
    for j in range(1, rings + 1):
        count = 6 * j
        starts.append(len(points))
        counts.append(count)
        phase = 0.5 * (j % 2) * 2.0 * math.pi / count
        for i in range(count):
            t = phase + 2.0 * math.pi * i / count
            s = outline_reach(kind, k, radius, t) * j / rings
            points.append((s * math.cos(t), s * math.sin(t)))
    triangles = []
    for j in range(1, rings + 1):
        inner, outer = (starts[j - 1], counts[j - 1]), (starts[j], counts[j])
        if inner[1] == 1:
            for i in range(outer[1]):
                triangles.append((0, outer[0] + i, outer[0] + (i + 1) % outer[1]))
            continue
        # Walk both rings by angle, always advancing the one whose next point comes first.
        a = b = 0

        def angle(start, count, i):
            x, y = points[start + i % count]
            return math.atan2(y, x) % (2.0 * math.pi) + 2.0 * math.pi * (i // count)

        base_a = angle(inner[0], inner[1], 0)
        base_b = angle(outer[0], outer[1], 0)
        while a < inner[1] or b < outer[1]:
            ia, ib = inner[0] + a % inner[1], outer[0] + b % outer[1]
            na = (angle(inner[0], inner[1], a + 1) - base_a) if a < inner[1] else float("inf")
            nb = (angle(outer[0], outer[1], b + 1) - base_b) if b < outer[1] else float("inf")
            if nb <= na:
                triangles.append((ia, ib, outer[0] + (b + 1) % outer[1]))
                b += 1
            else:
                triangles.append((ia, ib, inner[0] + (a + 1) % inner[1]))
                a += 1
    return points, triangles


def rotation(axis, angle):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(angle), math.sin(angle)
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]


def write(path, vertices, triangles, comment):
    used = sorted({i for t in triangles for i in t})
    index = {v: n + 1 for n, v in enumerate(used)}
    with open(path + ".tmp", "w") as f:
        f.write("# %s\n" % comment)
        for v in used:
            f.write("v %.9g %.9g %.9g\n" % vertices[v])
        for t in triangles:
            f.write("f %d %d %d\n" % tuple(index[i] for i in t))
    os.replace(path + ".tmp", path)


def make(name, out, kind, k, radius, slope, scale, tilt, shift, noise, holes, rng, dish=None):
    points, triangles = rings_mesh(kind, k, radius, 28)
    vertices = []
    turn = rotation(tilt[0], math.radians(tilt[1]))
    for x, y in points:
        rho, t = math.hypot(x, y), math.atan2(y, x)
        if dish is not None:
            z = dish * rho * rho
        else:
            # The slope at the corners (rho = radius, falling): a k rho^(k-1) = slope.
            z = slope / (k * radius ** (k - 1)) * rho ** k * math.cos(k * t)
        z += rng.gauss(0.0, noise)
        p = [x, y, z]
        q = tuple(scale * (sum(turn[r][c] * p[c] for c in range(3)) + shift[r]) for r in range(3))
        vertices.append(q)
    for centre, hole in holes:
        triangles = [t for t in triangles
                     if math.dist([sum(points[i][0] for i in t) / 3, sum(points[i][1] for i in t) / 3],
                                  centre) > hole]
    write(os.path.join(out, name + ".obj"), vertices, triangles,
          "%s: k = %d over a %s of reach %g m, slope %g at the corners" %
          (name, k, kind, radius, slope))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("--seed", type=int, default=25)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(args.seed)
    make("polygon_saddle_k2_lens", args.out, "lens", 2, 0.09, 3.2, 100.0,
         ([1, 0.3, 0], 20), [0.01, 0.0, 0.02], 0.0, [], rng)
    make("polygon_saddle_k3", args.out, "polygon", 3, 0.11, 2.1, 100.0,
         ([0.2, 1, 0.4], rng.uniform(10, 50)), [0.05, -0.1, 0.3], 0.0003, [], rng)
    make("polygon_saddle_k4", args.out, "polygon", 4, 0.12, 1.8, 1.0,
         ([1, -1, 0.5], 30), [0.2, 0.1, -0.4], 0.0002,
         [((0.03, 0.04), 0.012), ((-0.05, -0.02), 0.01)], rng)
    make("polygon_saddle_k5", args.out, "polygon", 5, 0.10, 1.5, 1000.0,
         ([0, 0, 1], 0), [0.0, 0.0, 0.0], 0.0, [], rng)
    make("polygon_dish_k4", args.out, "polygon", 4, 0.12, 0.0, 1.0,
         ([1, -1, 0.5], 30), [0.2, 0.1, -0.4], 0.0002, [], rng, dish=2.0)


if __name__ == "__main__":
    main()
