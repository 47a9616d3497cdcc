#!/usr/bin/python3
"""Bowls, dishes and a plate as height fields over a clipped triangle lattice (issue 38, 2), as OBJ.

Written unlike the other generators (polar grids, hexagonal disks, numpy grids, spline or eased
profile tables): each mesh is an equilateral triangle lattice in the plane, clipped to an outline
(a circle or a superellipse), the lattice points just outside the outline pulled onto it, and each
point raised by a closed-form height z = f(x, y) (so no mesh has rings, and one shape has no axis of
revolution); then the whole is turned about an oblique axis and moved off the origin. Standard
library only; one fixed seed. Shapes:
  serving_oval   a 28 x 18 cm serving bowl, superelliptic outline (exponent 3), flat-ish bottom,
                 5.5 cm deep, tilted 20 degrees (no axis of revolution);
  plate_tilted   a 24 cm plate: flat well 15 cm across, a rim rising at 18 degrees, a flat lip,
                 tilted 40 degrees;
  mixing_noisy   a 22 cm mixing bowl (a sphere's cap, wall 62 degrees at the rim), noise of 0.25%
                 of its size along z and 5 holes (triangles removed);
  deep_cup       an 8 cm cup 5 cm deep (a steep paraboloid-like wall, 70 degrees at the rim).
Usage: bench/make_lattice_bowls.py OUTDIR
"""
import math
import os
import random
import sys

rand = random.Random(38_2_7)


def superellipse_radius(angle, a, b, p):
    """Distance from the centre to a superellipse |x/a|^p + |y/b|^p = 1 along `angle`."""
    c, s = abs(math.cos(angle)), abs(math.sin(angle))
    return (((c / a) ** p) + ((s / b) ** p)) ** (-1.0 / p)


def lattice(outline, spacing, extent):
    """Points of an equilateral lattice inside `outline(angle)` (those just outside pulled onto it)
    and the lattice's triangles among them."""
    rows = int(2 * extent / (spacing * math.sqrt(3) / 2)) + 2
    cols = int(2 * extent / spacing) + 2
    index, points = {}, []
    for j in range(rows):
        y = -extent + j * spacing * math.sqrt(3) / 2
        for i in range(cols):
            x = -extent + i * spacing + (0.5 * spacing if j % 2 else 0.0)
            r, a = math.hypot(x, y), math.atan2(y, x)
            limit = outline(a)
            if r > limit + 0.45 * spacing:
                continue
            if r > limit:
                x, y = x * limit / r, y * limit / r
            index[(i, j)] = len(points)
            points.append((x, y))
    triangles = []
    for j in range(rows - 1):
        for i in range(cols - 1):
            # Odd rows are shifted right by half a step.
            if j % 2 == 0:
                quads = [((i, j), (i + 1, j), (i, j + 1)), ((i + 1, j), (i + 1, j + 1), (i, j + 1))]
            else:
                quads = [((i, j), (i + 1, j), (i + 1, j + 1)), ((i, j), (i + 1, j + 1), (i, j + 1))]
            for tri in quads:
                if all(k in index for k in tri):
                    triangles.append(tuple(index[k] for k in tri))
    return points, triangles


def rotation(axis, degrees):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def write(path, points3, triangles, axis=(1, 0, 0), degrees=0.0, offset=(0, 0, 0)):
    m = rotation(axis, degrees) if degrees else None
    with open(path, "w") as f:
        f.write("# made by bench/make_lattice_bowls.py (not by curvefold)\n")
        for p in points3:
            q = [sum(m[r][c] * p[c] for c in range(3)) for r in range(3)] if m else list(p)
            f.write("v %.6f %.6f %.6f\n" % tuple(q[k] + offset[k] for k in range(3)))
        for a, b, c in triangles:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def drop_unused(points3, triangles):
    used = sorted({v for t in triangles for v in t})
    renumber = {v: k for k, v in enumerate(used)}
    return [points3[v] for v in used], [tuple(renumber[v] for v in t) for t in triangles]


def main(out):
    os.makedirs(out, exist_ok=True)

    # Serving oval: superelliptic outline, height by the superelliptic radius (flat-ish bottom).
    a, b, p = 0.14, 0.09, 3.0
    pts, tris = lattice(lambda t: superellipse_radius(t, a, b, p), 0.0075, 0.15)
    p3 = []
    for x, y in pts:
        rho = (abs(x / a) ** p + abs(y / b) ** p) ** (1.0 / p)
        p3.append((x, y, 0.055 * min(rho, 1.0) ** 2.6))
    write(os.path.join(out, "serving_oval.obj"), p3, tris, (0.3, 1.0, 0.2), 20.0, (0.4, -0.1, 0.2))

    # Plate: flat well to 7.5 cm, rim at 18 degrees to 11 cm, flat lip to 12 cm.
    rise = math.tan(math.radians(18.0)) * (0.11 - 0.075)
    def plate(r):
        if r < 0.075:
            return 0.0
        if r < 0.11:
            u = (r - 0.075) / 0.035
            return rise * (u * u * (3 - 2 * u) * 0.35 + 0.65 * u)  # a rounded start, then straight
        return rise
    pts, tris = lattice(lambda t: 0.12, 0.008, 0.125)
    write(os.path.join(out, "plate_tilted.obj"), [(x, y, plate(math.hypot(x, y))) for x, y in pts],
          tris, (1.0, -0.5, 0.3), 40.0, (-0.2, 0.3, 0.05))

    # Mixing bowl: a sphere's cap (radius 12.4 cm) out to 11 cm, noise along z and holes.
    R, rim = 0.124, 0.11
    pts, tris = lattice(lambda t: rim, 0.0065, 0.115)
    p3 = [(x, y, R - math.sqrt(max(R * R - x * x - y * y, 0.0)) + rand.gauss(0.0, 0.00055))
          for x, y in pts]
    for _ in range(5):
        cx, cy = rand.uniform(-0.07, 0.07), rand.uniform(-0.07, 0.07)
        tris = [t for t in tris
                if min(math.hypot(pts[v][0] - cx, pts[v][1] - cy) for v in t) > 0.008]
    p3, tris = drop_unused(p3, tris)
    write(os.path.join(out, "mixing_noisy.obj"), p3, tris, (0.0, 1.0, 1.0), 15.0, (0.0, 0.0, 0.3))

    # Deep cup: z = depth * (r / rim)^2.6, wall about 70 degrees at the rim.
    rim, depth = 0.04, 0.05
    pts, tris = lattice(lambda t: rim, 0.0022, 0.042)
    write(os.path.join(out, "deep_cup.obj"),
          [(x, y, depth * (math.hypot(x, y) / rim) ** 2.6) for x, y in pts], tris)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
