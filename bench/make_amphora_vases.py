#!/usr/bin/python3
"""Two vases for `fit` (issue 38, 2), made apart from curvefold and unlike the other generators
(awk grids, numpy grids, splines, Bezier, Hermite, elliptic fans, a helix, staggered B-spline
rings): the Python standard library only; each profile a closed formula of its own, lathed on
rows spaced by the profile's arc length (not its height), each row's vertex count following its
circumference (6 to 72), neighbouring rows of different counts zipped together (the next
vertex taken from whichever row lags in angle), so triangles differ in size and shape around
and along.

amphora_two_bulges: 32 cm tall, the axis pointing down and tilted (the lip below the foot), a
foot of 3.6 cm radius, a low bulge of 9.6 cm, a waist of 5.2 cm, a second, smaller bulge of 6.8
cm, a narrow neck of 2.6 cm and a lip flaring to 5.4 cm (a rational function: a sum of Cauchy
bumps, a flare 1 / (1 + ((1 - t) / 0.06)^2)); clean.

urn_oblique_scan: 24 cm tall, the axis tilted off every world axis (about (0.41, 0.73, 0.55)),
moved to (-0.3, 0.5, 0.2), a radius r(t) = 6.5 cm (1 + 0.25 sin(pi t) - 0.35 t^3 sin^2(2 pi t))
(a belly high up, a neck under a short lip), 0.5 mm of seeded noise along each vertex's normal
and two holes (the triangles within 2.2 cm of two surface points), as a scan leaves it.

Usage: bench/make_amphora_vases.py OUTDIR
"""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from formula_meshes import vertex_normals  # noqa: E402


def amphora(t):
    bump = lambda c, w: 1.0 / (1.0 + ((t - c) / w) ** 2)
    return (0.030 + 0.066 * bump(0.28, 0.16) + 0.022 * bump(0.62, 0.09) - 0.012 * bump(0.47, 0.05)
            - 0.010 * bump(0.85, 0.05) + 0.034 / (1.0 + ((1.0 - t) / 0.06) ** 2))


def urn(t):
    return 0.065 * (1 + 0.25 * math.sin(math.pi * t) - 0.35 * t ** 3 * math.sin(2 * math.pi * t) ** 2)


def rows_by_arc_length(profile, height, count, fine=2000):
    """Heights t in [0, 1] spaced evenly by the profile's arc length, measured on `fine` steps."""
    pts = [(profile(i / fine), height * i / fine) for i in range(fine + 1)]
    s = [0.0]
    for i in range(fine):
        s.append(s[-1] + math.dist(pts[i], pts[i + 1]))
    out, j = [], 0
    for k in range(count + 1):
        goal = s[-1] * k / count
        while j < fine - 1 and s[j + 1] < goal:
            j += 1
        f = (goal - s[j]) / max(s[j + 1] - s[j], 1e-15)
        out.append((j + f) / fine)
    return out


def lathe(profile, height, rows, spacing):
    """Vertices and triangles of the surface of revolution about +y (rows zipped)."""
    verts, rings = [], []
    for t in rows_by_arc_length(profile, height, rows):
        r = profile(t)
        n = max(6, min(72, round(2 * math.pi * r / spacing)))
        phase = 0.37 * len(rings)  # rows start at different angles
        ring = []
        for i in range(n):
            a = phase + 2 * math.pi * i / n
            ring.append(len(verts))
            verts.append((r * math.cos(a), t * height, r * math.sin(a), a))
        rings.append(ring)
    faces = []
    for lo, hi in zip(rings, rings[1:]):
        i = j = 0
        while i < len(lo) or j < len(hi):
            a = verts[lo[i % len(lo)]][3] + 2 * math.pi * (i // len(lo)) + 2 * math.pi / len(lo)
            b = verts[hi[j % len(hi)]][3] + 2 * math.pi * (j // len(hi)) + 2 * math.pi / len(hi)
            if j >= len(hi) or (i < len(lo) and a <= b):
                faces.append((lo[i % len(lo)], lo[(i + 1) % len(lo)], hi[j % len(hi)]))
                i += 1
            else:
                faces.append((lo[i % len(lo)], hi[(j + 1) % len(hi)], hi[j % len(hi)]))
                j += 1
    return [v[:3] for v in verts], faces


def rotate(axis, angle, p):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(angle), math.sin(angle)
    d = x * p[0] + y * p[1] + z * p[2]
    cr = (y * p[2] - z * p[1], z * p[0] - x * p[2], x * p[1] - y * p[0])
    return tuple(p[k] * c + cr[k] * s + (x, y, z)[k] * d * (1 - c) for k in range(3))


def write(path, comment, verts, faces):
    used = sorted({i for f in faces for i in f})
    index = {old: new + 1 for new, old in enumerate(used)}
    with open(path, "w") as out:
        out.write("# " + comment + "\n")
        for i in used:
            out.write("v %.7f %.7f %.7f\n" % verts[i])
        for f in faces:
            out.write("f %d %d %d\n" % tuple(index[i] for i in f))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_amphora_vases.py OUTDIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    rng = random.Random(1138)

    verts, faces = lathe(amphora, 0.32, 70, 0.008)
    verts = [rotate((1.0, 0.0, 0.3), math.radians(160.0), v) for v in verts]
    verts = [(v[0] + 0.05, v[1] + 0.25, v[2] - 0.1) for v in verts]
    write(os.path.join(sys.argv[1], "amphora_two_bulges.obj"),
          "amphora_two_bulges: make_amphora_vases.py (two bulges, narrow neck, flared lip, axis down)",
          verts, faces)

    verts, faces = lathe(urn, 0.24, 56, 0.007)
    ns = vertex_normals(verts, faces)
    verts = [tuple(v[k] + rng.gauss(0.0, 0.0005) * n[k] for k in range(3)) for v, n in zip(verts, ns)]
    holes = [verts[rng.randrange(len(verts))] for _ in range(2)]
    faces = [f for f in faces
             if all(math.dist(verts[f[0]], h) > 0.022 for h in holes)]
    verts = [rotate((0.8, -0.1, -0.6), math.radians(48.0), v) for v in verts]
    verts = [(v[0] - 0.3, v[1] + 0.5, v[2] + 0.2) for v in verts]
    write(os.path.join(sys.argv[1], "urn_oblique_scan.obj"),
          "urn_oblique_scan: make_amphora_vases.py (oblique axis, 0.5 mm noise, two holes)",
          verts, faces)


if __name__ == "__main__":
    main()
