#!/usr/bin/python3
"""Three smooth shapes for issue 38's designer targets, from formulas of their own (not those of
scripts/make-example-targets.sh or the other bench generators), in the catalogue's frame:

- vase20: a surface of revolution about the y axis, y in [-0.105, 0.105], radius
  r(y) = 0.045 + 0.011 sin(1.7 pi (y + 0.105) / 0.21) - 0.006 (2 (y + 0.105) / 0.21 - 1)^2
  (a belly low, a narrower neck), open at both ends; 72 x 36 quads, each split along
  alternate diagonals.
- bowl20: a catenary-profile bowl about the z axis, z = 0.055 (cosh(r / 0.075) - 1), r up to
  0.095, a fan at the centre and 24 rings of 80 points, the rings turned by half a step each
  (a lattice unlike a grid).
- saddle20: z = 2.2 (x^2 - y^2) + 0.6 x y over a disk-ish square |x|, |y| <= 0.1 with rounded
  corners (corner radius 0.03), triangulated from jittered points on a 41 x 41 lattice.

Usage: bench/make_judge20_shapes.py OUTDIR   (writes vase20.obj, bowl20.obj, saddle20.obj,
manifest.tsv naming cylinder, disk and square as each shape's --from)
"""
import math
import os
import random
import sys


def write(path, verts, faces):
    with open(path, "w") as f:
        name = os.path.basename(path)
        f.write("# %s: made from a formula by bench/make_judge20_shapes.py\n" % name)
        for v in verts:
            f.write("v %.7f %.7f %.7f\n" % tuple(v))
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def vase():
    nu, nv = 72, 36
    verts, faces = [], []
    for j in range(nv + 1):
        y = -0.105 + 0.21 * j / nv
        s = (y + 0.105) / 0.21
        r = 0.045 + 0.011 * math.sin(1.7 * math.pi * s) - 0.006 * (2 * s - 1) ** 2
        for i in range(nu):
            a = 2 * math.pi * i / nu
            verts.append((r * math.sin(a), y, r * math.cos(a)))
    for j in range(nv):
        for i in range(nu):
            a, b = j * nu + i, j * nu + (i + 1) % nu
            c, d = a + nu, b + nu
            if (i + j) % 2:
                faces += [(a, b, d), (a, d, c)]
            else:
                faces += [(a, b, c), (b, d, c)]
    return verts, faces


def bowl():
    rings, n = 24, 80
    verts, faces = [(0.0, 0.0, 0.0)], []
    for k in range(1, rings + 1):
        r = 0.095 * k / rings
        z = 0.055 * (math.cosh(r / 0.075) - 1)
        m = n if k > 3 else 8 * k
        for i in range(m):
            a = 2 * math.pi * (i + 0.5 * (k % 2)) / m
            verts.append((r * math.cos(a), r * math.sin(a), z))
    # Triangulate ring to ring by marching around both (rings of different counts near the centre).
    start = [0, 1]
    for k in range(1, rings + 1):
        start.append(start[-1] + (n if k > 3 else 8 * k))
    for i in range(8):
        faces.append((0, 1 + i, 1 + (i + 1) % 8))
    for k in range(1, rings):
        s0, m0 = start[k], start[k + 1] - start[k]
        s1, m1 = start[k + 1], start[k + 2] - start[k + 1]
        i = j = 0
        while i < m0 or j < m1:
            a0 = (i + 0.5 * (k % 2)) / m0
            a1 = (j + 0.5 * ((k + 1) % 2)) / m1
            if j >= m1 or (i < m0 and a0 < a1):
                faces.append((s0 + i % m0, s1 + j % m1, s0 + (i + 1) % m0))
                i += 1
            else:
                faces.append((s0 + i % m0, s1 + j % m1, s1 + (j + 1) % m1))
                j += 1
    return verts, faces


def saddle():
    rng = random.Random(20)
    n = 41
    h = 0.2 / (n - 1)
    idx, verts = {}, []
    for j in range(n):
        for i in range(n):
            x, y = -0.1 + i * h, -0.1 + j * h
            if 0 < i < n - 1 and 0 < j < n - 1:
                x += rng.uniform(-0.3, 0.3) * h
                y += rng.uniform(-0.3, 0.3) * h
            cx, cy = max(abs(x) - 0.07, 0.0), max(abs(y) - 0.07, 0.0)
            if math.hypot(cx, cy) > 0.03 + 1e-9:
                continue
            idx[i, j] = len(verts)
            verts.append((x, y, 2.2 * (x * x - y * y) + 0.6 * x * y))
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            q = [idx.get(p) for p in ((i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1))]
            a, b, c, d = q
            if None not in q:
                faces += [(a, b, c), (a, c, d)] if (i * 7 + j * 3) % 2 else [(a, b, d), (b, c, d)]
            else:
                have = [p for p in q if p is not None]
                if len(have) == 3:
                    faces.append(tuple(have))
    return verts, faces


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, make in (("vase20", vase), ("bowl20", bowl), ("saddle20", saddle)):
        write(os.path.join(out, name + ".obj"), *make())
    with open(os.path.join(out, "manifest.tsv"), "w") as f:
        for name, kind in (("vase20", "cylinder"), ("bowl20", "disk"), ("saddle20", "square")):
            f.write("%s\t%s\t\t0\tsmooth\n" % (name, kind))


if __name__ == "__main__":
    sys.exit(main())
