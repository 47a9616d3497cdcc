#!/usr/bin/python3
"""Smooth targets for `fit` made apart from curvefold (issue 38, 2): numpy formulas, written as OBJ.

Unlike scripts/make-example-targets.sh (awk, in the catalogue's frame) and fit_quality's own
shapes: other scales, axes off y and tilted, other resolutions and an irregular triangulation,
noise and holes (a scanned object). Usage: bench/make_smooth_targets.py OUTDIR
"""
import math
import os
import sys

import numpy as np

rng = np.random.default_rng(20261205)


def rotation(axis, degrees):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    a = math.radians(degrees)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * k @ k


def grid(nu, nv, point, wrap_u=False, jitter=0.0):
    """Vertices point(u, v) over [0,1]^2 (u jittered inside the grid), two triangles per cell."""
    us = np.linspace(0, 1, nu + 1)
    vs = np.linspace(0, 1, nv + 1)
    verts = []
    for j, v in enumerate(vs):
        for i, u in enumerate(us):
            du = dv = 0.0
            if jitter and 0 < i < nu and 0 < j < nv:
                du, dv = rng.uniform(-jitter, jitter, 2) / np.array([nu, nv])
            verts.append(point(u + du, v + dv))
    verts = np.array(verts)
    faces = []
    for j in range(nv):
        for i in range(nu):
            k = j * (nu + 1) + i
            a, b, c, d = k, k + 1, k + nu + 2, k + nu + 1
            # alternate the diagonal: a triangulation unlike the other generators'
            if (i + j) % 2:
                faces += [(a, b, c), (a, c, d)]
            else:
                faces += [(a, b, d), (b, c, d)]
    faces = np.array(faces)
    if wrap_u:  # glue the seam: last column onto the first
        index = np.arange(len(verts))
        for j in range(nv + 1):
            index[j * (nu + 1) + nu] = j * (nu + 1)
        faces = index[faces]
    return verts, faces


def place(verts, rot, shift):
    return verts @ rot.T + np.asarray(shift)


def add_noise(verts, faces, fraction):
    diag = np.linalg.norm(verts.max(0) - verts.min(0))
    return verts + rng.normal(0, fraction * diag, verts.shape)


def cut_holes(verts, faces, count, radius_fraction):
    diag = np.linalg.norm(verts.max(0) - verts.min(0))
    centres = verts[rng.choice(len(verts), count, replace=False)]
    mid = verts[faces].mean(1)
    keep = np.ones(len(faces), bool)
    for c in centres:
        keep &= np.linalg.norm(mid - c, axis=1) > radius_fraction * diag
    return faces[keep]


