#!/usr/bin/python3
"""Vases with a V-shaped waist for `fit` (issue 38, 2), made apart from curvefold and unlike the
other generators (awk grids, numpy grids, splines, Bezier, Hermite, Catmull-Rom, elliptic fans,
a helix, staggered rings, arc-length rows zipped, Cauchy or Gaussian bumps, Rivara bisection,
twisted quads, marching tetrahedra): numpy only; each profile is the smooth minimum of two
curves, an ellipse (the belly) and a hyperbola r(h) = sqrt(r_n^2 + (k (h - h_n))^2) with one
slope k below the neck and another above it (a V with a rounded bottom, its two sides straight
far from the neck: the waist a paper artist folds); the surface is meshed by 4-to-1 midpoint
subdivision of a coarse ring mesh (every edge split at its middle, three times), each new vertex
put back on the surface by its height and angle, so the coarse mesh's irregular vertices stay and
the triangles follow the profile's slope in size; in millimetres, the axis tilted off every
world axis and moved off the origin.

waist_v_mm: 280 mm tall, belly 70 mm at 0.35 of the height, a neck of 18 mm (0.26 of the belly)
at 0.74 of it, its sides falling at slope 1.0 below and rising at 1.6 above, to a lip of 44 mm;
open at both ends; axis along (0.35, 0.9, -0.25), centred at (40, -25, 610) mm.

trumpet_waist_mm: 220 mm tall, belly 52 mm low down (0.22 of the height), a neck of 21 mm (0.40 of
the belly) at 0.5, then a long straight flare at slope 0.45 to a lip of 46 mm (the lip lies far
past the neck, not just over it); a closed-off base ring left open; axis along (-0.6, 0.2, 0.77),
centred at (-150, 300, 20) mm.

Also writes OUTDIR/targets.tsv (name, start kind, description, vertices, faces), the table
bench/run_judge_shapes.sh reads.

Usage: bench/make_hyperbola_neck_vases.py OUTDIR
"""
import argparse
import os

import numpy as np


def smooth_min(a, b, p=8.0):
    """A p-norm minimum of two positive radii: the smaller where they differ, rounded where close."""
    return (a ** -p + b ** -p) ** (-1.0 / p)


def profile(h, height, belly, belly_at, neck, neck_at, below, lip, foot):
    """The radius at height h (0 to height): the belly's ellipse and the neck's hyperbola, its
    slope above the neck set so the lip's radius is `lip` at the top."""
    hn = neck_at * height
    above = np.sqrt(lip ** 2 - neck ** 2) / (height - hn)
    semi = np.where(h < belly_at * height, 1.5 * belly_at, 1.1 * (neck_at - belly_at)) * height
    ellipse_at = lambda x: belly * np.sqrt(np.clip(1.0 - ((x - belly_at * height) / semi) ** 2, 0.01, None))
    # Past the neck the belly's curve rises steeply away: the hyperbola alone makes the lip (the
    # ellipse, 2-3 times the neck's radius there, weighs under a percent in the minimum).
    ellipse = np.where(h < hn, ellipse_at(np.minimum(h, hn)), ellipse_at(hn) + 10.0 * (h - hn))
    d = h - hn
    hyperbola = np.sqrt(neck ** 2 + (np.where(d < 0, below, above) * d) ** 2)
    r = smooth_min(ellipse, hyperbola)
    return np.maximum(r, foot * (1.0 - h / height))  # the base no narrower than the foot's cone


def coarse_mesh(rows, around):
    """A ring mesh of (angle, height) parameters, each quad cut along alternating diagonals."""
    par = [(2 * np.pi * (j + 0.5 * (i % 2)) / around, i / (rows - 1)) for i in range(rows)
           for j in range(around)]
    tris = []
    for i in range(rows - 1):
        for j in range(around):
            a, b = i * around + j, i * around + (j + 1) % around
            c, d = a + around, b + around
            tris += [(a, b, d), (a, d, c)] if (i + j) % 2 else [(a, b, c), (b, d, c)]
    return par, tris


