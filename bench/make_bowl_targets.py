#!/usr/bin/python3
"""Bowls and dishes for `fit --from disk` made apart from curvefold (issue 38, 2), as OBJ.

Unlike bench/make_smooth_targets.py (numpy grids) and bench/make_revolution_targets.py (spline
profiles on rectangular grids): Python's standard library only, each mesh a "hexagonal" disk (ring
j of 6j vertices stitched to ring j + 1, so triangles grow no thinner toward the centre and no
vertex sits at a pole of a grid), profiles from closed formulas: an ellipsoidal cap, a paraboloid
with a flat bottom, a bowl with a rim lip flaring out, a tilted coarse hemisphere, a wide shallow
dish along x, an upside-down scanned cap with noise and holes, a small steep cup. 7 to 40 cm.
Usage: bench/make_bowl_targets.py OUTDIR
"""
import math
import os
import random
import sys

rand = random.Random(38_2_2026)


def hex_disk(rings):
    """(u, v) points of the unit disk in rings of 6j, and their triangles."""
    points = [(0.0, 0.0)]
    starts = [0]
    for j in range(1, rings + 1):
        starts.append(len(points))
        for i in range(6 * j):
            a = 2 * math.pi * i / (6 * j)
            points.append((j / rings * math.cos(a), j / rings * math.sin(a)))
    triangles = []
    for j in range(rings):
        inner = [0] if j == 0 else list(range(starts[j], starts[j] + 6 * j))
        outer = list(range(starts[j + 1], starts[j + 1] + 6 * (j + 1)))
        # walk both rings by angle, always advancing the one whose next vertex comes first
        ni, no = len(inner), len(outer)
        a = b = 0
        while a < ni or b < no:
            if j == 0:
                triangles.append((inner[0], outer[b % no], outer[(b + 1) % no]))
                b += 1
                if b >= no:
                    break
                continue
            next_inner = (a + 1) / ni
            next_outer = (b + 1) / no
            if b < no and (a >= ni or next_outer <= next_inner):
                triangles.append((inner[a % ni], outer[b % no], outer[(b + 1) % no]))
                b += 1
            else:
                triangles.append((inner[a % ni], outer[b % no], inner[(a + 1) % ni]))
                a += 1
    return points, triangles


def rotate(p, axis, degrees):
    n = math.sqrt(sum(c * c for c in axis))
    k = [c / n for c in axis]
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    dot = sum(k[i] * p[i] for i in range(3))
    cross = (k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0])
    return tuple(p[i] * c + cross[i] * s + k[i] * dot * (1 - c) for i in range(3))


def revolve(profile, rings, radius):
    """A bowl about z: ring at distance rho = radius * t lies at (r(t), z(t)) = profile(t)."""
    uv, triangles = hex_disk(rings)
    verts = []
    for u, v in uv:
        t = math.hypot(u, v)
        a = math.atan2(v, u)
        r, z = profile(t)
        verts.append((r * math.cos(a), r * math.sin(a), z))
    return verts, triangles


def write(path, comment, verts, triangles):
    with open(path, "w") as f:
        f.write(f"# {comment} (bench/make_bowl_targets.py)\n")
        for p in verts:
            f.write("v %.9g %.9g %.9g\n" % p)
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def scanned(verts, triangles, noise, holes):
    """Noise along random directions and holes cut around random vertices (a scan)."""
    lo = [min(p[i] for p in verts) for i in range(3)]
    hi = [max(p[i] for p in verts) for i in range(3)]
    diag = math.dist(lo, hi)
    verts = [tuple(c + rand.gauss(0, noise * diag) for c in p) for p in verts]
    for _ in range(holes):
        centre = verts[rand.randrange(len(verts))]
        cut = 0.06 * diag
        triangles = [t for t in triangles if min(math.dist(verts[i], centre) for i in t) > cut]
    return verts, triangles


def main(out):
    os.makedirs(out, exist_ok=True)
    # ellipsoidal cap: semi-axes 11 cm across, 7 cm deep, cut 5 cm below the equator... 20 cm
    a, c = 0.11, 0.07
    def ellipsoid(t):
        phi = t * math.radians(65)  # from the bottom
        return a * math.sin(phi), c * (1 - math.cos(phi))
    write(os.path.join(out, "ellipsoid_cap.obj"), "an ellipsoidal cap 20 cm across",
          *revolve(ellipsoid, 20, 1))

    # paraboloid with a flat bottom, 30 cm across, opening along +y
    R, flat = 0.15, 0.06
    def flat_paraboloid(t):
        r = R * t
        return r, 0.0 if r < flat else (r - flat) ** 2 / 0.12
    v, tr = revolve(flat_paraboloid, 24, 1)
    v = [rotate(p, (1, 0, 0), -90) for p in v]
    write(os.path.join(out, "flat_bottom.obj"), "a paraboloid with a flat bottom, 30 cm, along y",
          v, tr)

    # a bowl with a rim lip: a spherical cap to 55 degrees, then a lip flaring out flat, 12 cm
    rs = 0.045
    def lipped(t):
        if t < 0.8:
            phi = t / 0.8 * math.radians(55)
            return rs * math.sin(phi), rs * (1 - math.cos(phi))
        r0, z0 = rs * math.sin(math.radians(55)), rs * (1 - math.cos(math.radians(55)))
        s = (t - 0.8) / 0.2
        return r0 + 0.022 * s, z0 + 0.004 * math.sin(s * math.pi / 2)
    write(os.path.join(out, "lipped_bowl.obj"), "a bowl with a rim lip, 12 cm", *revolve(lipped, 18, 1))

    # a coarse hemisphere 9 cm across, tilted 35 degrees about (1, 1, 0), moved
    rh = 0.045
    def hemisphere(t):
        phi = t * math.pi / 2
        return rh * math.sin(phi), rh * (1 - math.cos(phi))
    v, tr = revolve(hemisphere, 7, 1)
    v = [tuple(x + s for x, s in zip(rotate(p, (1, 1, 0), 35), (0.2, -0.1, 0.05))) for p in v]
    write(os.path.join(out, "hemisphere_tilted.obj"), "a coarse hemisphere 9 cm, tilted 35 degrees",
          v, tr)

    # a wide shallow dish 40 cm across, 3 cm deep, axis along x, fine
    def dish(t):
        r = 0.2 * t
        return r, 0.03 * (1 - math.cos(math.pi * t)) / 2
    v, tr = revolve(dish, 40, 1)
    v = [rotate(p, (0, 1, 0), 90) for p in v]
    write(os.path.join(out, "wide_dish.obj"), "a shallow dish 40 cm across, along x", v, tr)

    # a scanned cap, upside down (opening along -z): 15 cm, noise 0.3% of its size, 3 holes
    rc = 0.1
    def cap(t):
        phi = t * math.radians(50)
        return rc * math.sin(phi), -rc * (1 - math.cos(phi))
    v, tr = scanned(*revolve(cap, 22, 1), 0.003, 3)
    write(os.path.join(out, "cap_scan.obj"), "an upside-down cap 15 cm, scanned: noise and holes",
          v, tr)

    # a small steep cup 7 cm across, 4 cm deep: z = depth * (r / R)^3
    def cup(t):
        return 0.035 * t, 0.04 * t ** 3
    write(os.path.join(out, "small_cup.obj"), "a small steep cup 7 cm", *revolve(cup, 12, 1))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: bench/make_bowl_targets.py OUTDIR")
    main(sys.argv[1])