def write(path, verts, faces, comment):
    used = np.unique(faces)
    remap = -np.ones(len(verts), int)
    remap[used] = np.arange(len(used))
    with open(path, "w") as out:
        out.write(f"# {comment} (bench/make_smooth_targets.py)\n")
        for p in verts[used]:
            out.write(f"v {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
        for f in remap[faces]:
            out.write(f"f {f[0] + 1} {f[1] + 1} {f[2] + 1}\n")
    print("wrote", path, len(used), "vertices", len(faces), "triangles")


def vase_tilted():
    # 26 cm tall about an axis tilted off every coordinate axis: a foot, a belly, a neck, a lip.
    def point(u, v):
        t = v * 0.26
        r = 0.035 + 0.02 * math.sin(math.pi * v) ** 2 - 0.012 * v + 0.01 * max(0.0, v - 0.8) * 5
        a = 2 * math.pi * u
        return np.array([r * math.cos(a), r * math.sin(a), t - 0.13])

    v, f = grid(56, 30, point, wrap_u=True)
    return place(v, rotation([1, 0.4, 0.2], 70), [0.03, -0.02, 0.01]), f


def bowl_large():
    # A spherical cap 36 cm across and 9 cm deep opening along +y (rim radius 0.18, sphere 0.225).
    R, rim = 0.225, 0.18
    half = math.asin(rim / R)

    def point(u, v):
        a = 2 * math.pi * u
        phi = half * (0.03 + 0.97 * v)
        return np.array([R * math.sin(phi) * math.cos(a), R - R * math.cos(phi), R * math.sin(phi) * math.sin(a)])

    return grid(80, 20, point, wrap_u=True)


def bowl_small_tilted():
    # A round-bottomed bowl 7 cm across, z = 9 r^2 + 60 r^4 (profile of a cup), tilted 35 degrees.
    def point(u, v):
        a = 2 * math.pi * u
        r = 0.002 + 0.033 * v
        return np.array([r * math.cos(a), r * math.sin(a), 9 * r * r + 60 * r ** 4])

    v, f = grid(40, 16, point, wrap_u=True)
    return place(v, rotation([0.3, 1, 0], 35), [0, 0, 0.01]), f


def saddle_rotated():
    # z = x y / 0.16 (a saddle 45 degrees round from x^2 - y^2) over a 24 cm square, turned 30
    # degrees about z and tilted 15 degrees about x, on a jittered grid.
    def point(u, v):
        x, y = 0.24 * (u - 0.5), 0.24 * (v - 0.5)
        return np.array([x, y, x * y / 0.16])

    v, f = grid(36, 36, point, jitter=0.3)
    return place(v, rotation([1, 0, 0], 15) @ rotation([0, 0, 1], 30), [0.01, 0.0, -0.02]), f


def saddle_monkey_free():
    # A long saddle (pringle) over a disk of radius 9 cm: z = 0.5 (x^2 / a - y^2 / b), a != b.
    def point(u, v):
        a = 2 * math.pi * u
        r = 0.09 * math.sqrt(0.02 + 0.98 * v)
        x, y = r * math.cos(a), r * math.sin(a)
        return np.array([x, y, 0.5 * (x * x / 0.08 - y * y / 0.12)])

    return grid(64, 18, point, wrap_u=True)


def vase_scan():
    # A scanned vase about y, 18 cm tall: noise of 0.3% of the diagonal and four holes.
    def point(u, v):
        a = 2 * math.pi * u
        r = 0.05 - 0.018 * math.sin(math.pi * v * 1.2) + 0.004 * math.cos(6 * math.pi * v)
        return np.array([r * math.sin(a), 0.18 * (v - 0.5), r * math.cos(a)])

    v, f = grid(72, 40, point, wrap_u=True)
    v = add_noise(v, f, 0.003)
    return v, cut_holes(v, f, 4, 0.04)


def bowl_scan():
    # A scanned bowl (paraboloid 14 cm across, 5 cm deep, opening along +z): noise and holes.
    def point(u, v):
        a = 2 * math.pi * u
        r = 0.004 + 0.066 * v
        return np.array([r * math.cos(a), r * math.sin(a), 0.05 * (r / 0.07) ** 2])

    v, f = grid(60, 22, point, wrap_u=True)
    v = add_noise(v, f, 0.003)
    return v, cut_holes(v, f, 3, 0.05)


SHAPES = {
    "vase_tilted": (vase_tilted, "a vase about a tilted axis, 26 cm tall"),
    "vase_scan": (vase_scan, "a scanned vase about y with noise and holes"),
    "bowl_large": (bowl_large, "a spherical cap 36 cm across opening along y"),
    "bowl_small_tilted": (bowl_small_tilted, "a cup-shaped bowl 7 cm across, tilted"),
    "bowl_scan": (bowl_scan, "a scanned paraboloid bowl with noise and holes"),
    "saddle_rotated": (saddle_rotated, "a saddle z = xy/0.16, turned and tilted, jittered grid"),
    "saddle_disk": (saddle_monkey_free, "an unequal saddle over a disk"),
}


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_smooth_targets.py OUTDIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    for name, (make, comment) in SHAPES.items():
        v, f = make()
        write(os.path.join(sys.argv[1], name + ".obj"), v, f, comment)


if __name__ == "__main__":
    main()