def subdivide(par, tris):
    """Every triangle into four by its edges' midpoints in the (angle, height) domain (numpy:
    each edge's midpoint made once, by the edge's sorted ends)."""
    par, tris = np.asarray(par, float), np.asarray(tris, int)
    ends = np.sort(tris[:, [[0, 1], [1, 2], [2, 0]]], axis=2).reshape(-1, 2)
    edges, which = np.unique(ends, axis=0, return_inverse=True)
    u0, u1 = par[edges[:, 0], 0], par[edges[:, 1], 0]
    du = (u1 - u0 + np.pi) % (2 * np.pi) - np.pi  # across the seam the short way
    middles = np.column_stack([(u0 + 0.5 * du) % (2 * np.pi),
                               0.5 * (par[edges[:, 0], 1] + par[edges[:, 1], 1])])
    m = len(par) + which.reshape(-1, 3)  # the midpoints of edges ab, bc, ca of each triangle
    a, b, c = tris.T
    ab, bc, ca = m.T
    four = np.stack([np.column_stack(t) for t in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))])
    return np.vstack([par, middles]), four.reshape(-1, 3)


def frame(direction):
    """Two unit vectors across `direction` and the unit direction itself."""
    w = np.asarray(direction, float)
    w /= np.linalg.norm(w)
    u = np.cross(w, [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    return u, np.cross(w, u), w


def vase(shape, levels=3):
    par, tris = coarse_mesh(shape["rows"], shape["around"])
    for _ in range(levels):
        par, tris = subdivide(par, tris)
    height = shape["height"]
    h = par[:, 1] * height
    r = profile(h, height, shape["belly"], shape["belly_at"], shape["neck"], shape["neck_at"],
                shape["below"], shape["lip"], shape["foot"])
    u, v, w = frame(shape["axis"])
    pts = (np.cos(par[:, 0])[:, None] * r[:, None] * u + np.sin(par[:, 0])[:, None] * r[:, None] * v
           + (h - 0.5 * height)[:, None] * w + np.asarray(shape["centre"], float))
    return pts, tris


SHAPES = [
    dict(name="waist_v_mm", height=280.0, belly=70.0, belly_at=0.35, neck=18.0, neck_at=0.8,
         below=1.0, lip=44.0, foot=40.0, rows=7, around=7, axis=(0.35, 0.9, -0.25),
         centre=(40.0, -25.0, 610.0),
         what="a V waist (hyperbola) under a near lip, 280 mm, belly 70, neck 18, lip 44, tilted, mm"),
    dict(name="trumpet_waist_mm", height=220.0, belly=52.0, belly_at=0.22, neck=21.0, neck_at=0.5,
         below=0.8, lip=46.0, foot=30.0, rows=6, around=9, axis=(-0.6, 0.2, 0.77),
         centre=(-150.0, 300.0, 20.0),
         what="a low belly, a V waist at half height, a long straight flare to the lip, mm"),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", help="where the OBJ files and targets.tsv go")
    args = ap.parse_args()
    os.makedirs(args.dir, exist_ok=True)
    table = []
    for shape in SHAPES:
        pts, tris = vase(shape)
        path = os.path.join(args.dir, shape["name"] + ".obj")
        with open(path, "w") as out:
            out.write(f"# {shape['name']}: {shape['what']} (bench/make_hyperbola_neck_vases.py)\n")
            out.writelines(f"v {x:.5f} {y:.5f} {z:.5f}\n" for x, y, z in pts)
            out.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in tris.tolist())
        table.append((shape["name"], "cylinder", shape["what"], len(pts), len(tris)))
    with open(os.path.join(args.dir, "targets.tsv"), "w") as out:
        for row in table:
            out.write("\t".join(str(c) for c in row) + "\n")


if __name__ == "__main__":
    main()
