#!/usr/bin/python3
"""Saddle targets for `curvefold fit` made apart from curvefold (issue 38, 2), in pure Python.

Unlike bench/make_saddle_targets.py (grids, polar rings), bench/make_saddle_scatter.py (jittered
grids) and bench/make_saddle_lattice.awk (awk lattices): scattered points (dart throwing, uneven
density) joined by a Delaunay triangulation (Bowyer-Watson) in the plane, so triangles vary in
size and shape and no row or ring of edges exists:
  horse_saddle.obj  z = x^2/0.5 - y^2/0.2 (uneven curvatures) over a 30 x 22 cm rounded
                    rectangle, points twice as dense at one end, turned 30 degrees about z;
  pringle.obj       z = (x^2 - y^2)/0.12 over a 9 x 6 cm ellipse (a chip), tilted 25 degrees
                    and moved off the origin;
  hypar_disk_scan.obj  z = x y/0.18 over a disk r 13 cm, turned 30, noise 0.4 mm along z,
                    two holes, a few triangles dropped at random.
Usage: bench/make_saddle_delaunay.py OUTDIR (deterministic: a fixed seed).
"""
import math
import os
import random
import sys

from formula_meshes import place, write_obj


def darts(inside, box, spacing, rng, tries=30000):
    """Points inside `inside(x, y)`, each at least spacing(x, y) from the others (dart throwing)."""
    (x0, y0), (x1, y1) = box
    pts = []
    for _ in range(tries):
        x, y = rng.uniform(x0, x1), rng.uniform(y0, y1)
        if not inside(x, y):
            continue
        s = spacing(x, y)
        if all((x - px) ** 2 + (y - py) ** 2 >= s * s for px, py in pts):
            pts.append((x, y))
    return pts


def circumcircle(a, b, c):
    d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    if abs(d) < 1e-18:
        return (0.0, 0.0, float("inf"))
    ux = ((a[0] ** 2 + a[1] ** 2) * (b[1] - c[1]) + (b[0] ** 2 + b[1] ** 2) * (c[1] - a[1]) +
          (c[0] ** 2 + c[1] ** 2) * (a[1] - b[1])) / d
    uy = ((a[0] ** 2 + a[1] ** 2) * (c[0] - b[0]) + (b[0] ** 2 + b[1] ** 2) * (a[0] - c[0]) +
          (c[0] ** 2 + c[1] ** 2) * (b[0] - a[0])) / d
    return (ux, uy, (a[0] - ux) ** 2 + (a[1] - uy) ** 2)


def delaunay(pts):
    """Bowyer-Watson: triangles (index triples, counter-clockwise) of the points' Delaunay mesh."""
    big = 100.0
    p = list(pts) + [(-big, -big), (big, -big), (0.0, big)]
    n = len(pts)
    tris = {(n, n + 1, n + 2): circumcircle(p[n], p[n + 1], p[n + 2])}
    for i in range(n):
        x, y = p[i]
        bad = [t for t, (cx, cy, r2) in tris.items() if (x - cx) ** 2 + (y - cy) ** 2 < r2]
        edges = {}
        for t in bad:
            for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                key = tuple(sorted(e))
                edges[key] = None if key in edges else e
            del tris[t]
        for e in edges.values():
            if e is not None:
                t = (e[0], e[1], i)
                tris[t] = circumcircle(p[t[0]], p[t[1]], p[t[2]])
    out = []
    for a, b, c in tris:
        if max(a, b, c) >= n:
            continue
        cross = (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0])
        out.append((a, b, c) if cross > 0 else (a, c, b))
    return out


def boundary_points(curve, count):
    return [curve(2 * math.pi * k / count) for k in range(count)]


def shape(rim, inside, box, spacing, rim_count, rng):
    # The rim's points moved inward at random by up to 0.3%: points on one circle make the
    # Delaunay test tie (and the triangulation overlap).
    pts = [(x * (1 - 0.003 * rng.random()), y * (1 - 0.003 * rng.random()))
           for x, y in boundary_points(rim, rim_count)]
    pts += [q for q in darts(inside, box, spacing, rng) if inside(q[0] * 1.03, q[1] * 1.03)]
    # Triangles of the convex hull outside a concave rim would be kept by Delaunay: drop those
    # whose centroid lies outside.
    tris = [t for t in delaunay(pts)
            if inside(sum(pts[i][0] for i in t) / 3, sum(pts[i][1] for i in t) / 3)]
    return pts, tris


def write(path, comment, verts, tris):
    write_obj(path, comment, "bench/make_saddle_delaunay.py", verts, tris)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_saddle_delaunay.py OUTDIR")
    outdir = sys.argv[1]
    os.makedirs(outdir, exist_ok=True)
    rng = random.Random(77)

    # Horse saddle: a rounded rectangle 30 x 22 cm (superellipse), twice as dense at x > 0.
    a, b, m = 0.15, 0.11, 4.0

    def rect_inside(x, y):
        return abs(x / a) ** m + abs(y / b) ** m <= 1.0

    def rect_rim(t):
        c, s = math.cos(t), math.sin(t)
        return (a * math.copysign(abs(c) ** (2 / m), c), b * math.copysign(abs(s) ** (2 / m), s))
    pts, tris = shape(rect_rim, rect_inside, ((-a, -b), (a, b)),
                      lambda x, y: 0.011 if x < 0 else 0.0075, 90, rng)
    verts = [place((x, y, x * x / 0.5 - y * y / 0.2), 30, 0, (0.02, 0.01, 0.0)) for x, y in pts]
    write(os.path.join(outdir, "horse_saddle.obj"),
          "z = x^2/0.5 - y^2/0.2 over a 30 x 22 cm rounded rectangle, Delaunay, turned 30", verts,
          tris)

    # Pringle: a chip 9 x 6 cm, strongly curved.
    ea, eb = 0.045, 0.03
    pts, tris = shape(lambda t: (ea * math.cos(t), eb * math.sin(t)),
                      lambda x, y: (x / ea) ** 2 + (y / eb) ** 2 <= 1.0, ((-ea, -eb), (ea, eb)),
                      lambda x, y: 0.0028 + 0.002 * (x + ea) / (2 * ea), 64, rng)
    verts = [place((x, y, (x * x - y * y) / 0.12), -15, 25, (0.1, -0.05, 0.02)) for x, y in pts]
    write(os.path.join(outdir, "pringle.obj"), "z = (x^2 - y^2)/0.12 over a 9 x 6 cm ellipse, tilted",
          verts, tris)

    # A scanned hypar over a disk: noise, two holes, some triangles missing.
    r = 0.13
    pts, tris = shape(lambda t: (r * math.cos(t), r * math.sin(t)),
                      lambda x, y: x * x + y * y <= r * r, ((-r, -r), (r, r)),
                      lambda x, y: 0.008 + 0.006 * (y + r) / (2 * r), 80, rng)
    holes = [((0.05, -0.03), 0.022), ((-0.06, 0.06), 0.016)]

    def kept(t):
        cx = sum(pts[i][0] for i in t) / 3
        cy = sum(pts[i][1] for i in t) / 3
        return all(math.dist((cx, cy), c) > hr for c, hr in holes) and rng.random() > 0.01
    tris = [t for t in tris if kept(t)]
    verts = [place((x, y, x * y / 0.18 + rng.gauss(0.0, 0.0004)), 30, 0, (0.0, 0.0, 0.1))
             for x, y in pts]
    write(os.path.join(outdir, "hypar_disk_scan.obj"),
          "z = xy/0.18 over a disk r 13 cm, Delaunay, noise 0.4 mm, two holes", verts, tris)


if __name__ == "__main__":
    main()
