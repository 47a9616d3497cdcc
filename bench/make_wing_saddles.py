#!/usr/bin/python3
"""Saddles of two, three and four wings over irregular outlines, for `curvefold fit` (issue 38, 2).

Unlike the other saddle generators (grids, rings, lattices, fans, dart-thrown Delaunay meshes over
rounded outlines): points drawn uniformly at random in the unit disk (numpy, no spacing rule, so
triangles range from slivers to large ones) and a ring of random boundary points, triangulated in
the disk by Bowyer-Watson on numpy arrays, then mapped onto a lobed star outline
r(t) = R (1 + a2 cos(2 t + p2) + a5 cos(5 t + p5)) (random lobes), so no outline is a circle,
ellipse or rectangle. Heights z = c rho^k cos(k t) (k wings rising, k falling), with Gaussian
noise along z, then turned about a random axis and moved:
  wing_saddle_k2_mm.obj  k = 2, R 12 cm, slope about 3 at the rim, in millimetres;
  wing_saddle_k3.obj     k = 3 (a monkey saddle), R 12 cm, wings 7 cm high, in metres;
  wing_saddle_k4.obj     k = 4, R 14 cm, wings 5 cm high, in metres.
Usage: bench/make_wing_saddles.py OUT_DIR [--seed S] (default seed 23; deterministic).
"""
import os
import sys

import numpy as np


def delaunay(xy):
    """Triangles (index triples) of the Delaunay mesh of points `xy` (n x 2), Bowyer-Watson."""
    n = len(xy)
    pts = np.vstack([xy, [[-50.0, -50.0], [50.0, -50.0], [0.0, 50.0]]])
    tris = [(n, n + 1, n + 2)]
    centres = [None]

    def circle(t):
        a, b, c = pts[list(t)]
        d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
        sa, sb, sc = a @ a, b @ b, c @ c
        ux = (sa * (b[1] - c[1]) + sb * (c[1] - a[1]) + sc * (a[1] - b[1])) / d
        uy = (sa * (c[0] - b[0]) + sb * (a[0] - c[0]) + sc * (b[0] - a[0])) / d
        return ux, uy, (a[0] - ux) ** 2 + (a[1] - uy) ** 2

    centres[0] = circle(tris[0])
    for i in range(n):
        x, y = pts[i]
        cx = np.array([c[0] for c in centres])
        cy = np.array([c[1] for c in centres])
        r2 = np.array([c[2] for c in centres])
        bad = np.nonzero((cx - x) ** 2 + (cy - y) ** 2 < r2)[0]
        edges = {}
        for j in bad:
            a, b, c = tris[j]
            for e in ((a, b), (b, c), (c, a)):
                key = tuple(sorted(e))
                edges[key] = None if key in edges else e
        keep = np.ones(len(tris), bool)
        keep[bad] = False
        tris = [t for t, k in zip(tris, keep) if k]
        centres = [c for c, k in zip(centres, keep) if k]
        for e in edges.values():
            if e is None:
                continue
            t = (e[0], e[1], i)
            tris.append(t)
            centres.append(circle(t))
    out = []
    for a, b, c in tris:
        if max(a, b, c) >= n:
            continue
        # Counter-clockwise in the plane.
        u, v = pts[b] - pts[a], pts[c] - pts[a]
        out.append((a, b, c) if u[0] * v[1] - u[1] * v[0] > 0 else (a, c, b))
    return out


def rotation(rng):
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    angle = rng.uniform(0.3, 1.2)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def wing_saddle(rng, k, radius, height, interior, rim, noise):
    rho = np.sqrt(rng.uniform(0.0, 0.97, interior))
    t = rng.uniform(0.0, 2 * np.pi, interior)
    tb = np.sort(rng.uniform(0.0, 2 * np.pi, rim))
    rho = np.concatenate([rho, np.ones(rim)])
    t = np.concatenate([t, tb])
    disk = np.column_stack([rho * np.cos(t), rho * np.sin(t)])
    tris = delaunay(disk)
    a2, a5 = rng.uniform(0.1, 0.22), rng.uniform(0.04, 0.1)
    p2, p5 = rng.uniform(0, 2 * np.pi, 2)
    r = radius * rho * (1 + a2 * np.cos(2 * t + p2) + a5 * np.cos(5 * t + p5))
    x, y = r * np.cos(t), r * np.sin(t)
    z = height * (r / radius) ** k * np.cos(k * t) + rng.normal(0.0, noise, len(t))
    v = np.column_stack([x, y, z]) @ rotation(rng).T + rng.uniform(-0.05, 0.05, 3)
    return v, tris


def write_obj(path, v, tris, scale=1.0):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        for p in v * scale:
            f.write("v %.7g %.7g %.7g\n" % tuple(p))
        for a, b, c in tris:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    os.replace(tmp, path)


def main():
    args = sys.argv[1:]
    if not args or args[0].startswith("-"):
        sys.exit("usage: make_wing_saddles.py OUT_DIR [--seed S]")
    out, seed = args[0], 23
    if "--seed" in args:
        seed = int(args[args.index("--seed") + 1])
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(seed)
    # (name, k, R, wing height, interior points, rim points, noise, scale to the file's units)
    shapes = [("wing_saddle_k2_mm", 2, 0.12, 0.18, 900, 110, 0.0004, 1000.0),
              ("wing_saddle_k3", 3, 0.12, 0.07, 1100, 120, 0.0003, 1.0),
              ("wing_saddle_k4", 4, 0.14, 0.05, 1300, 140, 0.0003, 1.0)]
    for name, k, radius, height, interior, rim, noise, scale in shapes:
        v, tris = wing_saddle(rng, k, radius, height, interior, rim, noise)
        write_obj(os.path.join(out, name + ".obj"), v, tris, scale)
        print("%s.obj: %d vertices, %d triangles" % (name, len(v), len(tris)))


if __name__ == "__main__":
    main()
