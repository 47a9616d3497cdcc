#!/usr/bin/python3
"""A tilted teacup for `fit --from disk` (issue 38, 2), as OBJ, made apart from curvefold.

Unlike the other bowl generators (hexagonal disks, lattices, polar grids of a fixed count per
ring, closed-form or tabled profiles): Python's standard library only, the profile a flat bottom
and a cubic Bezier wall (a rounded heel, a wall near 80 degrees, a lip flaring out to about 60
degrees at the rim), sampled by arc length; each ring of the mesh has as many vertices as its
circumference holds at the ring spacing (so the triangles stay near equilateral from the centre
to the rim), and neighbouring rings of different counts are stitched by walking both at once
(whichever advances less around the turn goes next). The cup is turned 30 degrees about an
oblique axis and moved off the origin.

  teacup_tilted   9 cm across the rim, 5.5 cm deep, a flat bottom 4.4 cm across.

Usage: bench/make_teacup_targets.py OUTDIR
"""
import math
import os
import sys


def bezier(p0, p1, p2, p3, t):
    s = 1.0 - t
    return tuple(s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * c + t * t * t * d
                 for a, b, c, d in zip(p0, p1, p2, p3))


def profile_by_arc(spacing):
    """(r, z) points along the profile, `spacing` apart by arc length, from the centre."""
    foot = 0.022
    wall = [(foot, 0.0), (0.037, 0.0), (0.035, 0.036), (0.045, 0.055)]
    dense = [(foot * i / 200, 0.0) for i in range(200)]
    dense += [bezier(*wall, i / 2000) for i in range(2001)]
    points, walked, next_at = [dense[0]], 0.0, spacing
    for a, b in zip(dense, dense[1:]):
        step = math.dist(a, b)
        while walked + step >= next_at:
            f = (next_at - walked) / step
            points.append((a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])))
            next_at += spacing
        walked += step
    if math.dist(points[-1], dense[-1]) > 0.3 * spacing:
        points.append(dense[-1])
    else:
        points[-1] = dense[-1]
    return points


def revolve(profile, spacing):
    verts, rings = [], []
    for r, z in profile:
        count = 1 if r == 0.0 else max(6, round(2 * math.pi * r / spacing))
        start = len(verts)
        for i in range(count):
            a = 2 * math.pi * i / count
            verts.append((r * math.cos(a), r * math.sin(a), z))
        rings.append((start, count))
    triangles = []
    for (s0, n0), (s1, n1) in zip(rings, rings[1:]):
        i = j = 0
        while i < n0 or j < n1:
            # advance the ring whose next vertex comes first around the turn
            if j < n1 and (i >= n0 or (j + 1) / n1 <= (i + 1) / n0):
                triangles.append((s0 + i % n0, s1 + j % n1, s1 + (j + 1) % n1))
                j += 1
            else:
                triangles.append((s0 + i % n0, s1 + j % n1, s0 + (i + 1) % n0))
                i += 1
    return verts, [t for t in triangles if len(set(t)) == 3]


def turned(verts, axis, degrees, offset):
    n = math.sqrt(sum(c * c for c in axis))
    x, y, z = (c / n for c in axis)
    a = math.radians(degrees)
    c, s, k = math.cos(a), math.sin(a), 1 - math.cos(a)
    m = [[c + x * x * k, x * y * k - z * s, x * z * k + y * s],
         [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
         [z * x * k - y * s, z * y * k + x * s, c + z * z * k]]
    return [tuple(sum(m[r][i] * p[i] for i in range(3)) + offset[r] for r in range(3))
            for p in verts]


def main(out):
    os.makedirs(out, exist_ok=True)
    verts, triangles = revolve(profile_by_arc(0.0025), 0.0025)
    verts = turned(verts, (0.6, 1.0, 0.2), 30.0, (0.12, -0.05, 0.3))
    with open(os.path.join(out, "teacup_tilted.obj"), "w") as f:
        f.write("# a teacup 9 cm across, 5.5 cm deep, flared lip, tilted (bench/make_teacup_targets.py)\n")
        for v in verts:
            f.write("v %.7f %.7f %.7f\n" % v)
        for t in triangles:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
